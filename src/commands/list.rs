//! `contact-lab list`, and the greeting of a bare `contact-lab`.

use std::io::Write;

use super::io;
use crate::error::AppError;
use crate::lesson::{embedded, Lesson};

/// The embedded lessons as a table folded to `width` (the id and contact
/// count stay; a long title folds under itself).
fn table(out: &mut dyn Write, width: usize) -> Result<(), AppError> {
    let lessons: Vec<Lesson> = embedded::ids()
        .into_iter()
        .map(Lesson::load)
        .collect::<Result<_, _>>()
        .map_err(|e| AppError::Runtime(format!("an embedded lesson is invalid: {e}")))?;
    let head = ["id", "contacts", "title — source"].map(String::from);
    let rows: Vec<Vec<String>> = lessons
        .iter()
        .map(|l| {
            vec![
                l.id.clone(),
                format!("{:>8}", l.contacts.len()),
                format!("{} — {}", l.title, l.source),
            ]
        })
        .collect();
    let text = crate::render::wrap::table(0, 2, &head, &rows, width);
    out.write_all(text.as_bytes()).map_err(io)
}

pub fn list(out: &mut dyn Write, width: usize) -> Result<(), AppError> {
    table(out, width)?;
    scenes(out, width)
}

/// The scenes, which `simulate` steps in time.
fn scenes(out: &mut dyn Write, width: usize) -> Result<(), AppError> {
    let scenes: Vec<Lesson> = embedded::scene_ids()
        .into_iter()
        .map(Lesson::load)
        .collect::<Result<_, _>>()
        .map_err(|e| AppError::Runtime(format!("an embedded scene is invalid: {e}")))?;
    let w = scenes.iter().map(|l| l.id.len()).max().unwrap_or(2).max(2);
    writeln!(out, "\nScenes (contact-lab simulate ID):").map_err(io)?;
    for l in &scenes {
        let line = format!("{:w$}  {}", l.id, l.title);
        writeln!(out, "{}", crate::render::wrap::wrap(&line, width)).map_err(io)?;
    }
    Ok(())
}

pub fn welcome(out: &mut dyn Write) -> Result<(), AppError> {
    writeln!(
        out,
        "contact-lab — step through rigid-body contact resolution, stage by stage.\n"
    )
    .map_err(io)?;
    table(out, super::text_width(None))?;
    writeln!(
        out,
        "\nStart with:  contact-lab solve lecture-2      (the lecture's second worked example)\n             contact-lab glossary             (every symbol: meaning, unit, stages)\n             contact-lab solve LESSON --format json\n             contact-lab resolve box-four-corners   (a scene's contacts resolved together)\n             contact-lab --help"
    )
    .map_err(io)?;
    // Run by a path (./target/release/contact-lab), the bare name may not be
    // on PATH: say how to run it as it was run, or install it.
    if let Some(program) = std::env::args().next().filter(|p| p.contains('/')) {
        writeln!(
            out,
            "\n`contact-lab` above means this program: run it as {program} (e.g. {program} solve lecture-2),\nor put it on your PATH with `cargo install --path .`."
        )
        .map_err(io)?;
    }
    Ok(())
}
