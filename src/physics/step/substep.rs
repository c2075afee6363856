//! Continuous detection in the step ("Lecture IV Collisions", the time
//! issue). After the step's contacts are resolved, the positions are not
//! simply moved by v Δt: with `ccd` on, the pairs whose movement bounds
//! ([`super::swept`]) meet over what is left of the step get their time of
//! collision ([`crate::physics::detect::toi_sweep`]); every moving body
//! advances to the earliest, that pair's contact is resolved there (the
//! velocity phase, one contact), and the rest of the step is spent the same
//! way, earliest first. A body the resolution changes moves from then on,
//! woken if it slept ([`Spent::woken`]). Pairs already in contact at the
//! step's start are the discrete resolver's, and a pair resolved here is
//! not searched again in the same step.
//!
//! At most [`MAX_SUBSTEPS`] collisions are resolved in one step; when the
//! cap is hit the rest of the step is one plain move (the tunnelling auditor
//! still watches it). Each sub-step costs a swept broad phase and one search
//! per candidate pair (docs/ccd.md).

use nalgebra::Vector3;

use super::ccd::{self, Tunnelled};
use super::energy;
use super::integrate::integrate_position;
use super::report::ToiEvent;
use super::simulation::contacts::contact_input;
use super::swept::{motion_of, Earlier, MovementBound, SweptPairs};
use crate::physics::detect::toi_sweep::{closing_bound, swept_toi};
use crate::physics::detect::{
    query, Convex, EpaOptions, GjkOptions, MovingPair, QueryOptions, ToiEnd, ToiMethod, ToiOptions,
};
use crate::physics::params::{Material, SimParams};
use crate::physics::pose::Pose;
use crate::physics::resolver::{Implementation, Resolver, Silent};
use crate::physics::{c, to_f64, BodyId, Contact, Real, World};

/// The most collisions continuous detection resolves inside one step.
pub const MAX_SUBSTEPS: usize = 8;

/// What one step's continuous detection did.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Spent {
    pub hits: Vec<ToiEvent>,
    pub crossed: Vec<Tunnelled>,
    /// The cap on sub-steps was hit.
    pub capped: bool,
    /// Bodies that were not moving (asleep) until a collision resolved here
    /// changed their velocity: they move for the rest of the step, and the
    /// step wakes them (as the discrete step wakes a sleeper it acts on).
    /// Each with the body that struck it.
    pub woken: Vec<(BodyId, BodyId)>,
    /// The GJK calls of every time-of-collision search of the step, the
    /// pairs that met and those that did not (the work continuous
    /// detection adds; 0 with `ccd = "none"`, whose tunnelling audit is not
    /// counted: it runs whatever the knob).
    pub tests: usize,
}

/// Scratch kept from step to step.
#[derive(Debug, Clone)]
pub struct Substeps<T: Real> {
    pub moving: Vec<bool>,
    swept: SweptPairs<T>,
    done: Vec<(usize, usize)>,
    /// Rolling back: each body's time to go back (rollback.rs).
    pub back: Vec<T>,
    /// Each moving body's movement bounds over the whole step, as the
    /// step's first swept broad phase made them (`None`: not moving, or
    /// no convex shape); for pictures.
    pub bounds: Vec<Option<MovementBound<T>>>,
}

impl<T: Real> Default for Substeps<T> {
    fn default() -> Self {
        Substeps {
            moving: Vec::new(),
            swept: SweptPairs::default(),
            done: Vec::new(),
            back: Vec::new(),
            bounds: Vec::new(),
        }
    }
}

fn to3<T: Real>(v: &Vector3<T>) -> [f64; 3] {
    [to_f64(v.x), to_f64(v.y), to_f64(v.z)]
}

impl<T: Real> Substeps<T> {
    /// Moves the bodies over the step `p.dt` (module docs); `self.moving`
    /// must say which bodies move.
    pub fn spend(
        &mut self,
        world: &mut World<T>,
        p: &SimParams<T>,
        materials: &[Material],
        earlier: Option<Earlier<'_, T>>,
        out: &mut Spent,
    ) {
        let Some(method) = p.ccd.method() else {
            ccd::tunnelled(
                world,
                p.dt,
                &self.moving,
                &mut self.swept,
                earlier,
                &mut out.crossed,
            );
            self.keep_bounds();
            advance(world, &self.moving, p.dt);
            return;
        };
        self.done.clear();
        let mut elapsed = T::zero();
        loop {
            let left = p.dt - elapsed;
            if out.hits.len() == MAX_SUBSTEPS {
                out.capped = true;
                break;
            }
            let Some((i, j, s, tests)) = self.earliest(world, method, left, &mut out.tests) else {
                break;
            };
            advance(world, &self.moving, s);
            elapsed += s;
            self.done.push((i, j));
            if let Some(hit) = resolve_at(world, p, materials, i, j) {
                for (body, by) in [(hit.body1, hit.body2), (hit.body2, hit.body1)] {
                    if world.bodies[body.0].movable && !self.moving[body.0] {
                        self.moving[body.0] = true;
                        out.woken.push((body, by));
                    }
                }
                out.hits.push(ToiEvent {
                    method,
                    time: to_f64(elapsed),
                    tests,
                    ..hit
                });
            }
        }
        let left = p.dt - elapsed;
        let moving = &self.moving;
        let from = out.crossed.len();
        ccd::tunnelled(
            world,
            left,
            moving,
            &mut self.swept,
            earlier,
            &mut out.crossed,
        );
        for t in &mut out.crossed[from..] {
            t.time += to_f64(elapsed);
        }
        advance(world, moving, left);
    }

    /// The moving bodies' bounds from the last sweep, kept in `bounds`.
    fn keep_bounds(&mut self) {
        let (swept, moving) = (&self.swept, &self.moving);
        self.bounds.clear();
        self.bounds
            .extend((0..moving.len()).map(|i| if moving[i] { swept.bound(i) } else { None }));
    }

    /// The pair that meets first within `left`, its time and its tests;
    /// every search's tests are added to `spent`.
    fn earliest(
        &mut self,
        world: &World<T>,
        method: ToiMethod,
        left: T,
        spent: &mut usize,
    ) -> Option<(usize, usize, T, usize)> {
        self.swept.find(world, &self.moving, left);
        if self.done.is_empty() {
            // The step's first sweep: over the whole step.
            self.keep_bounds();
        }
        let touching = ccd::contact_pairs(world);
        let mut best: Option<(usize, usize, T, usize)> = None;
        for &(i, j) in &self.swept.pairs {
            if self.done.contains(&(i, j)) || touching.contains(&ccd::key(i, j)) {
                continue;
            }
            let (Some(a), Some(b)) = (shape(world, i), shape(world, j)) else {
                continue;
            };
            let (ma, mb) = (
                motion_of(world, i, self.moving[i]),
                motion_of(world, j, self.moving[j]),
            );
            let pair = MovingPair::new(&a, &ma, &b, &mb);
            let options = search_options(method, &a, &b, closing_bound(&pair));
            let toi = swept_toi(method, &pair, left, &options, &mut ());
            *spent += toi.iterations;
            let time = match (toi.end, toi.time) {
                (ToiEnd::Converged | ToiEnd::IterationCap, Some(t)) if t < left => t,
                _ => continue,
            };
            if best.is_none_or(|b| time < b.2) {
                best = Some((i, j, time, toi.iterations));
            }
        }
        best
    }
}

fn shape<T: Real>(world: &World<T>, i: usize) -> Option<Convex> {
    Convex::from_shape(world.bodies[i].shape.as_ref()?)
}

/// The tolerance of a search: 10⁻⁴ of the smaller bounding radius (metres:
/// advancement's distance), or the time the pair takes to close it at its
/// bound on the closing speed `mu` (bisection's interval).
pub fn search_options<T: Real>(method: ToiMethod, a: &Convex, b: &Convex, mu: T) -> ToiOptions<T> {
    let length: T = c(1e-4 * a.bounding_radius().min(b.bounding_radius()));
    let tolerance = match method {
        ToiMethod::Conservative => length,
        ToiMethod::Bisection if mu > T::zero() => length / mu,
        ToiMethod::Bisection => length,
    };
    ToiOptions {
        tolerance,
        ..ToiOptions::default()
    }
}

/// x ← x + v dt, q ← q + ½ [0, ω dt] q for every moving body (the integrator's update).
fn advance<T: Real>(world: &mut World<T>, moving: &[bool], dt: T) {
    for (body, moves) in world.bodies.iter_mut().zip(moving) {
        if *moves {
            integrate_position(&mut body.state, dt);
        }
    }
}

/// The contact of bodies `i` and `j` where they are now (GJK's closest
/// points, or EPA's normal if the pair overlaps), resolved alone by the
/// velocity phase. Body 1 is a movable one. `None` when the pair is not
/// closing there.
fn resolve_at<T: Real>(
    world: &mut World<T>,
    p: &SimParams<T>,
    materials: &[Material],
    i: usize,
    j: usize,
) -> Option<ToiEvent> {
    let (i, j) = if world.bodies[i].movable {
        (i, j)
    } else {
        (j, i)
    };
    let (a, b) = (shape(world, i)?, shape(world, j)?);
    let pose = |k: usize| {
        let s = &world.bodies[k].state;
        Pose::new(s.position, &s.orientation)
    };
    let q = query(
        &a,
        &pose(i),
        &b,
        &pose(j),
        &QueryOptions {
            gjk: GjkOptions::default(),
            epa: EpaOptions::default(),
        },
        &mut (),
        &mut (),
    );
    let (point, normal, penetration) = match q.penetration {
        Some(pen) => (pen.point, pen.normal, pen.depth),
        None => {
            let gap = q.gjk.closest_a - q.gjk.closest_b;
            let d = gap.norm();
            if d <= T::zero() {
                return None;
            }
            (
                (q.gjk.closest_a + q.gjk.closest_b) * c::<T>(0.5),
                gap / d,
                -d,
            )
        }
    };
    let m = materials[i].combine(&materials[j]);
    let contact = Contact {
        body1: BodyId(i),
        body2: Some(BodyId(j)),
        input: contact_input(p, &m, point, normal, penetration),
        duration: (!p.acceleration_compensation).then(T::zero),
    };
    let normal_speed = |w: &World<T>| {
        let v = |k: usize| {
            let s = &w.bodies[k].state;
            s.point_velocity(&(point - s.position))
        };
        to_f64((v(i) - v(j)).dot(&normal))
    };
    let closing = -normal_speed(world);
    if closing <= 0.0 {
        // Met but not closing (a grazing or turning-away pair): nothing to resolve.
        return None;
    }
    let kinetic_before = to_f64(energy::kinetic(world));
    let kept = std::mem::replace(&mut world.contacts, vec![contact]);
    let mut resolver = Resolver::prepare(world, &p.resolver);
    resolver.velocity_phase(Implementation::Indexed, &mut Silent);
    resolver.write_back(world);
    world.contacts = kept;
    Some(ToiEvent {
        body1: BodyId(i),
        body2: BodyId(j),
        method: ToiMethod::Conservative,
        time: 0.0,
        tests: 0,
        point: to3(&point),
        normal: to3(&normal),
        closing,
        separating: normal_speed(world),
        kinetic_before,
        kinetic_after: to_f64(energy::kinetic(world)),
    })
}
