//! ONE contact: its frame, the problem view, the stages in lecture order,
//! the solve that runs them, the invariant checks and the causes that
//! explain their verdicts.
//!
//! A [`Problem`] is a by-value view of one contact of a [`crate::physics::World`]:
//! the two bodies (either may be absent or immovable, written `None`) and the
//! contact. [`solve`] runs the stages of `stages/` and returns a [`Solution`]
//! with one typed record per stage, each named by a [`StageId`].

pub mod causes;
pub mod checks;
pub mod frame;
pub mod numbers;
pub mod problem;
pub mod solve;
pub mod stage_id;
pub mod stages;

pub use problem::{ContactInput, Problem};
pub use solve::{checks_of, solve, solve_stages, solve_stages_into, Solution, Stages};
pub use stage_id::StageId;

use super::{c, Real, RigidBody};
