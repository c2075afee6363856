//! `contact-lab study --broad-phase`: the broad-phase study (docs/study.md,
//! "The broad phase"), with a progress bar on stderr on a terminal.

use std::io::Write;

use super::{io, progress};
use crate::cli::{StudyArgs, StudyFormat};
use crate::error::AppError;
use crate::format::Fmt;
use crate::render::study::broad as render;
use crate::study::broad::{self, COUNTS};

/// The most bodies one point may have.
const MAX_BODIES: usize = 100_000;

pub fn study(args: &StudyArgs, out: &mut dyn Write) -> Result<(), AppError> {
    let counts: Vec<usize> = if args.bodies.is_empty() {
        COUNTS.to_vec()
    } else {
        args.bodies.clone()
    };
    if let Some(bad) = counts.iter().find(|&&n| !(2..=MAX_BODIES).contains(&n)) {
        return Err(AppError::Usage(format!(
            "--bodies: each count must be from 2 to {MAX_BODIES}, got {bad}"
        )));
    }
    if args.format == StudyFormat::Html {
        return Err(AppError::Usage(
            "study --broad-phase has no web page: --format text, md, json, csv or svg".into(),
        ));
    }
    let total = (counts.len() * broad::Case::ALL.len()) as u64;
    let bar = progress::bar(
        total,
        "points",
        &format!(
            "study --broad-phase: 3 methods × {} body counts × 2 cases",
            counts.len()
        ),
    );
    let study = broad::run(&counts, !args.no_timing, &mut |done, _| {
        bar.bar.set_position(done as u64)
    });
    drop(bar);
    let fmt = Fmt::new(args.digits as usize);
    let text = match args.format {
        StudyFormat::Text => {
            let width = super::text_width(args.fold.width);
            crate::render::wrap::wrap(&render::text(&study, &fmt, false), width)
        }
        StudyFormat::Md => render::text(&study, &fmt, true),
        StudyFormat::Json => render::json(&study),
        StudyFormat::Svg => render::svg(&study),
        StudyFormat::Csv => render::csv(&study),
        StudyFormat::Html => unreachable!("refused above"),
    };
    match &args.output {
        Some(path) => super::write_atomic(path, text.as_bytes()),
        None => out.write_all(text.as_bytes()).map_err(io),
    }
}
