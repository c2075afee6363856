//! Why a check came out as it did: every ✗ is a real defect of the model,
//! named by its actual cause, and a result that only round-off or a model's
//! own rule explains is not called a failure.
//!
//! Energy that rises is explained by solving the contact again without one
//! ingredient at a time (counterfactuals): without last frame's acceleration
//! (the compensation asks for more separation than restitution alone), or
//! without friction (Newton's restitution with friction, Kane's example). A
//! rise within what an ill-conditioned or failed 3×3 solve can produce is
//! round-off, not physics.

use super::stages::friction::FrictionIssue;
use super::stages::{
    apply_impulse, condition_number, contact_frame, desired_delta_velocity, friction_clamp,
    impulse, unit_impulse, Impulse, MatrixSolve,
};
use nalgebra::Matrix3;

use super::{c, Problem, Real};

/// The cause a check's note names.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cause<T: Real> {
    /// The 3×3 solve for g lost digits (κ(M) large) or failed: the difference
    /// is within what round-off in g can produce (`allowance`, 10 κ ε of the
    /// sizes involved).
    RoundOff { condition: T, allowance: T },
    /// Acceleration compensation: without last frame's acceleration the
    /// energy after would be `energy_without` (not above the energy before).
    AccelerationCompensation { energy_without: T },
    /// Newton's restitution with friction (Kane's example): without friction
    /// the energy after would be `energy_without`.
    Friction { energy_without: T },
    /// Both together: neither alone explains the rise, removing both does.
    AccelerationAndFriction { energy_without: T },
    /// Kinetic-direction model: its normal impulse is the companions' closed
    /// form j, not re-solved for the acceleration compensation or for the
    /// normal velocity its own tangential impulse causes (M₀₁, M₀₂).
    KineticDirectionNormal,
    /// Kinetic-direction model with nothing sliding: t is undefined, no
    /// friction acts, and the normal impulse alone starts the slide.
    NoFrictionWhileNotSliding,
    /// The friction matrix could not be factorised; the frictionless impulse
    /// was used, so no friction acted.
    FrictionlessFallback,
    /// Sticking removed the contact velocity with the planar part of last
    /// frame's acceleration × duration (`planar`, its size) added, as the
    /// reference engine does: the slip left is what one frame of that
    /// acceleration adds back.
    PlanarAcceleration { planar: T },
    /// Velocity-scaling model (the friction lecture: PSE Friction): it scales the planar velocity
    /// rather than bounding the impulse, so it may leave the cone.
    VelocityScalingModel,
    /// None of the above: a real defect of the arithmetic or of the code.
    Unexplained,
}

/// Kinetic energy before and after the velocity stages of `problem` alone.
fn energies<T: Real>(problem: &Problem<T>) -> (T, T) {
    let frame = contact_frame(problem);
    let unit = unit_impulse(problem, &frame, problem.contact.has_friction());
    let desired = desired_delta_velocity(problem, &frame);
    let (mut before, mut after) = (T::zero(), T::zero());
    let applied = (desired.desired > T::zero()).then(|| {
        let g = impulse(problem, &frame, &unit, &desired);
        let g = if problem.contact.has_friction() {
            friction_clamp(problem, &frame, &unit, &desired, &g).impulse_world
        } else {
            g.impulse_world
        };
        apply_impulse(problem, &frame, &g)
    });
    for (i, body) in problem.bodies.iter().enumerate() {
        let Some(b) = body else { continue };
        before += b.kinetic_energy(&b.velocity, &b.angular_velocity);
        after += match applied.as_ref().and_then(|a| a.bodies[i].as_ref()) {
            Some(a) => b.kinetic_energy(&a.v, &a.w),
            None => b.kinetic_energy(&b.velocity, &b.angular_velocity),
        };
    }
    (before, after)
}

/// Relative tolerance of the checks: 10⁴ ε of the float type (f64: 2.2e-12,
/// f32: 1.2e-3), applied to the size of the terms each check adds up, so a
/// check fails only on an error far above round-off. Here beside [`rose`], the
/// causes' own use of it ([`super::checks`] reads it from here).
pub fn tolerance<T: Real>() -> T {
    T::default_epsilon() * c(1e4)
}

/// Whether `after` exceeds `before` by more than the checks' tolerance.
pub fn rose<T: Real>(before: T, after: T) -> bool {
    let tol = tolerance::<T>();
    after > before * (T::one() + tol) + tol * before.abs()
}

/// The 3×3 solves behind the applied impulse (if any): the largest κ and
/// whether one failed. A solve loses about log₁₀ κ digits whether or not it
/// is flagged ILL-CONDITIONED (κ·ε > 10⁻³), so every one counts.
///
/// Every solve is of the same `M` (the unit-impulse stage's `matrix`), so its
/// exact κ is computed here, once, from `M` itself: the stage path stores only
/// the factor's bound when that shows M well-conditioned.
fn conditioning<'a, T: Real>(
    impulse: Option<&'a Impulse<T>>,
    friction: Option<&'a MatrixSolve<T>>,
    matrix: Option<&Matrix3<T>>,
) -> Option<(T, bool)> {
    let solves = impulse
        .and_then(|g| g.solve.as_ref())
        .into_iter()
        .chain(friction);
    let kappa = matrix.map(condition_number);
    solves
        .map(|s| (kappa.unwrap_or(s.condition_number), s.singular))
        .reduce(|a, b| (a.0.max(b.0), a.1 || b.1))
}

/// Round-off allowance of an ill-conditioned solve: 10 κ ε of the sizes
/// involved (κ ε is the relative forward error of g; 10 leaves room for the
/// few operations after it). Infinite when the solve failed or M looked
/// indefinite.
fn allowance<T: Real>(condition: T, singular: bool, size: T) -> T {
    let k = T::default_epsilon() * condition * super::c(10.0);
    if singular || !k.is_finite() || condition >= T::max_value().unwrap_or(condition) {
        T::max_value().unwrap_or(size)
    } else {
        k * size
    }
}

/// Why the kinetic energy rose from `before` to `after`.
pub fn energy_rise<T: Real>(
    problem: &Problem<T>,
    impulse: Option<&Impulse<T>>,
    friction_solve: Option<&MatrixSolve<T>>,
    matrix: Option<&Matrix3<T>>,
    (before, after): (T, T),
) -> Cause<T> {
    if let Some((condition, singular)) = conditioning(impulse, friction_solve, matrix) {
        let allowance = allowance(condition, singular, before.abs() + after.abs());
        if after - before <= allowance {
            return Cause::RoundOff {
                condition,
                allowance,
            };
        }
    }
    let accelerates = problem
        .bodies
        .iter()
        .flatten()
        .any(|b| b.acceleration.iter().any(|a| *a != T::zero()));
    let friction = problem.contact.has_friction();
    let without = |no_acceleration: bool, no_friction: bool| {
        let mut p = problem.clone();
        for b in p.bodies.iter_mut().flatten() {
            if no_acceleration {
                b.acceleration = nalgebra::Vector3::zeros();
            }
        }
        if no_friction {
            p.contact.static_friction = T::zero();
            p.contact.dynamic_friction = T::zero();
        }
        let (b, a) = energies(&p);
        (!rose(b, a)).then_some(a)
    };
    if accelerates {
        if let Some(energy_without) = without(true, false) {
            return Cause::AccelerationCompensation { energy_without };
        }
    }
    if friction {
        if let Some(energy_without) = without(false, true) {
            return Cause::Friction { energy_without };
        }
    }
    if accelerates && friction {
        if let Some(energy_without) = without(true, true) {
            return Cause::AccelerationAndFriction { energy_without };
        }
    }
    Cause::Unexplained
}

/// Why the separating velocity missed its target by `error` (of `size`).
pub fn restitution_miss<T: Real>(
    problem: &Problem<T>,
    impulse: Option<&Impulse<T>>,
    friction_solve: Option<&MatrixSolve<T>>,
    matrix: Option<&Matrix3<T>>,
    error: T,
    size: T,
) -> Cause<T> {
    if let Some((condition, singular)) = conditioning(impulse, friction_solve, matrix) {
        let allowance = allowance(condition, singular, size);
        if error <= allowance {
            return Cause::RoundOff {
                condition,
                allowance,
            };
        }
    }
    if problem.contact.has_friction()
        && problem.contact.friction_model == crate::physics::FrictionModel::KineticDirection
    {
        return Cause::KineticDirectionNormal;
    }
    Cause::Unexplained
}

/// Why the slip speed rose under a static regime (where sticking should
/// leave none), when the model or round-off explains it; `None` otherwise.
/// `planar_slip` is the size of the planar acceleration term when the slip
/// with it added did not rise (the stages met their own target).
pub fn slip_rise<T: Real>(
    impulse: Option<&Impulse<T>>,
    friction_solve: Option<&MatrixSolve<T>>,
    matrix: Option<&Matrix3<T>>,
    (issue, planar_slip): (Option<FrictionIssue>, Option<T>),
    slip_after: T,
    size: T,
) -> Option<Cause<T>> {
    if issue == Some(FrictionIssue::UndefinedDirection) {
        return Some(Cause::NoFrictionWhileNotSliding);
    }
    if impulse
        .and_then(|g| g.solve.as_ref())
        .is_some_and(|s| s.singular)
    {
        return Some(Cause::FrictionlessFallback);
    }
    if let Some(planar) = planar_slip {
        return Some(Cause::PlanarAcceleration { planar });
    }
    let (condition, singular) = conditioning(impulse, friction_solve, matrix)?;
    let allowance = allowance(condition, singular, size);
    (slip_after <= allowance).then_some(Cause::RoundOff {
        condition,
        allowance,
    })
}

/// Why the impulse left the friction cone.
pub fn cone_miss<T: Real>(
    problem: &Problem<T>,
    impulse: Option<&Impulse<T>>,
    friction_solve: Option<&MatrixSolve<T>>,
    matrix: Option<&Matrix3<T>>,
    error: T,
    size: T,
) -> Cause<T> {
    match problem.contact.friction_model {
        crate::physics::FrictionModel::VelocityScaling => return Cause::VelocityScalingModel,
        // Its normal impulse is the closed form, which can come out negative.
        crate::physics::FrictionModel::KineticDirection => return Cause::KineticDirectionNormal,
        crate::physics::FrictionModel::Millington => {}
    }
    match conditioning(impulse, friction_solve, matrix) {
        Some((condition, singular)) if error <= allowance(condition, singular, size) => {
            Cause::RoundOff {
                condition,
                allowance: allowance(condition, singular, size),
            }
        }
        _ => Cause::Unexplained,
    }
}
