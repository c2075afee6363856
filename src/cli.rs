//! Command-line interface (clap derive types only).

use clap::{Args, Parser, Subcommand, ValueEnum};

const EXAMPLES: &str = "\
Examples:
  contact-lab                                       the interactive app (in a terminal)
  contact-lab tui lecture-2 --contact 0             the app, opened on one contact
  contact-lab list                                  the embedded lessons
  contact-lab solve lecture-2                       the lecture's second worked example
  contact-lab solve lecture-2 --format json         the same as JSON (GUIDE §4)
  contact-lab solve my-scene.toml --contact 1 --digits 4
  contact-lab solve friction-slides --compare-friction

Exit codes: 0 success, 1 runtime failure, 2 usage, 65 invalid lesson data, 66 lesson file missing.";

#[derive(Debug, Parser)]
#[command(name = "contact-lab", version, about = "Step-by-step rigid-body contact resolution (Millington's impulse-based resolver)", after_help = EXAMPLES)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// List the embedded lessons: id, title, source, contacts.
    List,
    /// Print the worked solution of one contact.
    Solve(SolveArgs),
    /// Step through a lesson interactively (also what a bare `contact-lab` does in a terminal).
    Tui(TuiArgs),
}

#[derive(Debug, Clone, Args)]
pub struct TuiArgs {
    /// Embedded lesson id or path to a lesson file to open (default: lecture-2).
    pub lesson: Option<String>,
    /// Which contact of the lesson to open (0-based).
    #[arg(long, short, default_value_t = 0)]
    pub contact: usize,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Text,
    Json,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FrictionModelArg {
    Millington,
    KineticDirection,
    VelocityScaling,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ProjectionArg {
    Linear,
    Nonlinear,
}

/// Options that change how a lesson is solved.
#[derive(Debug, Clone, Args)]
pub struct ModelArgs {
    /// Friction model for every contact (default: the lesson's, else millington).
    #[arg(long, value_enum)]
    pub friction_model: Option<FrictionModelArg>,
    /// Penetration resolution: linear (inverse mass only) or nonlinear (the lecture's).
    #[arg(long, value_enum)]
    pub projection: Option<ProjectionArg>,
    /// Share of the penetration resolved, in (0, 1].
    #[arg(long)]
    pub relaxation: Option<f64>,
    /// Max angular move as a multiple of |r⊥| (inf = no limit).
    #[arg(long)]
    pub angular_limit: Option<f64>,
}

#[derive(Debug, Clone, Args)]
pub struct SolveArgs {
    /// Embedded lesson id (see `contact-lab list`) or path to a lesson file.
    pub lesson: String,
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
    #[command(flatten)]
    pub model: ModelArgs,
}
