//! A change to a run's input at a step (a body's mass or velocity, a pair's
//! coefficients, a contact setting of every generated contact), and the run
//! computed again from that step: frames and events before it are kept.

use nalgebra::Vector3;

use super::Player;
use crate::knobs::{Knob, Value};
use crate::physics::step::Simulation;
use crate::physics::Settings;

/// What an edit changes, from the start of a step on.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneEdit {
    /// The body's mass (its inertia scaled with it: same shape, same
    /// distribution).
    Mass {
        body: usize,
        mass: f64,
    },
    /// Added to the body's velocity at the start of the step.
    Velocity {
        body: usize,
        change: [f64; 3],
    },
    AngularVelocity {
        body: usize,
        change: [f64; 3],
    },
    /// Both bodies of a pair take the value: a pair combines restitution by
    /// the larger and friction by √(μ₁μ₂), so their contacts get exactly it
    /// (and their other pairs change too).
    Restitution {
        bodies: Vec<usize>,
        value: f64,
    },
    StaticFriction {
        bodies: Vec<usize>,
        value: f64,
    },
    DynamicFriction {
        bodies: Vec<usize>,
        value: f64,
    },
    /// A knob of the run (a setting of every generated contact, the
    /// resolver's, the world's, sleep's).
    Knob(&'static Knob, Value),
}

impl SceneEdit {
    fn apply(&self, sim: &mut Simulation<f64>) {
        let add = |v: &mut Vector3<f64>, d: &[f64; 3]| *v += Vector3::from(*d);
        match self {
            SceneEdit::Mass { body, mass } => {
                if let Some(b) = sim.world.bodies.get_mut(*body) {
                    let s = &mut b.state;
                    let ratio = mass / s.mass;
                    if ratio.is_finite() && ratio > 0.0 {
                        s.mass = *mass;
                        s.inverse_mass = 1.0 / mass;
                        s.inertia_body *= ratio;
                        s.inverse_inertia_body /= ratio;
                    }
                }
            }
            SceneEdit::Velocity { body, change } => {
                if let Some(b) = sim.world.bodies.get_mut(*body) {
                    add(&mut b.state.velocity, change);
                }
            }
            SceneEdit::AngularVelocity { body, change } => {
                if let Some(b) = sim.world.bodies.get_mut(*body) {
                    add(&mut b.state.angular_velocity, change);
                }
            }
            SceneEdit::Restitution { bodies, value } => {
                for (_, m) in sim
                    .materials
                    .iter_mut()
                    .enumerate()
                    .filter(|(i, _)| bodies.contains(i))
                {
                    m.restitution = *value;
                }
            }
            SceneEdit::StaticFriction { bodies, value } => {
                for (_, m) in sim
                    .materials
                    .iter_mut()
                    .enumerate()
                    .filter(|(i, _)| bodies.contains(i))
                {
                    m.static_friction = *value;
                }
            }
            SceneEdit::DynamicFriction { bodies, value } => {
                for (_, m) in sim
                    .materials
                    .iter_mut()
                    .enumerate()
                    .filter(|(i, _)| bodies.contains(i))
                {
                    m.dynamic_friction = *value;
                }
            }
            SceneEdit::Knob(knob, value) => {
                let mut all = Settings::of_run(&sim.params);
                (knob.set)(&mut all, *value);
                sim.params = all.sim_params();
            }
        }
        // The bodies it changed wake: the run must see the change.
        for b in self.bodies() {
            sim.wake_for_edit(b);
        }
    }

    /// The bodies the edit changes.
    fn bodies(&self) -> Vec<usize> {
        match self {
            SceneEdit::Mass { body, .. }
            | SceneEdit::Velocity { body, .. }
            | SceneEdit::AngularVelocity { body, .. } => vec![*body],
            SceneEdit::Restitution { bodies, .. }
            | SceneEdit::StaticFriction { bodies, .. }
            | SceneEdit::DynamicFriction { bodies, .. } => bodies.clone(),
            _ => vec![],
        }
    }
}

impl Player {
    /// Applies `edit` from the start of step `step` (1 … computed) and
    /// computes the run again up to that step; false when there is no such step.
    pub fn edit(&mut self, step: u64, edit: &SceneEdit) -> bool {
        if step == 0 || step > self.computed() {
            return false;
        }
        let Some(mut sim) = self.state_after(step - 1) else {
            return false;
        };
        edit.apply(&mut sim);
        self.background = None;
        self.run.frames.truncate(step as usize);
        self.run.events.retain(|e| e.step < step);
        self.run.stopped = None;
        self.checkpoints.retain(|(s, _)| *s < step - 1);
        self.checkpoints.push((step - 1, sim.clone()));
        self.sim = sim;
        self.reach(step)
    }
}
