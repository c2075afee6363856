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

    /// The velocity at time t of the body's point at world `p`: v + ω × (p − x(t)).
    pub fn point_velocity(&self, t: T, p: &Vector3<T>) -> Vector3<T> {
        self.velocity
            + self
                .angular_velocity
                .cross(&(p - (self.position + self.velocity * t)))
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

/// Tolerance and cap of a search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToiOptions<T: Real> {
    /// Bisection: stop when t₁ − t₀ ≤ this (seconds). Conservative
    /// advancement: stop when the distance ≤ this (metres).
    pub tolerance: T,
    /// At most this many intersection or distance tests.
    pub max_iterations: usize,
    pub gjk: GjkOptions<T>,
    /// Advancement: a pair within the tolerance whose closest points move
    /// apart has not met (it is leaving a touch just resolved): advance past
    /// it instead of stopping there.
    pub skip_receding: bool,
}

impl<T: Real> Default for ToiOptions<T> {
    fn default() -> Self {
        ToiOptions {
            tolerance: c(1e-6),
            max_iterations: 64,
            gjk: GjkOptions::default(),
            skip_receding: false,
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
}

/// What a time-of-collision search asks of a pair over the step: the test
/// at a time, and what bounds its closing speed. Two convex shapes
/// ([`MovingPair`]: GJK) and a convex shape against a half-space
/// ([`super::toi_plane::PlanePair`]: a closed form) answer it.
pub trait SweptPair<T: Real> {
    /// At time t into the step: whether the pair intersects, its distance
    /// (≥ 0; 0 when intersecting) and the gap between the closest points
    /// (A's minus B's: along the normal from B toward A).
    fn distance_at(&self, t: T, options: &GjkOptions<T>) -> (bool, T, Vector3<T>);
    /// v_A − v_B.
    fn relative_velocity(&self) -> Vector3<T>;
    /// The rotation part of the closing bound, |ω_A| ρ_A + |ω_B| ρ_B, ρ the
    /// farthest point of each shape from its body origin (the centre of
    /// mass): no point of either moves faster than this by turning.
    fn spin(&self) -> T;
    /// The width the scan's pieces are cut to: half the sum of the two
    /// shapes' smallest widths (a half-space counts as deep as the shape).
    fn width(&self) -> T;
    /// The rate at which the gap between the closest points grows at time
    /// t (> 0: they move apart); `None` where there is no normal (the
    /// pair intersects).
    fn gap_rate(&self, t: T, options: &GjkOptions<T>) -> Option<T>;
}

impl<T: Real, A: Support<T> + ?Sized, B: Support<T> + ?Sized> SweptPair<T>
    for MovingPair<'_, T, A, B>
{
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

    fn relative_velocity(&self) -> Vector3<T> {
        self.motion_a.velocity - self.motion_b.velocity
    }

    fn spin(&self) -> T {
        self.motion_a.angular_velocity.norm() * bounding_radius(self.a)
            + self.motion_b.angular_velocity.norm() * bounding_radius(self.b)
    }

    fn width(&self) -> T {
        (smallest_width(self.a) + smallest_width(self.b)) * c::<T>(0.5)
    }

    fn gap_rate(&self, t: T, options: &GjkOptions<T>) -> Option<T> {
        let (ma, mb) = (self.motion_a, self.motion_b);
        let r = gjk(
            self.a,
            &ma.pose_at(t),
            self.b,
            &mb.pose_at(t),
            options,
            &mut (),
        );
        let gap = r.closest_a - r.closest_b;
        let d = gap.norm();
        if r.verdict == GjkVerdict::Intersecting || d <= T::zero() {
            return None;
        }
        Some(
            (ma.point_velocity(t, &r.closest_a) - mb.point_velocity(t, &r.closest_b))
                .dot(&(gap / d)),
        )
    }
}

/// The smallest width of a shape over its body axes: min_k s(e_k) − s(−e_k).
pub fn smallest_width<T: Real, S: Support<T> + ?Sized>(shape: &S) -> T {
    (0..3)
        .map(|i| {
            let mut d = Vector3::<T>::zeros();
            d[i] = T::one();
            shape.local_support(&d)[i] - shape.local_support(&-d)[i]
        })
        .fold(c::<T>(f64::INFINITY), |m, w| m.min(w))
}

/// Runs `method` over [0, dt].
pub fn toi<T, P, O>(
    method: ToiMethod,
    pair: &P,
    dt: T,
    options: &ToiOptions<T>,
    observer: &mut O,
) -> Toi<T>
where
    T: Real,
    P: SweptPair<T> + ?Sized,
    O: ToiObserver<T> + ?Sized,
{
    match method {
        ToiMethod::Bisection => bisection(pair, dt, options, observer),
        ToiMethod::Conservative => conservative_advancement(pair, dt, options, observer),
    }
}

/// Bisection on [0, dt] (module docs).
pub fn bisection<T, P, O>(pair: &P, dt: T, options: &ToiOptions<T>, observer: &mut O) -> Toi<T>
where
    T: Real,
    P: SweptPair<T> + ?Sized,
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
pub fn conservative_advancement<T, P, O>(
    pair: &P,
    dt: T,
    options: &ToiOptions<T>,
    observer: &mut O,
) -> Toi<T>
where
    T: Real,
    P: SweptPair<T> + ?Sized,
    O: ToiObserver<T> + ?Sized,
{
    let done = |time, iterations, end| Toi {
        method: ToiMethod::Conservative,
        time,
        iterations,
        end,
    };
    // The rotation part of μ: |ω_A| ρ_A + |ω_B| ρ_B (constant over the step).
    let spin = pair.spin();
    let relative = pair.relative_velocity();
    let mut t = T::zero();
    for index in 0..options.max_iterations {
        let (hit, distance, gap) = pair.distance_at(t, &options.gjk);
        if hit && index == 0 && !options.skip_receding {
            return done(Some(t), 0, ToiEnd::AtStart);
        }
        let near = hit || distance <= options.tolerance;
        // A touch just resolved, the pair leaving it: not a meeting.
        let receding = near
            && options.skip_receding
            && pair
                .gap_rate(t, &options.gjk)
                .is_some_and(|r| r > T::zero());
        let close = near && !receding;
        // μ = −v_rel·n + spin, n from B toward A.
        let normal = if distance > T::zero() {
            gap / distance
        } else {
            Vector3::zeros()
        };
        let mu = -relative.dot(&normal) + spin;
        let next = if receding {
            // Past the touch: no farther than the gap (or the tolerance)
            // can close at the bound on the closing speed, |v_rel| + spin.
            t + distance.max(options.tolerance) / (relative.norm() + spin)
        } else if close || mu <= T::zero() {
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
        if (!receding && mu <= T::zero()) || next > dt {
            return done(None, index + 1, ToiEnd::NoHitInStep);
        }
        t = next;
    }
    done(Some(t), options.max_iterations, ToiEnd::IterationCap)
}
