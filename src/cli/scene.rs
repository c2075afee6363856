//! The arguments of the commands on scenes: `resolve`, `simulate` and
//! `study`, and the resolver settings they share.

use clap::{Args, ValueEnum};

use super::*;

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ResolveFormat {
    Text,
    Json,
    /// Markdown: headings and tables.
    #[value(alias = "markdown")]
    Md,
    /// One self-contained web page: the iterations one at a time, Enter on
    /// the taken contact opens its worked stages (docs/html.md).
    Html,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ImplementationArg {
    /// The lecture's loop: scan every contact twice per iteration.
    Scan,
    /// A priority queue and the body → contacts adjacency (same result, faster).
    Indexed,
}

/// `--show position:K` or `--show velocity:K`: iteration K of that phase.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Show {
    pub velocity: bool,
    pub iteration: usize,
}

/// `A,B`: two spellings of the `solver` knob.
fn parse_compare(s: &str) -> Result<[crate::physics::Solver; 2], String> {
    use crate::knobs::Choice;
    let names = crate::physics::Solver::NAMES.join(", ");
    let one = |x: &str| {
        crate::physics::Solver::from_name(x.trim())
            .ok_or_else(|| format!("unknown solver '{x}' (solvers: {names})"))
    };
    let (a, b) = s
        .split_once(',')
        .ok_or_else(|| format!("expected two solvers A,B (solvers: {names}), got '{s}'"))?;
    Ok([one(a)?, one(b)?])
}

fn parse_show(s: &str) -> Result<Show, String> {
    let bad =
        || format!("expected position:K or velocity:K (K an iteration number from 0), got '{s}'");
    let (phase, k) = s.split_once(':').ok_or_else(bad)?;
    let iteration = k.trim().parse().map_err(|_| bad())?;
    match phase.trim() {
        "position" => Ok(Show {
            velocity: false,
            iteration,
        }),
        "velocity" => Ok(Show {
            velocity: true,
            iteration,
        }),
        _ => Err(bad()),
    }
}

#[derive(Debug, Clone, Args)]
pub struct ResolveArgs {
    /// Embedded lesson id (see `contact-lab list`) or path to a lesson file.
    pub lesson: std::ffi::OsString,
    /// Output format.
    #[arg(long, short, value_enum, default_value_t = ResolveFormat::Text)]
    pub format: ResolveFormat,
    /// JSON: include every iteration (`log`); text and Markdown always show them.
    #[arg(long)]
    pub log: bool,
    /// Time the resolver N times and report the fastest run's phases (JSON `seconds`).
    #[arg(long, default_value_t = 1, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=10000))]
    pub repeat: u32,
    /// The single-contact worked solution of the contact taken at iteration K
    /// of a phase, with the bodies as they are at that moment.
    #[arg(long, value_name = "PHASE:K", value_parser = parse_show)]
    pub show: Option<Show>,
    /// Resolve with two solvers and print the answers side by side (text or JSON),
    /// e.g. `--compare deepest-first,lcp`: the lecture's sequence beside the simultaneous solve.
    #[arg(long, value_name = "A,B", value_parser = parse_compare, conflicts_with = "show")]
    pub compare: Option<[crate::physics::Solver; 2]>,
    /// Which implementation runs the phases (both give the same result).
    #[arg(long, value_enum, default_value_t = ImplementationArg::Indexed)]
    pub implementation: ImplementationArg,
    /// Significant digits of human formats (JSON always carries full f64).
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
    /// Write the output to FILE (atomically) instead of stdout.
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
    #[command(flatten)]
    pub fold: WidthArg,
    /// A contact's and the resolver's knobs, each over the lesson's.
    #[command(flatten)]
    pub knobs: KnobArgs<ResolveLevel>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum RunFormat {
    Text,
    Json,
    /// A film strip of the scene and charts of energy, penetration and awake bodies.
    Svg,
    /// One self-contained web page: a player of the recorded frames, the
    /// energy chart, the events, `--trace-step`'s iterations (docs/html.md).
    Html,
}

/// Options of `simulate`: each overrides the lesson's value.
#[derive(Debug, Clone, Args)]
pub struct SimulateArgs {
    /// Embedded scene id (see `contact-lab list`) or path to a lesson file with [world] or [step].
    pub lesson: std::ffi::OsString,
    /// How long to run, in seconds of simulated time.
    #[arg(long, conflicts_with = "steps", allow_negative_numbers = true)]
    pub seconds: Option<f64>,
    /// Record one step in every K (the last step is always recorded).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..))]
    pub every: u64,
    /// Output format.
    #[arg(long, short, value_enum, default_value_t = RunFormat::Text)]
    pub format: RunFormat,
    /// Significant digits of the text table.
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
    /// Text: the full table, one row per recorded step (thinned by
    /// `--every`), with the events between the rows. Without it the text
    /// is a summary: energy, penetration, iterations, events, final state.
    #[arg(long)]
    pub table: bool,
    #[command(flatten)]
    pub fold: WidthArg,
    /// The plane of the film strip (svg).
    #[arg(long, value_enum, default_value_t = PlaneArg::Xy)]
    pub plane: PlaneArg,
    /// Fraction of linear and angular velocity kept per second, (0, 1]: sets
    /// both damping knobs.
    #[arg(long, allow_negative_numbers = true)]
    pub damping: Option<f64>,
    /// Print the resolver trace of step N instead (as `resolve` prints one; text or json);
    /// with `--format html` the player opens step N's iterations.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    pub trace_step: Option<u64>,
    /// Every knob (a contact's, the resolver's, the step's, the world's,
    /// sleep's), each over the lesson's.
    #[command(flatten)]
    pub knobs: KnobArgs<RunLevel>,
    /// Run even beyond the work cap (steps × movable bodies over 100 million).
    #[arg(long)]
    pub force: bool,
    /// Write the output to FILE (atomically) instead of stdout.
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StudyFormat {
    /// A table per scene, the Pareto front marked, the trade in one sentence.
    Text,
    Json,
    Csv,
    /// Error against work per simulated second (the cost the front is
    /// computed on), log–log, one panel per scene.
    Svg,
    /// A report to hand out.
    #[value(alias = "markdown")]
    Md,
    /// One self-contained web page: the chart with hover details, the
    /// tables sortable (docs/html.md).
    Html,
}

#[derive(Debug, Clone, Args)]
pub struct StudyArgs {
    /// Scene ids or lesson files with [world] or [step] (default: the study's nine scenes).
    pub scenes: Vec<std::ffi::OsString>,
    /// Output format.
    #[arg(long, short, value_enum, default_value_t = StudyFormat::Text)]
    pub format: StudyFormat,
    /// Leave timing out (the cost is then contact visits per step): deterministic output.
    #[arg(long)]
    pub no_timing: bool,
    /// A reduced grid: budgets 1, 8 and converged for both solvers, f32, dt = 1/30
    /// (with --verdicts: the scenes at reduced sizes).
    #[arg(long)]
    pub quick: bool,
    /// Run the cross product of these knobs' values around each scene's default
    /// instead of the default grid, e.g. --grid budget=1,4,16 --grid solver=deepest_first,sequential_impulse.
    #[arg(long, value_name = "KNOB=V1,V2")]
    pub grid: Vec<String>,
    /// Timed runs per configuration (their median is reported, with min and max).
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub repeat: u32,
    /// Simulated seconds per scene (default: the study's choice per scene, 0.5 to 2 s).
    #[arg(long)]
    pub seconds: Option<f64>,
    /// Significant digits of text and Markdown (JSON and CSV carry full f64).
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
    #[command(flatten)]
    pub fold: WidthArg,
    /// Run even beyond the caps (over 2,000 configurations or 10 million simulated steps).
    #[arg(long)]
    pub force: bool,
    /// Write the output to FILE (atomically) instead of stdout.
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
    /// The verdict matrix instead: a fixed set of test scenes under every
    /// solver, each criterion a pass or a fail with its figure (text, json
    /// or svg; with --quick, reduced sizes).
    #[arg(long)]
    pub verdicts: bool,
    /// The broad-phase study instead: sort and sweep, the uniform grid and the
    /// dynamic tree on 10 to 10,000 bodies, scattered and clustered; box tests
    /// counted and (without --no-timing) each call timed; where each wins.
    #[arg(long, conflicts_with_all = ["scenes", "grid", "quick", "verdicts"])]
    pub broad_phase: bool,
    /// With --broad-phase: the body counts (default 10,100,1000,10000; at most 100,000).
    #[arg(
        long,
        value_delimiter = ',',
        requires = "broad_phase",
        value_name = "N,N,…"
    )]
    pub bodies: Vec<usize>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AdviseFormat {
    /// The configuration to paste, what each knob buys, what the run exercised.
    Text,
    #[value(alias = "markdown")]
    Md,
    Json,
}

/// `advise --per`: what the error target bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PerArg {
    /// The run's final positions (the study's error).
    Run,
    /// Every step: the largest, over the steps, of the distance to the
    /// reference at the same time.
    Step,
}

#[derive(Debug, Clone, Args)]
pub struct AdviseArgs {
    /// A scene id or a lesson file with [world] or [step].
    pub scene: std::ffi::OsString,
    /// The largest error allowed against the scene's reference, m (RMS over
    /// the movable bodies of the distance to the reference's positions: at
    /// the end with `--per run`, at every step with `--per step`).
    #[arg(long)]
    pub error: f64,
    /// What the error bounds: the run's final positions, or every step's.
    #[arg(long, value_enum, default_value_t = PerArg::Run)]
    pub per: PerArg,
    /// Output format.
    #[arg(long, short, value_enum, default_value_t = AdviseFormat::Text)]
    pub format: AdviseFormat,
    /// Simulated seconds (default: the study's choice for the scene, 0.5 to 2 s).
    #[arg(long)]
    pub seconds: Option<f64>,
    /// Significant digits of text and Markdown (JSON carries full f64).
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
}

/// The search `detect --toi` runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ToiMethodArg {
    /// The lecture's: [t₀, t₁] halved (after a scan of the step).
    Bisection,
    /// Conservative advancement: distance / bound on the closing speed.
    Conservative,
}
