//! `contact-lab detect`'s arguments.

use clap::{Args, ValueEnum};

use super::{Format, KnobArgs, PlaneArg, RunLevel, ToiMethodArg};

#[derive(Debug, Clone, Args)]
pub struct DetectArgs {
    /// Embedded lesson or scene id, or path to a lesson file.
    pub lesson: std::ffi::OsString,
    /// Only the pair of bodies A and B (by name), run even where the broad
    /// phase rules it out.
    #[arg(long, value_name = "A,B")]
    pub pair: Option<String>,
    /// Detect after N steps of the scene (0: at the poses the file gives);
    /// with --toi, the step searched (1 = the first; 0 is taken as 1).
    #[arg(long, visible_alias = "at", value_name = "N", default_value_t = 0,
          value_parser = clap::value_parser!(u64).range(0..=1_000_000))]
    pub step: u64,
    /// Each pair's time of collision over the step instead, test by test
    /// (docs/ccd.md): the pairs whose movement bounds meet, or --pair.
    #[arg(long)]
    pub toi: bool,
    /// With --toi (only), the search: bisection (the lecture's) or
    /// conservative advancement. Default: the scene's ccd method, or
    /// bisection when its ccd is off.
    #[arg(long, value_enum, requires = "toi")]
    pub method: Option<ToiMethodArg>,
    /// Output format (--toi: text or JSON).
    #[arg(long, short, value_enum, default_value_t = Format::Text)]
    pub format: Format,
    /// Significant digits of human formats (JSON always carries full f64).
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u8).range(1..=17))]
    pub digits: u8,
    /// Write the output to FILE (atomically) instead of stdout.
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<std::path::PathBuf>,
    #[command(flatten)]
    pub fold: super::WidthArg,
    /// Also write an SVG figure of the (first) pair: both shapes, the
    /// Minkowski difference A - B, the simplex or EPA's face, the normal.
    #[arg(long, value_name = "F.svg")]
    pub figure: Option<std::path::PathBuf>,
    /// The figure draws iteration K (1 = the first, as the text numbers
    /// them) of the list --phase names: its simplex (GJK) or closest face
    /// (EPA), v_k, w_k and d_k. Default: the last iteration.
    #[arg(long, value_name = "K", requires = "figure",
          value_parser = clap::value_parser!(u64).range(1..))]
    pub iteration: Option<u64>,
    /// Which iterations --iteration counts: GJK's (the default) or EPA's.
    /// Alone, the figure draws that phase's last iteration.
    #[arg(long, value_enum, requires = "figure")]
    pub phase: Option<DetectPhaseArg>,
    /// The plane the figure shows.
    #[arg(long, value_enum, default_value_t = PlaneArg::Xy)]
    pub plane: PlaneArg,
    /// Every knob over the lesson's (`--narrow-phase gjk` forces GJK/EPA).
    #[command(flatten)]
    pub knobs: KnobArgs<RunLevel>,
}

/// The iteration list `detect --iteration` counts in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DetectPhaseArg {
    /// GJK: the simplex, v_k, w_k and the search direction d_k.
    Gjk,
    /// EPA: the face closest to the origin, v_k on it, w_k and d_k (its normal).
    Epa,
}
