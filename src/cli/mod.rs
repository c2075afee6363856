//! Command-line interface (clap derive types only).

use clap::{Args, Parser, Subcommand, ValueEnum};

mod detect;
mod knobs;
mod scene;
pub use detect::*;
pub use knobs::*;
pub use scene::*;

const EXAMPLES: &str = "\
Examples:
  contact-lab                                       the interactive app (in a terminal)
  contact-lab tui lecture-2 --contact 0             the app, opened on one contact
  contact-lab list                                  the embedded lessons
  contact-lab solve lecture-2                       the lecture's second worked example
  contact-lab solve lecture-2 --format json         the same as JSON (docs/json.md)
  contact-lab solve my-scene.toml --contact 1 --digits 4
  contact-lab solve spinning-ball -c 1 --compare-friction
  contact-lab solve rod-reverses --exact stronge
  contact-lab solve lecture-3 --format latex > lecture-3.tex      a worked solution to compile
  contact-lab solve friction-cube --all-contacts --format md --figures figs > friction.md
  contact-lab resolve box-four-corners              every contact resolved together, iteration by iteration
  contact-lab resolve sphere-row --format json --log --repeat 5
  contact-lab resolve box-four-corners --show position:2   the worked solution of that iteration's contact
  contact-lab figure lecture-2 -o lecture-2.svg     the contact as a slide-ready picture
  contact-lab detect hull-stack --pair hexagon,octagon   GJK and EPA iteration by iteration
  contact-lab check                                 the lectures' printed numbers vs the computed ones
  contact-lab study stack-5 ramp-stick              speed against accuracy: tables with the Pareto front
  contact-lab study --format svg > study.svg        error against work per simulated second
  contact-lab advise ramp-stick --error 0.001       the cheapest model within 1 mm, to paste
  contact-lab exercise --seed 1 --count 5 --answers --format md
  contact-lab knobs                                 every tunable: what it trades, default, values

Exit codes: 0 success, 1 runtime failure, 2 usage, 65 invalid lesson data, 66 lesson file missing
(when each is returned: docs/exit-codes.md).";

#[derive(Debug, Parser)]
#[command(name = "contact-lab", version, about = "Step-by-step rigid-body contact resolution (Millington's impulse-based resolver)", after_help = EXAMPLES)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// List the embedded lessons: id, title, source, contacts.
    List(ListArgs),
    /// Print the worked solution of one contact (or all: --all-contacts).
    Solve(SolveArgs),
    /// Resolve every contact of a lesson together: position phase, then velocity phase.
    Resolve(ResolveArgs),
    /// Draw one contact as an SVG figure: bodies, normal, arms, velocities, impulse.
    Figure(FigureArgs),
    /// Advance a scene in time: integrate, generate contacts, resolve them, sleep.
    Simulate(SimulateArgs),
    /// How a scene's contacts are found: broad phase, GJK and EPA step by step, the contacts; --toi: each pair's time of collision over a step.
    Detect(DetectArgs),
    /// Speed against accuracy: run scenes under a grid of knobs, cost and error against a reference.
    Study(StudyArgs),
    /// The cheapest configuration whose error against the scene's reference stays below a target.
    Advise(AdviseArgs),
    /// Compare every number a lesson prints ([[printed]]) with the computed one.
    #[command(name = "check")]
    Errata(ErrataArgs),
    /// Generate exercises with worked answers, the same for the same seed.
    Exercise(ExerciseArgs),
    /// Every symbol of the worked solutions: meaning, unit, stages, the lectures' names.
    Glossary(GlossaryArgs),
    /// Every knob: where it lives, what it trades, its default and values (docs/knobs.md).
    Knobs,
    /// Step through a lesson interactively (also what a bare `contact-lab` does in a terminal).
    Tui(TuiArgs),
}

#[derive(Debug, Clone, Args)]
pub struct GlossaryArgs {
    /// text, json, md (Markdown) or latex (a standalone document).
    #[arg(long, short, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

#[derive(Debug, Clone, Args)]
pub struct TuiArgs {
    /// Embedded lesson id or path to a lesson file to open (default: lecture-2).
    pub lesson: Option<std::ffi::OsString>,
    /// Which contact of the lesson to open (0-based); without it a lesson
    /// with several contacts opens on its resolver iterations, a scene on its run.
    #[arg(long, short)]
    pub contact: Option<usize>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Text,
    Json,
    /// Markdown with LaTeX maths ($…$).
    #[value(alias = "markdown")]
    Md,
    /// A standalone LaTeX document (article + amsmath).
    #[value(alias = "tex")]
    Latex,
    /// One self-contained web page (solve): MathML formulas, inline SVG
    /// figures, one stage at a time with the script on (docs/html.md).
    Html,
}

/// `--width`: the columns plain text folds to, on every command that
/// prints text (one declaration, flattened into each).
#[derive(Debug, Clone, Copy, Args)]
pub struct WidthArg {
    /// Text: fold lines to N columns (0: never); tables fold as tables
    /// (columns split into blocks). Default: the terminal's width, or 100
    /// when stdout is not a terminal. Markdown, LaTeX and JSON are never
    /// folded.
    #[arg(long, value_name = "N")]
    pub width: Option<usize>,
}

#[derive(Debug, Clone, Copy, Args)]
pub struct ListArgs {
    #[command(flatten)]
    pub fold: WidthArg,
}

/// A contact's knobs (`--friction-model`, …), from the knob table.
pub type ModelArgs = KnobArgs<ContactLevel>;

#[derive(Debug, Clone, Args)]
pub struct SolveArgs {
    /// Embedded lesson id (see `contact-lab list`) or path to a lesson file.
    pub lesson: std::ffi::OsString,
    /// Which contact of the lesson (0-based).
    #[arg(long, short, default_value_t = 0)]
    pub contact: usize,
    /// Output format.
    #[arg(long, short, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// Significant digits of human formats (JSON always carries full f64).
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
    /// Print every friction model's result for this contact side by side.
    #[arg(long)]
    pub compare_friction: bool,
    /// Solve every contact of the lesson, one after another.
    #[arg(long, conflicts_with = "contact")]
    pub all_contacts: bool,
    /// LaTeX: the document body only, to \input into your own document.
    #[arg(long)]
    pub fragment: bool,
    /// Markdown: write an SVG figure of each contact to DIR and link it.
    #[arg(long, value_name = "DIR")]
    pub figures: Option<std::path::PathBuf>,
    /// Write the output to FILE (atomically) instead of stdout.
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
    #[command(flatten)]
    pub fold: WidthArg,
    #[command(flatten)]
    pub model: ModelArgs,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PlaneArg {
    /// x to the right, y up, z toward the viewer.
    Xy,
    /// y to the right, z up, x toward the viewer.
    Yz,
    /// z to the right, x up, y toward the viewer.
    Zx,
}

#[derive(Debug, Clone, Args)]
pub struct FigureArgs {
    /// Embedded lesson id or path to a lesson file.
    pub lesson: std::ffi::OsString,
    /// Which contact of the lesson (0-based).
    #[arg(long, short, default_value_t = 0)]
    pub contact: usize,
    /// Write the SVG to FILE (atomically) instead of stdout.
    #[arg(long, short, value_name = "FILE.svg")]
    pub output: Option<std::path::PathBuf>,
    /// The plane the figure shows.
    #[arg(long, value_enum, default_value_t = PlaneArg::Xy)]
    pub plane: PlaneArg,
    /// Draw the state this stage works on (e.g. impulse: velocities before,
    /// the impulse; apply_impulse: before and after); default: every mark.
    #[arg(long, value_name = "STAGE", value_parser = parse_stage)]
    pub stage: Option<crate::physics::StageId>,
    #[command(flatten)]
    pub model: ModelArgs,
}

fn parse_stage(s: &str) -> Result<crate::physics::StageId, String> {
    crate::physics::StageId::from_json_name(s).ok_or_else(|| {
        format!(
            "unknown stage (stages: {})",
            crate::physics::StageId::ALL
                .map(crate::physics::StageId::json_name)
                .join(", ")
        )
    })
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ErrataFormat {
    Text,
    Json,
}

#[derive(Debug, Clone, Args)]
pub struct ErrataArgs {
    /// Lesson ids or paths (default: every embedded lesson).
    pub lessons: Vec<std::ffi::OsString>,
    /// Output format.
    #[arg(long, short, value_enum, default_value_t = ErrataFormat::Text)]
    pub format: ErrataFormat,
    #[command(flatten)]
    pub fold: WidthArg,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ExerciseKind {
    /// Restitution only: no friction, no penetration.
    Frictionless,
    /// Friction that holds: the contact sticks.
    StaticFriction,
    /// Friction that gives: the contact slides.
    DynamicFriction,
    /// Bodies interpenetrate: projection (and orientation update).
    Penetration,
    /// Each exercise of one of the kinds above.
    Mixed,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SheetFormat {
    Md,
    Latex,
    /// Lesson files (one per exercise; several need --dir).
    Toml,
}

#[derive(Debug, Clone, Args)]
pub struct ExerciseArgs {
    /// Seed: the same seed gives the same exercises, byte for byte.
    #[arg(long, required_unless_present = "grade")]
    pub seed: Option<u64>,
    /// What the exercises practise.
    #[arg(long, value_enum, default_value_t = ExerciseKind::Mixed)]
    pub kind: ExerciseKind,
    /// How many exercises.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u16).range(1..=50))]
    pub count: u16,
    /// Append the worked solutions.
    #[arg(long)]
    pub answers: bool,
    /// Output format.
    #[arg(long, short, value_enum, default_value_t = SheetFormat::Md)]
    pub format: SheetFormat,
    /// TOML: write exercise-SEED-N.toml files into DIR.
    #[arg(long, value_name = "DIR")]
    pub dir: Option<std::path::PathBuf>,
    /// Write the sheet to FILE (atomically) instead of stdout; Markdown
    /// also writes each exercise's figure beside it (FILE-N.svg) and links
    /// it (on stdout the figure is embedded as a data: URI image).
    #[arg(long, short, value_name = "FILE", conflicts_with_all = ["dir", "grade", "answer_template"])]
    pub output: Option<std::path::PathBuf>,
    /// Significant digits of the answers.
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
    /// Print an answer file to fill in (TOML: seed, kind, count, one
    /// [[exercise]] table of empty answers each), for --grade.
    #[arg(long, conflicts_with_all = ["answers", "grade", "dir"])]
    pub answer_template: bool,
    /// Grade a student's answer file (made from --answer-template): each
    /// answer against the worked solution, with the right answer, the
    /// difference and a score.
    #[arg(long, value_name = "ANSWERS.toml")]
    pub grade: Option<std::path::PathBuf>,
}
