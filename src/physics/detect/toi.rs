//! Time of collision over one step ("Lecture IV Collisions", the time issue),
//! two ways, each recorded step by step through an observer whose methods do
//! nothing by default:
//!
//! - bisection, as the lecture gives it: keep [t₀, t₁] with the pair apart at
//!   t₀ and intersecting at t₁; test the midpoint t_m = (t₀ + t₁)/2 and keep
//!   the half that still brackets the collision, until t₁ − t₀ ≤ tol. From
//!   [0, Δt] that takes ⌈log₂(Δt / tol)⌉ tests. It needs a collision at the
//!   end of the step: a pair that crossed (tunnelled) is apart at both ends and
//!   bisection cannot see it ([`ToiEnd::NoHitAtEnd`]).
//! - conservative advancement: t ← t + d(t) / μ with d the GJK distance and
//!   μ = −v_rel·n + |ω_A| ρ_A + |ω_B| ρ_B a bound on the closing speed
//!   (n the unit normal from B's closest point toward A's, ρ a bounding radius
//!   of each shape about its body origin), until d ≤ tol. It never passes the
//!   first contact, so it also finds a collision inside the step.
//!
//! Motion over the step is the integrator's: constant linear and angular
//! velocity, x(t) = x₀ + v t, q(t) = exp(ω t) q₀. The time returned is the
//! last time known to be apart (t₀ for bisection), so advancing the pair
//! there leaves it touching, not penetrating.

use nalgebra::{UnitQuaternion, Vector3};

use super::gjk::{gjk, GjkOptions, GjkVerdict};
use super::support::Support;
use crate::physics::pose::Pose;
use crate::physics::{c, Real};

/// A body's motion over the step, from its pose at the step's start.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion<T: Real> {
    pub position: Vector3<T>,
    pub orientation: UnitQuaternion<T>,
    pub velocity: Vector3<T>,
    pub angular_velocity: Vector3<T>,
}

impl<T: Real> Motion<T> {
    /// A body that does not move.
    pub fn fixed(position: Vector3<T>) -> Self {
        Motion {
            position,
            orientation: UnitQuaternion::identity(),
            velocity: Vector3::zeros(),
            angular_velocity: Vector3::zeros(),
        }
    }

    /// The pose at time t into the step: x₀ + v t, exp(ω t) q₀.
    pub fn pose_at(&self, t: T) -> Pose<T> {
        let turn = UnitQuaternion::from_scaled_axis(self.angular_velocity * t);
        Pose::from_unit(
            self.position + self.velocity * t,
            &(turn * self.orientation),
        )
    }
}

/// The method of a time-of-collision search.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ToiMethod {
    Bisection,
    Conservative,
}

impl ToiMethod {
    pub fn json_name(self) -> &'static str {
        match self {
            ToiMethod::Bisection => "bisection",
            ToiMethod::Conservative => "conservative",
        }
    }
}

/// Tolerance and cap of a search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToiOptions<T: Real> {
    /// Bisection: stop when t₁ − t₀ ≤ this (seconds). Conservative
    /// advancement: stop when the distance ≤ this (metres).
    pub tolerance: T,
    /// At most this many intersection or distance tests.
    pub max_iterations: usize,
    pub gjk: GjkOptions<T>,
}

impl<T: Real> Default for ToiOptions<T> {
    fn default() -> Self {
        ToiOptions {
            tolerance: c(1e-6),
            max_iterations: 64,
            gjk: GjkOptions::default(),
        }
    }
}

/// One test of a search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToiStep<T: Real> {
    pub index: usize,
    /// The interval before this test (bisection), or the time tested and the
    /// time advanced to (conservative advancement: t₁ = t₀ + d/μ).
    pub t0: T,
    pub t1: T,
    /// The time the pair was tested at.
    pub trial: T,
    /// The pair intersects (bisection) or is within the tolerance (advancement) there.
    pub hit: bool,
    /// The GJK distance at `trial` (0 when intersecting).
    pub distance: T,
}

/// Observer of a search; does nothing by default.
pub trait ToiObserver<T: Real> {
    fn step(&mut self, _step: &ToiStep<T>) {}
    /// Bisection's scan of the step (`toi_sweep`): the piece [t0, t1] and
    /// whether the pair intersects at its end.
    fn scan(&mut self, _t0: T, _t1: T, _hit: bool) {}
}

impl<T: Real> ToiObserver<T> for () {}

/// Keeps every step.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ToiRecorder<T: Real> {
    pub steps: Vec<ToiStep<T>>,
}

impl<T: Real> ToiObserver<T> for ToiRecorder<T> {
    fn step(&mut self, step: &ToiStep<T>) {
        self.steps.push(*step);
    }
}

/// Why a search ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ToiEnd {
    /// The interval (bisection) or the distance (advancement) is within the tolerance.
    Converged,
    /// The pair already intersects at the step's start: time 0.
    AtStart,
    /// Bisection: apart at the end of the step, nothing to bracket.
    NoHitAtEnd,
    /// Advancement: the pair does not close, or the next time is past the step.
    NoHitInStep,
    /// The iteration cap was reached.
    IterationCap,
}

/// The outcome of a search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Toi<T: Real> {
    pub method: ToiMethod,
    /// Time into the step of the first contact (last time known apart), if any.
    pub time: Option<T>,
    pub iterations: usize,
    pub end: ToiEnd,
}

/// Two shapes and their motions over the step: what every time-of-collision
/// search takes.
pub struct MovingPair<'s, T: Real, A: ?Sized, B: ?Sized> {
    pub a: &'s A,
    pub motion_a: &'s Motion<T>,
    pub b: &'s B,
    pub motion_b: &'s Motion<T>,
}

impl<'s, T: Real, A: Support<T> + ?Sized, B: Support<T> + ?Sized> MovingPair<'s, T, A, B> {
    pub fn new(a: &'s A, motion_a: &'s Motion<T>, b: &'s B, motion_b: &'s Motion<T>) -> Self {
        MovingPair {
            a,
            motion_a,
            b,
            motion_b,
        }
    }

    /// GJK at time t: whether they intersect, their distance and the gap
    /// between their closest points (A's minus B's).
    fn distance_at(&self, t: T, options: &GjkOptions<T>) -> (bool, T, Vector3<T>) {
        let (a, b) = (self.a, self.b);
        let r = gjk(
            a,
            &self.motion_a.pose_at(t),
            b,
            &self.motion_b.pose_at(t),
            options,
            &mut (),
        );
        let hit = r.verdict == GjkVerdict::Intersecting;
        (hit, r.distance, r.closest_a - r.closest_b)
    }
}

/// Runs `method` over [0, dt].
pub fn toi<T, A, B, O>(
    method: ToiMethod,
    pair: &MovingPair<'_, T, A, B>,
    dt: T,
    options: &ToiOptions<T>,
    observer: &mut O,
) -> Toi<T>
where
    T: Real,
    A: Support<T> + ?Sized,
    B: Support<T> + ?Sized,
    O: ToiObserver<T> + ?Sized,
{
    match method {
        ToiMethod::Bisection => bisection(pair, dt, options, observer),
        ToiMethod::Conservative => conservative_advancement(pair, dt, options, observer),
    }
}

/// Bisection on [0, dt] (module docs).
pub fn bisection<T, A, B, O>(
    pair: &MovingPair<'_, T, A, B>,
    dt: T,
    options: &ToiOptions<T>,
    observer: &mut O,
) -> Toi<T>
where
    T: Real,
    A: Support<T> + ?Sized,
    B: Support<T> + ?Sized,
    O: ToiObserver<T> + ?Sized,
{
    let done = |time, iterations, end| Toi {
        method: ToiMethod::Bisection,
        time,
        iterations,
        end,
    };
    if pair.distance_at(T::zero(), &options.gjk).0 {
        return done(Some(T::zero()), 0, ToiEnd::AtStart);
    }
    if !pair.distance_at(dt, &options.gjk).0 {
        return done(None, 0, ToiEnd::NoHitAtEnd);
    }
    let (mut t0, mut t1) = (T::zero(), dt);
    let mut index = 0;
    while t1 - t0 > options.tolerance {
        if index == options.max_iterations {
            return done(Some(t0), index, ToiEnd::IterationCap);
        }
        let trial = (t0 + t1) * c::<T>(0.5);
        let (hit, distance, _) = pair.distance_at(trial, &options.gjk);
        observer.step(&ToiStep {
            index,
            t0,
            t1,
            trial,
            hit,
            distance,
        });
        if hit {
            t1 = trial;
        } else {
            t0 = trial;
        }
        index += 1;
    }
    done(Some(t0), index, ToiEnd::Converged)
}

/// A bound on |p| over the shape, p in the body frame: the corner of the
/// body-frame box spanned by the supports along ±x, ±y, ±z.
pub fn bounding_radius<T: Real, S: Support<T> + ?Sized>(shape: &S) -> T {
    let mut corner = Vector3::<T>::zeros();
    for i in 0..3 {
        let mut d = Vector3::<T>::zeros();
        d[i] = T::one();
        let hi = shape.local_support(&d)[i].abs();
        let lo = shape.local_support(&-d)[i].abs();
        corner[i] = hi.max(lo);
    }
    corner.norm()
}

/// Conservative advancement on [0, dt] (module docs).
pub fn conservative_advancement<T, A, B, O>(
    pair: &MovingPair<'_, T, A, B>,
    dt: T,
    options: &ToiOptions<T>,
    observer: &mut O,
) -> Toi<T>
where
    T: Real,
    A: Support<T> + ?Sized,
    B: Support<T> + ?Sized,
    O: ToiObserver<T> + ?Sized,
{
    let done = |time, iterations, end| Toi {
        method: ToiMethod::Conservative,
        time,
        iterations,
        end,
    };
    // The rotation part of μ: |ω_A| ρ_A + |ω_B| ρ_B (constant over the step).
    let (ma, mb) = (pair.motion_a, pair.motion_b);
    let spin = ma.angular_velocity.norm() * bounding_radius(pair.a)
        + mb.angular_velocity.norm() * bounding_radius(pair.b);
    let relative = ma.velocity - mb.velocity;
    let mut t = T::zero();
    for index in 0..options.max_iterations {
        let (hit, distance, gap) = pair.distance_at(t, &options.gjk);
        if hit && index == 0 {
            return done(Some(t), 0, ToiEnd::AtStart);
        }
        let close = hit || distance <= options.tolerance;
        // μ = −v_rel·n + spin, n from B toward A.
        let normal = if distance > T::zero() {
            gap / distance
        } else {
            Vector3::zeros()
        };
        let mu = -relative.dot(&normal) + spin;
        let next = if close || mu <= T::zero() {
            t
        } else {
            t + distance / mu
        };
        observer.step(&ToiStep {
            index,
            t0: t,
            t1: next,
            trial: t,
            hit: close,
            distance,
        });
        if close {
            return done(Some(t), index + 1, ToiEnd::Converged);
        }
        if mu <= T::zero() || next > dt {
            return done(None, index + 1, ToiEnd::NoHitInStep);
        }
        t = next;
    }
    done(Some(t), options.max_iterations, ToiEnd::IterationCap)
}
