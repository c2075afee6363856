//! Movement bounds as pictures draw them ("Lecture IV Collisions": a bound
//! on where a body can be during the step): each moving body's swept AABB
//! and swept sphere over a step, as the swept broad phase of continuous
//! detection made them (physics/step/swept.rs). Carried by the run's
//! frames and by `detect`'s trace when continuous detection is on.

use crate::physics::step::swept::MovementBound;

/// One body's movement bounds (world coordinates, metres).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Movement {
    /// The swept AABB's corners, min and max.
    pub aabb: [[f64; 3]; 2],
    /// The swept sphere: centre x₀ + v Δt/2, radius ρ + |v| Δt/2.
    pub centre: [f64; 3],
    pub radius: f64,
}

impl From<&MovementBound<f64>> for Movement {
    fn from(b: &MovementBound<f64>) -> Self {
        Movement {
            aabb: [b.aabb.min.into(), b.aabb.max.into()],
            centre: b.centre.into(),
            radius: b.radius,
        }
    }
}

/// Per body (in world order), its bounds, `None` for a body that does not
/// move or has no convex shape.
pub fn of_bounds(bounds: &[Option<MovementBound<f64>>]) -> Vec<Option<Movement>> {
    bounds
        .iter()
        .map(|b| b.as_ref().map(Movement::from))
        .collect()
}
