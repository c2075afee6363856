//! ONE contact described: one builder per stage, mirroring
//! `physics/contact/stages/`, each turning a solved contact's record into a
//! [`Step`] (formulas with `{name}` placeholders, named values, notes).
//!
//! The builders read a [`Problem`], its [`Solution`] and the [`ContactNames`]
//! to show, never a lesson: a resolver trace can describe "contact 3,
//! iteration 7" with the same builders.

/// A text naming body slot `i` (0 or 1), fixed at compile time: `N`
/// stands for the body's number (1, 2), `S` for its subscript (₁, ₂),
/// `MINUS` for body 2's sign (`-`; nothing for body 1), e.g.
/// `slot!(i => "{m" N "}")` is `"{m1}"` or `"{m2}"`: a `&'static str`, no
/// allocation (the names and formulas of a body are the same text each time).
macro_rules! slot {
    (@1 N) => { "1" };
    (@2 N) => { "2" };
    (@1 S) => { "₁" };
    (@2 S) => { "₂" };
    (@1 MINUS) => { "" };
    (@2 MINUS) => { "-" };
    (@$k:tt $lit:literal) => { $lit };
    ($i:expr => $($part:tt)+) => {
        [
            concat!($(slot!(@1 $part)),+),
            concat!($(slot!(@2 $part)),+),
        ][$i]
    };
}

mod apply_impulse;
mod builder;
mod causes;
mod checks;
mod contact_frame;
mod desired_velocity;
mod exact_curves;
mod exact_impact;
mod friction;
mod impulse;
mod orientation;
mod projection;
#[cfg(test)]
mod tests;
mod unit_impulse;

use nalgebra::Matrix3;

pub use apply_impulse::apply_impulse;
pub use builder::SolvedContact;
pub use checks::{check_values, checks, verdicts};
pub use contact_frame::contact_frame;
pub use desired_velocity::{desired_velocity, VELOCITY_LIMIT};
pub use exact_curves::impact_curves;
pub use exact_impact::{exact_impact, phase_line};
pub use friction::{friction, regime_name};
pub use impulse::impulse;
pub use orientation::orientation;
pub use projection::projection;
pub use unit_impulse::unit_impulse;

use super::{AfterState, Step};
use crate::physics::{Problem, Solution, StageId};

/// What the trace shows beside the physics: who the bodies are, what the
/// contact is called, and what the scene as written says that the physics
/// view does not keep.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ContactNames {
    /// The name of the body in each slot (body 1, body 2); `None` where the
    /// slot is empty (a contact against the world). A named immovable body
    /// has a name here and no body in the problem.
    pub bodies: [Option<String>; 2],
    /// A short label, e.g. `0: ball ↔ floor`.
    pub label: String,
    /// The scene as written, where it says more than the physics.
    pub written: AsWritten,
    /// A scene step's penetrating contact: the normal from the closest
    /// points one frame earlier (t − Δt), beside the contact's own.
    pub previous_normal: Option<[f64; 3]>,
}

/// What a scene file wrote that the physics view drops, for the notes.
#[derive(Debug, Clone, PartialEq)]
pub struct AsWritten {
    /// Length of the normal as written; it was normalised when ≠ 1 (default: 1).
    pub normal_length: f64,
    /// The inertia tensor each body's shape formula gives, per slot (default: none).
    pub shape_inertia: [Option<Matrix3<f64>>; 2],
}

impl Default for AsWritten {
    fn default() -> Self {
        AsWritten {
            normal_length: 1.0,
            shape_inertia: [None, None],
        }
    }
}

impl ContactNames {
    /// The names of the non-empty slots, body 1 first.
    pub fn slot_names(&self) -> Vec<String> {
        self.bodies.iter().flatten().cloned().collect()
    }
}

/// The description of one stage.
pub fn stage(id: StageId, c: &SolvedContact) -> Step {
    match id {
        StageId::ContactFrame => contact_frame(c),
        StageId::UnitImpulse => unit_impulse(c),
        StageId::DesiredDeltaVelocity => desired_velocity(c),
        StageId::Impulse => impulse(c),
        StageId::FrictionClamp => friction(c),
        StageId::ApplyImpulse => apply_impulse(c),
        StageId::NonlinearProjection => projection(c),
        StageId::OrientationUpdate => orientation(c),
        StageId::ExactImpact => exact_impact(c),
        StageId::Checks => checks(c),
    }
}

/// Every stage of the solved contact, in [`StageId::ALL`] order.
pub fn build(problem: &Problem<f64>, solution: &Solution<f64>, names: &ContactNames) -> Vec<Step> {
    let c = SolvedContact::new(problem, solution, names);
    StageId::ALL.into_iter().map(|id| stage(id, &c)).collect()
}

/// Each movable body's state after the contact is resolved, by name.
pub fn after(
    problem: &Problem<f64>,
    solution: &Solution<f64>,
    names: &ContactNames,
) -> Vec<(String, AfterState)> {
    (0..2)
        .filter_map(|i| {
            let a = solution.after(problem, i)?;
            let name = names.bodies[i].clone()?;
            Some((
                name,
                AfterState {
                    position: a.position.into(),
                    orientation: [
                        a.orientation.w,
                        a.orientation.i,
                        a.orientation.j,
                        a.orientation.k,
                    ],
                    velocity: a.velocity.into(),
                    angular_velocity: a.angular_velocity.into(),
                },
            ))
        })
        .collect()
}
