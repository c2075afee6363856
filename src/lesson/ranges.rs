//! The numbers contact-lab accepts, and why: what the stages compute with
//! must stay finite and not underflow, whatever a valid lesson holds.
//!
//! Every non-zero input has a magnitude from 10⁻⁶⁰ to 10⁶⁰, and so does what
//! the stages take from the inputs: 1/m, and the inertia tensor and its
//! inverse (principal moments from 10⁻⁶⁰ to 10⁶⁰). Stages multiply at most
//! five such numbers together, so every intermediate lies between 10⁻³⁰⁰ and
//! 10³⁰⁰, inside f64's normal range (2.2·10⁻³⁰⁸ to 1.8·10³⁰⁸). Norms and
//! the regime decisions use `physics::scale`, so nothing depends on the
//! units within that range.

use nalgebra::{Matrix3, Vector3};

use crate::format::exact;
use crate::physics::scale::{stable_inverse, stable_norm_matrix};

/// The largest magnitude an input may have.
pub const MAX_MAGNITUDE: f64 = 1e60;
/// The smallest non-zero magnitude an input may have (0 itself is fine).
pub const MIN_MAGNITUDE: f64 = 1e-60;
/// Above this condition number an inertia tensor's inverse keeps no
/// correct digit in f64 (κ·ε ≈ 0.2).
pub const MAX_CONDITION: f64 = 1e15;

/// Zero, or finite with a magnitude from [`MIN_MAGNITUDE`] to [`MAX_MAGNITUDE`].
pub fn in_range(x: f64) -> bool {
    x == 0.0 || (MIN_MAGNITUDE..=MAX_MAGNITUDE).contains(&x.abs())
}

/// Why `x` is out of range (`None` when it is in range).
pub fn problem(x: f64) -> Option<String> {
    if in_range(x) {
        None
    } else if !x.is_finite() {
        Some(format!("must be a finite number, got {x}"))
    } else if x.abs() > MAX_MAGNITUDE {
        Some(format!(
            "{x:e} is outside contact-lab's range of ±1e60 (larger inputs could overflow a stage)"
        ))
    } else {
        Some(too_small(x))
    }
}

/// The refusal of a non-zero magnitude below [`MIN_MAGNITUDE`].
pub fn too_small(x: f64) -> String {
    format!(
        "{} is below contact-lab's smallest non-zero magnitude, 1e-60 (smaller inputs could underflow a stage); write 0 if zero is meant",
        exact(x)
    )
}

/// The refusal of a magnitude below [`MIN_MAGNITUDE`] for a value that
/// must be positive (a share, a duration, a damping): 0 is no way out.
pub fn too_small_positive(x: f64) -> String {
    format!(
        "{} is below contact-lab's smallest magnitude, 1e-60 (smaller inputs could underflow a stage)",
        exact(x)
    )
}

/// A unit vector's components below [`MIN_MAGNITUDE`] set to 0: they are far
/// below f64's resolution of a direction (about 1e-16), so the direction is
/// the same, and every product of the stages stays in the normal range.
pub fn flush_tiny(v: Vector3<f64>) -> Vector3<f64> {
    v.map(|x| if x.abs() < MIN_MAGNITUDE { 0.0 } else { x })
}

/// Principal moments (eigenvalues) of a symmetric tensor, ascending,
/// computed on the tensor scaled to a largest entry of 1.
pub fn principal_moments(t: &Matrix3<f64>) -> [f64; 3] {
    let largest = t.amax();
    if largest == 0.0 || !largest.is_finite() {
        return [0.0; 3];
    }
    let s = crate::physics::scale::pow2_below(largest);
    let e = (t / s).symmetric_eigenvalues() * s;
    let mut e = [e[0], e[1], e[2]];
    e.sort_by(f64::total_cmp);
    e
}

/// Checks a symmetric positive-definite body-frame inertia tensor for what
/// the stages compute with: its principal moments and so its inverse within
/// range, an inverse with correct digits, an inverse f64 finds. `tensor` is
/// the tensor as text, for the message.
pub fn inertia(t: &Matrix3<f64>) -> Result<(), String> {
    let [lo, _, hi] = principal_moments(t);
    let shown = crate::format::Fmt::new(3);
    if hi > MAX_MAGNITUDE {
        return Err(format!(
            "its largest principal moment is {}, above contact-lab's 1e60 (it multiplies the angular velocity in the energy and momentum)",
            shown.num(hi)
        ));
    }
    if lo < MIN_MAGNITUDE {
        return Err(format!(
            "its smallest principal moment is {}, below contact-lab's 1e-60: its inverse I⁻¹ would reach {}, which the stages multiply with lengths and impulses",
            shown.num(lo),
            shown.num(1.0 / lo)
        ));
    }
    let condition = hi / lo;
    if condition > MAX_CONDITION {
        return Err(format!(
            "its condition number (largest / smallest principal moment) is {}: above 1e15 its inverse keeps no correct digit in 64-bit floats",
            shown.num(condition)
        ));
    }
    match stable_inverse(t) {
        Some(i) if stable_norm_matrix(&(t * i - Matrix3::identity())) <= 0.5 => Ok(()),
        _ => Err("it cannot be inverted in 64-bit floats".into()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn diag(a: f64, b: f64, c: f64) -> Matrix3<f64> {
        Matrix3::from_diagonal(&Vector3::new(a, b, c))
    }

    #[test]
    fn range_is_symmetric_about_one() {
        for x in [0.0, 1e-60, -1e-60, 1.0, 1e60, -1e60] {
            assert!(in_range(x), "{x:e}");
        }
        for x in [1e-61, -1e-170, 1e61, f64::NAN, f64::INFINITY, 5e-324] {
            assert!(!in_range(x), "{x:e}");
        }
        assert!(problem(1e-170).unwrap().starts_with("1e-170 is below"));
        assert!(problem(-1e200).unwrap().starts_with("-1e200 is outside"));
    }

    #[test]
    fn tensors_the_stages_cannot_use_are_refused_with_the_reason() {
        assert!(inertia(&diag(240.0, 240.0, 240.0)).is_ok());
        assert!(inertia(&diag(1e-55, 1e-55, 1e-55)).is_ok());
        assert!(
            inertia(&diag(1e6, 1e6, 1e-6)).is_ok(),
            "κ = 1e12 is accepted"
        );
        // Entries in range, inverse enormous: the NaN of issue 17.
        let e = inertia(&diag(1.0, 1.0, 1e-300)).unwrap_err();
        assert!(e.contains("smallest principal moment is 1e-300"), "{e}");
        let e = inertia(&diag(1.0, 1.0, 1e-20)).unwrap_err();
        assert!(e.contains("condition number"), "{e}");
        let e = inertia(&diag(4e179, 4e179, 4e179)).unwrap_err();
        assert!(e.contains("largest principal moment is 4e179"), "{e}");
        // A full tensor with a tiny eigenvalue hidden in entries of size 1.
        let near = Matrix3::new(1.0, 1.0, 0.0, 1.0, 1.0 + 1e-15, 0.0, 0.0, 0.0, 1.0);
        let e = inertia(&near).unwrap_err();
        assert!(e.contains("condition number"), "{e}");
    }

    #[test]
    fn principal_moments_do_not_depend_on_the_units() {
        let t = Matrix3::new(5.0, 1.0, 0.5, 1.0, 4.0, 0.25, 0.5, 0.25, 3.0);
        let base = principal_moments(&t);
        for k in [-55, -20, 20, 55] {
            let s = 10f64.powi(k);
            let m = principal_moments(&(t * s));
            for i in 0..3 {
                assert!((m[i] / (base[i] * s) - 1.0).abs() < 1e-13, "10^{k}");
            }
        }
    }
}
