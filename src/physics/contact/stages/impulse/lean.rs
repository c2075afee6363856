//! Twin of [`FactoredMatrix::new`] and of nalgebra's `cholesky()`, held bit
//! for bit by the test below (`the_lean_factor_is_news_factor_bit_for_bit`)
//! and `tests/physics/lean_prepare.rs`.
//!
//! [`FactoredMatrix::lean`]: the deepest-first prepare's factoring, the
//! same factor as [`FactoredMatrix::new`] with a cheaper bound of κ, and
//! nalgebra's 3×3 Cholesky written out ([`cholesky3`]).

use nalgebra::{Cholesky, Matrix3, U3};

use super::{Factor, FactoredMatrix};
use crate::physics::{c, Real};

/// `m.cholesky()` written out for 3×3: nalgebra's operations in its order
/// (column j: `a_ij ← (−a_jk)·a_ik + a_ij` for k < j, then `√a_jj`, None
/// for a zero, negative or NaN pivot, and the column below divided by it),
/// without its general loops (`tests`: the same factor bit for bit).
#[inline(always)]
fn cholesky3<T: Real>(m: &Matrix3<T>) -> Option<Cholesky<T, U3>> {
    let root = |v: T| if v.is_zero() { None } else { v.try_sqrt() };
    let mut a = *m;
    let l00 = root(a[(0, 0)])?;
    a[(0, 0)] = l00;
    a[(1, 0)] /= l00;
    a[(2, 0)] /= l00;
    let f = -a[(1, 0)];
    a[(1, 1)] = f * a[(1, 0)] + a[(1, 1)];
    a[(2, 1)] = f * a[(2, 0)] + a[(2, 1)];
    let l11 = root(a[(1, 1)])?;
    a[(1, 1)] = l11;
    a[(2, 1)] /= l11;
    let f = -a[(2, 0)];
    a[(2, 2)] = f * a[(2, 0)] + a[(2, 2)];
    let f = -a[(2, 1)];
    a[(2, 2)] = f * a[(2, 1)] + a[(2, 2)];
    a[(2, 2)] = root(a[(2, 2)])?;
    Some(Cholesky::pack_dirty(a))
}

impl<T: Real> FactoredMatrix<T> {
    /// Factors `m` for solving as [`FactoredMatrix::new`] does, the same
    /// factor, with `‖M‖_F ‖L⁻¹‖_F²` (`L` the Cholesky factor already at hand;
    /// `‖M⁻¹‖_F ≤ ‖L⁻¹‖_F²`, so at most 3√3 κ) standing in for κ instead of
    /// `M⁻¹`'s norm: where that bound shows κ·ε < 1e-3, `new` would factor by
    /// Cholesky too (its own bound or the exact κ then lets it); otherwise
    /// exactly `new`. The deepest-first prepare's per-frame path, which never
    /// reports κ (`tests` below: the same factor as `new`, bit for bit).
    #[inline]
    pub fn lean(m: Matrix3<T>) -> Self {
        if let Some(ch) = cholesky3(&m) {
            let l = ch.l_dirty();
            // L⁻¹ (lower triangular), from L L⁻¹ = 𝟙 row by row.
            let (x00, x11, x22) = (
                T::one() / l[(0, 0)],
                T::one() / l[(1, 1)],
                T::one() / l[(2, 2)],
            );
            let x10 = -(l[(1, 0)] * x00) * x11;
            let x21 = -(l[(2, 1)] * x11) * x22;
            let x20 = -(l[(2, 0)] * x00 + l[(2, 1)] * x10) * x22;
            let inverse_sq = x00 * x00 + x11 * x11 + x22 * x22 + x10 * x10 + x21 * x21 + x20 * x20;
            let b = m.norm() * inverse_sq;
            if b.is_finite() && b * T::default_epsilon() <= c(1e-3) {
                return FactoredMatrix {
                    matrix: m,
                    factor: Factor::Cholesky(ch),
                    condition_number: b,
                };
            }
        }
        Self::new(m)
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Cholesky, Matrix3, Vector3, U3};

    use super::super::tests::with_eigenvalues;
    use super::super::{Factor, FactoredMatrix};
    use super::cholesky3;

    /// The factor's kind and bits (Cholesky's L, or LU's solve of a fixed rhs).
    fn factor_bits(f: &FactoredMatrix<f64>) -> (u8, Vec<u64>) {
        match &f.factor {
            Factor::Cholesky(ch) => (0, ch.l().iter().map(|x| x.to_bits()).collect()),
            Factor::Lu(lu) => {
                let g = lu.solve(&Vector3::new(0.3, -1.2, 2.5));
                (1, g.iter().flatten().map(|x| x.to_bits()).collect())
            }
            Factor::Hopeless => (2, Vec::new()),
        }
    }

    #[test]
    fn the_lean_factor_is_news_factor_bit_for_bit() {
        let mut x: u64 = 0x2545_f491_4f6c_dd1d;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut kinds = [0usize; 3];
        let mut leaned = 0;
        for i in 0..20_000 {
            // Eigenvalues over 40 decades (some negative, some zero), and
            // now and then a non-symmetric or non-finite entry.
            let mut l = [0.0; 3];
            for v in &mut l {
                *v = 10f64.powf(next() * 40.0 - 30.0);
            }
            match i % 11 {
                0 => l[0] = -l[0],
                1 => l[1] = 0.0,
                _ => {}
            }
            let mut m = with_eigenvalues::<f64>(l, next() * 6.0);
            match i % 97 {
                3 => m[(0, 1)] += 0.5,
                5 => m[(2, 2)] = f64::NAN,
                7 => m[(1, 1)] = f64::INFINITY,
                _ => {}
            }
            // The written-out factor is nalgebra's, dirty upper part included.
            let (mine, theirs) = (cholesky3(&m), m.cholesky());
            assert_eq!(mine.is_some(), theirs.is_some(), "{m}");
            if let (Some(x), Some(y)) = (mine, theirs) {
                let bits = |c: &Cholesky<f64, U3>| c.l_dirty().map(f64::to_bits);
                assert_eq!(bits(&x), bits(&y), "{m}");
            }
            let (lean, new) = (FactoredMatrix::lean(m), FactoredMatrix::new(m));
            let (a, b) = (factor_bits(&lean), factor_bits(&new));
            assert_eq!(a, b, "factor of {m}");
            kinds[usize::from(a.0)] += 1;
            leaned +=
                usize::from(lean.condition_number.to_bits() != new.condition_number.to_bits());
            // Where both bounds stand in for a well-conditioned M (rounding
            // far below 1e-6): `‖M⁻¹‖_F ≤ ‖L⁻¹‖_F² ≤ 3‖M⁻¹‖₂`, so the lean
            // bound is new's at least and three times it at most.
            let (lb, nb) = (lean.condition_number, new.condition_number);
            if a.0 == 0 && m == m.transpose() && nb < 1e6 && lb < 1e6 {
                assert!(
                    lb >= nb * (1.0 - 1e-6) && lb <= 3.0 * nb * (1.0 + 1e-6),
                    "{m}"
                );
            }
        }
        // Zero, negative-zero and exactly vanishing pivots, non-finite entries.
        let (z, nz, inf, nan) = (0.0, -0.0, f64::INFINITY, f64::NAN);
        for m in [
            Matrix3::zeros(),
            Matrix3::new(nz, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
            Matrix3::new(1.0, 1.0, z, 1.0, 1.0, z, z, z, 1.0),
            Matrix3::new(4.0, nz, 2.0, nz, 9.0, nz, 2.0, nz, 5.0),
            Matrix3::new(inf, 1.0, 0.0, 1.0, 2.0, 0.0, 0.0, 0.0, 3.0),
            Matrix3::new(2.0, nan, 0.0, nan, 2.0, 0.0, 0.0, 0.0, 3.0),
            Matrix3::new(2.0, 1.0, -inf, 1.0, 2.0, 0.0, -inf, 0.0, 3.0),
        ] {
            let (mine, theirs) = (cholesky3(&m), m.cholesky());
            assert_eq!(mine.is_some(), theirs.is_some(), "{m}");
            if let (Some(x), Some(y)) = (mine, theirs) {
                assert_eq!(x.l_dirty().map(f64::to_bits), y.l_dirty().map(f64::to_bits));
            }
            let (a, b) = (FactoredMatrix::lean(m), FactoredMatrix::new(m));
            assert_eq!(factor_bits(&a), factor_bits(&b), "factor of {m}");
        }
        // Every kind was met (LU only near the boundary), and the lean bound stood in often.
        assert!(
            kinds[0] > 5_000 && kinds[1] > 20 && kinds[2] > 1_000,
            "{kinds:?}"
        );
        assert!(leaned > 2_000, "{leaned}");
    }
}
