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
            "unknown exercise kind \"{name}\" (kinds: mixed, frictionless, static-friction, dynamic-friction, penetration)"
        ))
    })
}

/// `exercise --grade FILE`: the sheet regenerated from the file's seed, each
/// answer graded, the report and the score.
fn grade_file(path: &std::path::Path, out: &mut dyn Write) -> Result<(), AppError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| AppError::Runtime(format!("cannot read {}: {e}", path.display())))?;
    let (id, answers) = exercise::grade::read(&text)
        .map_err(|e| AppError::Usage(format!("{}: {e}", path.display())))?;
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
    let text = match args.format {
        SheetFormat::Md => {
            let figures = match &args.output {
                None => sheet::MdFigures::Inline,
                Some(path) => sheet::MdFigures::Files(write_figures(path, &exercises)?),
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
        Some(path) => write_atomic(path, text.as_bytes()),
        None => out.write_all(text.as_bytes()).map_err(io),
    }
}

/// Each exercise's figure written beside the sheet `path` (`STEM-N.svg`,
/// N from 1); the links, relative to the sheet.
fn write_figures(
    path: &std::path::Path,
    exercises: &[exercise::Exercise],
) -> Result<Vec<String>, AppError> {
    let stem = path
        .file_stem()
        .map_or_else(|| "sheet".into(), |s| s.to_string_lossy().into_owned());
    let dir = path.parent().unwrap_or(std::path::Path::new(""));
    let mut links = vec![];
    for (i, e) in exercises.iter().enumerate() {
        let name = format!("{stem}-{}.svg", i + 1);
        write_atomic(&dir.join(&name), sheet::figure_svg(e).as_bytes())?;
        // A Markdown link target: no raw spaces or parentheses.
        let link = name
            .replace(' ', "%20")
            .replace('(', "%28")
            .replace(')', "%29");
        links.push(link);
    }
    Ok(links)
}
