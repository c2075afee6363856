//! A step's resolution run again from its inputs with switches off: the
//! experiment behind every energy event ([`super::audit`]). The inputs are
//! the world as the step hands it to the resolver (bodies after the
//! velocity update, this step's contacts) and last step's warm-start cache;
//! the step keeps them untouched until the resolver writes back, so nothing
//! is copied on the fast path: a re-run clones them only when a gain is
//! being explained.

use nalgebra::{Matrix3, Vector3};

use super::audit::{gain, EnergyCause, Switch, Switches};
use super::total_audit::TotalStart;
use crate::physics::resolver::sequential::WarmCache;
use crate::physics::resolver::{Implementation, Resolver, Silent};
use crate::physics::{to_f64, FrictionModel, Real, ResolverParams, Solver, World};

/// What one resolution did to the energy of the bodies it moved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolved {
    /// Kinetic energy of the resolved bodies before and after (J).
    pub kinetic_before: f64,
    pub kinetic_after: f64,
    /// Potential energy the position phase added, `−Σ m g·Δx` (J).
    pub potential_rise: f64,
    /// `Σ m |g|` over the resolved bodies (kg m/s², the weight that a lift
    /// is measured against).
    pub weight: f64,
}

/// Energy of `r`'s bodies before (as in `world`) and after resolution
/// (`½ m v·v + ½ ωᵀ I ω`, with I in the orientation after projection).
pub fn resolved<T: Real>(world: &World<T>, r: &Resolver<T>, gravity: &Vector3<T>) -> Resolved {
    resolved_with(world, r, gravity, None, &mut Vec::new())
}

/// [`resolved`] with each world body's inertia `R I Rᵀ` as `world` holds
/// it already at hand (`inertia[i]` for body `i`), the same numbers; each
/// resolver body's kinetic energy after is left in `kinetic_after` (by
/// resolver body), for [`total_after`].
pub fn resolved_with<T: Real>(
    world: &World<T>,
    r: &Resolver<T>,
    gravity: &Vector3<T>,
    inertia: Option<&[Matrix3<T>]>,
    kinetic_after: &mut Vec<T>,
) -> Resolved {
    kinetic_after.clear();
    let mut out = Resolved {
        kinetic_before: 0.0,
        kinetic_after: 0.0,
        potential_rise: 0.0,
        weight: 0.0,
    };
    for b in &r.bodies {
        let before = &world.body(b.id).state;
        let (v, w) = (&before.velocity, &before.angular_velocity);
        out.kinetic_before += to_f64(match inertia {
            Some(inertia) => before.kinetic_energy_with(&inertia[b.id.0], v, w),
            None => before.kinetic_energy(v, w),
        });
        // Unturned by the position phase, the body's inertia is the one at hand.
        let kinetic = match inertia {
            Some(inertia) if b.orientation == before.orientation => {
                before.kinetic_energy_with(&inertia[b.id.0], &b.velocity, &b.angular_velocity)
            }
            _ => {
                let mut after = before.clone();
                after.orientation = b.orientation;
                after.kinetic_energy(&b.velocity, &b.angular_velocity)
            }
        };
        kinetic_after.push(kinetic);
        out.kinetic_after += to_f64(kinetic);
        out.potential_rise -= to_f64(before.mass * gravity.dot(&(b.position - before.position)));
        out.weight += to_f64(before.mass * gravity.norm());
    }
    out
}

/// The total energy of the bodies in `touched` at the end of the step as
/// resolution `r` leaves them, less the projection's lift: kinetic energy
/// after resolution, and the potential energy at the positions before
/// projection moved on by the resolved velocity for `dt`
/// (`Σ ½ m v'·v' + ½ ω'ᵀ I ω' − m g·(x + v' Δt)`); the kinetic energies
/// after are `kinetic_after`'s when [`resolved_with`] left them for `r`.
pub fn total_after<T: Real>(
    world: &World<T>,
    r: &Resolver<T>,
    gravity: &Vector3<T>,
    dt: f64,
    touched: &[bool],
    kinetic_after: Option<&[T]>,
) -> f64 {
    let dt: T = crate::physics::c(dt);
    let mut total = 0.0;
    for (k, b) in r
        .bodies
        .iter()
        .enumerate()
        .filter(|(_, b)| touched.get(b.id.0) == Some(&true))
    {
        let before = &world.body(b.id).state;
        let kinetic = match kinetic_after.and_then(|e| e.get(k)) {
            Some(kinetic) => *kinetic,
            None => {
                let mut after = before.clone();
                after.orientation = b.orientation;
                after.kinetic_energy(&b.velocity, &b.angular_velocity)
            }
        };
        let end = before.position + b.velocity * dt;
        total += to_f64(kinetic - before.mass * gravity.dot(&end));
    }
    total
}

/// A step's resolution inputs.
#[derive(Debug, Clone, Copy)]
pub struct StepInputs<'a, T: Real> {
    /// Bodies after the velocity update; this step's contacts.
    pub world: &'a World<T>,
    pub params: &'a ResolverParams,
    /// Last step's accumulated impulses (used when warm starting).
    pub warm: &'a WarmCache<T>,
    pub gravity: Vector3<T>,
    /// The scene's energy scale (J), for what counts as a gain.
    pub scale: f64,
}

impl<T: Real> StepInputs<'_, T> {
    fn warm_starts(&self) -> bool {
        self.params.warm_start && self.params.solver == Solver::SequentialImpulse
    }

    /// The switches that change anything in this step.
    pub fn applicable(&self) -> Switches {
        let w = self.world;
        let any = |f: &dyn Fn(&crate::physics::Contact<T>) -> bool| w.contacts.iter().any(f);
        let mut s = Switches::empty();
        if any(&|k| k.input.restitution > T::zero() && k.input.has_friction()) {
            s.insert(Switch::RestitutionWithFriction);
        }
        for (model, switch) in [
            (FrictionModel::VelocityScaling, Switch::VelocityScaling),
            (FrictionModel::KineticDirection, Switch::KineticDirection),
        ] {
            if any(&|k| k.input.has_friction() && k.input.friction_model == model) {
                s.insert(switch);
            }
        }
        if self.warm_starts() && !self.warm.is_empty() {
            s.insert(Switch::WarmStart);
        }
        let accelerated = w
            .bodies
            .iter()
            .filter_map(|b| b.dynamic())
            .any(|b| b.acceleration.iter().any(|a| *a != T::zero()));
        let compensated = any(&|k| k.duration.is_none_or(|d| d != T::zero()));
        if accelerated && compensated && w.step.duration != T::zero() {
            s.insert(Switch::AccelerationCompensation);
        }
        if !w.contacts.is_empty() {
            s.insert(Switch::Projection);
        }
        if any(&|k| k.input.has_friction()) {
            s.insert(Switch::Friction);
        }
        if any(&|k| k.input.restitution > T::zero()) {
            s.insert(Switch::Restitution);
        }
        if self.params.solver == Solver::DeepestFirst && w.contacts.len() > 1 {
            s.insert(Switch::OneAtATime);
        }
        s
    }

    /// The step's resolution again with `off` switched off.
    pub fn replay(&self, off: Switches) -> Resolved {
        let (world, r) = self.replayed(off);
        resolved(&world, &r, &self.gravity)
    }

    /// The world with `off` switched off on its contacts, and the
    /// resolution of it.
    fn replayed(&self, off: Switches) -> (World<T>, Resolver<T>) {
        let mut world = self.world.clone();
        for k in &mut world.contacts {
            let friction = k.input.has_friction();
            if off.contains(Switch::RestitutionWithFriction) && friction {
                k.input.restitution = T::zero();
            }
            let model = k.input.friction_model;
            if (off.contains(Switch::VelocityScaling) && model == FrictionModel::VelocityScaling)
                || (off.contains(Switch::KineticDirection)
                    && model == FrictionModel::KineticDirection)
            {
                k.input.friction_model = FrictionModel::Millington;
            }
            if off.contains(Switch::Friction) {
                k.input.static_friction = T::zero();
                k.input.dynamic_friction = T::zero();
            }
            if off.contains(Switch::Restitution) {
                k.input.restitution = T::zero();
            }
            if off.contains(Switch::AccelerationCompensation) {
                k.duration = Some(T::zero());
            }
        }
        let mut params = *self.params;
        if off.contains(Switch::WarmStart) {
            params.warm_start = false;
        }
        if off.contains(Switch::OneAtATime) {
            params.solver = Solver::SequentialImpulse;
            params.warm_start = false;
            world.step.speculative = false;
        }
        let mut r = Resolver::prepare(&world, &params);
        if self.warm_starts() && params.warm_start {
            self.warm.stage(&world, &mut r);
        }
        if !off.contains(Switch::Projection) {
            r.position_phase(Implementation::Indexed, &mut Silent);
        }
        r.velocity_phase(Implementation::Indexed, &mut Silent);
        (world, r)
    }

    /// Whether the step, re-run with `off` switched off, still gains kinetic energy.
    pub fn gains(&self, off: Switches) -> Option<f64> {
        let e = self.replay(off);
        gain(e.kinetic_before, e.kinetic_after, self.scale)
    }

    /// Whether the step, re-run with `off` switched off, still raises the
    /// total energy of the bodies in contact above the audit's tolerance
    /// ([`super::total_audit`]).
    pub fn rises(&self, off: Switches, start: &TotalStart<'_>) -> Option<f64> {
        let (_, r) = self.replayed(off);
        start.rise(total_after(
            self.world,
            &r,
            &self.gravity,
            start.dt,
            start.touched,
            None,
        ))
    }

    /// The causes of a kinetic-energy gain, by experiment (see [`Self::attribute_by`]).
    pub fn attribute(&self) -> EnergyCause {
        self.attribute_by(|off| self.gains(off))
    }

    /// The causes of a total-energy rise, by the same experiments.
    pub fn attribute_rise(&self, start: &TotalStart<'_>) -> EnergyCause {
        self.attribute_by(|off| self.rises(off, start))
    }

    /// The causes of what `still` finds (a gain with the switches given
    /// off), by experiment: each applicable narrow switch on its own, then
    /// each broad one, then the order, then all together.
    fn attribute_by(&self, still: impl Fn(Switches) -> Option<f64>) -> EnergyCause {
        let tried = self.applicable();
        let removes = |tier: u8| -> Switches {
            tried
                .iter()
                .filter(|s| s.tier() == tier && still(Switches::one(*s)).is_none())
                .collect()
        };
        let each = (0..3)
            .map(removes)
            .find(|each| !each.is_empty())
            .unwrap_or_default();
        if !each.is_empty() {
            EnergyCause::Each(each)
        } else if tried.len() > 1 && still(tried).is_none() {
            EnergyCause::Together(tried)
        } else {
            EnergyCause::Unexplained { tried }
        }
    }
}
