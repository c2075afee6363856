//! `resolve --show position:K` / `velocity:K`: the single-contact worked
//! solution of the contact taken at iteration K, with the bodies as that
//! iteration finds them — the student's way from the scene to one contact's
//! stages.

use std::io::Write;

use super::io;
use crate::cli::{ResolveFormat, Show};
use crate::error::AppError;
use crate::format::Fmt;
use crate::lesson::Lesson;
use crate::physics::resolver::{
    Implementation, Observer, PositionMoves, Resolver, ResolverBody, VelocityImpulse,
};
use crate::physics::ResolverParams;
use crate::render;

/// What the chosen iteration found and did.
struct Moment {
    contact: usize,
    value: f64,
    bodies: Vec<ResolverBody<f64>>,
    /// The resolver's own move or impulse, described.
    action: String,
}

/// Keeps the bodies and the contact of one iteration of one phase.
struct Capture {
    velocity: bool,
    iteration: usize,
    names: Vec<String>,
    bodies: Option<Vec<ResolverBody<f64>>>,
    moment: Option<Moment>,
    /// Iterations the phase ran.
    used: [usize; 2],
}

impl Capture {
    fn name(&self, slots: &[Option<usize>; 2], i: usize) -> &str {
        slots[i].map_or("", |b| self.names[b].as_str())
    }
}

impl Observer<f64> for Capture {
    fn before_position(&mut self, i: usize, _k: usize, bodies: &[ResolverBody<f64>]) {
        self.used[0] = i + 1;
        if !self.velocity && i == self.iteration {
            self.bodies = Some(bodies.to_vec());
        }
    }
    fn position_taken(&mut self, i: usize, k: usize, penetration: f64, moves: &PositionMoves<f64>) {
        if self.velocity || i != self.iteration {
            return;
        }
        let f = Fmt::default();
        let v = |x: &nalgebra::Vector3<f64>| format!("({})", f.list(x.as_slice()));
        let action = (0..2)
            .filter_map(|s| {
                let m = moves.bodies[s].as_ref()?;
                Some(format!(
                    "{} Δp {}, Δθ {}",
                    self.name(&moves.slots, s),
                    v(&m.linear_change),
                    v(&m.angular_change)
                ))
            })
            .collect::<Vec<_>>()
            .join("; ");
        self.moment = Some(Moment {
            contact: k,
            value: penetration,
            bodies: self.bodies.take().unwrap_or_default(),
            action: format!("it moved {action}"),
        });
    }
    fn before_velocity(&mut self, i: usize, _k: usize, bodies: &[ResolverBody<f64>]) {
        self.used[1] = i + 1;
        if self.velocity && i == self.iteration {
            self.bodies = Some(bodies.to_vec());
        }
    }
    fn velocity_taken(&mut self, i: usize, k: usize, desired: f64, impulse: &VelocityImpulse<f64>) {
        if !self.velocity || i != self.iteration {
            return;
        }
        let f = Fmt::default();
        self.moment = Some(Moment {
            contact: k,
            value: desired,
            bodies: self.bodies.take().unwrap_or_default(),
            action: format!(
                "its impulse was g = ({}) in contact space",
                f.list(impulse.impulse_contact.as_slice())
            ),
        });
    }
}

pub fn show(
    lesson: &Lesson,
    params: &ResolverParams,
    implementation: Implementation,
    show: Show,
    format: ResolveFormat,
    fmt: &Fmt,
    out: &mut dyn Write,
) -> Result<(), AppError> {
    let (trace, preamble) = at_iteration(lesson, params, implementation, show, fmt)?;
    let text = match format {
        ResolveFormat::Json => render::contact::json::render(&trace),
        ResolveFormat::Text => {
            format!("{preamble}\n{}", render::contact::text::render(&trace, fmt))
        }
        ResolveFormat::Md => format!(
            "> {}\n\n{}",
            render::contact::markdown::escape(preamble.trim_end()).replace('\n', "\n> "),
            render::contact::markdown::document(&[trace], fmt, &[])
        ),
        ResolveFormat::Html => render::html::solve::document(&[trace], fmt, Some(&preamble)),
    };
    out.write_all(text.as_bytes()).map_err(io)
}

/// The worked solution of the contact iteration `show` takes, with the
/// bodies as that iteration finds them, and the words that say so.
pub(crate) fn at_iteration(
    lesson: &Lesson,
    params: &ResolverParams,
    implementation: Implementation,
    show: Show,
    fmt: &Fmt,
) -> Result<(crate::trace::Trace, String), AppError> {
    let world = lesson.world::<f64>();
    let mut resolver = Resolver::prepare(&world, params);
    let mut capture = Capture {
        velocity: show.velocity,
        iteration: show.iteration,
        names: resolver
            .bodies
            .iter()
            .map(|b| lesson.bodies[b.id.0].name.clone())
            .collect(),
        bodies: None,
        moment: None,
        used: [0, 0],
    };
    resolver.position_phase(implementation, &mut capture);
    if show.velocity {
        resolver.velocity_phase(implementation, &mut capture);
    }
    let phase = if show.velocity {
        "velocity"
    } else {
        "position"
    };
    let Some(moment) = capture.moment else {
        let used = capture.used[usize::from(show.velocity)];
        return Err(AppError::Usage(format!(
            "--show {phase}:{}: the {phase} phase of '{}' ran {used} iteration(s), numbered from 0",
            show.iteration, lesson.id
        )));
    };
    // The lesson as that iteration finds it.
    let mut at = lesson.clone();
    for b in &moment.bodies {
        let def = &mut at.bodies[b.id.0];
        def.position = b.position;
        def.orientation = b.unit_orientation();
        def.velocity = b.velocity;
        def.angular_velocity = b.angular_velocity;
    }
    let k = moment.contact;
    at.contacts[k].penetration = if show.velocity { 0.0 } else { moment.value };
    let trace = crate::worked_solution(&at, k);
    Ok((trace, preamble(lesson, show, &moment, fmt)))
}

fn preamble(lesson: &Lesson, show: Show, m: &Moment, fmt: &Fmt) -> String {
    let label = lesson.contact_label(m.contact);
    let lines = if show.velocity {
        [
            format!(
                "Velocity iteration {} of `resolve {}` takes contact {label} at desired Δv {}.",
                show.iteration,
                lesson.id,
                fmt.num(m.value)
            ),
            "The bodies are as that iteration finds them: positions after the position phase, velocities after the earlier velocity iterations. The penetration is left out (0): the position phase has dealt with it.".to_string(),
            format!(
                "The contact point is where the lesson puts it (collision detection is not run again). The resolver keeps every contact's r and I⁻¹ from before the phases, as the reference engine does; once earlier iterations have moved the bodies its numbers differ slightly from this solution's: {}.",
                m.action
            ),
        ]
    } else {
        [
            format!(
                "Position iteration {} of `resolve {}` takes contact {label} at penetration {} (the resolver's bookkeeping).",
                show.iteration,
                lesson.id,
                fmt.num(m.value)
            ),
            "The bodies are as that iteration finds them (earlier iterations moved them). The velocity stages below treat this contact alone: the resolver's velocity phase comes after the position phase.".to_string(),
            format!(
                "The contact point is where the lesson puts it (collision detection is not run again). The resolver keeps every contact's r and I⁻¹ from before the phase, as the reference engine does; once earlier iterations have moved the bodies its numbers differ slightly from this solution's: {}.",
                m.action
            ),
        ]
    };
    lines.join("\n") + "\n"
}
