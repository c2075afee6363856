//! An edit made on the stepper of a scene's step, carried into the run: the
//! field edited becomes a [`SceneEdit`] from the start of that step, and the
//! run is computed again from there (the step's resolution recorded anew).

use crate::knobs::{Knob, Offered};
use crate::lesson::edit::{Field, Key};
use crate::lesson::Lesson;
use crate::session::SceneEdit;
use crate::tui::app::App;

/// The change to the run that an edit of `field` (contact `k`, `before` →
/// `after`) stands for, or why it has none.
fn scene_edit(
    field: &Field,
    before: &Lesson,
    after: &Lesson,
    k: usize,
) -> Result<SceneEdit, &'static str> {
    let c = &after.contacts[k];
    let pair = || {
        std::iter::once(c.bodies.0)
            .chain(c.bodies.1)
            .collect::<Vec<_>>()
    };
    let change =
        |a: nalgebra::Vector3<f64>, b: nalgebra::Vector3<f64>| [a.x - b.x, a.y - b.y, a.z - b.z];
    Ok(match (field.key, field.body) {
        (Key::Restitution, _) => SceneEdit::Restitution {
            bodies: pair(),
            value: c.restitution,
        },
        (Key::StaticFriction, _) => SceneEdit::StaticFriction {
            bodies: pair(),
            value: c.static_friction,
        },
        (Key::DynamicFriction, _) => SceneEdit::DynamicFriction {
            bodies: pair(),
            value: c.dynamic_friction,
        },
        (Key::Knob(knob), _) => {
            let mut all = after.knobs();
            if knob.level == crate::knobs::Level::Contact {
                all.contact = c.settings;
            }
            if knob.level == crate::knobs::Level::Contact && !knob_in_run(knob) {
                return Err(knob_note(knob));
            }
            SceneEdit::Knob(knob, (knob.get)(&all))
        }
        (Key::Mass, Some(b)) => SceneEdit::Mass {
            body: b,
            mass: after.bodies[b].mass,
        },
        (Key::Velocity, Some(b)) => SceneEdit::Velocity {
            body: b,
            change: change(after.bodies[b].velocity, before.bodies[b].velocity),
        },
        (Key::AngularVelocity, Some(b)) => SceneEdit::AngularVelocity {
            body: b,
            change: change(
                after.bodies[b].angular_velocity,
                before.bodies[b].angular_velocity,
            ),
        },
        (Key::Penetration, _) => {
            return Err("a scene's penetrations come from its shapes at each step")
        }
        (Key::Acceleration, _) => {
            return Err("in a run a body's acceleration is what gravity and damping give it")
        }
        (_, None) => return Err("no body"),
    })
}

/// A contact's knob the run's generated contacts take (not the frame's
/// duration, which is the time step, nor the exact impact, which applies
/// nothing).
fn knob_in_run(knob: &Knob) -> bool {
    knob.study == Offered::Yes
}

/// Why a contact's knob does not change the run.
fn knob_note(knob: &Knob) -> &'static str {
    match knob.study {
        Offered::No(why) => why,
        Offered::Yes => "",
    }
}

impl App {
    /// After an edit on the stepper: when it was opened from a scene's
    /// step, the run is computed again from that step; the words to add to
    /// the status line.
    pub(crate) fn scene_edited(&mut self, field: &Field, before: &Lesson) -> Option<String> {
        let (Some(run), Some(r), Some(opened)) = (
            self.run.as_deref_mut(),
            self.resolver.as_deref_mut(),
            self.opened.as_ref(),
        ) else {
            return None;
        };
        let step = r.trace.step;
        let edit = match scene_edit(field, before, &opened.lesson, self.contact) {
            Ok(e) => e,
            Err(why) => return Some(format!("; the run is unchanged ({why})")),
        };
        if step == 0 || step > run.player.computed() {
            return Some(format!("; the run stopped before step {step}: unchanged"));
        }
        self.run_edits += 1;
        if !run.player.edit(step, &edit) {
            // The run computed again stopped before the step edited (a
            // blow-up): the frames before it are kept, the step's resolution
            // no longer exists, so the run screen shows where it stopped.
            run.frame = run.player.computed() as usize;
            run.playing = false;
            let why = run.player.run.stopped.clone().unwrap_or_default();
            self.resolver = None;
            self.opened = None;
            self.baseline = None;
            self.screen = super::Screen::Run;
            return Some(format!(
                "; the run computed again from step {step} stopped: {why}"
            ));
        }
        run.frame = step as usize;
        if let Some(trace) = run.player.record(step) {
            r.stop = r.stop.min(trace.tables.len() - 1);
            r.selected = r.selected.min(trace.world.contacts.len().saturating_sub(1));
            r.trace = trace;
        }
        Some(format!("; the run is computed again from step {step}"))
    }
}
