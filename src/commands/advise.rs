//! `contact-lab advise SCENE --error E`: the cheapest configuration whose
//! error against the scene's reference stays at or below E (docs/study.md).

use std::io::Write;

use super::{io, progress, warn};
use crate::cli::{AdviseArgs, AdviseFormat, PerArg};
use crate::error::AppError;
use crate::format::Fmt;
use crate::lesson::Lesson;
use crate::render::study::advise as render;
use crate::study::advise::{Per, Watch};

pub fn advise(args: &AdviseArgs, out: &mut dyn Write, err: &mut dyn Write) -> Result<(), AppError> {
    if !(args.error.is_finite() && args.error > 0.0) {
        return Err(AppError::Usage(format!(
            "--error must be a distance > 0 (metres), got {}",
            args.error
        )));
    }
    if let Some(t) = args.seconds {
        if !(t.is_finite() && t > 0.0 && t <= super::study::MAX_SECONDS) {
            return Err(AppError::Usage(format!(
                "--seconds must be a time > 0 and at most {} s, got {t}",
                super::study::MAX_SECONDS
            )));
        }
    }
    let lesson = Lesson::load(&args.scene)?;
    warn(&lesson, err);
    let Some((default_seconds, solver)) = crate::study::advise::run_of(&lesson) else {
        return Err(AppError::Usage(format!(
            "{} is not a scene: it has no [world], [step] or [sleep] table, so nothing says how to step it",
            lesson.id
        )));
    };
    let seconds = args.seconds.unwrap_or(default_seconds);
    let per = match args.per {
        PerArg::Run => Per::Run,
        PerArg::Step => Per::Step,
    };
    // Progress on a terminal (a search on a 200-sphere pile runs for
    // minutes): the stages done, with an estimate of the time left.
    let shown = Shown {
        progress: progress::bar(
            1,
            "stages",
            &format!(
                "advise: the cheapest model of {} within {} m of its reference ({} s per run), searched in stages; the time left is estimated from the stages done",
                lesson.id,
                Fmt::new(3).num(args.error),
                Fmt::new(3).num(seconds)
            ),
        ),
        begun: std::cell::Cell::new(0),
        stage: std::cell::RefCell::new(String::new()),
    };
    let advice =
        crate::study::advise::advise_watched(&lesson, seconds, solver, args.error, per, &shown);
    drop(shown);
    let Some(advice) = advice else {
        return Err(AppError::Runtime(format!("{} cannot be run", lesson.id)));
    };
    let fmt = Fmt::new(args.digits as usize);
    let text = match args.format {
        AdviseFormat::Text => render::text(&advice, &fmt),
        AdviseFormat::Md => render::markdown(&advice, &fmt),
        AdviseFormat::Json => render::json(&advice),
    };
    out.write_all(text.as_bytes()).map_err(io)
}

/// The search's progress as a bar of stages, the current one and the
/// configurations run named beside it.
struct Shown {
    progress: progress::Progress,
    begun: std::cell::Cell<u64>,
    stage: std::cell::RefCell<String>,
}

impl Watch for Shown {
    fn plan(&self, stages: usize) {
        self.progress.bar.set_length(stages as u64);
    }

    fn stage(&self, what: &str) {
        self.progress.bar.set_position(self.begun.get());
        self.begun.set(self.begun.get() + 1);
        self.progress.bar.set_message(what.to_string());
        *self.stage.borrow_mut() = what.to_string();
    }

    fn ran(&self, runs: usize, steps: usize) {
        self.progress.bar.set_message(format!(
            "{}: {runs} configurations, {steps} steps",
            self.stage.borrow()
        ));
    }
}
