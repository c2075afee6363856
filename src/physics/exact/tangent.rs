//! Tangent-plane maths of the impact: the blocks of K, the sticking ratio
//! τ = -K_tt⁻¹ K_tn, invariant slip directions and the direction slip
//! restarts in when the cone cannot hold the contact.

use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};

use crate::physics::{c, Real};

/// `K_tt`, the tangential 2×2 block of K.
pub(super) fn k_tt<T: Real>(k: &Matrix3<T>) -> Matrix2<T> {
    k.fixed_view::<2, 2>(1, 1).into_owned()
}

/// `K_tn`, tangential velocity per unit normal impulse.
pub(super) fn k_tn<T: Real>(k: &Matrix3<T>) -> Vector2<T> {
    Vector2::new(k[(1, 0)], k[(2, 0)])
}

/// The tangential part of a contact-space vector.
pub(super) fn tangential<T: Real>(v: &Vector3<T>) -> Vector2<T> {
    Vector2::new(v.y, v.z)
}

/// `(1, t)`: an impulse rate with unit normal part and tangential part t.
pub(super) fn with_unit_normal<T: Real>(t: &Vector2<T>) -> Vector3<T> {
    Vector3::new(T::one(), t.x, t.y)
}

/// `A⁻¹ b` for a symmetric positive-definite 2×2 A (explicit inverse; A's
/// determinant is positive because A is a principal block of an SPD matrix).
fn solve2<T: Real>(a: &Matrix2<T>, b: &Vector2<T>) -> Vector2<T> {
    let det = a[(0, 0)] * a[(1, 1)] - a[(0, 1)] * a[(1, 0)];
    Vector2::new(
        (a[(1, 1)] * b.x - a[(0, 1)] * b.y) / det,
        (a[(0, 0)] * b.y - a[(1, 0)] * b.x) / det,
    )
}

/// Sticking ratio `τ = -K_tt⁻¹ K_tn`: the tangential impulse per unit normal
/// impulse that keeps u_t = 0. The contact can stick while `|τ| ≤ μ_s`.
pub(super) fn stick_ratio<T: Real>(k: &Matrix3<T>) -> Vector2<T> {
    -solve2(&k_tt(k), &k_tn(k))
}

/// Rate of change of the tangential velocity while slipping along s,
/// `du_t/dP_n = K_tn - μ_d K_tt s`.
pub(super) fn slip_rate<T: Real>(k: &Matrix3<T>, mu: T, s: &Vector2<T>) -> Vector2<T> {
    k_tn(k) - k_tt(k) * s * mu
}

/// True when slipping along s keeps its direction: `du_t/dP_n ∥ s` to within
/// 64 ε (then u is linear in P_n and the stretch has a closed form).
pub(super) fn is_invariant<T: Real>(k: &Matrix3<T>, mu: T, s: &Vector2<T>) -> bool {
    let b = slip_rate(k, mu, s);
    let cross = b.x * s.y - b.y * s.x;
    cross.abs() <= T::default_epsilon() * c(64.0) * (b.norm() + k.amax() * (T::one() + mu))
}

/// The direction slip restarts in from rest when the cone cannot hold the
/// contact (`|τ| > μ_d`): the unit s with `K_tn - μ_d K_tt s = λ s`, λ > 0,
/// so that the slip it starts grows along itself and stays consistent
/// (Mirtich's thesis ch. 4; Stronge, Impact Mechanics ch. 5). It is
/// `s(λ) = (λ𝟙 + μ_d K_tt)⁻¹ K_tn` for the unique λ > 0 with `|s(λ)| = 1`:
/// `|s(λ)|` falls monotonically from `|τ|/μ_d > 1` at λ = 0 to at most 1 at
/// λ = |K_tn|. Returns `(s, λ)`, or `None` when no such λ exists (`|τ| ≤ μ_d`:
/// kinetic friction can hold the contact, which then sticks).
pub(super) fn restart_direction<T: Real>(k: &Matrix3<T>, mu: T) -> Option<(Vector2<T>, T)> {
    let ktn = k_tn(k);
    let ktt = k_tt(k);
    let size = ktn.norm();
    if size <= T::zero() {
        return None;
    }
    let s_of = |lambda: T| solve2(&(Matrix2::identity() * lambda + ktt * mu), &ktn);
    if mu <= T::zero() {
        return Some((ktn / size, size));
    }
    if s_of(T::zero()).norm() <= T::one() {
        return None;
    }
    // Safeguarded Newton on φ(λ) = 1/|s(λ)| - 1, increasing and nearly linear
    // (as in trust-region solvers); bisection whenever Newton leaves the bracket.
    let (mut lo, mut hi) = (T::zero(), size);
    let mut lambda = size * c(0.5);
    let two = c::<T>(2.0);
    for _ in 0..200 {
        let s = s_of(lambda);
        let norm = s.norm();
        let phi = T::one() / norm - T::one();
        if phi < T::zero() {
            lo = lambda;
        } else {
            hi = lambda;
        }
        if phi.abs() <= T::default_epsilon() * c(4.0)
            || hi - lo <= T::default_epsilon() * c(4.0) * hi
        {
            break;
        }
        // ds/dλ = -(λ𝟙 + μ K_tt)⁻¹ s,  φ' = -(s·s')/|s|³.
        let ds = -solve2(&(Matrix2::identity() * lambda + ktt * mu), &s);
        let dphi = -s.dot(&ds) / (norm * norm * norm);
        let newton = lambda - phi / dphi;
        lambda = if dphi > T::zero() && newton > lo && newton < hi {
            newton
        } else {
            (lo + hi) / two
        };
    }
    let s = s_of(lambda);
    let s = s / s.norm();
    let rate = slip_rate(k, mu, &s).dot(&s);
    Some((s, rate))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn k() -> Matrix3<f64> {
        Matrix3::new(2.0, 0.5, -0.3, 0.5, 1.5, 0.2, -0.3, 0.2, 1.0)
    }

    #[test]
    fn stick_ratio_keeps_the_tangential_velocity_at_zero() {
        let k = k();
        let tau = stick_ratio(&k);
        let du = k * with_unit_normal(&tau);
        assert!(du.y.abs() < 1e-15 && du.z.abs() < 1e-15, "{du}");
    }

    #[test]
    fn restart_direction_is_invariant_and_grows() {
        let k = k();
        let tau = stick_ratio(&k).norm();
        let mu = 0.5 * tau;
        let (s, lambda) = restart_direction(&k, mu).expect("|τ| > μ restarts");
        assert!((s.norm() - 1.0).abs() < 1e-15);
        assert!(lambda > 0.0, "{lambda}");
        let b = slip_rate(&k, mu, &s);
        assert!((b - s * lambda).norm() < 1e-14, "{b} vs {}", s * lambda);
        assert!(is_invariant(&k, mu, &s));
        // No restart when kinetic friction can hold the contact.
        assert!(restart_direction(&k, 1.01 * tau).is_none());
    }

    #[test]
    fn planar_restart_reverses_along_the_axis() {
        // K_tn along t0 and K_tt diagonal: the restart direction is ±t0.
        let k = Matrix3::new(2.5, -1.5, 0.0, -1.5, 2.5, 0.0, 0.0, 0.0, 4.0);
        let (s, lambda): (Vector2<f64>, f64) = restart_direction(&k, 0.5).unwrap();
        assert_eq!(s, Vector2::new(-1.0, 0.0));
        // λ = s·(K_tn - μ K_tt s) = 1.5 - 0.5·2.5 = 0.25.
        assert!((lambda - 0.25).abs() < 1e-15, "{lambda}");
    }
}
