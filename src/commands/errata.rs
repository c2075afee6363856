//! `contact-lab check`: the errata — every printed lecture number against the
//! computed one; exit 1 on a disagreement that is not a known erratum.

use std::io::Write;

use super::io;
use crate::cli::{ErrataArgs, ErrataFormat};
use crate::errata::{self, Tally};
use crate::error::AppError;
use crate::format::Fmt;
use crate::lesson::{embedded, Lesson};
use crate::render;

pub fn errata(args: &ErrataArgs, out: &mut dyn Write, err: &mut dyn Write) -> Result<(), AppError> {
    let names: Vec<std::ffi::OsString> = if args.lessons.is_empty() {
        embedded::ids().into_iter().map(Into::into).collect()
    } else {
        args.lessons.clone()
    };
    let mut lessons = Vec::new();
    let mut items = Vec::new();
    for name in &names {
        let lesson = Lesson::load(name)?;
        super::warn(&lesson, err);
        let traces: Vec<_> = (0..lesson.contacts.len())
            .map(|k| crate::worked_solution(&lesson, k))
            .collect();
        items.extend(errata::lesson(&lesson, &traces));
        lessons.push((lesson.id.clone(), lesson.title.clone()));
    }
    // The papers' errata beside the lecture's: in the default run only (a
    // run over named lessons checks those lessons).
    let papers = args.lessons.is_empty().then(errata::xpbd::measure);
    let text = match args.format {
        ErrataFormat::Text => {
            let fmt = Fmt::default();
            let mut sheet = render::errata::text(&lessons, &items, &fmt);
            if let Some(e) = &papers {
                sheet.push('\n');
                sheet.push_str(&render::errata::xpbd_text(e, &fmt));
            }
            render::wrap::wrap(&sheet, super::text_width(args.fold.width))
        }
        ErrataFormat::Json => render::errata::json(&items, papers.as_ref()),
    };
    out.write_all(text.as_bytes()).map_err(io)?;
    let tally = Tally::of(&items);
    if tally.failures() > 0 {
        return Err(AppError::Runtime(format!(
            "check failed: {} new disagreement(s), {} stale erratum note(s), {} printed value(s) not computed",
            tally.new, tally.stale, tally.not_computed
        )));
    }
    Ok(())
}
