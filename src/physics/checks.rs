//! Invariants checked after a contact is resolved: momentum, restitution,
//! energy, the friction cone, slip, penetration actually removed, unit quaternions.

use nalgebra::{UnitQuaternion, Vector3};

use super::causes::{self, Cause};
use super::scale::{stable_hypot, stable_norm as norm, stable_norm_quaternion};
use super::stages::{
    AppliedImpulse, ContactFrame, DesiredVelocity, FrictionClamp, Impulse, OrientationUpdate,
    Projection,
};
use super::{c, Problem, Real};

/// Relative tolerance of the checks: 10⁴ ε of the float type (f64: 2.2e-12,
/// f32: 1.2e-3), applied to the size of the terms each check adds up, so a
/// check fails only on an error far above round-off.
pub fn tolerance<T: Real>() -> T {
    T::default_epsilon() * c(1e4)
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CheckKind {
    /// Σ m v before = after (two movable bodies).
    LinearMomentum,
    /// Each body's angular momentum about the contact point is unchanged.
    AngularMomentum(usize),
    /// Normal separating velocity after = v_s + Δv (= −c v_s without acceleration).
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

#[derive(Debug, Clone, PartialEq)]
pub struct CheckItem<T: Real> {
    pub kind: CheckKind,
    /// `None` for a check that informs rather than passes or fails.
    pub passed: Option<bool>,
    /// Named measurements (JSON names of the `checks` stage).
    pub values: Vec<(String, T)>,
    /// Why a check failed, or why a result that looks like a failure is
    /// not one (`physics::causes`).
    pub cause: Option<Cause<T>>,
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
        self.items.iter().find(|i| i.kind == kind)
    }
}

/// Inputs of the checks: the stage records they read.
pub struct CheckInputs<'a, T: Real> {
    pub problem: &'a Problem<T>,
    pub frame: &'a ContactFrame<T>,
    pub desired: &'a DesiredVelocity<T>,
    pub impulse: Option<&'a Impulse<T>>,
    pub applied: Option<&'a AppliedImpulse<T>>,
    pub friction: Option<&'a FrictionClamp<T>>,
    pub projection: Option<&'a Projection<T>>,
    pub orientation: Option<&'a OrientationUpdate<T>>,
}

fn item<T: Real>(kind: CheckKind, passed: Option<bool>, values: Vec<(String, T)>) -> CheckItem<T> {
    CheckItem {
        kind,
        passed,
        values,
        cause: None,
    }
}

/// Passed, unless `cause` says why not: a limit of the arithmetic (round-off
/// of an ill-conditioned solve, the fallback of a failed one) only informs
/// (`None`); anything else is a defect of the model, named.
fn verdict<T: Real>(cause: Option<Cause<T>>) -> Option<bool> {
    match cause {
        None => Some(true),
        Some(Cause::RoundOff { .. } | Cause::FrictionlessFallback) => None,
        Some(_) => Some(false),
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
    let pairs: Vec<_> = (0..2)
        .filter_map(|i| Some((i, problem.bodies[i].as_ref()?, applied.bodies[i].as_ref()?)))
        .collect();

    if pairs.len() == 2 {
        let (mut before, mut after, mut scale) = (Vector3::zeros(), Vector3::zeros(), T::zero());
        for (_, b, a) in &pairs {
            before += b.velocity * b.mass;
            after += a.v * b.mass;
            scale += norm(&(b.velocity * b.mass)) + norm(&a.impulse);
        }
        let error = norm(&(after - before));
        items.push(item(
            CheckKind::LinearMomentum,
            Some(error <= tol * scale),
            vec![("linear_momentum_error".into(), error)],
        ));
    }

    for (i, b, a) in &pairs {
        let before = b.angular_momentum_about(&q, &b.velocity, &b.angular_velocity);
        let after = b.angular_momentum_about(&q, &a.v, &a.w);
        let scale = norm(&before)
            + norm(&(b.inertia_world() * a.w))
            + norm(&(b.position - q)) * b.mass * (norm(&b.velocity) + norm(&a.v));
        let error = norm(&(after - before));
        items.push(item(
            CheckKind::AngularMomentum(*i),
            Some(error <= tol * scale),
            vec![(format!("angular_momentum_error{}", i + 1), error)],
        ));
    }

    // Separating velocity after the impulse, along the normal.
    let mut after_world = Vector3::zeros();
    let mut scale = norm(&input.desired.contact_velocity_world);
    for (i, b, a) in &pairs {
        let r = input.frame.r[*i].unwrap_or_else(Vector3::zeros);
        let v = a.w.cross(&r) + a.v;
        scale += norm(&v) + norm(&b.point_velocity(&r));
        after_world += v * Problem::<T>::sign(*i);
    }
    let separating = after_world.dot(&d);
    let expected = input.desired.separating() + input.desired.desired;
    let error = (separating - expected).abs();
    let friction_solve = input.friction.and_then(|f| f.solve.as_ref());
    let missed = (error > tol * scale)
        .then(|| causes::restitution_miss(problem, input.impulse, friction_solve, error, scale));
    items.push(item(
        CheckKind::Restitution,
        verdict(missed),
        vec![
            (
                "separating_velocity_before".into(),
                input.desired.separating(),
            ),
            ("separating_velocity".into(), separating),
            ("separating_velocity_expected".into(), expected),
        ],
    ));
    items.last_mut().expect("just pushed").cause = missed;

    let (mut e_before, mut e_after) = (T::zero(), T::zero());
    for (_, b, a) in &pairs {
        e_before += b.kinetic_energy(&b.velocity, &b.angular_velocity);
        e_after += b.kinetic_energy(&a.v, &a.w);
    }
    let rise = causes::rose(e_before, e_after)
        .then(|| causes::energy_rise(problem, input.impulse, friction_solve, (e_before, e_after)));
    items.push(item(
        CheckKind::Energy,
        verdict(rise),
        vec![
            ("energy_before".into(), e_before),
            ("energy_after".into(), e_after),
            ("energy_change".into(), e_after - e_before),
        ],
    ));
    items.last_mut().expect("just pushed").cause = rise;

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
            causes::cone_miss(problem, input.impulse, friction_solve, error, norm(&g))
        });
        items.push(item(
            CheckKind::FrictionCone,
            verdict(outside),
            vec![
                ("normal_impulse".into(), g.x),
                ("tangential_impulse".into(), tangential),
                ("cone_limit".into(), mu * g.x),
            ],
        ));
        items.last_mut().expect("just pushed").cause = outside;
        let slip = |v: Vector3<T>| {
            let vc = input.frame.to_contact(&v);
            stable_hypot(vc.y, vc.z)
        };
        let before = slip(input.desired.contact_velocity_world);
        let after = slip(after_world);
        // Sticking must leave no slip; sliding may end faster than it began,
        // because the normal impulse itself drives the point sideways (M₀₁, M₀₂).
        let rose = after > before * (T::one() + tol) + tol * scale;
        // Under a static regime the slip must not rise, unless the model
        // applied no friction (kinetic-direction with nothing sliding, or the
        // frictionless fallback of a failed solve) or round-off explains it.
        let (passed, cause) = match (rose, f.regime) {
            (false, _) => (Some(true), None),
            (true, super::stages::FrictionRegime::Dynamic) => (None, None),
            (true, super::stages::FrictionRegime::Static) => {
                let cause = causes::slip_rise(input.impulse, friction_solve, f.issue, after, scale);
                // Unexplained, or a defect of the model: fails.
                let passed = if cause.is_some() {
                    verdict(cause)
                } else {
                    Some(false)
                };
                (passed, cause)
            }
        };
        items.push(item(
            CheckKind::Slip,
            passed,
            vec![
                ("slip_speed_before".into(), before),
                ("slip_speed_after".into(), after),
            ],
        ));
        items.last_mut().expect("just pushed").cause = cause;
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
        CheckKind::ResidualPenetration,
        None,
        vec![
            ("depth_to_resolve".into(), depth),
            ("separation_gained".into(), gained),
            ("residual_penetration".into(), residual),
        ],
    ));
    if let Some(o) = input.orientation {
        for (i, b) in o.bodies.iter().enumerate() {
            if let Some(b) = b {
                let error = (stable_norm_quaternion(&b.normalised) - T::one()).abs();
                items.push(item(
                    CheckKind::UnitQuaternion(i),
                    Some(error <= tol),
                    vec![(format!("orientation_norm_error{}", i + 1), error)],
                ));
            }
        }
    }
}
