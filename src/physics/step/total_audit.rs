//! The total-energy audit of a step. The kinetic audit ([`super::audit`])
//! compares kinetic energy around the resolver; a resolution that leaves a
//! body rising with little kinetic energy (a slender box kicked up at one
//! corner, then another) passes it, and the gain shows as potential energy
//! once the position update has carried the body up. This audit adds the
//! potential energy in the gravity field: for the bodies in a contact this
//! step,
//!
//! `E = Σ ½ m v·v + ½ ωᵀ I ω − m g·x`
//!
//! at the step's start and at its end as the position update gives it
//! (`x + v' Δt` with the resolved velocity v'), less the potential energy the
//! position phase added (projection's lift, an event of its own). Gravity
//! alone loses `½ m |g|² Δt²` a step (symplectic Euler) and damping loses
//! too, so the end may exceed the start only through the resolution. A rise
//! above the tolerance
//!
//! `Σ m (|g| ε_v Δt + ½ ε_v²)`
//!
//! (the bodies left moving at the velocity epsilon ε_v, the closing speed
//! the velocity phase leaves alone, and lifted at it for one step) is an
//! event, and its cause is found by the same replay as the kinetic audit's.

use nalgebra::{Matrix3, Vector3};

use crate::physics::{to_f64, Real, World};

/// Total energy `½ m v·v + ½ ωᵀ I ω − m g·x` of body `i` (J; 0 when
/// immovable), with its world inertia `R I Rᵀ` when the step holds it.
pub fn body_total<T: Real>(
    world: &World<T>,
    i: usize,
    gravity: &Vector3<T>,
    inertia: Option<&Matrix3<T>>,
) -> f64 {
    world.bodies[i].dynamic().map_or(0.0, |b| {
        let (v, w) = (&b.velocity, &b.angular_velocity);
        let kinetic = match inertia {
            Some(inertia) => b.kinetic_energy_with(inertia, v, w),
            None => b.kinetic_energy(v, w),
        };
        to_f64(kinetic - b.mass * gravity.dot(&b.position))
    })
}

/// The tolerance of a step: `Σ m (|g| ε_v Δt + ½ ε_v²)` over the bodies of
/// total mass `mass` (J).
pub fn tolerance(mass: f64, gravity: f64, velocity_epsilon: f64, dt: f64) -> f64 {
    mass * (gravity * velocity_epsilon * dt + 0.5 * velocity_epsilon * velocity_epsilon)
}

/// The bodies in contact this step and their energy at its start.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TotalStart<'a> {
    /// `touched[i]`: body `i` is in one of the step's contacts.
    pub touched: &'a [bool],
    /// Their total energy at the step's start (J).
    pub energy: f64,
    /// Their mass (kg).
    pub mass: f64,
    pub dt: f64,
    /// What a step may add before it is an event (J).
    pub tolerance: f64,
}

impl TotalStart<'_> {
    /// The rise of a step that ends with `end` J, when above the tolerance.
    pub fn rise(&self, end: f64) -> Option<f64> {
        let gained = end - self.energy;
        let rounding = 1e-9 * self.energy.abs().max(1e-12);
        (gained > self.tolerance + rounding).then_some(gained)
    }
}

/// The audit's storage, kept from step to step (nothing is allocated once
/// it holds a world this size).
#[derive(Debug, Clone, Default)]
pub struct TotalAudit {
    start: Vec<f64>,
    touched: Vec<bool>,
}

/// Whether the last step rose (an event when it starts, as the kinetic
/// audit's), and the bodies in contact over the steps of the rise going on:
/// a rise that takes in a body not among them is a new one, with its event
/// (a ball's rise going on hid the next ball's, +6.6 J with no event).
#[derive(Debug, Clone, Default)]
pub struct RiseStreak {
    rising: bool,
    bodies: Vec<bool>,
}

impl RiseStreak {
    /// Whether this step's rise (`rises`) is a new one, to be reported:
    /// the last step did not rise, or this one takes in a body the rise
    /// going on did not; and the bodies of the rise going on, kept.
    pub fn new_rise(&mut self, rises: bool, touched: &[bool]) -> bool {
        let joined = (touched.iter().enumerate())
            .any(|(i, t)| *t && !self.bodies.get(i).copied().unwrap_or(false));
        let new = rises && (!self.rising || joined);
        if !rises || new {
            self.bodies.clear();
        }
        if rises {
            self.bodies.resize(touched.len(), false);
            for (was, t) in self.bodies.iter_mut().zip(touched) {
                *was |= *t;
            }
        }
        self.rising = rises;
        new
    }
}

impl TotalAudit {
    /// Each body's total energy at the step's start; `inertia[i]` is body
    /// `i`'s world inertia as `world` holds it (the step's, the same numbers).
    pub fn begin<T: Real>(
        &mut self,
        world: &World<T>,
        gravity: &Vector3<T>,
        inertia: &[Matrix3<T>],
    ) {
        self.start.clear();
        self.start
            .extend((0..world.bodies.len()).map(|i| body_total(world, i, gravity, inertia.get(i))));
    }

    /// The moving bodies (`moving(i)`: body `i` was integrated this step;
    /// a sleeper does not move) in `world`'s contacts (this step's), their
    /// start energy and mass, and the step's tolerance.
    pub fn start<T: Real>(
        &mut self,
        world: &World<T>,
        moving: impl Fn(usize) -> bool,
        gravity: f64,
        velocity_epsilon: f64,
        dt: f64,
    ) -> TotalStart<'_> {
        self.touched.clear();
        self.touched.resize(world.bodies.len(), false);
        // A pair's contacts follow one another: each pair marked once
        // (marking is the same for every contact of it).
        let mut last = None;
        for k in &world.contacts {
            if last.replace((k.body1, k.body2)) == Some((k.body1, k.body2)) {
                continue;
            }
            for id in k.slots().into_iter().flatten() {
                self.touched[id.0] = world.bodies[id.0].movable && moving(id.0);
            }
        }
        let (mut energy, mut mass) = (0.0, 0.0);
        for (i, _) in self.touched.iter().enumerate().filter(|(_, t)| **t) {
            energy += self.start.get(i).copied().unwrap_or(0.0);
            mass += world.bodies[i].dynamic().map_or(0.0, |b| to_f64(b.mass));
        }
        TotalStart {
            touched: &self.touched,
            energy,
            mass,
            dt,
            tolerance: tolerance(mass, gravity, velocity_epsilon, dt),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tolerance_is_the_velocity_epsilon_kept_and_lifted_for_a_step() {
        // 1 kg, |g| = 10, ε_v = 0.01 m/s, Δt = 0.1 s: 10 × 0.01 × 0.1 + ½ × 1e-4.
        assert!((tolerance(1.0, 10.0, 0.01, 0.1) - 0.01005).abs() < 1e-15);
        assert_eq!(tolerance(2.0, 0.0, 0.0, 0.1), 0.0);
    }

    #[test]
    fn a_rise_is_what_the_step_added_beyond_the_tolerance() {
        let touched = [true];
        let start = TotalStart {
            touched: &touched,
            energy: 1.0,
            mass: 1.0,
            dt: 0.1,
            tolerance: 0.01,
        };
        assert_eq!(start.rise(1.005), None);
        assert_eq!(start.rise(0.5), None);
        let gained = start.rise(1.02).expect("a rise");
        assert!((gained - 0.02).abs() < 1e-12);
    }
}
