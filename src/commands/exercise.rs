//! `contact-lab exercise`: a question sheet (and answers) from a seed.

use std::io::Write;

use super::{io, write_atomic};
use crate::cli::{ExerciseArgs, ExerciseKind, SheetFormat};
use crate::error::AppError;
use crate::exercise::{self, sheet, Kind};
use crate::format::Fmt;

fn kind(k: ExerciseKind) -> (Option<Kind>, &'static str) {
    match k {
        ExerciseKind::Frictionless => (Some(Kind::Frictionless), "frictionless"),
        ExerciseKind::StaticFriction => (Some(Kind::StaticFriction), "static-friction"),
        ExerciseKind::DynamicFriction => (Some(Kind::DynamicFriction), "dynamic-friction"),
        ExerciseKind::Penetration => (Some(Kind::Penetration), "penetration"),
        ExerciseKind::Mixed => (None, "mixed"),
    }
}

/// The kind named in an answer file.
fn kind_named(name: &str) -> Result<ExerciseKind, AppError> {
    use clap::ValueEnum;
    ExerciseKind::from_str(name, false).map_err(|_| {
        AppError::Usage(format!(
            "unknown exercise kind \"{}\" (kinds: mixed, frictionless, static-friction, dynamic-friction, penetration)",
            exercise::grade::echo(name)
        ))
    })
}

/// `exercise --grade FILE`: the sheet regenerated from the file's seed, each
/// answer graded, the report and the score.
/// The file is read as a lesson is (a regular file only, never a FIFO or a
/// device) and refused above [`exercise::grade::MAX_BYTES`].
fn grade_file(path: &std::path::Path, out: &mut dyn Write) -> Result<(), AppError> {
    use crate::lesson::read::{read_regular, Refused};
    let shown = crate::output_file::shown(path);
    let cannot =
        |reason: String| AppError::Runtime(format!("cannot read answer file {shown}: {reason}"));
    let limit = exercise::grade::MAX_BYTES;
    let bytes = read_regular(path, limit).map_err(|e| match e {
        Refused::Open(e) | Refused::Read(e) => cannot(e.to_string()),
        Refused::NotRegular(what) => cannot(format!(
            "it is {what}, not an answer file (an answer file is a TOML file)"
        )),
    })?;
    if bytes.len() > limit {
        return Err(cannot(format!(
            "larger than {} KiB; an answer file for at most 50 exercises is a few KiB",
            limit >> 10
        )));
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        cannot(format!(
            "not UTF-8 text (invalid bytes at byte {})",
            e.utf8_error().valid_up_to()
        ))
    })?;
    let (id, answers) =
        exercise::grade::read(&text).map_err(|e| AppError::Usage(format!("{shown}: {e}")))?;
    let (k, _) = kind(kind_named(&id.kind)?);
    let exercises = exercise::generate(id.seed, k, id.count).map_err(AppError::Runtime)?;
    let (report, _) = exercise::grade::report(&exercises, &answers);
    out.write_all(report.as_bytes()).map_err(io)
}

pub fn exercise(args: &ExerciseArgs, out: &mut dyn Write) -> Result<(), AppError> {
    if let Some(path) = &args.grade {
        return grade_file(path, out);
    }
    let seed = args.seed.expect("clap requires --seed without --grade");
    let count = args.count as usize;
    if args.format == SheetFormat::Toml && count > 1 && args.dir.is_none() {
        return Err(AppError::Usage(
            "--format toml writes one lesson file per exercise: give --dir DIR for --count > 1"
                .into(),
        ));
    }
    if args.dir.is_some() && args.format != SheetFormat::Toml {
        return Err(AppError::Usage("--dir applies to --format toml".into()));
    }
    let (k, name) = kind(args.kind);
    let exercises = exercise::generate(seed, k, count).map_err(AppError::Runtime)?;
    if args.answer_template {
        let id = exercise::grade::SheetId {
            seed,
            kind: name.to_string(),
            count,
        };
        let text = exercise::grade::template(&id, &exercises);
        return out.write_all(text.as_bytes()).map_err(io);
    }
    let request = sheet::Request {
        seed,
        kind: name,
        count,
    };
    let fmt = Fmt::new(args.digits as usize);
    // The figures written beside the sheet, removed again if the sheet is not.
    let mut written = vec![];
    let text = match args.format {
        SheetFormat::Md => {
            let figures = match &args.output {
                None => sheet::MdFigures::Inline,
                Some(path) => {
                    // The sheet's target refused (a directory, a link) before
                    // any figure is written beside it.
                    crate::output_file::check(path, crate::output_file::Existing::Replace)
                        .map_err(|e| AppError::Runtime(format!("cannot write {e}")))?;
                    let (links, files) = write_figures(path, &exercises)?;
                    written = files;
                    sheet::MdFigures::Files(links)
                }
            };
            sheet::markdown(&exercises, &request, args.answers, &fmt, &figures)
        }
        SheetFormat::Latex => sheet::latex(&exercises, &request, args.answers, &fmt),
        SheetFormat::Toml => match &args.dir {
            None => exercises[0].toml.clone(),
            Some(dir) => {
                std::fs::create_dir_all(dir).map_err(|e| {
                    AppError::Runtime(format!("cannot create {}: {e}", dir.display()))
                })?;
                let mut list = String::new();
                for e in &exercises {
                    let path = dir.join(format!("{}.toml", e.lesson.id));
                    write_atomic(&path, e.toml.as_bytes())?;
                    list.push_str(&format!("{}\n", path.display()));
                }
                list
            }
        },
    };
    match &args.output {
        Some(path) => write_atomic(path, text.as_bytes()).inspect_err(|_| {
            for f in &written {
                let _ = std::fs::remove_file(f);
            }
        }),
        None => out.write_all(text.as_bytes()).map_err(io),
    }
}

/// Each exercise's figure written beside the sheet `path` (`STEM-N.svg`,
/// N from 1); the links, relative to the sheet, and the files written (a
/// failure part way removes those already written).
fn write_figures(
    path: &std::path::Path,
    exercises: &[exercise::Exercise],
) -> Result<(Vec<String>, Vec<std::path::PathBuf>), AppError> {
    let stem = path
        .file_stem()
        .map_or_else(|| "sheet".into(), |s| s.to_string_lossy().into_owned());
    let dir = path.parent().unwrap_or(std::path::Path::new(""));
    let mut links = vec![];
    let mut files: Vec<std::path::PathBuf> = vec![];
    for (i, e) in exercises.iter().enumerate() {
        let name = format!("{stem}-{}.svg", i + 1);
        let file = dir.join(&name);
        if let Err(err) = write_atomic(&file, sheet::figure_svg(e).as_bytes()) {
            for f in &files {
                let _ = std::fs::remove_file(f);
            }
            return Err(err);
        }
        files.push(file);
        // A Markdown link target: no raw spaces or parentheses.
        let link = name
            .replace(' ', "%20")
            .replace('(', "%28")
            .replace(')', "%29");
        links.push(link);
    }
    Ok((links, files))
}
