//! The verdict matrix's scenes and their criteria: one table ([`SCENES`]),
//! which the run, every output and docs/study.md ("The verdict matrix")
//! read. A criterion passes when its measured figure is at most its bound.

use nalgebra::Vector3;

use super::record::Record;
use super::scenes;
use super::Size;

/// One criterion: what is measured on a run, and the most it may be.
#[derive(Debug, Clone, Copy)]
pub struct Criterion {
    /// The matrix row's name.
    pub name: &'static str,
    /// The criterion in words, its bound included (docs/study.md quotes it).
    pub text: &'static str,
    pub unit: &'static str,
    /// Passes when measured ≤ bound.
    pub bound: f64,
    pub measure: fn(&Record) -> f64,
}

/// One scene of the matrix.
#[derive(Debug, Clone, Copy)]
pub struct Scene {
    pub id: &'static str,
    /// What it is (the full size).
    pub what: &'static str,
    /// Simulated seconds: full, reduced.
    pub seconds: [f64; 2],
    /// Its lesson text at a size, over a time.
    pub build: fn(Size, f64) -> String,
    /// Whether a criterion reads the overlap (it costs a detection a step).
    pub penetration: bool,
    pub criteria: &'static [Criterion],
}

impl Scene {
    pub fn seconds(&self, size: Size) -> f64 {
        match size {
            Size::Full => self.seconds[0],
            Size::Reduced => self.seconds[1],
        }
    }
}

/// The overlap below which the overlapped stack counts as separated (m).
pub const SEPARATED: f64 = 0.01;
/// The push-out speed cap: Box2D v3's `contactPushMaxVelocity` default,
/// the soft step's `push_out_speed` (m/s).
pub const PUSH_OUT_CAP: f64 = 3.0;
/// From when the slender box must be still (s).
pub const STILL_FROM: f64 = 1.0;
/// Gravity's size in the ramp's closed form (the lessons' default, m/s²).
pub const G: f64 = 9.81;

pub const SCENES: &[Scene] = &[
    Scene {
        id: "stack",
        what: "a vertical stack of 15 boxes (1 m, 1 kg, μ 0.6) on the floor, 10 s",
        seconds: [10.0, 2.0],
        build: scenes::stack,
        penetration: false,
        criteria: &[Criterion {
            name: "top drift",
            text: "standing at the end: the top box moved at most 1 cm across gravity",
            unit: "m",
            bound: 0.01,
            measure: top_drift,
        }],
    },
    Scene {
        id: "pyramid",
        what: "a pyramid with a base of 20 boxes (210 boxes of 1 m, 5 cm apart in a row, μ 0.6), 10 s",
        seconds: [10.0, 2.0],
        build: scenes::pyramid,
        penetration: false,
        criteria: &[Criterion {
            name: "largest move",
            text: "standing at the end: no box moved more than 1 cm from where it started",
            unit: "m",
            bound: 0.01,
            measure: largest_move,
        }],
    },
    Scene {
        id: "mass-ratio",
        what: "a 20 × 1 × 20 m plate of 400 kg on two 1 m boxes of 1 kg under its ends, 10 s",
        seconds: [10.0, 2.0],
        build: scenes::mass_ratio,
        penetration: false,
        criteria: &[Criterion {
            name: "plate sag",
            text: "sag bounded: the plate never sank more than 2 cm below where it started (the two contact layers' position tolerance, position_epsilon 1 cm each; the same plate of 1 kg sinks 1 cm)",
            unit: "m",
            bound: 0.02,
            measure: plate_sag,
        }],
    },
    Scene {
        id: "friction-ramp",
        what: "five 1 m boxes on a 0.25 rad ramp, effective μ 0.387, 0.316, 0.265, 0.141 and 0 (tan 0.25 = 0.2553), 2 s",
        seconds: [2.0, 1.0],
        build: scenes::ramp,
        penetration: false,
        criteria: &[Criterion {
            name: "acceleration error",
            text: "the first three stick, the last two slide at g(sin θ − μ cos θ): every box's mean acceleration down the slope, 2d/t², within 0.05 m/s² of the closed form (0 for a box that sticks)",
            unit: "m/s²",
            bound: 0.05,
            measure: ramp_error,
        }],
    },
    Scene {
        id: "overlap-recovery",
        what: "a stack of 3 boxes started 25 % overlapped (each 0.25 m into the one below, the bottom one into the floor), 2 s",
        seconds: [2.0, 1.0],
        build: scenes::overlap,
        penetration: true,
        criteria: &[
            Criterion {
                name: "push-out speed",
                text: "no body faster than the push-out cap, 3 m/s (the soft step's push_out_speed default, Box2D v3's)",
                unit: "m/s",
                bound: PUSH_OUT_CAP,
                measure: fastest,
            },
            Criterion {
                name: "energy after separation",
                text: "once separated (deepest overlap ≤ 1 cm) the kinetic + potential energy never exceeds the stack's at rest, each box touching the one below, by more than 0.01 J (1 mm of one box's lift)",
                unit: "J",
                bound: 0.01,
                measure: energy_after_separation,
            },
        ],
    },
    Scene {
        id: "confined-crowd",
        what: "64 spheres (r = 0.5 m, 1 kg) on a 0.9 m grid, each 10 cm into its neighbours, no gravity, boxed in by walls 5 cm inside them, 2 s",
        seconds: [2.0, 1.0],
        build: scenes::crowd,
        penetration: false,
        criteria: &[Criterion {
            name: "top speed",
            text: "no sphere ever faster than 1 m/s",
            unit: "m/s",
            bound: 1.0,
            measure: fastest,
        }],
    },
    Scene {
        id: "slender-box",
        what: "the slender box of the lecture's order: 0.42 × 0.8 × 0.42 m, 1 kg, standing on an immovable 2 × 1 × 2 m box, μ 0.5, restitution 0.2, 2 s",
        seconds: [2.0, 1.5],
        build: scenes::slender,
        penetration: false,
        criteria: &[Criterion {
            name: "|ω| after 1 s",
            text: "still: its spin |ω| at most 0.01 rad/s at every step after 1 s",
            unit: "rad/s",
            bound: 0.01,
            measure: spin_after,
        }],
    },
];

fn up(r: &Record) -> Vector3<f64> {
    let g = r.gravity;
    if g.norm() > 0.0 {
        -g / g.norm()
    } else {
        Vector3::zeros()
    }
}

/// The top body's (the last movable one's) move across gravity, start to end.
fn top_drift(r: &Record) -> f64 {
    let (a, b) = (r.first(), r.last());
    let Some(k) = a.positions.len().checked_sub(1) else {
        return 0.0;
    };
    let moved = b.positions[k] - a.positions[k];
    let up = up(r);
    (moved - up * moved.dot(&up)).norm()
}

/// The largest move of any body, start to end.
fn largest_move(r: &Record) -> f64 {
    let (a, b) = (r.first(), r.last());
    a.positions
        .iter()
        .zip(&b.positions)
        .map(|(p, q)| (q - p).norm())
        .fold(0.0, f64::max)
}

/// How far the plate (the third movable body) ever sank below its start.
fn plate_sag(r: &Record) -> f64 {
    let y0 = r.first().positions[2].y;
    r.frames
        .iter()
        .map(|f| y0 - f.positions[2].y)
        .fold(0.0, f64::max)
}

/// The fastest any body moved, over the run.
fn fastest(r: &Record) -> f64 {
    r.frames
        .iter()
        .flat_map(|f| f.velocities.iter().map(|v| v.norm()))
        .fold(0.0, f64::max)
}

/// The largest excess of the energy, from the first frame with the deepest
/// overlap ≤ [`SEPARATED`], over the overlapped stack's at rest (its boxes
/// of 1 kg touching, the k-th from the floor at (k − ½) m, none moving);
/// not a number if it never separated.
fn energy_after_separation(r: &Record) -> f64 {
    let Some(k) = r.frames.iter().position(|f| f.penetration <= SEPARATED) else {
        return f64::NAN;
    };
    let g = r.gravity.norm();
    let rest: f64 = (0..r.first().positions.len())
        .map(|i| g * (i as f64 + 0.5))
        .sum();
    r.frames[k..]
        .iter()
        .map(|f| f.energy - rest)
        .fold(0.0, f64::max)
}

/// The largest |ω| of the first body at the frames from [`STILL_FROM`].
fn spin_after(r: &Record) -> f64 {
    (0..r.frames.len())
        .filter(|&k| r.time(k) >= STILL_FROM - 1e-9)
        .map(|k| r.frames[k].spins[0].norm())
        .fold(0.0, f64::max)
}

/// One box of the friction ramp against the closed form.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RampBox {
    /// Its effective μ with the ramp, √(μ_box μ_ramp).
    pub mu: f64,
    /// How far it slid down the slope (m).
    pub slid: f64,
    /// Its mean acceleration down the slope, 2d/t² (m/s²).
    pub measured: f64,
    /// g(sin θ − μ cos θ) when μ < tan θ, else 0 (it sticks).
    pub closed: f64,
}

/// The ramp's boxes, measured over the whole run.
pub fn ramp_boxes(r: &Record) -> Vec<RampBox> {
    let [ux, uy, uz] = scenes::ramp_uphill();
    let down = -Vector3::new(ux, uy, uz);
    let t = r.time(r.frames.len() - 1);
    let (s, c) = scenes::RAMP_ANGLE.sin_cos();
    scenes::RAMP_BOX_FRICTION
        .iter()
        .enumerate()
        .map(|(k, mu_box)| {
            let mu = (mu_box * scenes::RAMP_FRICTION).sqrt();
            let slid = (r.last().positions[k] - r.first().positions[k]).dot(&down);
            let closed = if mu < s / c { G * (s - mu * c) } else { 0.0 };
            RampBox {
                mu,
                slid,
                measured: if t > 0.0 { 2.0 * slid / (t * t) } else { 0.0 },
                closed,
            }
        })
        .collect()
}

fn ramp_error(r: &Record) -> f64 {
    ramp_boxes(r)
        .iter()
        .map(|b| (b.measured - b.closed).abs())
        .fold(0.0, f64::max)
}
