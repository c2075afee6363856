//! Continuous detection in the step ("Lecture IV Collisions", the time
//! issue). After the step's contacts are resolved, the positions are not
//! simply moved by v Δt: with `ccd` on, the pairs whose movement bounds
//! ([`super::swept`]) meet over what is left of the step, and each moving
//! body with each half-space it can reach ([`super::ccd_pairs`]), get their
//! time of collision ([`crate::physics::detect::toi_sweep`]); every moving
//! body advances to the earliest, that pair's contacts are resolved there
//! (the velocity phase, [`super::toi_resolve`]), and the rest of the step
//! is spent the same way, earliest first. A body the resolution changes
//! moves from then on, woken if it slept ([`Spent::woken`]). Pairs already
//! in contact at the step's start are the discrete resolver's; a pair
//! resolved here is searched again only while its gap can still shrink
//! (a spinning body), past the touch it is leaving.
//!
//! At most [`MAX_SUBSTEPS`] collisions and [`MAX_ROUNDS`] searches are run
//! in one step; when a cap is hit the rest of the step is one plain move
//! (the tunnelling auditor still watches it, and a pair resolved in the
//! step that crosses in it is reported). Each sub-step costs a swept broad
//! phase and one search per candidate pair (docs/ccd.md).

use super::ccd::{self, Tunnelled};
use super::ccd_pairs;
use super::integrate::integrate_position;
use super::report::ToiEvent;
use super::swept::{motion_of, Earlier, MovementBound, SweptPairs};
use super::toi_resolve::{advance_along, apart_for_good, resolve_at, shape, to3};
use super::touching;
use crate::physics::detect::toi_sweep::{closing_bound, swept_toi, Later};
use crate::physics::detect::{
    gjk, Convex, GjkOptions, GjkVerdict, MovingPair, PlanePair, SweptPair, ToiEnd, ToiMethod,
    ToiOptions,
};
use crate::physics::params::{Material, SimParams};
use crate::physics::{c, to_f64, BodyId, Real, World};

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
    /// The pairs resolved so far in the step (module docs, "again").
    done: Vec<Done>,
    planes: Vec<(usize, usize)>,
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
            planes: Vec::new(),
            back: Vec::new(),
            bounds: Vec::new(),
        }
    }
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
        let mut rounds = 0;
        loop {
            let left = p.dt - elapsed;
            if out.hits.len() == MAX_SUBSTEPS || rounds == MAX_ROUNDS {
                out.capped = true;
                break;
            }
            rounds += 1;
            let Some(found) = self.earliest(world, method, left, &mut out.tests) else {
                break;
            };
            let (i, j) = found.pair;
            advance_along(world, &self.moving, found.time);
            elapsed += found.time;
            if !found.met {
                // Advancement's cap: the pair is still apart there, and
                // nothing met before (safe to move to; search again).
                continue;
            }
            let hit = resolve_at(world, p, materials, i, j, found.tolerance);
            let key = (i.min(j), i.max(j));
            self.done.retain(|d| d.pair != key);
            self.done.push(Done {
                pair: key,
                for_good: hit.as_ref().is_none_or(|h| apart_for_good(world, h)),
                tolerance: found.tolerance,
            });
            if let Some(hit) = hit {
                for (body, by) in [(hit.body1, hit.body2), (hit.body2, hit.body1)] {
                    if world.bodies[body.0].movable && !self.moving[body.0] {
                        self.moving[body.0] = true;
                        out.woken.push((body, by));
                    }
                }
                out.hits.push(ToiEvent {
                    method: found.method,
                    time: to_f64(elapsed),
                    tests: found.tests,
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
        if out.capped {
            self.unfinished(world, method, left, elapsed, &mut out.crossed);
        }
        advance(world, &self.moving, left);
    }

    /// The cap was hit: a pair resolved in the step whose gap could still
    /// shrink (not [`Done::for_good`]) is searched once more over what is
    /// left; if it meets there and is apart again at the step's end, it
    /// crossed unseen, and says so (a `tunnelled` event; the auditor, which
    /// starts from the touch the pair has just had, cannot see it).
    fn unfinished(
        &self,
        world: &World<T>,
        method: ToiMethod,
        left: T,
        elapsed: T,
        crossed: &mut Vec<Tunnelled>,
    ) {
        for d in self.done.iter().filter(|d| !d.for_good) {
            let (i, j) = d.pair;
            if crossed
                .iter()
                .any(|t| (t.body1.0.min(t.body2.0), t.body1.0.max(t.body2.0)) == d.pair)
            {
                continue;
            }
            let (Some(a), Some(b)) = (shape(world, i), shape(world, j)) else {
                continue; // A half-space cannot be crossed: the discrete step sees the overlap.
            };
            let (ma, mb) = (
                motion_of(world, i, self.moving[i]),
                motion_of(world, j, self.moving[j]),
            );
            let pair = MovingPair::new(&a, &ma, &b, &mb);
            let radius = a.bounding_radius().min(b.bounding_radius());
            let Some(Found {
                time: t, met: true, ..
            }) = search(&pair, method, radius, left, Some(d.tolerance))
            else {
                continue;
            };
            let gjk_at = |s: T| {
                gjk(
                    &a,
                    &ma.pose_at(s),
                    &b,
                    &mb.pose_at(s),
                    &GjkOptions::default(),
                    &mut (),
                )
            };
            if gjk_at(left).verdict != GjkVerdict::Separated {
                continue;
            }
            let hit = gjk_at(t);
            let point = (hit.closest_a + hit.closest_b) * c::<T>(0.5);
            crossed.push(Tunnelled {
                body1: BodyId(i),
                body2: BodyId(j),
                time: to_f64(elapsed + t),
                point: to3(&point),
            });
        }
    }

    /// The moving bodies' bounds from the last sweep, kept in `bounds`.
    fn keep_bounds(&mut self) {
        let (swept, moving) = (&self.swept, &self.moving);
        self.bounds.clear();
        self.bounds
            .extend((0..moving.len()).map(|i| if moving[i] { swept.bound(i) } else { None }));
    }

    /// The pair that meets first within `left` (convex pairs from the
    /// swept broad phase, then a body against a half-space); every
    /// search's tests are added to `spent`.
    fn earliest(
        &mut self,
        world: &World<T>,
        method: ToiMethod,
        left: T,
        spent: &mut usize,
    ) -> Option<Found<T>> {
        self.swept.find(world, &self.moving, left);
        if self.done.is_empty() {
            // The step's first sweep: over the whole step.
            self.keep_bounds();
        }
        ccd_pairs::plane_pairs(world, &self.moving, left, &mut self.planes);
        let touching = touching::contact_pairs(world);
        let mut best: Option<Found<T>> = None;
        let pairs = self.swept.pairs.iter().chain(&self.planes);
        for &(i, j) in pairs {
            let key = (i.min(j), i.max(j));
            let again = match self.done.iter().find(|d| d.pair == key) {
                Some(d) if d.for_good => continue,
                Some(d) => Some(d.tolerance),
                None => None,
            };
            if touching.contains(&touching::key(i, j)) {
                continue;
            }
            let Some(a) = shape(world, i) else {
                continue;
            };
            let ma = motion_of(world, i, self.moving[i]);
            let found = match ccd_pairs::half_space(world, j) {
                Some((normal, point)) => {
                    let pair = PlanePair::new(&a, &ma, normal, point);
                    let radius = a.bounding_radius();
                    search(&pair, method, radius, left, again)
                }
                None => {
                    let Some(b) = shape(world, j) else {
                        continue;
                    };
                    let mb = motion_of(world, j, self.moving[j]);
                    let pair = MovingPair::new(&a, &ma, &b, &mb);
                    let radius = a.bounding_radius().min(b.bounding_radius());
                    search(&pair, method, radius, left, again)
                }
            };
            let Some(found) = found else {
                continue;
            };
            *spent += found.tests;
            if best.as_ref().is_none_or(|b| found.time < b.time) {
                best = Some(Found {
                    pair: (i, j),
                    ..found
                });
            }
        }
        best
    }
}

/// At most this many rounds (searches of the whole scene) in one step,
/// collisions and advancement's caps together.
pub const MAX_ROUNDS: usize = 4 * MAX_SUBSTEPS;

/// A pair resolved in the step.
#[derive(Debug, Clone, Copy)]
struct Done {
    pair: (usize, usize),
    /// Its gap cannot shrink for the rest of the step: not searched again.
    for_good: bool,
    /// Its search's tolerance (metres).
    tolerance: f64,
}

/// The earliest meeting of a round.
#[derive(Debug, Clone, Copy)]
struct Found<T: Real> {
    pair: (usize, usize),
    /// Seconds from now.
    time: T,
    /// The pair meets there (false: advancement's cap, still apart).
    met: bool,
    tests: usize,
    /// The length the search worked to (metres).
    tolerance: f64,
    /// The search that found it (bisection falls back to advancement
    /// where its scan cannot certify the step).
    method: ToiMethod,
}

/// One pair's search over `left`: its time, whether it met there, its
/// tests and its tolerance in metres (`radius`: the smaller bounding
/// radius). `again`: the pair was resolved earlier in the step with that
/// tolerance and still touches: advancement steps past the touch while the
/// pair's closest points move apart; bisection starts once the gap could
/// have closed the tolerance at the closing bound.
fn search<T: Real, P: SweptPair<T>>(
    pair: &P,
    method: ToiMethod,
    radius: f64,
    left: T,
    again: Option<f64>,
) -> Option<Found<T>> {
    let mu = closing_bound(pair);
    let options = ToiOptions {
        // Advancement steps past the touch itself while the pair leaves it.
        skip_receding: again.is_some(),
        ..search_options_for(method, radius, mu)
    };
    let length = 1e-4 * radius;
    let from = match (again, method) {
        (Some(_), ToiMethod::Conservative) => T::zero(),
        (Some(tol), _) if mu > T::zero() => c::<T>(tol) / mu,
        (Some(_), _) => return None,
        (None, _) => T::zero(),
    };
    if from >= left {
        return None;
    }
    let later = Later { pair, by: from };
    let toi = swept_toi(method, &later, left - from, &options, &mut ());
    let (time, met) = match (toi.end, toi.time) {
        (ToiEnd::Converged, Some(t)) => (t, true),
        (ToiEnd::AtStart, Some(t)) if again.is_some() => (t, true),
        (ToiEnd::IterationCap, Some(t)) if toi.method == ToiMethod::Conservative => (t, false),
        (ToiEnd::IterationCap, Some(t)) => (t, true),
        _ => return None,
    };
    (time + from < left).then_some(Found {
        pair: (0, 0),
        time: time + from,
        met,
        tests: toi.iterations,
        tolerance: length,
        method: toi.method,
    })
}

/// The tolerance of a search: 10⁻⁴ of the smaller bounding radius (metres:
/// advancement's distance), or the time the pair takes to close it at its
/// bound on the closing speed `mu` (bisection's interval).
pub fn search_options<T: Real>(method: ToiMethod, a: &Convex, b: &Convex, mu: T) -> ToiOptions<T> {
    search_options_for(method, a.bounding_radius().min(b.bounding_radius()), mu)
}

/// [`search_options`] with the smaller bounding radius given (a half-space
/// has none: the shape's own).
pub fn search_options_for<T: Real>(method: ToiMethod, radius: f64, mu: T) -> ToiOptions<T> {
    let length: T = c(1e-4 * radius);
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
