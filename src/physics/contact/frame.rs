//! Contact basis (Millington's `makeOrthonormalBasis`) and relative positions.

use nalgebra::{Matrix3, Vector3};

use super::Real;

/// Which world axis seeded the tangents.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GuessAxis {
    X,
    Y,
}

/// Orthonormal right-handed basis with the contact normal as first column:
/// guess world y, or world x when |d.x| ≤ |d.y|; `t0 = guess × d / |guess × d|`,
/// `t1 = d × t0`. The reference code's `t1.x = d.y·t0.x` typo is not copied.
#[inline]
pub fn contact_basis<T: Real>(d: &Vector3<T>) -> (Matrix3<T>, GuessAxis) {
    let guess = if d.x.abs() > d.y.abs() {
        GuessAxis::Y
    } else {
        GuessAxis::X
    };
    let axis = match guess {
        GuessAxis::Y => Vector3::y(),
        GuessAxis::X => Vector3::x(),
    };
    let t0 = axis.cross(d).normalize();
    let t1 = d.cross(&t0);
    (Matrix3::from_columns(&[*d, t0, t1]), guess)
}

/// Skew-symmetric matrix `[v]×` with `[v]× w = v × w`.
pub fn skew<T: Real>(v: &Vector3<T>) -> Matrix3<T> {
    v.cross_matrix()
}

/// Significant digits `r = q - p` keeps when q and p are stored in `T`: each
/// coordinate is held to about ε·|x|, so r is known to ±ε·max(|q|, |p|)
/// (componentwise max). Capped at the type's own digits.
pub fn difference_digits<T: Real>(r: &Vector3<T>, q: &Vector3<T>, p: &Vector3<T>) -> T {
    let eps = T::default_epsilon();
    let full = -eps.log10();
    let size = q.amax().max(p.amax());
    let length = crate::physics::scale::stable_norm(r);
    if length == T::zero() || size == T::zero() {
        return full;
    }
    (length / (eps * size)).log10().min(full)
}
