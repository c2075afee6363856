//! Automatic substeps for small bodies. Where gravity moves a body more
//! than its size in one step (g·Δt² > s, with s the smallest movable
//! body's half-width, the tolerances' scale: [`super::tolerance`]), each step leaves a closing velocity of many
//! sizes a second to remove, and the lecture's order (one contact at a
//! time, a few visits each) does not converge: a 1 mm box rocks and sinks
//! through a 1 mm plate. The step is then spent as n = ⌈g·Δt²/s⌉ substeps
//! of Δt/n (at most [`MAX_SPLIT`]), so gravity moves it less than its size
//! in each; a run says so once, before its first step. (Split by the
//! bounding radius instead, 4 substeps for a 1 mm box, a 1 mm tetrahedron
//! still went through a 1 mm box under the lecture's order.) A body that
//! would need more than [`MAX_SPLIT`] is left whole: the split would not
//! bring its fall below its size (a nanometre body needs millions).

/// The most substeps a step is split into.
pub const MAX_SPLIT: u32 = 16;

/// Why and how far a scene's steps are split.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Split {
    /// Substeps per step (at least 2).
    pub substeps: u32,
    /// What a step needs (the same as `substeps` while under the cap).
    pub needed: u32,
    /// The smallest movable body's half-width (m).
    pub radius: f64,
    /// How far gravity moves a body from rest in one step, g·Δt² (m).
    pub fall: f64,
}

/// The split a step of `dt` s under gravity `g` m/s² needs for bodies of
/// half-width `radius` (`None`: one step is fine, or more than
/// [`MAX_SPLIT`] substeps would be needed).
pub fn split(g: f64, dt: f64, radius: Option<f64>) -> Option<Split> {
    let radius = radius?;
    let fall = g * dt * dt;
    if fall.is_nan() || fall <= radius {
        return None;
    }
    let ratio = (fall / radius).ceil();
    if ratio > f64::from(MAX_SPLIT) {
        // More than the cap would still leave the body falling more than
        // its size in a substep: the step is left whole (and said so).
        return None;
    }
    let needed = ratio as u32;
    Some(Split {
        substeps: needed,
        needed,
        radius,
        fall,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_millimetre_body_is_split_and_a_metre_one_is_not() {
        let dt = 1.0 / 60.0;
        assert_eq!(split(9.81, dt, Some(1.0)), None);
        assert_eq!(split(9.81, dt, None), None);
        // g Δt² = 2.725 mm over a 0.5 mm half-width: 6 substeps.
        let s = split(9.81, dt, Some(0.5e-3)).unwrap();
        assert_eq!((s.substeps, s.needed), (6, 6));
        // A nanometre body would need millions: left whole.
        assert_eq!(split(9.81, dt, Some(1e-9)), None);
        assert_eq!(split(0.0, dt, Some(1e-9)), None);
    }
}
