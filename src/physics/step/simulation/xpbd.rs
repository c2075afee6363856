//! The step's arm for `solver = "xpbd"`: XPBD's substeps resolve the
//! contacts and move the bodies (step/xpbd), in place of the resolver's
//! phases and the position update.

use super::super::substep::Spent;
use super::super::xpbd::{self, StepInput};
use super::{wake_sleep, Event, Resolved, Simulation};
use crate::physics::Real;

impl<T: Real> Simulation<T> {
    pub(super) fn xpbd_step(&mut self, events: &mut Vec<Event>) -> Resolved<T> {
        let p = self.params;
        let enabled = p.sleep.enabled;
        let moving: Vec<bool> = (self.world.bodies.iter().zip(&self.sleep))
            .map(|(b, s)| b.movable && (s.awake || !enabled))
            .collect();
        let input = StepInput {
            dt: p.dt,
            substeps: p.resolver.substeps,
            gravity: p.world.gravity,
            linear_damping: p.world.linear_damping,
            angular_damping: p.world.angular_damping,
            moving: &moving,
            options: self.xpbd,
            position_epsilon: p.resolver.position_epsilon,
            velocity_epsilon: p.resolver.velocity_epsilon,
        };
        // A traced step's substeps (the TUI's resolver screen reads them).
        if let Some(r) = self.xpbd_trace.as_mut() {
            r.clear();
        }
        let record = self.xpbd_trace.as_mut();
        let [position, velocity] = xpbd::step(&mut self.world, &input, record);
        if enabled {
            wake_sleep::wake_changed(&mut self.world, &mut self.sleep, p.sleep.epsilon, events);
        }
        self.keep_resolved_speeds();
        (position, velocity, [None, None, None], Spent::default())
    }
}
