//! `contact-lab study --verdicts`: the verdict matrix (docs/study.md "The
//! verdict matrix"). Says what it will run, runs its cells on every core
//! with a progress bar on a terminal, and renders it; Ctrl-C stops at the
//! cells running and prints what was done (exit 1, as `simulate`).

use std::io::Write;
use std::sync::atomic::Ordering;

use super::{io, progress};
use crate::cli::{StudyArgs, StudyFormat};
use crate::error::AppError;
use crate::format::Fmt;
use crate::render::study::verdicts as render;
use crate::study::verdicts::{self, criteria::SCENES, Size};

pub fn verdicts(args: &StudyArgs, out: &mut dyn Write) -> Result<(), AppError> {
    let given = [
        (!args.scenes.is_empty(), "scenes"),
        (!args.grid.is_empty(), "--grid"),
        (args.seconds.is_some(), "--seconds"),
    ];
    if let Some((_, what)) = given.iter().find(|(g, _)| *g) {
        return Err(AppError::Usage(format!(
            "--verdicts runs its own fixed scenes for their own times: it takes no {what} (--quick gives reduced sizes)"
        )));
    }
    if matches!(
        args.format,
        StudyFormat::Csv | StudyFormat::Md | StudyFormat::Html
    ) {
        return Err(AppError::Usage(
            "--verdicts prints text, json or svg".to_string(),
        ));
    }
    let size = if args.quick {
        Size::Reduced
    } else {
        Size::Full
    };
    let columns = verdicts::columns();
    let cells = SCENES.len() * columns.len();
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let bar = progress::bar(
        cells as u64,
        "cells",
        &format!(
            "study --verdicts: {} scenes × {} solvers = {cells} runs on {threads} thread(s){}",
            SCENES.len(),
            columns.len(),
            if size == Size::Reduced {
                ", reduced sizes"
            } else {
                ""
            }
        ),
    );
    let stop = progress::interrupted();
    let matrix = verdicts::run(size, threads, stop, &|done, _, scene| {
        bar.bar.set_message(scene.to_string());
        bar.bar.set_position(done as u64);
    });
    drop(bar);
    let fmt = Fmt::new(args.digits as usize);
    let text = match args.format {
        StudyFormat::Json => render::json(&matrix),
        StudyFormat::Svg => render::svg(&matrix, &fmt),
        _ => {
            let width = super::text_width(args.fold.width);
            crate::render::wrap::wrap(&render::text(&matrix, &fmt, width), width)
        }
    };
    match &args.output {
        Some(path) => super::write_atomic(path, text.as_bytes())?,
        None => out.write_all(text.as_bytes()).map_err(io)?,
    }
    if stop.load(Ordering::SeqCst) || matrix.not_run > 0 {
        return Err(AppError::Runtime(format!(
            "study --verdicts: interrupted (Ctrl-C) with {} of {cells} cells not run; the output shows those done",
            matrix.not_run
        )));
    }
    Ok(())
}
