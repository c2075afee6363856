//! A scene's detection and time of collision at a step, as traces: the one
//! place `contact-lab detect` (and `--toi`) and the TUI's detection screen
//! build them, from a simulation standing at the step.

use super::Player;
use crate::lesson::Lesson;
use crate::physics::collide::record;
use crate::physics::collide::Options;
use crate::physics::detect::toi::Motion;
use crate::physics::detect::Convex;
use crate::physics::detect::ToiMethod;
use crate::physics::step::ccd_pairs::plane_pairs;
use crate::physics::step::swept::{motion_of, swept_aabb, swept_sphere, MovementBound};
use crate::physics::step::swept::{movement_bounds, SweptPairs};
use crate::physics::step::toi_pair::search_pair;
use crate::physics::step::Simulation;
use crate::physics::to_f64;
use crate::trace::detect::{build, Context, DetectTrace};
use crate::trace::movement;
use crate::trace::movement::Movement;
use crate::trace::toi::{DetectToi, Overlap, PairToi, PictureBody, SearchRecord, ToiPicture};
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
    let found = record::detect(&sim.world.bodies, &options_of(sim), sim.params.dt, only);
    build_trace(sim, lesson, step, plane, &found)
}

/// The step's contact generation options.
fn options_of(sim: &Simulation<f64>) -> Options<f64> {
    let p = &sim.params;
    Options {
        box_box: p.box_box,
        tolerance: p.contact_margin,
        narrow_phase: p.narrow_phase,
        broad_phase: p.broad_phase,
        internal_edges: p.internal_edges,
    }
}

/// [`detect_trace`], telling `watch` the pairs done (of how many) as the
/// narrow phase goes; `None` when `watch` says stop (returns false).
pub fn detect_trace_watched(
    sim: &Simulation<f64>,
    lesson: &Lesson,
    step: u64,
    plane: Plane,
    only: Option<(usize, usize)>,
    watch: &mut dyn FnMut(usize, usize) -> bool,
) -> Option<DetectTrace> {
    let (bodies, dt) = (&sim.world.bodies, sim.params.dt);
    let found = record::detect_watched(bodies, &options_of(sim), dt, only, watch)?;
    Some(build_trace(sim, lesson, step, plane, &found))
}

/// The trace of `found`, the detection of `sim`'s bodies.
fn build_trace(
    sim: &Simulation<f64>,
    lesson: &Lesson,
    step: u64,
    plane: Plane,
    found: &record::DetectRecord,
) -> DetectTrace {
    let names: Vec<String> = lesson.bodies.iter().map(|b| b.name.clone()).collect();
    let p = &sim.params;
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
    let mut trace = build(&cx, found);
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
            let mut planes = Vec::new();
            plane_pairs(&world, &moving, dt, &mut planes);
            swept.pairs.iter().chain(&planes).copied().collect()
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
            // The search that ran: bisection falls back to advancement
            // where its scan cannot certify the step.
            method: s.toi.method,
            time: s.toi.time.map(to_f64),
            end: s.toi.end,
            tests: s.toi.iterations,
            record,
            at_end: s.at_end.map(|(n, depth)| Overlap {
                normal: v(n),
                depth,
            }),
            previous_frame: s.previous_frame.map(v),
            half_space: [i, j].iter().any(|k| {
                matches!(
                    world.bodies[*k].shape,
                    Some(crate::physics::Shape::HalfSpace { .. })
                )
            }),
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

/// The picture of pair `k` of `toi` (`toi_trace`'s, `sim` standing where
/// it stood): each body at the step's start and at the time found, with its
/// movement bounds over the step. `None`: no such pair.
pub fn toi_picture(
    sim: &Simulation<f64>,
    lesson: &Lesson,
    toi: &DetectToi,
    k: usize,
) -> Option<ToiPicture> {
    let p = toi.pairs.get(k)?;
    let (world, moving) = sim.resolved_next();
    let index = |name: &str| lesson.bodies.iter().position(|b| b.name == name);
    let dt = toi.dt;
    let body = |i: usize| {
        let b = &world.bodies[i];
        let m = motion_of(&world, i, moving[i]);
        let pose = |t: f64| {
            let x = m.position + m.velocity * t;
            let q =
                nalgebra::UnitQuaternion::from_scaled_axis(m.angular_velocity * t) * m.orientation;
            ([x.x, x.y, x.z], [q.w, q.i, q.j, q.k])
        };
        let movement = (moving[i])
            .then(|| {
                let shape = b.shape.as_ref()?;
                let aabb = swept_aabb(shape, &m, dt)?;
                let r = Convex::from_shape(shape)?.bounding_radius();
                let (centre, radius) = swept_sphere(r, &m, dt);
                Some(Movement::from(&MovementBound {
                    aabb,
                    centre,
                    radius,
                }))
            })
            .flatten();
        PictureBody {
            name: lesson.bodies[i].name.clone(),
            shape: b.shape.clone(),
            start: pose(0.0),
            found: p.time.map(pose),
            movement,
        }
    };
    let (i, j) = (index(&p.a)?, index(&p.b)?);
    Some(ToiPicture {
        lesson: toi.lesson.clone(),
        step: toi.step,
        method: p.method,
        time: p.time,
        end: p.end,
        dt,
        bodies: [body(i), body(j)],
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
