//! Scale-invariant norms, inverses and comparisons.
//!
//! `√(x² + y² + z²)` squares first: below about 1e-154 the squares underflow
//! to 0 and above about 1e154 they overflow to inf, so a regime or a check
//! decided on such a norm changes with the units. These helpers divide by
//! the power of two at or just below the largest magnitude first, so
//! `stable_norm(s·v) = s·stable_norm(v)` to round-off over f64's whole
//! range, as BLAS `nrm2` and `hypot` do. Scaling by a power of two is exact,
//! so where the plain formula neither underflows nor overflows the result
//! is bit for bit the plain one.

use nalgebra::{Matrix3, Quaternion, Vector3};

use super::{c, to_f64, Real};

/// The power of two at or just below `x > 0` (`x` itself where that power
/// is not representable in `T`).
pub fn pow2_below<T: Real>(x: T) -> T {
    let wide = to_f64(x);
    let power = if wide >= f64::MIN_POSITIVE && wide.is_finite() {
        // A normal number's exponent bits alone (mantissa cleared) are that power.
        f64::from_bits(wide.to_bits() & 0x7ff0_0000_0000_0000)
    } else {
        2f64.powi(wide.log2().floor().clamp(-1022.0, 1023.0) as i32)
    };
    let s: T = c(power);
    if s > T::zero() && s.is_finite() {
        s
    } else {
        x
    }
}

/// `√(Σ xᵢ²)` without underflow or overflow in the squares.
pub fn stable_norm_of<T: Real>(xs: &[T]) -> T {
    let largest = xs.iter().fold(T::zero(), |m, x| m.max(x.abs()));
    if largest == T::zero() || !largest.is_finite() {
        return largest;
    }
    let s = pow2_below(largest);
    let sum = xs
        .iter()
        .fold(T::zero(), |acc, x| acc + (*x / s) * (*x / s));
    s * sum.sqrt()
}

/// |v| for a 3-vector.
pub fn stable_norm<T: Real>(v: &Vector3<T>) -> T {
    stable_norm_of(&[v.x, v.y, v.z])
}

/// √(a² + b²), e.g. the planar part of a contact-space vector.
pub fn stable_hypot<T: Real>(a: T, b: T) -> T {
    stable_norm_of(&[a, b])
}

/// |q| for a quaternion (summed in nalgebra's storage order i, j, k, w, so
/// that it is bit for bit `q.norm()` in the normal range).
pub fn stable_norm_quaternion<T: Real>(q: &Quaternion<T>) -> T {
    stable_norm_of(&[q.i, q.j, q.k, q.w])
}

/// The Frobenius norm of a 3×3 matrix.
pub fn stable_norm_matrix<T: Real>(m: &Matrix3<T>) -> T {
    stable_norm_of(m.as_slice())
}

/// `v / |v|`, or `None` for the zero vector (or a non-finite one).
pub fn stable_normalize<T: Real>(v: &Vector3<T>) -> Option<Vector3<T>> {
    let n = stable_norm(v);
    (n > T::zero() && n.is_finite()).then(|| v / n)
}

/// The inverse of `m`, computed on `m / s` with `s` its largest magnitude and
/// scaled back: the determinant of `m` itself may overflow (entries ~1e120)
/// or underflow (entries ~1e-120) while the inverse is representable, and a
/// determinant of inf or 0 must not make an invertible matrix look singular
/// (nalgebra's `try_inverse` would give a zero matrix for the first).
pub fn stable_inverse<T: Real>(m: &Matrix3<T>) -> Option<Matrix3<T>> {
    let largest = m.amax();
    if largest == T::zero() || !largest.is_finite() {
        return None;
    }
    let s = pow2_below(largest);
    let inverse = (m / s).try_inverse()? / s;
    inverse.iter().all(|x| x.is_finite()).then_some(inverse)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn norms_scale_over_the_whole_range() {
        let v = Vector3::new(3.0, -4.0, 12.0);
        assert_eq!(stable_norm(&v), 13.0);
        for k in [-300, -200, -170, -100, 0, 100, 200, 290] {
            let s = 10f64.powi(k);
            let n = stable_norm(&(v * s));
            assert!((n / (13.0 * s) - 1.0).abs() < 1e-15, "10^{k}: {n:e}");
        }
        // The naive norm is 0 here: the squares underflow.
        assert_eq!((v * 1e-170).norm(), 0.0);
        assert!((stable_hypot(3e-170f64, 4e-170) / 5e-170 - 1.0).abs() < 1e-15);
        assert_eq!(stable_norm(&Vector3::<f64>::zeros()), 0.0);
        assert!(stable_norm(&Vector3::new(f64::INFINITY, 0.0, 0.0)).is_infinite());
        let q = Quaternion::new(1e-170, 0.0, 0.0, 0.0);
        assert_eq!(stable_norm_quaternion(&q), 1e-170);
        let n = stable_normalize(&Vector3::new(0.0, 1e-170, 0.0)).unwrap();
        assert_eq!(n, Vector3::y());
        assert!(stable_normalize(&Vector3::<f64>::zeros()).is_none());
    }

    #[test]
    fn in_the_normal_range_the_result_is_the_plain_one_bit_for_bit() {
        let v = Vector3::new(0.1, -2.165, 1.25);
        assert_eq!(stable_norm(&v), v.norm());
        let q = Quaternion::new(0.9659258262890683, 0.01, -0.3, -0.25881904510252074);
        assert_eq!(stable_norm_quaternion(&q), q.norm());
        let m = Matrix3::new(5.0, 1.0, 0.5, 1.0, 4.0, 0.25, 0.5, 0.25, 3.0) * 0.37;
        assert_eq!(stable_inverse(&m).unwrap(), m.try_inverse().unwrap());
        assert_eq!(pow2_below(3.0f64), 2.0);
        assert_eq!(pow2_below(0.3f64), 0.25);
        assert_eq!(pow2_below(4.0f64), 4.0, "a power of two is its own");
        assert_eq!(pow2_below(1.0f64 - f64::EPSILON / 2.0), 0.5, "just below 1");
        assert_eq!(pow2_below(1e300f64), 2f64.powi(996));
        assert_eq!(pow2_below(3.0f32), 2.0);
        assert_eq!(
            pow2_below(1e-320f64),
            2f64.powi(-1022),
            "clamped at the normal range"
        );
    }

    #[test]
    fn an_inverse_whose_determinant_overflows_is_found() {
        let big = Matrix3::from_diagonal(&Vector3::new(1e120f64, 2e120, 4e120));
        assert!(big.determinant().is_infinite());
        let inv = stable_inverse(&big).expect("invertible");
        assert!((inv[(0, 0)] * 1e120 - 1.0).abs() < 1e-15);
        assert!((inv[(2, 2)] * 4e120 - 1.0).abs() < 1e-15);
        let small = Matrix3::from_diagonal(&Vector3::new(1e-120f64, 1e-120, 1e-120));
        assert_eq!(small.determinant(), 0.0);
        let inv = stable_inverse(&small).expect("invertible");
        assert!((inv[(1, 1)] * 1e-120 - 1.0).abs() < 1e-15);
        assert!(stable_inverse(&Matrix3::<f64>::zeros()).is_none());
        let singular = Matrix3::new(1.0, 2.0, 3.0, 2.0, 4.0, 6.0, 0.0, 0.0, 1.0);
        assert!(stable_inverse(&singular).is_none());
    }
}
