//! What each subcommand does: load, solve, render, write.

mod advise;
mod detect;
mod detect_toi;
mod errata;
mod exercise;
mod figure;
mod list;
mod progress;
mod resolve;
mod resolve_compare;
mod show;
mod simulate;
pub mod simulate_html;
mod soft_trace;
mod solve;
mod study;
mod study_broad;
mod verdicts;

use std::io::Write;

use crate::cli::{flag, Cli, Command, KnobArgs, Levels};
use crate::error::AppError;
use crate::lesson::{knob_value, Lesson, Overrides};

/// Runs the parsed command line, writing results to `out` and warnings to `err`.
pub fn run(cli: Cli, out: &mut dyn Write, err: &mut dyn Write) -> Result<(), AppError> {
    match cli.command {
        None if interactive() => crate::tui::run(crate::tui::open(None::<&std::ffi::OsStr>, None)?),
        None => list::welcome(out),
        Some(Command::Tui(args)) => {
            let app = crate::tui::open(args.lesson.as_deref(), args.contact)?;
            if !interactive() {
                return Err(AppError::Usage(
                    "the TUI needs a terminal on stdin and stdout; for a script use `contact-lab solve LESSON`".into(),
                ));
            }
            crate::tui::run(app)
        }
        Some(Command::List(args)) => list::list(out, text_width(args.fold.width)),
        Some(Command::Knobs) => out
            .write_all(crate::render::knobs::markdown().as_bytes())
            .map_err(io),
        Some(Command::Solve(args)) => solve::solve(&args, out, err),
        Some(Command::Resolve(args)) => resolve::resolve(&args, out, err),
        Some(Command::Figure(args)) => figure::figure(&args, out, err),
        Some(Command::Simulate(args)) => simulate::simulate(&args, out, err),
        Some(Command::Detect(args)) => detect::detect(&args, out, err),
        Some(Command::Study(args)) => study::study(&args, out, err),
        Some(Command::Advise(args)) => advise::advise(&args, out, err),
        Some(Command::Errata(args)) => errata::errata(&args, out, err),
        Some(Command::Exercise(args)) => exercise::exercise(&args, out),
        Some(Command::Glossary(args)) => {
            use crate::cli::Format;
            use crate::render::glossary;
            let text = match args.format {
                Format::Text => glossary::text(),
                Format::Json => glossary::json(),
                Format::Md => glossary::markdown(),
                Format::Latex => glossary::latex(),
                Format::Html => return Err(html_elsewhere("glossary")),
            };
            out.write_all(text.as_bytes()).map_err(io)
        }
    }
}

/// `--format html` on a command that has no page yet: a usage error.
pub(crate) fn html_elsewhere(command: &str) -> AppError {
    AppError::Usage(format!(
        "{command} has no web page yet: --format html applies to solve, resolve and detect"
    ))
}

/// The width plain text is folded to: `--width` when given (0: never),
/// else the terminal's, else [`DEFAULT_WIDTH`](crate::render::wrap::DEFAULT_WIDTH).
pub(crate) fn text_width(asked: Option<usize>) -> usize {
    use std::io::IsTerminal;
    asked.unwrap_or_else(|| {
        let terminal = std::io::stdout()
            .is_terminal()
            .then(|| crossterm::terminal::size().ok())
            .flatten();
        terminal.map_or(crate::render::wrap::DEFAULT_WIDTH, |(w, _)| usize::from(w))
    })
}

/// Both stdin and stdout are a terminal, so the TUI can run.
fn interactive() -> bool {
    use std::io::IsTerminal;
    std::io::stdout().is_terminal() && std::io::stdin().is_terminal()
}

/// Writes `bytes` to `path` through [`crate::output_file`]: atomically,
/// replacing only a regular file (a device, FIFO, directory or symbolic link
/// is refused with exit 1).
pub(crate) fn write_atomic(path: &std::path::Path, bytes: &[u8]) -> Result<(), AppError> {
    crate::output_file::write(path, bytes, crate::output_file::Existing::Replace)
        .map_err(|e| AppError::Runtime(format!("cannot write {e}")))
}

pub(crate) use crate::output_file::file_stem;

pub(crate) fn io(e: std::io::Error) -> AppError {
    AppError::Output(e)
}

/// Loads a lesson, applies the command-line overrides and checks the contact index.
pub(crate) fn load(
    name: &std::ffi::OsStr,
    overrides: &Overrides,
    contact: Option<usize>,
) -> Result<Lesson, AppError> {
    let mut lesson = Lesson::load(name)?;
    lesson.apply(overrides);
    if !overrides.is_empty() {
        crate::lesson::overflow::check_all(&lesson)
            .map_err(|e| AppError::Usage(format!("with these options, {e}")))?;
    }
    if let Some(k) = contact {
        if lesson.contacts.is_empty() && lesson.simulation.is_some() {
            return Err(AppError::Usage(format!(
                "'{}' is a scene and writes no [[contact]]: its contacts are generated from the shapes at every step. \
                 Run it with `contact-lab simulate {}` (one step's contacts: `--trace-step N`)",
                lesson.id,
                name.to_string_lossy()
            )));
        }
        if k >= lesson.contacts.len() {
            return Err(AppError::Usage(format!(
                "--contact {k}: lesson '{}' has {} contact(s), numbered from 0",
                lesson.id,
                lesson.contacts.len()
            )));
        }
    }
    Ok(lesson)
}

/// The knobs given on the command line, each checked by the lesson's rules.
pub(crate) fn overrides<L: Levels>(args: &KnobArgs<L>) -> Result<Overrides, AppError> {
    let mut o = Overrides::default();
    for (knob, text) in &args.given {
        let value = knob_value::from_text(knob, text)
            .map_err(|e| AppError::Usage(format!("--{}: {e}", flag(knob))))?;
        o.set(knob, value);
    }
    Ok(o)
}

/// Lesson warnings go to stderr, once each.
pub(crate) fn warn(lesson: &Lesson, err: &mut dyn Write) {
    for w in &lesson.warnings {
        let _ = writeln!(err, "warning: {w}");
    }
    let zeros = crate::errata::zero_warnings(lesson, |k| crate::worked_solution(lesson, k));
    for w in zeros {
        let _ = writeln!(err, "warning: {w}");
    }
}

/// A warning for knobs that do nothing as set: warm starting belongs to
/// sequential impulses (the deepest-first order keeps no impulses to start from).
pub(crate) fn warn_knobs(resolver: &crate::physics::ResolverParams, err: &mut dyn Write) {
    if resolver.warm_start && resolver.solver == crate::physics::Solver::DeepestFirst {
        let _ = writeln!(
            err,
            "warning: warm starting applies to sequential impulses only; the deepest-first solver ignores it (add --solver sequential-impulse)"
        );
    }
}

/// A run that blew up, as the error a command ends with.
pub(crate) fn blew_up(lesson: &Lesson, e: &crate::physics::step::BlowUp) -> AppError {
    let names = crate::trace::resolver::Names::of_lesson(lesson);
    AppError::Runtime(format!(
        "{}: {}; try a smaller --dt or more iterations",
        lesson.id,
        crate::session::blew_up(&names, e)
    ))
}
