//! A time step's own record under a solver that moves the bodies in
//! substeps (the soft step, XPBD): what the TUI's resolver screen walks for
//! such a step in place of the lecture's phases. Taken from the step as it
//! ran, never computed again.

use crate::physics::step::soft::SoftTrace;
use crate::physics::step::xpbd::SubstepRecord;
use crate::physics::step::Simulation;
use crate::physics::Solver;

/// The record of one step, by solver.
#[derive(Debug, Clone, PartialEq)]
pub enum SubstepsRecord {
    /// The soft step's coefficients, each contact's impulse and separation
    /// after every substep, and the stored impulses.
    Soft(SoftTrace),
    /// XPBD's substeps: per active contact the position pass (C, w, λ_n,
    /// Δλ_n, static friction) and the velocity pass.
    Xpbd(Vec<SubstepRecord>),
}

/// Asks `sim` to record its next step when its solver moves the bodies in
/// substeps; returns whether it does.
pub fn ask(sim: &mut Simulation<f64>) -> bool {
    match sim.params.resolver.solver {
        Solver::SoftStep => {
            sim.soft_trace = Some(SoftTrace::default());
            true
        }
        Solver::Xpbd => {
            sim.xpbd_trace = Some(Vec::new());
            true
        }
        _ => false,
    }
}

/// The record of the step `sim` just took (after [`ask`]); `None` when none
/// was asked.
pub fn take(sim: &mut Simulation<f64>) -> Option<SubstepsRecord> {
    if let Some(t) = sim.soft_trace.take() {
        return Some(SubstepsRecord::Soft(t));
    }
    sim.xpbd_trace.take().map(SubstepsRecord::Xpbd)
}
