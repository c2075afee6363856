//! Time stepping: integrate forces, generate contacts from the shapes,
//! resolve them together, update sleep (the lecture's "Resting Contacts and
//! Friction" and "Sleep"). The pieces: [`integrate`] one body, [`sleep`]
//! bookkeeping, [`energy`] of the world.

pub mod audit;
mod audits;
pub mod ccd;
pub mod ccd_pairs;
pub mod contact_events;
pub mod energy;
pub mod integrate;
pub mod kept_energy;
pub mod overlap;
pub mod previous_frame;
pub mod replay;
pub mod report;
pub mod rollback;
pub mod simulation;
pub mod sleep;
pub mod soft;
pub mod split;
pub mod substep;
pub mod swept;
pub mod toi_pair;
mod toi_resolve;
pub mod tolerance;
pub mod total_audit;
pub mod touching;
mod wake_sleep;
pub mod xpbd;

/// The `ccd` and `rollback` knobs' choices (declared with the other params).
pub use crate::physics::params::ccd_mode;
pub use integrate::{integrate, Loads};
pub use simulation::{BlowUp, Event, SimParams, Simulation, StepReport, WakeCause};
pub use sleep::{SleepMode, SleepState};
