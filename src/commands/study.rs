//! `contact-lab study`: speed against accuracy (docs/study.md). Loads the
//! scenes, says what it will run and runs it with a progress bar on stderr
//! (only on a terminal), renders it. Beyond its caps it asks for `--force`.

use std::io::Write;

use super::{io, progress, warn};
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
                "--seconds must be a time > 0 and at most {MAX_SECONDS} s, got {}",
                crate::format::exact(t)
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
    if args.broad_phase {
        return super::study_broad::study(args, out);
    }
    if args.verdicts {
        return super::verdicts::verdicts(args, out);
    }
    let mut user = Vec::new();
    for g in &args.grid {
        user.push(grid::parse_grid(g).map_err(|e| AppError::Usage(format!("--grid: {e}")))?);
    }
    // The cross product's size before it is built: building a huge one is
    // itself slow (issue 23: a 10⁶-configuration grid started with no word).
    let crossed = user
        .iter()
        .fold(1u64, |n, (_, v)| n.saturating_mul(v.len() as u64));
    if !args.force && crossed > progress::STUDY_CONFIGURATIONS_CAP {
        return Err(progress::beyond_cap(
            format!("the --grid cross product of up to {crossed} configurations"),
            "2,000 configurations",
        ));
    }
    let specs = specs(args, err)?;
    let options = Options {
        timed: !args.no_timing,
        repeats: args.repeat as usize,
        quick: args.quick,
        grid: user,
    };
    let total = sweep::planned(&specs, &options) as u64;
    let steps = planned_steps(&specs, &options);
    if !args.force && total > progress::STUDY_CONFIGURATIONS_CAP {
        return Err(progress::beyond_cap(
            format!("{total} configurations"),
            "2,000 configurations",
        ));
    }
    if !args.force && steps > progress::STUDY_STEPS_CAP {
        return Err(progress::beyond_cap(
            format!("{steps} simulated steps ({total} configurations, timing repeats included)"),
            "10 million steps (the default study simulates about half a million)",
        ));
    }
    let progress = progress::bar(
        total,
        "configurations",
        &format!(
            "study: {total} configurations over {} scene(s), {steps} simulated steps in all",
            specs.len()
        ),
    );
    let study = sweep::study(&specs, &options, &mut |done, scene| {
        progress.bar.set_message(scene.to_string());
        progress.bar.set_position(done as u64);
    });
    drop(progress);
    let fmt = Fmt::new(args.digits as usize);
    let text = match args.format {
        StudyFormat::Text => {
            let width = super::text_width(args.fold.width);
            crate::render::wrap::wrap(&render::text(&study, &fmt, width), width)
        }
        StudyFormat::Json => render::json::render(&study),
        StudyFormat::Csv => render::csv::render(&study),
        StudyFormat::Svg => render::svg::render(&study),
        StudyFormat::Md => render::markdown::render(&study, &fmt),
        StudyFormat::Html => crate::render::html::study::document(&study, &fmt),
    };
    match &args.output {
        Some(path) => super::write_atomic(path, text.as_bytes()),
        None => out.write_all(text.as_bytes()).map_err(io),
    }
}

/// The steps the study will simulate: each configuration's run, and its
/// timed repeats when timed, over every scene (the reference included).
fn planned_steps(specs: &[SceneSpec], o: &Options) -> u64 {
    use crate::study::run::steps;
    let runs = 1 + if o.timed { o.repeats.max(1) as u64 } else { 0 };
    specs
        .iter()
        .map(|s| {
            let Some(d) = grid::default_config(&s.lesson) else {
                return 0;
            };
            let reference =
                steps(s.seconds, grid::reference(&d, s.reference_solver).params.dt) as u64;
            grid::rows(&d, grid::features(&s.lesson), o.quick, &o.grid)
                .iter()
                .map(|(_, _, c)| runs.saturating_mul(steps(s.seconds, c.params.dt) as u64))
                .fold(reference, u64::saturating_add)
        })
        .fold(0, u64::saturating_add)
}
