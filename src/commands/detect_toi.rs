//! `contact-lab detect SCENE --toi [--pair A,B] [--step N] [--method …]`:
//! each pair's time of collision over one step, test by test. The scene is
//! run up to the step; the step's contacts are resolved; then each pair
//! whose movement bounds meet (or the one `--pair` names) is searched as
//! continuous detection searches it. The entry point for a fuller `detect`
//! command is [`detect_toi`] (its `--toi` mode) or [`trace`] (the trace).

use std::io::Write;

use super::io;
use crate::cli::{DetectArgs, Format, ToiMethodArg};
use crate::error::AppError;
use crate::format::Fmt;
use crate::lesson::Lesson;
use crate::physics::detect::ToiMethod;
use crate::physics::step::Simulation;
use crate::render::toi as render;
use crate::trace::toi::DetectToi;

/// `detect --toi` on the lesson `detect` loaded (its knobs applied).
pub fn detect_toi(args: &DetectArgs, lesson: &Lesson, out: &mut dyn Write) -> Result<(), AppError> {
    let lesson = lesson.clone();
    let method = match args.method {
        ToiMethodArg::Bisection => ToiMethod::Bisection,
        ToiMethodArg::Conservative => ToiMethod::Conservative,
    };
    let pair = args
        .pair
        .as_deref()
        .map(|p| pair_of(&lesson, p))
        .transpose()?;
    let detected = trace(&lesson, args.step.max(1), method, pair)?;
    let text = match args.format {
        Format::Text => crate::render::wrap::wrap(
            &render::text(&detected, &Fmt::new(args.digits as usize)),
            super::text_width(args.fold.width),
        ),
        Format::Json => render::json(&detected),
        Format::Md | Format::Latex => {
            return Err(AppError::Usage(
                "detect --toi prints text or JSON (--format text|json)".into(),
            ))
        }
    };
    out.write_all(text.as_bytes()).map_err(io)
}

/// The indices of `--pair A,B`.
fn pair_of(lesson: &Lesson, text: &str) -> Result<(usize, usize), AppError> {
    let index = |name: &str| {
        lesson
            .bodies
            .iter()
            .position(|b| b.name == name.trim())
            .ok_or_else(|| {
                let names: Vec<&str> = lesson.bodies.iter().map(|b| b.name.as_str()).collect();
                AppError::Usage(format!(
                    "--pair {text}: {} has no body named {:?} (its bodies: {})",
                    lesson.id,
                    name.trim(),
                    names.join(", ")
                ))
            })
    };
    let Some((a, b)) = text.split_once(',') else {
        return Err(AppError::Usage(format!(
            "--pair {text}: give two body names separated by a comma, e.g. --pair bullet,wall"
        )));
    };
    let (i, j) = (index(a)?, index(b)?);
    if i == j {
        return Err(AppError::Usage(format!(
            "--pair {text}: a body does not collide with itself"
        )));
    }
    Ok((i, j))
}

/// The scene run up to step `step`, then that step's pairs searched.
pub fn trace(
    lesson: &Lesson,
    step: u64,
    method: ToiMethod,
    pair: Option<(usize, usize)>,
) -> Result<DetectToi, AppError> {
    let (Some(scene), Some(p)) = (lesson.simulation.as_ref(), lesson.sim_params()) else {
        return Err(AppError::Usage(format!(
            "{} is not a scene: it has no [world], [step] or [sleep] table, so it has no motion to search",
            lesson.id
        )));
    };
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, p, scene.materials.clone());
    for _ in 1..step {
        sim.advance().map_err(|e| {
            AppError::Runtime(format!(
                "{}: the run up to step {step} stopped: {e}",
                lesson.id
            ))
        })?;
    }
    crate::session::toi_trace(&sim, lesson, step, method, pair).map_err(|(i, j)| {
        AppError::Usage(format!(
            "--pair {},{}: both bodies need a convex shape (a sphere, box, cylinder or capsule) to be searched; a half-space or a body without a shape has no time of collision",
            lesson.bodies[i].name, lesson.bodies[j].name
        ))
    })
}
