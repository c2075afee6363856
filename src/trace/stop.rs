//! A moment of a resolution ([`Stop`]) and the contact table at it
//! ([`Table`]): what a recorded step ([`super::step`]) keeps per stop, whole
//! or elided (`elided.rs`).

use crate::physics::resolver::Phase;

/// A moment of the resolution: before iteration `iteration` of `phase`
/// (`iteration` = iterations used: the phase is done).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Stop {
    pub phase: Phase,
    pub iteration: usize,
}

/// The contact table at a stop. A huge step (its recording elided, see
/// [`crate::trace::resolver::ROW_BUDGET`]) keeps the whole table only at the
/// first and last stop of each phase; the others keep what changed.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    pub stop: Stop,
    /// The resolver's bookkeeping, per contact (both empty when `elided`).
    pub penetration: Vec<f64>,
    pub desired: Vec<f64>,
    /// The contact the next iteration takes (`None` when the phase is done).
    pub next: Option<usize>,
    /// What the iteration just before this stop changed: contact, from, to
    /// (its own contact included; the other contacts only when that
    /// iteration's rows were kept).
    pub changed: Vec<(usize, f64, f64)>,
    /// True when this stop's whole table was not kept.
    pub elided: bool,
}
