//! `simulate --solver soft-step --trace-step N`: step N recorded by the
//! soft step itself (its coefficients, each substep's impulses) and printed
//! as text or JSON (render/soft_step.rs).

use std::io::Write;

use super::{blew_up, io};
use crate::cli::{RunFormat, SimulateArgs};
use crate::error::AppError;
use crate::format::Fmt;
use crate::lesson::Lesson;
use crate::physics::step::soft::SoftTrace;
use crate::physics::step::Simulation;

/// Records the next step (step `n`) and prints it.
pub(super) fn print(
    lesson: &Lesson,
    args: &SimulateArgs,
    mut sim: Simulation<f64>,
    n: u64,
    out: &mut dyn Write,
) -> Result<(), AppError> {
    sim.soft_trace = Some(SoftTrace::default());
    sim.advance().map_err(|e| blew_up(lesson, &e))?;
    let trace = sim.soft_trace.take().unwrap_or_default();
    let names: Vec<String> = lesson.bodies.iter().map(|b| b.name.clone()).collect();
    let text = match args.format {
        RunFormat::Text => {
            crate::render::soft_step::text(&trace, &names, n, &Fmt::new(args.digits as usize))
        }
        RunFormat::Json => {
            let value = crate::render::soft_step::json(&trace, &names, n);
            serde_json::to_string_pretty(&value).unwrap_or_default() + "\n"
        }
        RunFormat::Svg => {
            return Err(AppError::Usage(
                "--trace-step prints text or json, not svg".into(),
            ))
        }
        RunFormat::Html => {
            return Err(AppError::Usage(
                "--trace-step with the soft step prints text or json, not html".into(),
            ))
        }
    };
    out.write_all(text.as_bytes()).map_err(io)
}
