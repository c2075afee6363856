//! The step's arm for `solver = "xpbd"`: XPBD's substeps resolve the
//! contacts and move the bodies (step/xpbd), in place of the resolver's
//! phases and the position update; a recording observer is handed each
//! substep.

use super::super::substep::Spent;
use super::super::xpbd::{self, StepInput};
use super::{wake_sleep, Event, Resolved, Simulation};
use crate::physics::resolver::Observer;
use crate::physics::Real;

impl<T: Real> Simulation<T> {
    pub(super) fn xpbd_step<O: Observer<T>>(
        &mut self,
        observer: &mut O,
        events: &mut Vec<Event>,
    ) -> Resolved<T> {
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
        let before = O::RECORDS.then(|| self.world.clone());
        let mut record = Vec::new();
        let recording = O::RECORDS.then_some(&mut record);
        let [position, velocity] = xpbd::step(&mut self.world, &input, recording);
        if let Some(world) = before {
            observer.xpbd_substeps(&world, &record);
        }
        if enabled {
            wake_sleep::wake_changed(&mut self.world, &mut self.sleep, p.sleep.epsilon, events);
        }
        self.keep_resolved_speeds();
        (position, velocity, [None, None, None], Spent::default())
    }
}
