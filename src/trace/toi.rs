//! `detect --toi`: the time-of-collision search of each pair over one step,
//! as the searches report it (bisection's scan and its [t₀, t₁] with the
//! test at each midpoint; advancement's distance and advance), the pair's
//! movement bounds, and the two normals of a fast pair side by side: EPA's
//! at the step's end, and the one from the closest points one frame earlier
//! (the lecture's proposal for fast motion).

use crate::physics::detect::{ToiEnd, ToiMethod, ToiObserver, ToiStep};
use crate::physics::{to_f64, Real};

/// One test of a search (seconds into the step; metres).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trial {
    pub t0: f64,
    pub t1: f64,
    pub trial: f64,
    pub hit: bool,
    pub distance: f64,
}

/// One piece of bisection's scan: [t0, t1], intersecting at t1 or not.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    pub t0: f64,
    pub t1: f64,
    pub hit: bool,
}

/// One test of a search in the order it ran: bisection's scan pieces
/// first (each tested at its end), then the trials.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Test {
    /// Piece `index` (0-based) of the scan.
    Scan {
        index: usize,
        piece: Piece,
    },
    Trial(Trial),
}

impl Test {
    /// The time (seconds into the step) the test puts the pair at.
    pub fn time(&self) -> f64 {
        match self {
            Test::Scan { piece, .. } => piece.t1,
            Test::Trial(t) => t.trial,
        }
    }
}

impl SearchRecord {
    /// Every test the search made, in order: the scan's pieces, then the
    /// trials (as many as the search's `tests`).
    pub fn tests(&self) -> Vec<Test> {
        let scan = self
            .scan
            .iter()
            .enumerate()
            .map(|(index, piece)| Test::Scan {
                index,
                piece: *piece,
            });
        scan.chain(self.trials.iter().copied().map(Test::Trial))
            .collect()
    }
}

/// Keeps a search's scan and tests, as f64.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SearchRecord {
    pub scan: Vec<Piece>,
    pub trials: Vec<Trial>,
}

impl<T: Real> ToiObserver<T> for SearchRecord {
    fn step(&mut self, s: &ToiStep<T>) {
        self.trials.push(Trial {
            t0: to_f64(s.t0),
            t1: to_f64(s.t1),
            trial: to_f64(s.trial),
            hit: s.hit,
            distance: to_f64(s.distance),
        });
    }
    fn scan(&mut self, t0: T, t1: T, hit: bool) {
        self.scan.push(Piece {
            t0: to_f64(t0),
            t1: to_f64(t1),
            hit,
        });
    }
}

/// EPA's normal and depth where the pair overlaps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Overlap {
    pub normal: [f64; 3],
    pub depth: f64,
}

/// One pair's search over the step.
#[derive(Debug, Clone, PartialEq)]
pub struct PairToi {
    pub a: String,
    pub b: String,
    /// The movement bounds: swept AABBs overlap, swept spheres meet.
    pub aabbs_overlap: bool,
    pub spheres_meet: bool,
    pub method: ToiMethod,
    /// Seconds into the step (the last time known apart), if found.
    pub time: Option<f64>,
    pub end: ToiEnd,
    pub tests: usize,
    pub record: SearchRecord,
    /// Whether one body is a half-space: the normals at either end are
    /// then the plane's own and the depth its closed form (no EPA, no
    /// closest points).
    pub half_space: bool,
    /// The overlap at the step's end poses (moved by v Δt), if any: EPA's,
    /// or the half-space's normal and depth.
    pub at_end: Option<Overlap>,
    /// From b's closest point toward a's at the step's start (one frame
    /// before the end), if the pair was apart then.
    pub previous_frame: Option<[f64; 3]>,
}

/// A `detect --toi` run: the step and each pair searched.
#[derive(Debug, Clone, PartialEq)]
pub struct DetectToi {
    pub lesson: String,
    /// The step searched (1-based) and its start time (s).
    pub step: u64,
    pub time: f64,
    pub dt: f64,
    pub method: ToiMethod,
    pub pairs: Vec<PairToi>,
}

/// The search's name in words.
pub fn method_words(m: ToiMethod) -> &'static str {
    match m {
        ToiMethod::Bisection => crate::knobs::toi_method_name(m),
        ToiMethod::Conservative => "conservative advancement",
    }
}

/// Why a search ended, in words.
pub fn end_text(end: ToiEnd) -> &'static str {
    match end {
        ToiEnd::Converged => "converged",
        ToiEnd::AtStart => "intersecting at the step's start",
        ToiEnd::NoHitAtEnd => "apart at the step's end: nothing to bracket",
        ToiEnd::NoHitInStep => "no collision in the step",
        ToiEnd::IterationCap => "iteration cap reached",
    }
}

/// Why a search ended, as the JSON names it.
pub fn end_name(end: ToiEnd) -> &'static str {
    match end {
        ToiEnd::Converged => "converged",
        ToiEnd::AtStart => "at_start",
        ToiEnd::NoHitAtEnd => "no_hit_at_end",
        ToiEnd::NoHitInStep => "no_hit_in_step",
        ToiEnd::IterationCap => "iteration_cap",
    }
}

/// One body of a time-of-collision picture (`detect --toi --figure`).
#[derive(Debug, Clone, PartialEq)]
pub struct PictureBody {
    pub name: String,
    pub shape: Option<crate::physics::Shape>,
    /// Position and orientation (w, x, y, z) at the step's start.
    pub start: ([f64; 3], [f64; 4]),
    /// The same at the time of collision found (`None`: none found).
    pub found: Option<([f64; 3], [f64; 4])>,
    /// Its movement bounds over the step (`None`: it does not move, or a half-space).
    pub movement: Option<crate::trace::movement::Movement>,
}

/// The picture of one pair's search: the pair at the step's start and at
/// the time found, and the bounds of their movement over the step.
#[derive(Debug, Clone, PartialEq)]
pub struct ToiPicture {
    pub lesson: String,
    pub step: u64,
    pub method: ToiMethod,
    /// Seconds into the step (`None`: no collision found).
    pub time: Option<f64>,
    pub end: ToiEnd,
    pub dt: f64,
    pub bodies: [PictureBody; 2],
}
