//! `contact-lab solve`: the worked solution of one contact, or of all.

use std::io::Write;

use super::{file_stem, io, load, warn, write_atomic};
use crate::cli::{Format, SolveArgs};
use crate::error::AppError;
use crate::format::Fmt;
use crate::physics::{FrictionModel, Solution};
use crate::render;
use crate::render::contact::compare::Compared;
use crate::render::contact::markdown::Figures;
use crate::render::svg::{self, Plane};

fn usage(args: &SolveArgs) -> Result<(), AppError> {
    let bad = |m: &str| Err(AppError::Usage(m.to_string()));
    if args.compare_friction && matches!(args.format, Format::Md | Format::Latex | Format::Html) {
        return bad("--compare-friction prints text or JSON (--format text|json)");
    }
    if args.compare_friction && args.all_contacts {
        return bad("--compare-friction compares one contact; leave out --all-contacts");
    }
    if args.fragment && args.format != Format::Latex {
        return bad("--fragment applies to --format latex");
    }
    if args.figures.is_some() && args.format != Format::Md {
        return bad("--figures applies to --format md");
    }
    Ok(())
}

pub fn solve(args: &SolveArgs, out: &mut dyn Write, err: &mut dyn Write) -> Result<(), AppError> {
    usage(args)?;
    let lesson = load(
        &args.lesson,
        &super::overrides(&args.model)?,
        Some(args.contact),
    )?;
    warn(&lesson, err);
    let fmt = Fmt::new(args.digits as usize);
    if args.compare_friction {
        let compared: Vec<_> = FrictionModel::ALL
            .into_iter()
            .map(|model| {
                let mut l = lesson.clone();
                for c in &mut l.contacts {
                    c.settings.friction_model = model;
                }
                let solution = solved(&l, args.contact)?;
                let trace = crate::trace::build(&l, args.contact, &solution);
                Ok(Compared {
                    model,
                    solution,
                    trace,
                })
            })
            .collect::<Result<_, AppError>>()?;
        let text = match args.format {
            Format::Json => render::contact::compare::json(&compared),
            _ => {
                let width = super::text_width(args.fold.width);
                crate::render::wrap::wrap(
                    &render::contact::compare::text(&compared, &fmt, width),
                    width,
                )
            }
        };
        return emit(args, &text, out);
    }
    let contacts: Vec<usize> = if args.all_contacts {
        (0..lesson.contacts.len()).collect()
    } else {
        vec![args.contact]
    };
    let traces = contacts
        .iter()
        .map(|&k| {
            let solution = solved(&lesson, k)?;
            let mut trace = crate::trace::build(&lesson, k, &solution);
            crate::trace::note_planar_acceleration(&mut trace, &solution);
            Ok(trace)
        })
        .collect::<Result<Vec<_>, AppError>>()?;
    let text = match args.format {
        Format::Text => traces
            .iter()
            .map(|t| render::contact::text::render(t, &fmt))
            .collect::<Vec<_>>()
            .join("\n"),
        Format::Json if args.all_contacts => {
            let all: Vec<_> = traces.iter().map(render::contact::json::to_json).collect();
            serde_json::to_string_pretty(&all).expect("JSON of traces") + "\n"
        }
        Format::Json => render::contact::json::render(&traces[0]),
        Format::Md => {
            let figures = match &args.figures {
                Some(dir) => figures(dir, &lesson.id, &contacts, &traces)?,
                None => vec![],
            };
            render::contact::markdown::document(&traces, &fmt, &figures)
        }
        Format::Latex => render::contact::latex::document(&traces, &fmt, args.fragment),
        Format::Html => {
            let note = (args.all_contacts && lesson.contacts.len() > 1)
                .then(|| alone_words(&lesson.id).replace('`', ""));
            render::html::solve::document(&traces, &fmt, note.as_deref())
        }
    };
    let text = if args.all_contacts && lesson.contacts.len() > 1 {
        alone_note(&text, &lesson.id, args.format)
    } else {
        text
    };
    let text = match args.format {
        Format::Text => crate::render::wrap::wrap(&text, super::text_width(args.fold.width)),
        _ => text,
    };
    emit(args, &text, out)
}

/// The output to `-o FILE` (atomically) or stdout.
fn emit(args: &SolveArgs, text: &str, out: &mut dyn Write) -> Result<(), AppError> {
    match &args.output {
        Some(path) => write_atomic(path, text.as_bytes()),
        None => out.write_all(text.as_bytes()).map_err(io),
    }
}

/// Contact `k` solved; an exact impact integration that could not finish is
/// a runtime failure (exit 1) with its reason, never a NaN in the output.
fn solved(lesson: &crate::lesson::Lesson, k: usize) -> Result<Solution<f64>, AppError> {
    let solution = crate::physics::solve(&lesson.problem::<f64>(k));
    if let Some(Err(e)) = &solution.exact {
        return Err(AppError::Runtime(format!("contact {k}: {e}")));
    }
    Ok(solution)
}

/// `--all-contacts` solves each contact alone, from the scene as given: say so
/// at the top of the output (JSON keeps its contract) and point to `resolve`.
fn alone_words(id: &str) -> String {
    format!(
        "Each contact below is solved alone, from the scene as given: the results are \
         independent of each other. To resolve the contacts together, in order, each \
         resolution updating the others, run `contact-lab resolve {id}`."
    )
}

fn alone_note(text: &str, id: &str, format: Format) -> String {
    let note = alone_words(id);
    match format {
        Format::Json | Format::Html => text.to_string(),
        Format::Text => format!("{note}\n\n{text}"),
        Format::Md => format!("> {}\n\n{text}", render::contact::markdown::escape(&note)),
        Format::Latex => {
            let para = format!(
                "\\noindent\\emph{{{}}}\n\n",
                crate::render::tex::escape_text(&note.replace('`', ""))
            );
            match text.find("\\begin{document}\n") {
                Some(at) => {
                    let at = at + "\\begin{document}\n".len();
                    format!("{}{para}{}", &text[..at], &text[at..])
                }
                None => format!("{para}{text}"),
            }
        }
    }
}

/// Writes one SVG per contact into `dir`, and the impulse-space figure of
/// each contact whose `exact_impact` stage ran; returns the links to them.
fn figures(
    dir: &std::path::Path,
    id: &str,
    contacts: &[usize],
    traces: &[crate::trace::Trace],
) -> Result<Vec<Figures>, AppError> {
    std::fs::create_dir_all(dir)
        .map_err(|e| AppError::Runtime(format!("cannot create {}: {e}", dir.display())))?;
    let write = |name: String, text: String| -> Result<String, AppError> {
        write_atomic(&dir.join(&name), text.as_bytes())?;
        let link = dir.join(&name).to_string_lossy().replace('\\', "/");
        Ok(link.replace(' ', "%20"))
    };
    contacts
        .iter()
        .zip(traces)
        .map(|(k, t)| {
            let stem = file_stem(id);
            // The contact's picture alone: the impulse-space figure has its own file.
            let mut picture = t.clone();
            picture.impact = None;
            let contact = write(
                format!("{stem}-contact-{k}.svg"),
                svg::render(&picture, Plane::Xy),
            )?;
            let impulse = render::contact::impact::svg(t)
                .map(|text| write(format!("{stem}-contact-{k}-impulse.svg"), text))
                .transpose()?;
            Ok(Figures {
                contact: Some(contact),
                impulse,
            })
        })
        .collect()
}
