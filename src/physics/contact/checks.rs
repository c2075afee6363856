//! Invariants checked after a contact is resolved: momentum, restitution,
//! energy, the friction cone, slip, penetration actually removed, unit quaternions.

use nalgebra::{UnitQuaternion, Vector3};

use super::causes::{self, tolerance, Cause};
use super::stages::{
    AppliedImpulse, ContactFrame, DesiredVelocity, FrictionClamp, Impulse, OrientationUpdate,
    Projection,
};
use super::{Problem, Real};
use crate::physics::scale::{stable_hypot, stable_norm as norm, stable_norm_quaternion};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CheckKind {
    /// Σ m v before = after (two movable bodies).
    LinearMomentum,
    /// Each body's angular momentum about the contact point is unchanged.
    AngularMomentum(usize),
    /// Normal separating velocity after = v_s + Δv (= -c v_s without acceleration).
    Restitution,
    /// Kinetic energy must not rise.
    Energy,
    /// g_n ≥ 0 and |g_t| ≤ μ_s g_n.
    FrictionCone,
    /// Tangential slip speed after ≤ before.
    Slip,
    /// Separation actually gained by the finite move against the depth to resolve.
    ResidualPenetration,
    /// |θ'| = 1 after normalising.
    UnitQuaternion(usize),
}

/// What one check measured. The trace names these numbers (the `checks`
/// stage's JSON values); physics only computes them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Measured<T: Real> {
    /// |Σ m v after - Σ m v before|.
    LinearMomentum { error: T },
    /// |L after - L before| of body slot `body` about q.
    AngularMomentum { body: usize, error: T },
    /// Normal separating velocity before and after, and the target v_s + Δv.
    Restitution { before: T, after: T, expected: T },
    /// Kinetic energy before and after, and `after - before`.
    Energy { before: T, after: T, change: T },
    /// Normal and tangential impulse (contact space) and the cone's μ g_n.
    FrictionCone { normal: T, tangential: T, limit: T },
    /// Tangential slip speed before and after.
    Slip { before: T, after: T },
    /// Depth to resolve, separation the finite move gained, what is left.
    ResidualPenetration { depth: T, gained: T, residual: T },
    /// | |θ′| - 1 | of body slot `body`.
    UnitQuaternion { body: usize, error: T },
}

impl<T: Real> Measured<T> {
    /// Which check this is.
    pub fn kind(&self) -> CheckKind {
        match *self {
            Measured::LinearMomentum { .. } => CheckKind::LinearMomentum,
            Measured::AngularMomentum { body, .. } => CheckKind::AngularMomentum(body),
            Measured::Restitution { .. } => CheckKind::Restitution,
            Measured::Energy { .. } => CheckKind::Energy,
            Measured::FrictionCone { .. } => CheckKind::FrictionCone,
            Measured::Slip { .. } => CheckKind::Slip,
            Measured::ResidualPenetration { .. } => CheckKind::ResidualPenetration,
            Measured::UnitQuaternion { body, .. } => CheckKind::UnitQuaternion(body),
        }
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct CheckItem<T: Real> {
    /// `None` for a check that informs rather than passes or fails.
    pub passed: Option<bool>,
    pub measured: Measured<T>,
    /// Why a check failed, or why a result that looks like a failure is
    /// not one (`physics::contact::causes`).
    pub cause: Option<Cause<T>>,
}

impl<T: Real> CheckItem<T> {
    pub fn kind(&self) -> CheckKind {
        self.measured.kind()
    }

    /// The check's values by their JSON names, in the order the `checks`
    /// stage lists them (suffix 1 or 2 is the body slot): identifiers, as
    /// stage ids are, from this one place.
    pub fn named_values(&self) -> Vec<(&'static str, T)> {
        let item = self;
        let named = |pairs: &[(&'static str, T)]| -> Vec<(&'static str, T)> { pairs.to_vec() };
        match item.measured {
            Measured::LinearMomentum { error } => named(&[("linear_momentum_error", error)]),
            Measured::AngularMomentum { body, error } => {
                let names = ["angular_momentum_error1", "angular_momentum_error2"];
                vec![(names[body], error)]
            }
            Measured::Restitution {
                before,
                after,
                expected,
            } => named(&[
                ("separating_velocity_before", before),
                ("separating_velocity", after),
                ("separating_velocity_expected", expected),
            ]),
            Measured::Energy {
                before,
                after,
                change,
            } => named(&[
                ("energy_before", before),
                ("energy_after", after),
                ("energy_change", change),
            ]),
            Measured::FrictionCone {
                normal,
                tangential,
                limit,
            } => named(&[
                ("normal_impulse", normal),
                ("tangential_impulse", tangential),
                ("cone_limit", limit),
            ]),
            Measured::Slip { before, after } => {
                named(&[("slip_speed_before", before), ("slip_speed_after", after)])
            }
            Measured::ResidualPenetration {
                depth,
                gained,
                residual,
            } => named(&[
                ("depth_to_resolve", depth),
                ("separation_gained", gained),
                ("residual_penetration", residual),
            ]),
            Measured::UnitQuaternion { body, error } => {
                let names = ["orientation_norm_error1", "orientation_norm_error2"];
                vec![(names[body], error)]
            }
        }
    }
}

#[derive(Debug, Clone, PartialEq, Default)]
pub struct Checks<T: Real> {
    pub items: Vec<CheckItem<T>>,
}

impl<T: Real> Checks<T> {
    pub fn all_passed(&self) -> bool {
        self.items.iter().all(|i| i.passed != Some(false))
    }

    pub fn get(&self, kind: CheckKind) -> Option<&CheckItem<T>> {
        self.items.iter().find(|i| i.kind() == kind)
    }
}

/// Inputs of the checks: the stage records they read.
pub struct CheckInputs<'a, T: Real> {
    pub problem: &'a Problem<T>,
    pub frame: &'a ContactFrame<T>,
    /// The friction matrix `M` (the unit-impulse stage's), for κ(M) in the causes.
    pub matrix: Option<&'a nalgebra::Matrix3<T>>,
    pub desired: &'a DesiredVelocity<T>,
    pub impulse: Option<&'a Impulse<T>>,
    pub applied: Option<&'a AppliedImpulse<T>>,
    pub friction: Option<&'a FrictionClamp<T>>,
    pub projection: Option<&'a Projection<T>>,
    pub orientation: Option<&'a OrientationUpdate<T>>,
}

fn item<T: Real>(passed: Option<bool>, measured: Measured<T>) -> CheckItem<T> {
    CheckItem {
        passed,
        measured,
        cause: None,
    }
}

/// A check's item with the cause that explains it: passed, unless `cause`
/// says why not; a limit of the arithmetic (round-off of an ill-conditioned
/// solve, the fallback of a failed one) only informs (`None`); anything else
/// is a defect of the model, named.
fn explained<T: Real>(cause: Option<Cause<T>>, measured: Measured<T>) -> CheckItem<T> {
    let passed = match cause {
        None => Some(true),
        Some(
            Cause::RoundOff { .. } | Cause::FrictionlessFallback | Cause::PlanarAcceleration { .. },
        ) => None,
        Some(_) => Some(false),
    };
    CheckItem {
        passed,
        measured,
        cause,
    }
}

pub fn run_checks<T: Real>(input: &CheckInputs<'_, T>) -> Checks<T> {
    let tol = tolerance::<T>();
    let mut items = Vec::new();
    if let Some(applied) = input.applied {
        velocity_checks(input, applied, tol, &mut items);
    }
    if let Some(projection) = input.projection {
        position_checks(input, projection, tol, &mut items);
    }
    Checks { items }
}

fn velocity_checks<T: Real>(
    input: &CheckInputs<'_, T>,
    applied: &AppliedImpulse<T>,
    tol: T,
    items: &mut Vec<CheckItem<T>>,
) {
    let problem = input.problem;
    let q = problem.contact.point;
    let d = input.frame.normal();
    // Each body's world inertia R I Rᵀ once, for momentum and energy.
    // (A fixed pair of slots, not a Vec: nothing allocated.)
    let slots = [0, 1].map(|i| {
        let b = problem.bodies[i].as_ref()?;
        Some((i, b, applied.bodies[i].as_ref()?, b.inertia_world()))
    });
    let pairs = || slots.iter().flatten();

    if pairs().count() == 2 {
        let (mut before, mut after, mut scale) = (Vector3::zeros(), Vector3::zeros(), T::zero());
        for (_, b, a, _) in pairs() {
            before += b.velocity * b.mass;
            after += a.v * b.mass;
            scale += norm(&(b.velocity * b.mass)) + norm(&a.impulse);
        }
        let error = norm(&(after - before));
        items.push(item(
            Some(error <= tol * scale),
            Measured::LinearMomentum { error },
        ));
    }

    for (i, b, a, inertia) in pairs() {
        let before = b.angular_momentum_about_with(inertia, &q, &b.velocity, &b.angular_velocity);
        let after = b.angular_momentum_about_with(inertia, &q, &a.v, &a.w);
        let scale = norm(&before)
            + norm(&(inertia * a.w))
            + norm(&(b.position - q)) * b.mass * (norm(&b.velocity) + norm(&a.v));
        let error = norm(&(after - before));
        items.push(item(
            Some(error <= tol * scale),
            Measured::AngularMomentum { body: *i, error },
        ));
    }

    // Separating velocity after the impulse, along the normal.
    let mut after_world = Vector3::zeros();
    let mut scale = norm(&input.desired.contact_velocity_world);
    for (i, b, a, _) in pairs() {
        let r = input.frame.r[*i].unwrap_or_else(Vector3::zeros);
        let v = a.w.cross(&r) + a.v;
        scale += norm(&v) + norm(&b.point_velocity(&r));
        after_world += v * Problem::<T>::sign(*i);
    }
    let separating = after_world.dot(&d);
    let expected = input.desired.separating() + input.desired.desired;
    let error = (separating - expected).abs();
    let friction_solve = input.friction.and_then(|f| f.solve.as_ref());
    let missed = (error > tol * scale).then(|| {
        causes::restitution_miss(
            problem,
            input.impulse,
            friction_solve,
            input.matrix,
            error,
            scale,
        )
    });
    items.push(explained(
        missed,
        Measured::Restitution {
            before: input.desired.separating(),
            after: separating,
            expected,
        },
    ));

    let (mut e_before, mut e_after) = (T::zero(), T::zero());
    for (_, b, a, inertia) in pairs() {
        e_before += b.kinetic_energy_with(inertia, &b.velocity, &b.angular_velocity);
        e_after += b.kinetic_energy_with(inertia, &a.v, &a.w);
    }
    let rise = causes::rose(e_before, e_after).then(|| {
        causes::energy_rise(
            problem,
            input.impulse,
            friction_solve,
            input.matrix,
            (e_before, e_after),
        )
    });
    items.push(explained(
        rise,
        Measured::Energy {
            before: e_before,
            after: e_after,
            change: e_after - e_before,
        },
    ));

    if let Some(f) = input.friction {
        let g = f.impulse_contact;
        let tangential = stable_hypot(g.y, g.z);
        let mu = problem
            .contact
            .static_friction
            .max(problem.contact.dynamic_friction);
        let ok =
            g.x >= -tol * norm(&g) && tangential <= mu * g.x * (T::one() + tol) + tol * norm(&g);
        let outside = (!ok).then(|| {
            let error = (tangential - mu * g.x).max(-g.x);
            causes::cone_miss(
                problem,
                input.impulse,
                friction_solve,
                input.matrix,
                error,
                norm(&g),
            )
        });
        items.push(explained(
            outside,
            Measured::FrictionCone {
                normal: g.x,
                tangential,
                limit: mu * g.x,
            },
        ));
        let slip = |v: Vector3<T>| {
            let vc = input.frame.to_contact(&v);
            stable_hypot(vc.y, vc.z)
        };
        let before = slip(input.desired.contact_velocity_world);
        let after = slip(after_world);
        // Sticking must leave no slip; sliding may end faster than it began,
        // because the normal impulse itself drives the point sideways (M₀₁, M₀₂).
        let rose = after > before * (T::one() + tol) + tol * scale;
        // Sticking aims at the contact velocity with the planar part of last
        // frame's acceleration (stage 3, as the reference engine): where that
        // slip did not rise, what is left is the slide one frame of
        // acceleration will add back.
        let planar = input.desired.planar_from_acceleration;
        let planar_slip = (planar != Vector3::zeros())
            .then(|| {
                let next = input.frame.to_contact(&after_world) + planar;
                let aimed = input.desired.contact_velocity;
                let rose = stable_hypot(next.y, next.z)
                    > stable_hypot(aimed.y, aimed.z) * (T::one() + tol) + tol * scale;
                (!rose).then(|| stable_hypot(planar.y, planar.z))
            })
            .flatten();
        // Under a static regime the slip must not rise, unless the model
        // applied no friction (kinetic-direction with nothing sliding, or the
        // frictionless fallback of a failed solve), the planar acceleration
        // term or round-off explains it.
        let measured = Measured::Slip { before, after };
        items.push(match (rose, f.regime) {
            (false, _) => item(Some(true), measured),
            (true, super::stages::FrictionRegime::Dynamic) => item(None, measured),
            (true, super::stages::FrictionRegime::Static) => {
                let why = (f.issue, planar_slip);
                match causes::slip_rise(
                    input.impulse,
                    friction_solve,
                    input.matrix,
                    why,
                    after,
                    scale,
                ) {
                    // A limit of the arithmetic informs, a defect of the model fails.
                    Some(cause) => explained(Some(cause), measured),
                    // Unexplained: fails.
                    None => item(Some(false), measured),
                }
            }
        });
    }
}

fn position_checks<T: Real>(
    input: &CheckInputs<'_, T>,
    projection: &Projection<T>,
    tol: T,
    items: &mut Vec<CheckItem<T>>,
) {
    let problem = input.problem;
    let q = problem.contact.point;
    let d = input.frame.normal();
    let mut gained = T::zero();
    for i in 0..2 {
        let (Some(body), Some(moved)) = (problem.bodies[i].as_ref(), projection.bodies[i].as_ref())
        else {
            continue;
        };
        let before = UnitQuaternion::new_normalize(body.orientation);
        let after = input
            .orientation
            .and_then(|o| o.bodies[i].as_ref())
            .map(|o| UnitQuaternion::new_normalize(o.normalised))
            .unwrap_or(before);
        // The body's material point at q, carried by the finite move.
        let local = before.inverse() * (q - body.position);
        let moved_point = moved.position + after * local;
        gained += (moved_point - q).dot(&d) * Problem::<T>::sign(i);
    }
    let residual = projection.resolved_depth - gained;
    let depth = projection.resolved_depth;
    items.push(item(
        None,
        Measured::ResidualPenetration {
            depth,
            gained,
            residual,
        },
    ));
    if let Some(o) = input.orientation {
        for (i, b) in o.bodies.iter().enumerate() {
            if let Some(b) = b {
                let error = (stable_norm_quaternion(&b.normalised) - T::one()).abs();
                items.push(item(
                    Some(error <= tol),
                    Measured::UnitQuaternion { body: i, error },
                ));
            }
        }
    }
}
