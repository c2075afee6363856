//! Printed values of a lesson's contacts resolved together, beside the
//! single-contact stages: `stage = "resolver"` names a body's velocity (or
//! angular velocity) after the resolver, under the lesson's solver or the
//! one the entry names (the sequence and the simultaneous answer of one
//! lesson); `stage = "lcp"` names the simultaneous impact's impulse or
//! normal velocity after at a contact. Each resolution comes from the
//! resolver's trace, computed once per solver a lesson's entries name.

use crate::knobs::Choice;
use crate::lesson::{Lesson, Printed};
use crate::physics::resolver::Implementation;
use crate::physics::{ResolverParams, Solver};
use crate::trace::resolver::{describe, ResolverTrace};
use crate::trace::Value;

/// The resolutions a lesson's entries asked for, each computed once.
#[derive(Debug, Default)]
pub struct Resolutions(Vec<(Solver, ResolverTrace)>);

impl Resolutions {
    fn of(&mut self, lesson: &Lesson, solver: Solver) -> &ResolverTrace {
        let at = match self.0.iter().position(|(s, _)| *s == solver) {
            Some(i) => i,
            None => {
                let params = ResolverParams {
                    solver,
                    ..lesson.resolver
                };
                let trace = describe(lesson, &params, Implementation::Indexed, false);
                self.0.push((solver, trace));
                self.0.len() - 1
            }
        };
        &self.0[at].1
    }
}

/// The solver a resolved entry is computed under.
pub fn solver(lesson: &Lesson, p: &Printed) -> Solver {
    match p.stage.as_str() {
        "lcp" => Solver::Lcp,
        _ => p.solver.unwrap_or(lesson.resolver.solver),
    }
}

/// The value a resolved entry names (its component not yet picked); None
/// when the resolution has no such value (an LCP that found no solution).
pub fn value(lesson: &Lesson, p: &Printed, all: &mut Resolutions) -> Option<Value> {
    let trace = all.of(lesson, solver(lesson, p));
    match p.stage.as_str() {
        "resolver" => {
            let body = p.body.as_deref()?;
            let after = trace.after.iter().find(|(n, _)| n == body);
            // A body the resolver leaves alone (immovable, or in no
            // contact) keeps its state.
            let (v, w) = match after {
                Some((_, s)) => (s.velocity, s.angular_velocity),
                None => {
                    let b = lesson.bodies.iter().find(|b| b.name == body)?;
                    (b.velocity.into(), b.angular_velocity.into())
                }
            };
            match p.value.as_str() {
                "velocity" => Some(Value::Vector(v)),
                "angular_velocity" => Some(Value::Vector(w)),
                _ => None,
            }
        }
        "lcp" => {
            let record = trace.lcp.as_ref().filter(|r| r.failure().is_none())?;
            let values = match p.value.as_str() {
                "impulse" => &record.impulses,
                "normal_velocity_after" => &record.velocities_after,
                _ => return None,
            };
            values.get(p.contact).map(|x| Value::Scalar(*x))
        }
        _ => None,
    }
}

/// The row's symbol (`v(ball0)`, `λ`, `v_n after`) and what it is of
/// (`after the resolver, lcp`, `simultaneous impact`), for `check`.
pub fn label(lesson: &Lesson, p: &Printed) -> (String, String) {
    let solver = solver(lesson, p).name();
    match (p.stage.as_str(), p.value.as_str()) {
        ("resolver", "angular_velocity") => (
            format!("ω({})", p.body.as_deref().unwrap_or("?")),
            format!("after the resolver, {solver}"),
        ),
        ("resolver", _) => (
            format!("v({})", p.body.as_deref().unwrap_or("?")),
            format!("after the resolver, {solver}"),
        ),
        (_, "impulse") => ("λ".into(), "simultaneous impact, lcp".into()),
        _ => ("v_n after".into(), "simultaneous impact, lcp".into()),
    }
}
