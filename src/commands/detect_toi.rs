//! `contact-lab detect SCENE --toi [--pair A,B] [--step N] [--method …]`:
//! each pair's time of collision over one step, test by test. The scene is
//! run up to the step; the step's contacts are resolved; then each pair
//! whose movement bounds meet (or the one `--pair` names) is searched as
//! continuous detection searches it. The entry point for a fuller `detect`
//! command is [`detect_toi`] (its `--toi` mode).

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
        Some(ToiMethodArg::Bisection) => ToiMethod::Bisection,
        Some(ToiMethodArg::Conservative) => ToiMethod::Conservative,
        None => lesson
            .sim_params()
            .and_then(|p| p.ccd.method())
            .unwrap_or(ToiMethod::Bisection),
    };
    let pair = args
        .pair
        .as_deref()
        .map(|p| pair_of(&lesson, p))
        .transpose()?;
    let (sim, detected) = traced(&lesson, args.step.max(1), method, pair)?;
    if let Some(path) = &args.figure {
        let picture = crate::session::toi_picture(&sim, &lesson, &detected, 0).ok_or_else(|| {
            AppError::Usage(
                "--figure: no pair's movement bounds meet over the step, so there is nothing to draw (name one with --pair A,B)".into(),
            )
        })?;
        let svg = crate::render::toi_svg::svg(&picture, super::figure::plane(args.plane));
        super::write_atomic(path, svg.as_bytes())?;
    }
    let text = match args.format {
        Format::Text => crate::render::wrap::wrap(
            &render::text(&detected, &Fmt::new(args.digits as usize)),
            super::text_width(args.fold.width),
        ),
        Format::Json => render::json(&detected),
        Format::Html => {
            let plane = super::figure::plane(args.plane);
            let pictures: Vec<Option<String>> = (0..detected.pairs.len())
                .take(crate::render::html::detect::PAIRS)
                .map(|k| {
                    crate::session::toi_picture(&sim, &lesson, &detected, k)
                        .map(|p| crate::render::toi_svg::svg(&p, plane))
                })
                .collect();
            let f = Fmt::new(args.digits as usize);
            crate::render::html::toi::document(&detected, &pictures, &f)
        }
        Format::Md | Format::Latex => {
            return Err(AppError::Usage(
                "detect --toi prints text, JSON or a web page (--format text|json|html)".into(),
            ))
        }
    };
    match &args.output {
        Some(path) => super::write_atomic(path, text.as_bytes()),
        None => out.write_all(text.as_bytes()).map_err(io),
    }
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

/// The scene run up to step `step`, then that step's pairs searched; and
/// the run standing where the searches started (for the figure).
fn traced(
    lesson: &Lesson,
    step: u64,
    method: ToiMethod,
    pair: Option<(usize, usize)>,
) -> Result<(Simulation<f64>, DetectToi), AppError> {
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
                "{}: the run up to step {step} stopped: {}",
                lesson.id,
                crate::trace::blow_up::plain(&e)
            ))
        })?;
    }
    let toi = crate::session::toi_trace(&sim, lesson, step, method, pair).map_err(|(i, j)| {
        AppError::Usage(format!(
            "--pair {},{}: a pair needs a convex shape (a sphere, box, cylinder, capsule or hull) against another or a half-space to be searched; two half-spaces, or a body without a shape, have no time of collision",
            lesson.bodies[i].name, lesson.bodies[j].name
        ))
    })?;
    Ok((sim, toi))
}
