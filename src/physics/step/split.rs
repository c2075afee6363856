//! Automatic substeps for small bodies. Where gravity moves a body more
//! than its size in one step (g·Δt² > r, with r the smallest movable
//! body's bounding radius), each step leaves a closing velocity of many
//! sizes a second to remove, and the lecture's order (one contact at a
//! time, a few visits each) does not converge: a 1 mm box rocks and sinks
//! through a 1 mm plate. The step is then spent as n = ⌈g·Δt²/r⌉ substeps
//! of Δt/n (at most [`MAX_SPLIT`]), so gravity moves it less than its size
//! in each; a run says so once, before its first step.

use crate::physics::{to_f64, Real, World};

/// The most substeps a step is split into.
pub const MAX_SPLIT: u32 = 16;

/// Why and how far a scene's steps are split.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Split {
    /// Substeps per step (at least 2).
    pub substeps: u32,
    /// What a step would need (more than `substeps` when capped).
    pub needed: u32,
    /// The smallest movable body's bounding radius (m).
    pub radius: f64,
    /// How far gravity moves a body from rest in one step, g·Δt² (m).
    pub fall: f64,
}

/// The smallest bounding radius of a movable body with a finite shape.
pub fn smallest_radius<T: Real>(world: &World<T>) -> Option<f64> {
    (world.bodies.iter())
        .filter(|b| b.movable)
        .filter_map(|b| b.shape.as_ref()?.bounding_radius())
        .filter(|r| r.is_finite() && *r > 0.0)
        .reduce(f64::min)
}

/// The split a step of `dt` s under gravity `g` m/s² needs for bodies of
/// bounding radius `radius` (`None`: one step is fine).
pub fn split(g: f64, dt: f64, radius: Option<f64>) -> Option<Split> {
    let radius = radius?;
    let fall = g * dt * dt;
    if !(fall > radius) {
        return None;
    }
    let ratio = (fall / radius).ceil();
    if ratio > f64::from(MAX_SPLIT) {
        // More than the cap would still leave the body falling more than
        // its size in a substep: the step is left whole (and said so).
        return None;
    }
    let needed = if ratio >= f64::from(u32::MAX) {
        u32::MAX
    } else {
        ratio as u32
    };
    Some(Split {
        substeps: needed.min(MAX_SPLIT),
        needed,
        radius,
        fall,
    })
}

/// The split of `world`'s steps of `dt` under gravity `g`.
pub fn of<T: Real>(world: &World<T>, g: T, dt: T) -> Option<Split> {
    split(to_f64(g), to_f64(dt), smallest_radius(world))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_millimetre_body_is_split_and_a_metre_one_is_not() {
        let dt = 1.0 / 60.0;
        assert_eq!(split(9.81, dt, Some(1.0)), None);
        assert_eq!(split(9.81, dt, None), None);
        // g Δt² = 2.725 mm over a 0.866 mm bounding radius: 4 substeps.
        let s = split(9.81, dt, Some(0.866e-3)).unwrap();
        assert_eq!((s.substeps, s.needed), (4, 4));
        // A nanometre body would need millions: capped.
        let s = split(9.81, dt, Some(1e-9)).unwrap();
        assert_eq!(s.substeps, MAX_SPLIT);
        assert!(s.needed > 1_000_000);
        assert_eq!(split(0.0, dt, Some(1e-9)), None);
    }
}
