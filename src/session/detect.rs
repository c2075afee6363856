//! A scene's detection and time of collision at a step, as traces: the one
//! place `contact-lab detect` (and `--toi`) and the TUI's detection screen
//! build them, from a simulation standing at the step.

use super::Player;
use crate::lesson::Lesson;
use crate::physics::collide::record::detect as record;
use crate::physics::collide::Options;
use crate::physics::detect::toi::Motion;
use crate::physics::detect::ToiMethod;
use crate::physics::step::swept::motion_of;
use crate::physics::step::swept::{movement_bounds, SweptPairs};
use crate::physics::step::toi_pair::search_pair;
use crate::physics::step::Simulation;
use crate::physics::to_f64;
use crate::trace::detect::{build, Context, DetectTrace};
use crate::trace::movement;
use crate::trace::toi::{DetectToi, Overlap, PairToi, SearchRecord};
use crate::trace::Plane;

/// The detection of `sim`'s bodies as they stand after `step` steps
/// (broad, mid and narrow phase; `only`: that pair alone).
pub fn detect_trace(
    sim: &Simulation<f64>,
    lesson: &Lesson,
    step: u64,
    plane: Plane,
    only: Option<(usize, usize)>,
) -> DetectTrace {
    let names: Vec<String> = lesson.bodies.iter().map(|b| b.name.clone()).collect();
    let p = &sim.params;
    let options = Options {
        box_box: p.box_box,
        tolerance: p.contact_margin,
        narrow_phase: p.narrow_phase,
    };
    let found = record(&sim.world.bodies, &options, p.dt, only);
    let cx = Context {
        lesson: &lesson.id,
        title: &lesson.title,
        step,
        time: step as f64 * p.dt,
        narrow_phase: p.narrow_phase,
        plane,
        names: &names,
        bodies: &sim.world.bodies,
    };
    let mut trace = build(&cx, &found);
    if p.ccd.method().is_some() {
        // The bounds the next step's swept broad phase makes (docs/ccd.md).
        let (world, moving) = sim.resolved_next();
        trace.movement = movement::of_bounds(&movement_bounds(&world, &moving, p.dt));
    }
    trace
}

/// Step `step`'s time-of-collision searches, `sim` standing after step
/// `step - 1`: each pair whose movement bounds meet, or `pair` alone. Err:
/// the pair asked for has a body without a convex shape.
pub fn toi_trace(
    sim: &Simulation<f64>,
    lesson: &Lesson,
    step: u64,
    method: ToiMethod,
    pair: Option<(usize, usize)>,
) -> Result<DetectToi, (usize, usize)> {
    let start = sim.time;
    let (world, moving) = sim.resolved_next();
    let dt = sim.params.dt;
    let pairs = match pair {
        Some(pair) => vec![pair],
        None => {
            let mut swept = SweptPairs::default();
            swept.find(&world, &moving, dt);
            swept.pairs.clone()
        }
    };
    let name = |k: usize| lesson.bodies[k].name.clone();
    let mut found = Vec::new();
    for (i, j) in pairs {
        let mut record = SearchRecord::default();
        let Some(s) = search_pair(&world, &moving, (i, j), dt, method, &mut record) else {
            if pair.is_some() {
                return Err((i, j));
            }
            continue;
        };
        let v = |x: nalgebra::Vector3<f64>| [x.x, x.y, x.z];
        found.push(PairToi {
            a: name(i),
            b: name(j),
            aabbs_overlap: s.aabbs_overlap,
            spheres_meet: s.spheres_meet,
            method,
            time: s.toi.time.map(to_f64),
            end: s.toi.end,
            tests: s.toi.iterations,
            record,
            at_end: s.at_end.map(|(n, depth)| Overlap {
                normal: v(n),
                depth,
            }),
            previous_frame: s.previous_frame.map(v),
        });
    }
    Ok(DetectToi {
        lesson: lesson.id.clone(),
        step,
        time: start,
        dt,
        method,
        pairs: found,
    })
}

/// One pair's time-of-collision search over a step, with the two bodies'
/// motions as the search moves them (for a picture at a trial's time).
#[derive(Debug, Clone)]
pub struct PairToiRun {
    pub trace: DetectToi,
    motions: [Motion<f64>; 2],
}

impl PairToiRun {
    /// The two bodies' positions and orientations (w, i, j, k) `t` seconds
    /// into the step: x₀ + v t, exp(ω t) q₀, the search's own motion.
    pub fn poses_at(&self, t: f64) -> [([f64; 3], [f64; 4]); 2] {
        self.motions.map(|m| {
            let x = m.position + m.velocity * t;
            let q =
                nalgebra::UnitQuaternion::from_scaled_axis(m.angular_velocity * t) * m.orientation;
            ([x.x, x.y, x.z], [q.w, q.i, q.j, q.k])
        })
    }
}

impl Player {
    /// The detection of the bodies after step `step` (≤ computed), from the
    /// nearest kept copy: what `detect --step N` prints for the run as edited.
    /// `only`: that pair's narrow phase alone, run even when the broad
    /// phase rules it out (`detect --pair A,B`).
    pub fn detect(
        &self,
        lesson: &Lesson,
        step: u64,
        plane: Plane,
        only: Option<(usize, usize)>,
    ) -> Option<DetectTrace> {
        let sim = self.state_after(step)?;
        Some(detect_trace(&sim, lesson, step, plane, only))
    }

    /// The time-of-collision searches of step `step + 1` for the bodies
    /// after step `step` (the pair `pair` alone, when given).
    pub fn toi(
        &self,
        lesson: &Lesson,
        step: u64,
        method: ToiMethod,
        (i, j): (usize, usize),
    ) -> Option<PairToiRun> {
        let sim = self.state_after(step)?;
        let trace = toi_trace(&sim, lesson, step + 1, method, Some((i, j))).ok()?;
        let (world, moving) = sim.resolved_next();
        Some(PairToiRun {
            trace,
            motions: [
                motion_of(&world, i, moving[i]),
                motion_of(&world, j, moving[j]),
            ],
        })
    }
}
