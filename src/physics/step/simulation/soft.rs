//! The soft step's arm of a step (`solver = "soft-step"`): the substeps
//! integrate velocities and positions themselves (../soft/), so the
//! ordinary velocity integration and the move over the step are skipped;
//! the energy audits, which replay the lecture's resolver, do not apply.

use super::{Resolved, Simulation};
use crate::physics::resolver::{Phase, PhaseOutcome};
use crate::physics::step::report::Event;
use crate::physics::step::substep::Spent;
use crate::physics::step::wake_sleep;
use crate::physics::{c, Real};

impl<T: Real> Simulation<T> {
    pub(super) fn soft_step(&mut self, events: &mut Vec<Event>) -> Resolved<T> {
        let p = self.params;
        let (sleep, enabled) = (&self.sleep, p.sleep.enabled);
        let moving = |i: usize| !enabled || sleep[i].awake;
        let outcome = self
            .soft
            .step(&mut self.world, &p, moving, self.soft_trace.as_mut());
        if p.sleep.enabled {
            wake_sleep::wake_changed(&mut self.world, &mut self.sleep, p.sleep.epsilon, events);
        }
        self.keep_resolved_speeds();
        let substeps = outcome.substeps;
        let phase = |phase, used, eps: f64, before: f64, after: f64| PhaseOutcome {
            phase,
            iterations_used: used,
            iteration_limit: used,
            epsilon: c::<T>(eps),
            max_before: c::<T>(before),
            max_after: c::<T>(after),
            max_after_contact: 0,
            limit_reached: false,
        };
        let r = &p.resolver;
        let position = phase(
            Phase::Position,
            substeps,
            r.position_epsilon,
            outcome.max_penetration_before,
            outcome.max_penetration_after,
        );
        let velocity = phase(
            Phase::Velocity,
            substeps * (1 + r.soft.relax_iterations),
            r.velocity_epsilon,
            outcome.max_closing_before,
            outcome.max_closing_after,
        );
        (position, velocity, [None, None, None], Spent::default())
    }
}
