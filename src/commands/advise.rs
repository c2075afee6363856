//! `contact-lab advise SCENE --error E`: the cheapest configuration whose
//! error against the scene's reference stays at or below E (docs/study.md).

use std::io::Write;

use super::{io, warn};
use crate::cli::{AdviseArgs, AdviseFormat, PerArg};
use crate::error::AppError;
use crate::format::Fmt;
use crate::lesson::Lesson;
use crate::render::study::advise as render;
use crate::study::advise::Per;

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
    let Some(advice) = crate::study::advise::advise(&lesson, seconds, solver, args.error, per)
    else {
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
