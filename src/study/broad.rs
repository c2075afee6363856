//! The broad-phase study (`study --broad-phase`, docs/study.md "The broad
//! phase"): what finding the pairs costs each method — sort and sweep, the
//! uniform grid, the dynamic tree — against the number of bodies, 10 to
//! 10,000, in two cases: boxes and spheres scattered at one density (one
//! body per 8 m³), and a cluster (four bodies in five small and packed in a
//! corner at one per litre, the rest ten times larger around them: the
//! grid's cell fits the small ones, so each large body spans too many cells
//! and is tested against every body). Each case plays [`FRAMES`] frames of small motion
//! after the first call (the methods keep their state from frame to frame,
//! as a run does): the counts are the last frame's (deterministic), the
//! time the median over the frames (measured, left out with `--no-timing`).

use std::time::Instant;

use nalgebra::{UnitQuaternion, Vector3};

use crate::knobs::Choice;
use crate::physics::collide::{Aabb, BroadPhaseMethod, PairFinder, Pose};
use crate::physics::Shape;

/// The body counts the study runs.
pub const COUNTS: [usize; 4] = [10, 100, 1_000, 10_000];

/// Frames of motion after the first call.
pub const FRAMES: usize = 8;

/// The two cases.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Case {
    /// Boxes and spheres scattered at one body per 8 m³.
    Scattered,
    /// Most bodies small and packed in a corner, the rest large around them.
    Clustered,
}

impl Case {
    pub const ALL: [Case; 2] = [Case::Scattered, Case::Clustered];

    pub fn name(self) -> &'static str {
        match self {
            Case::Scattered => "scattered",
            Case::Clustered => "clustered",
        }
    }

    pub fn words(self) -> &'static str {
        match self {
            Case::Scattered => {
                "boxes and spheres (0.5 to 1 m across) scattered in a cube at one body per 8 m³"
            }
            Case::Clustered => {
                "four bodies in five small (0.05 to 0.1 m across) packed in a corner at one per litre, one in five ten times larger scattered around at one per 8 m³"
            }
        }
    }
}

/// One method on one case at one body count.
#[derive(Debug, Clone, PartialEq)]
pub struct BroadRow {
    pub method: &'static str,
    /// Box-against-box tests of the last frame.
    pub tests: usize,
    /// Boxes swept, cells or tree nodes visited in the last frame.
    pub visited: usize,
    /// Pairs kept in the last frame (the same for every method).
    pub kept: usize,
    /// Boxes tested against every other in the last frame.
    pub loose: usize,
    /// Median microseconds per frame; `None` without timing.
    pub microseconds: Option<f64>,
}

/// One case at one body count, every method.
#[derive(Debug, Clone, PartialEq)]
pub struct BroadPoint {
    pub case: Case,
    pub bodies: usize,
    /// All-against-all's tests, n(n − 1)/2.
    pub all_pairs: usize,
    pub rows: Vec<BroadRow>,
}

impl BroadPoint {
    /// The method with the fewest tests (the first on ties).
    pub fn fewest_tests(&self) -> &'static str {
        self.rows
            .iter()
            .min_by_key(|r| r.tests)
            .map_or("", |r| r.method)
    }

    /// The fastest method, when timed.
    pub fn fastest(&self) -> Option<&'static str> {
        let timed = self
            .rows
            .iter()
            .filter_map(|r| Some((r.microseconds?, r.method)));
        timed.min_by(|a, b| a.0.total_cmp(&b.0)).map(|t| t.1)
    }
}

/// The whole study.
#[derive(Debug, Clone, PartialEq)]
pub struct BroadStudy {
    pub timed: bool,
    pub points: Vec<BroadPoint>,
}

/// Runs the study over `counts` (each case, each method). `progress` is
/// told each point done (done, of how many).
pub fn run(counts: &[usize], timed: bool, progress: &mut dyn FnMut(usize, usize)) -> BroadStudy {
    let total = counts.len() * Case::ALL.len();
    let mut points = Vec::new();
    for case in Case::ALL {
        for &n in counts {
            points.push(point(case, n, timed));
            progress(points.len(), total);
        }
    }
    BroadStudy { timed, points }
}

/// One case at `n` bodies under every method.
pub fn point(case: Case, n: usize, timed: bool) -> BroadPoint {
    let frames = frames(case, n);
    let rows = BroadPhaseMethod::VALUES
        .iter()
        .map(|&method| {
            let mut finder = PairFinder::new();
            let mut out = Vec::new();
            finder.candidate_pairs(method, &frames[0], &[], &mut out);
            let mut times = Vec::new();
            for frame in &frames[1..] {
                let start = Instant::now();
                finder.candidate_pairs(method, frame, &[], &mut out);
                times.push(start.elapsed().as_secs_f64() * 1e6);
            }
            let c = finder.counts();
            times.sort_by(f64::total_cmp);
            BroadRow {
                method: method.name(),
                tests: c.tests,
                visited: c.visited,
                kept: c.kept,
                loose: c.loose,
                microseconds: timed.then(|| times[times.len() / 2]),
            }
        })
        .collect();
    BroadPoint {
        case,
        bodies: n,
        all_pairs: n * n.saturating_sub(1) / 2,
        rows,
    }
}

/// SplitMix64 in [0, 1): the same bodies on every machine.
struct Mix(u64);

impl Mix {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as f64 / 2f64.powi(64)
    }
}

/// A body of the study: its shape, position, turn and velocity per frame.
type Moving = (Shape, Vector3<f64>, UnitQuaternion<f64>, Vector3<f64>);

/// The bodies' boxes in the first frame and the [`FRAMES`] after it: each
/// body a box or a sphere at a random turn, moving a few centimetres a frame.
pub fn frames(case: Case, n: usize) -> Vec<Vec<Option<Aabb<f64>>>> {
    let mut rng = Mix(n as u64 * 2 + (case == Case::Clustered) as u64);
    let side = (8.0 * n as f64).cbrt();
    // The cluster: one small body per litre.
    let cluster = (0.001 * (n - n / 5) as f64).cbrt();
    let bodies: Vec<Moving> = (0..n)
        .map(|i| {
            let small = case == Case::Clustered && i % 5 != 0;
            let (size, span) = if small { (0.05, cluster) } else { (0.5, side) };
            let size = size * (1.0 + rng.next());
            let shape = if i % 2 == 0 {
                Shape::Sphere { radius: size / 2.0 }
            } else {
                Shape::Box {
                    sides: [size, size * 0.8, size * 0.6],
                }
            };
            let p = Vector3::new(rng.next(), rng.next(), rng.next()) * span;
            let axis = Vector3::new(rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5);
            let turn = UnitQuaternion::from_scaled_axis(axis * 3.0);
            let v =
                Vector3::new(rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5) * 0.05 * size;
            (shape, p, turn, v)
        })
        .collect();
    (0..=FRAMES)
        .map(|f| {
            bodies
                .iter()
                .map(|(shape, p, turn, v)| {
                    let pose = Pose::from_unit(p + v * f as f64, turn);
                    Aabb::of(shape, &pose, 0.0)
                })
                .collect()
        })
        .collect()
}
