//! A time-of-collision search over a whole step, for continuous detection:
//! conservative advancement as it is ([`super::toi`] never passes the first
//! contact), and the lecture's bisection after a scan. Bisection needs an
//! interval [t₀, t₁] with the pair apart at t₀ and intersecting at t₁, and a
//! pair that crosses inside the step is apart at both ends; so the step is
//! first cut into pieces no longer than the time the pair takes to close
//! half its two smallest widths, w = (w_A + w_B) / 2, at the bound on its
//! closing speed μ (the same bound as advancement's): n = ⌈Δt μ / w⌉ pieces,
//! at most [`MAX_PIECES`]. The first piece whose end intersects is bisected.
//! A pair that only grazes (overlaps for less than a piece) can still be
//! missed; the tunnelling auditor reports it.

use nalgebra::{UnitQuaternion, Vector3};

use super::gjk::{gjk, GjkVerdict};
use super::support::Support;
use super::toi::{
    bisection, bounding_radius, conservative_advancement, Motion, MovingPair, Toi, ToiEnd,
    ToiMethod, ToiObserver, ToiOptions, ToiStep,
};
use crate::physics::{c, Real};

/// The most pieces bisection's scan cuts a step into.
pub const MAX_PIECES: usize = 256;

/// The motion `m` rebased to time `s`: the pose there, the same velocities.
pub fn rebased<T: Real>(m: &Motion<T>, s: T) -> Motion<T> {
    Motion {
        position: m.position + m.velocity * s,
        orientation: UnitQuaternion::from_scaled_axis(m.angular_velocity * s) * m.orientation,
        ..*m
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

/// μ: a bound on the pair's closing speed, |v_A − v_B| + |ω_A| ρ_A + |ω_B| ρ_B.
pub fn closing_bound<T: Real, A: Support<T> + ?Sized, B: Support<T> + ?Sized>(
    pair: &MovingPair<'_, T, A, B>,
) -> T {
    let (ma, mb) = (pair.motion_a, pair.motion_b);
    (ma.velocity - mb.velocity).norm()
        + ma.angular_velocity.norm() * bounding_radius(pair.a)
        + mb.angular_velocity.norm() * bounding_radius(pair.b)
}

/// Shifts the times a piece's bisection reports by the piece's start.
struct Shifted<'a, T: Real, O: ?Sized> {
    by: T,
    inner: &'a mut O,
}

impl<T: Real, O: ToiObserver<T> + ?Sized> ToiObserver<T> for Shifted<'_, T, O> {
    fn step(&mut self, s: &ToiStep<T>) {
        self.inner.step(&ToiStep {
            t0: s.t0 + self.by,
            t1: s.t1 + self.by,
            trial: s.trial + self.by,
            ..*s
        });
    }
}

/// Bisection over [0, dt] after the scan (module docs). `options.tolerance`
/// is the bisection's, in seconds.
pub fn scanned_bisection<T, A, B, O>(
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
    let (a, b) = (pair.a, pair.b);
    let width = (smallest_width(a) + smallest_width(b)) * c::<T>(0.5);
    let mu = closing_bound(pair);
    let pieces = if width > T::zero() {
        let n = (dt * mu / width).ceil();
        if n >= c::<T>(MAX_PIECES as f64) {
            MAX_PIECES
        } else {
            crate::physics::to_f64(n).max(1.0) as usize
        }
    } else {
        MAX_PIECES
    };
    let h = dt / c::<T>(pieces as f64);
    let mut tests = 0;
    for k in 0..pieces {
        let start = h * c::<T>(k as f64);
        let (pa, pb) = (rebased(pair.motion_a, start), rebased(pair.motion_b, start));
        let end = gjk(a, &pa.pose_at(h), b, &pb.pose_at(h), &options.gjk, &mut ());
        tests += 1;
        let hit = end.verdict == GjkVerdict::Intersecting;
        observer.scan(start, start + h, hit);
        if !hit {
            continue;
        }
        let mut shifted = Shifted {
            by: start,
            inner: observer,
        };
        let found = bisection(&MovingPair::new(a, &pa, b, &pb), h, options, &mut shifted);
        return Toi {
            time: found.time.map(|t| t + start),
            iterations: tests + found.iterations,
            ..found
        };
    }
    Toi {
        method: ToiMethod::Bisection,
        time: None,
        iterations: tests,
        end: ToiEnd::NoHitInStep,
    }
}

/// The search continuous detection runs: conservative advancement as it is,
/// bisection after the scan.
pub fn swept_toi<T, A, B, O>(
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
        ToiMethod::Bisection => scanned_bisection(pair, dt, options, observer),
        ToiMethod::Conservative => conservative_advancement(pair, dt, options, observer),
    }
}
