//! `contact-lab study`: speed against accuracy (docs/study.md). Loads the
//! scenes, runs the study with a progress bar on stderr (only on a terminal,
//! and only once the study has run for a second), renders it.

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use super::{io, warn};
use crate::cli::{StudyArgs, StudyFormat};
use crate::error::AppError;
use crate::format::Fmt;
use crate::lesson::Lesson;
use crate::physics::Solver;
use crate::render::study as render;
use crate::study::grid::{self, SCENES};
use crate::study::sweep::{self, Options, SceneSpec};

/// The most simulated seconds per scene.
pub(super) const MAX_SECONDS: f64 = 60.0;

fn specs(args: &StudyArgs, err: &mut dyn Write) -> Result<Vec<SceneSpec>, AppError> {
    let names: Vec<std::ffi::OsString> = if args.scenes.is_empty() {
        SCENES.iter().map(|(id, _, _)| (*id).into()).collect()
    } else {
        args.scenes.clone()
    };
    if let Some(t) = args.seconds {
        if !(t.is_finite() && t > 0.0 && t <= MAX_SECONDS) {
            return Err(AppError::Usage(format!(
                "--seconds must be a time > 0 and at most {MAX_SECONDS} s, got {t}"
            )));
        }
    }
    let mut specs = Vec::new();
    for name in names {
        let lesson = Lesson::load(&name)?;
        warn(&lesson, err);
        let Some(scene) = &lesson.simulation else {
            return Err(AppError::Usage(format!(
                "{} is not a scene: it has no [world], [step] or [sleep] table, so nothing says how to step it",
                lesson.id
            )));
        };
        let known = SCENES.iter().find(|(id, _, _)| *id == lesson.id);
        let seconds = args
            .seconds
            .unwrap_or_else(|| known.map_or((scene.steps as f64 * scene.dt).min(2.0), |k| k.1));
        let reference_solver = known.map_or(Solver::SequentialImpulse, |k| k.2);
        specs.push(SceneSpec {
            lesson,
            seconds,
            reference_solver,
        });
    }
    Ok(specs)
}

pub fn study(args: &StudyArgs, out: &mut dyn Write, err: &mut dyn Write) -> Result<(), AppError> {
    let mut user = Vec::new();
    for g in &args.grid {
        user.push(grid::parse_grid(g).map_err(|e| AppError::Usage(format!("--grid: {e}")))?);
    }
    let specs = specs(args, err)?;
    let options = Options {
        timed: !args.no_timing,
        repeats: args.repeat as usize,
        quick: args.quick,
        grid: user,
    };
    let total = sweep::planned(&specs, &options) as u64;
    let bar = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::hidden());
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} configurations · {msg} · {elapsed}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let start = Instant::now();
    let terminal = std::io::stderr().is_terminal();
    let mut shown = false;
    let study = sweep::study(&specs, &options, &mut |done, scene| {
        if !shown && terminal && start.elapsed() > Duration::from_secs(1) {
            bar.set_draw_target(ProgressDrawTarget::stderr());
            shown = true;
        }
        bar.set_message(scene.to_string());
        bar.set_position(done as u64);
    });
    bar.finish_and_clear();
    let fmt = Fmt::new(args.digits as usize);
    let text = match args.format {
        StudyFormat::Text => render::text(&study, &fmt),
        StudyFormat::Json => render::json::render(&study),
        StudyFormat::Csv => render::csv::render(&study),
        StudyFormat::Svg => render::svg::render(&study),
        StudyFormat::Md => render::markdown::render(&study, &fmt),
    };
    out.write_all(text.as_bytes()).map_err(io)
}
