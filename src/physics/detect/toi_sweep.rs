//! A time-of-collision search over a whole step, for continuous detection:
//! conservative advancement as it is ([`super::toi`] never passes the first
//! contact), and the lecture's bisection after a scan. Bisection needs an
//! interval [t₀, t₁] with the pair apart at t₀ and intersecting at t₁, and a
//! pair that crosses inside the step is apart at both ends; so the step is
//! first cut into pieces no longer than the time the pair takes to close
//! half its two smallest widths, w = (w_A + w_B) / 2, at the bound on its
//! closing speed μ (the same bound as advancement's): n = ⌈Δt μ / w⌉ pieces,
//! at most [`MAX_PIECES`]. The first piece whose end intersects is bisected.
//! A pair that needs more pieces than that (a bullet at 10⁴ m/s) falls back
//! to conservative advancement, which never passes the first contact, and
//! its result says so (method `conservative`).

use nalgebra::{UnitQuaternion, Vector3};

use super::gjk::GjkOptions;
use super::toi::{
    bisection, conservative_advancement, Motion, SweptPair, Toi, ToiEnd, ToiMethod, ToiObserver,
    ToiOptions, ToiStep,
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

/// μ: a bound on the pair's closing speed, |v_A − v_B| + |ω_A| ρ_A + |ω_B| ρ_B.
pub fn closing_bound<T: Real, P: SweptPair<T> + ?Sized>(pair: &P) -> T {
    pair.relative_velocity().norm() + pair.spin()
}

/// A pair seen from `by` seconds into the step: its test at t is the
/// pair's at `by + t`.
pub struct Later<'a, T: Real, P: ?Sized> {
    pub pair: &'a P,
    pub by: T,
}

impl<T: Real, P: SweptPair<T> + ?Sized> SweptPair<T> for Later<'_, T, P> {
    fn distance_at(&self, t: T, options: &GjkOptions<T>) -> (bool, T, Vector3<T>) {
        self.pair.distance_at(self.by + t, options)
    }
    fn relative_velocity(&self) -> Vector3<T> {
        self.pair.relative_velocity()
    }
    fn spin(&self) -> T {
        self.pair.spin()
    }
    fn width(&self) -> T {
        self.pair.width()
    }
    fn gap_rate(&self, t: T, options: &GjkOptions<T>) -> Option<T> {
        self.pair.gap_rate(self.by + t, options)
    }
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
pub fn scanned_bisection<T, P, O>(
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
    let width = pair.width();
    let mu = closing_bound(pair);
    let n = (dt * mu / width).ceil();
    if !(width > T::zero() && n <= c::<T>(MAX_PIECES as f64)) {
        // Pieces of at most half the widths would be more than the cap:
        // a scan with fewer could step over the pair, so it cannot
        // certify the step. Advancement can (it never passes the first
        // contact): the search falls back to it, and says so (its method).
        let length = options.tolerance * mu;
        let advancing = ToiOptions {
            tolerance: if length > T::zero() {
                length
            } else {
                options.tolerance
            },
            ..*options
        };
        return conservative_advancement(pair, dt, &advancing, observer);
    }
    let pieces = crate::physics::to_f64(n).max(1.0) as usize;
    // A pair that already intersects has met at the start (the search is
    // over its time of collision, not a new one): as plain bisection says.
    if pair.distance_at(T::zero(), &options.gjk).0 {
        return Toi {
            method: ToiMethod::Bisection,
            time: Some(T::zero()),
            iterations: 0,
            end: ToiEnd::AtStart,
        };
    }
    let h = dt / c::<T>(pieces as f64);
    let mut tests = 0;
    for k in 0..pieces {
        let start = h * c::<T>(k as f64);
        let later = Later { pair, by: start };
        let hit = later.distance_at(h, &options.gjk).0;
        tests += 1;
        observer.scan(start, start + h, hit);
        if !hit {
            continue;
        }
        let mut shifted = Shifted {
            by: start,
            inner: observer,
        };
        let found = bisection(&later, h, options, &mut shifted);
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
pub fn swept_toi<T, P, O>(
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
        ToiMethod::Bisection => scanned_bisection(pair, dt, options, observer),
        ToiMethod::Conservative => conservative_advancement(pair, dt, options, observer),
    }
}
