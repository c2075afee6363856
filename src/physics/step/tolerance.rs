//! Tolerances that scale with the bodies. The defaults (position and
//! velocity epsilon 0.01, contact margin 0.005 m, sleep epsilon 0.3 m²/s²)
//! suit bodies of tens of centimetres and more; for a 1 mm ball the 0.01 m
//! position epsilon is ten radii, and the ball can rest wholly under the
//! floor. The rule: with `s` the smallest half-width of a movable body
//! (sphere radius, half the smallest side of a box, the smaller of a
//! cylinder's radius and half height) and `u = √(|g| s)` the speed of a fall
//! through that size,
//!
//! - position epsilon and contact margin ≤ s / 10,
//! - velocity epsilon ≤ u / 10 (with gravity),
//! - sleep epsilon ≤ u² (with gravity; it is a `v·v + ω·ω`).
//!
//! A value already below its bound is kept. One scale for the whole scene:
//! in a scene of mixed sizes the large bodies get the small bodies'
//! tolerances (more iterations, never coarser physics).

use crate::physics::{c, to_f64, Real, Shape, World};

use super::SimParams;

/// The smallest half-width of a movable body with a finite shape.
pub fn smallest_size<T: Real>(world: &World<T>) -> Option<f64> {
    world
        .bodies
        .iter()
        .filter(|b| b.movable)
        .filter_map(|b| half_width(b.shape.as_ref()?))
        .reduce(f64::min)
}

/// A finite shape's smallest half-width (sphere radius, half the smallest
/// side of a box, …; `None` for a half-space).
fn half_width(shape: &Shape) -> Option<f64> {
    let s = match *shape {
        Shape::Sphere { radius } | Shape::HollowSphere { radius } => radius,
        Shape::Box { sides } => sides.iter().fold(f64::INFINITY, |m, s| m.min(*s)) / 2.0,
        Shape::Cylinder { radius, height } => radius.min(height / 2.0),
        Shape::Capsule { radius, .. } => radius,
        Shape::Hull(ref hull) => hull.inner_radius(),
        Shape::Mesh(ref mesh) => mesh.inner_radius()?,
        Shape::HalfSpace { .. } => return None,
    };
    (s.is_finite() && s > 0.0).then_some(s)
}

/// A movable body whose size is below ten times the rounding of its
/// position (the spacing of f64 at its largest coordinate): a 1e-12 m ball
/// at 1e12 m can only be placed to within 1.2e-4 m, 1.2e8 of its radii, so
/// its contacts' depths are rounding, not geometry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BelowRounding {
    pub body: usize,
    /// Its smallest half-width (m).
    pub size: f64,
    /// The spacing of f64 at its position (m).
    pub rounding: f64,
}

/// The movable bodies smaller than ten times the rounding of their position.
pub fn below_rounding<T: Real>(world: &World<T>) -> Vec<BelowRounding> {
    world
        .bodies
        .iter()
        .enumerate()
        .filter(|(_, b)| b.movable)
        .filter_map(|(body, b)| {
            let size = half_width(b.shape.as_ref()?)?;
            let far = b
                .state
                .position
                .iter()
                .fold(0.0f64, |m, x| m.max(to_f64(*x).abs()));
            // The spacing of f64 at `far`: its last bit's worth.
            let rounding =
                crate::physics::scale::pow2_below(far.max(f64::MIN_POSITIVE)) * f64::EPSILON;
            (size < 10.0 * rounding).then_some(BelowRounding {
                body,
                size,
                rounding,
            })
        })
        .collect()
}

/// A tolerance the rule lowered.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lowered {
    pub which: Tolerance,
    pub given: f64,
    pub used: f64,
}

/// The tolerances the rule can lower.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tolerance {
    PositionEpsilon,
    VelocityEpsilon,
    ContactMargin,
    SleepEpsilon,
}

/// The parameters with the scaled tolerances, and what was lowered.
pub fn scaled<T: Real>(params: &SimParams<T>, size: Option<f64>) -> (SimParams<T>, Vec<Lowered>) {
    scaled_in_step(params, size, to_f64(params.dt))
}

/// [`scaled`] for a substep of a step of `step_dt` s (`params.dt` the
/// substep's): the velocity epsilon is bounded by what moves a corner in
/// the whole step, as the warning before the run says.
pub fn scaled_in_step<T: Real>(
    params: &SimParams<T>,
    size: Option<f64>,
    step_dt: f64,
) -> (SimParams<T>, Vec<Lowered>) {
    let mut p = *params;
    let mut lowered = Vec::new();
    let Some(s) = size else {
        return (p, lowered);
    };
    let g = to_f64(params.world.gravity.norm());
    let u = (g * s).sqrt();
    let mut lower = |which: Tolerance, value: &mut f64, bound: f64| {
        if bound.is_finite() && bound > 0.0 && *value > bound {
            lowered.push(Lowered {
                which,
                given: *value,
                used: bound,
            });
            *value = bound;
        }
    };
    lower(
        Tolerance::PositionEpsilon,
        &mut p.resolver.position_epsilon,
        s / 10.0,
    );
    let mut margin = to_f64(p.contact_margin);
    lower(Tolerance::ContactMargin, &mut margin, s / 10.0);
    p.contact_margin = c(margin);
    if g > 0.0 {
        // A step in which gravity moves the body more than a tenth of its
        // size (g Δt² > s / 10: a 1 mm body at Δt = 1/60 s falls 2.7 mm in
        // a step) leaves each step a closing velocity g Δt of many sizes a
        // step to remove; what the resolver leaves must then move a corner
        // by at most a thousandth of the size in a step. (The lecture's
        // order kept u / 10 here: a 1 mm box on a floor rocked by 0.7 mm
        // and never slept; with the same bound it rests and sleeps.)
        let dt = step_dt;
        let coarse = dt > 0.0
            && g * dt * dt > s / 10.0
            && matches!(
                params.resolver.solver,
                crate::physics::Solver::SequentialImpulse | crate::physics::Solver::DeepestFirst
            );
        let bound = if coarse {
            (u / 10.0).min(s / (1000.0 * dt))
        } else {
            u / 10.0
        };
        lower(
            Tolerance::VelocityEpsilon,
            &mut p.resolver.velocity_epsilon,
            bound,
        );
        let mut sleep = to_f64(p.sleep.epsilon);
        lower(Tolerance::SleepEpsilon, &mut sleep, u * u);
        p.sleep.epsilon = c(sleep);
    }
    (p, lowered)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_millimetre_ball_gets_millimetre_tolerances_and_a_metre_box_keeps_the_defaults() {
        let p = SimParams::<f64>::default();
        let (q, lowered) = scaled(&p, Some(0.0005));
        assert_eq!(q.resolver.position_epsilon, 0.00005);
        assert!((q.contact_margin - 0.00005).abs() < 1e-18);
        let u: f64 = (9.81f64 * 0.0005).sqrt();
        // Gravity moves it more than a tenth of its size in a step: the
        // velocity epsilon moves a corner a thousandth of it a step at most.
        let v = (u / 10.0).min(0.0005 / (1000.0 * p.dt));
        assert!((q.resolver.velocity_epsilon - v).abs() < 1e-15);
        assert!((q.sleep.epsilon - u * u).abs() < 1e-15);
        assert_eq!(lowered.len(), 4);
        let (q, lowered) = scaled(&p, Some(0.5));
        assert_eq!(q, p);
        assert!(lowered.is_empty());
    }
}
