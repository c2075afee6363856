//! `contact-lab list`, and the greeting of a bare `contact-lab`.

use std::io::Write;

use super::io;
use crate::error::AppError;
use crate::lesson::{embedded, Lesson};

fn table(out: &mut dyn Write) -> Result<(), AppError> {
    let lessons: Vec<Lesson> = embedded::ids()
        .into_iter()
        .map(Lesson::load)
        .collect::<Result<_, _>>()
        .map_err(|e| AppError::Runtime(format!("an embedded lesson is invalid: {e}")))?;
    let w = lessons.iter().map(|l| l.id.len()).max().unwrap_or(2).max(2);
    writeln!(out, "{:w$}  {:>8}  title — source", "id", "contacts").map_err(io)?;
    for l in &lessons {
        writeln!(
            out,
            "{:w$}  {:>8}  {} — {}",
            l.id,
            l.contacts.len(),
            l.title,
            l.source
        )
        .map_err(io)?;
    }
    Ok(())
}

pub fn list(out: &mut dyn Write) -> Result<(), AppError> {
    table(out)?;
    scenes(out)
}

/// The scenes, which `simulate` steps in time.
fn scenes(out: &mut dyn Write) -> Result<(), AppError> {
    let scenes: Vec<Lesson> = embedded::scene_ids()
        .into_iter()
        .map(Lesson::load)
        .collect::<Result<_, _>>()
        .map_err(|e| AppError::Runtime(format!("an embedded scene is invalid: {e}")))?;
    let w = scenes.iter().map(|l| l.id.len()).max().unwrap_or(2).max(2);
    writeln!(out, "\nScenes (contact-lab simulate ID):").map_err(io)?;
    for l in &scenes {
        writeln!(out, "{:w$}  {}", l.id, l.title).map_err(io)?;
    }
    Ok(())
}

pub fn welcome(out: &mut dyn Write) -> Result<(), AppError> {
    writeln!(
        out,
        "contact-lab — step through rigid-body contact resolution, stage by stage.\n"
    )
    .map_err(io)?;
    table(out)?;
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
