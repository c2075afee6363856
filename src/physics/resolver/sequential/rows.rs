//! Solver-body arrays for sequential impulses: what a velocity visit reads,
//! computed once at prepare and laid out contiguously, so a visit is
//! straight-line arithmetic (no 3×3 matrices rebuilt, no optional bodies).
//!
//! Per contact, the world Jacobian rows of its three axes (columns of the
//! basis `C = [d t₀ t₁]`): linear part `±C`, angular part `A_i = s_i [r_i × d,
//! r_i × t₀, r_i × t₁]` (s = +1 for body 1, -1 for body 2), and `M⁻¹Jᵀ`:
//! `s_i m_i⁻¹` and `T_i = I_i⁻¹ A_i`. Then
//!
//! - contact velocity `v = Cᵀ(v₁ - v₂) + A₁ᵀω₁ + A₂ᵀω₂ + offset`;
//! - impulse `g` (contact space): `P = C g`, `v_i += s_i m_i⁻¹ P`, `ω_i += T_i g`.
//!
//! An empty slot (the world, an immovable body) points at the last solver
//! body, which has zero velocity and receives `0·g`: it never moves.

use nalgebra::{Matrix3, Vector3};

use super::super::{ContactSetup, FrictionData, ResolverBody, ResolverContact};
use crate::physics::stages::desired_velocity::applied_restitution;
use crate::physics::Real;

/// A body's velocities as the velocity phase changes them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverBody<T: Real> {
    pub v: Vector3<T>,
    pub w: Vector3<T>,
}

/// One contact's Jacobian rows and constants for a velocity visit.
#[derive(Debug, Clone, PartialEq)]
pub struct Rows<T: Real> {
    /// Solver body of each slot (the world's entry for an empty slot).
    pub bodies: [usize; 2],
    /// `C`, columns d, t₀, t₁ (body 1's linear rows; body 2's are `-C`).
    pub basis: Matrix3<T>,
    /// `A_i = s_i [r_i × d, r_i × t₀, r_i × t₁]` (zero for an empty slot).
    pub angular: [Matrix3<T>; 2],
    /// `s_i m_i⁻¹` (zero for an empty slot).
    pub inverse_mass: [T; 2],
    /// `T_i = I_i⁻¹ A_i`: each slot's Δω per unit contact-space impulse.
    pub turn: [Matrix3<T>; 2],
    /// `M⁻¹` with friction; frictionless (or `M` not invertible) only its
    /// (0,0) entry, `1/Δq̇_t`, so the step is along the normal.
    pub inverse: Matrix3<T>,
    /// Row 0 of `M` (the rim of a sliding contact reads it).
    pub normal_row: Vector3<T>,
    /// The part of the prepared contact velocity the bodies do not give.
    pub offset: Vector3<T>,
    /// `e (v₀ - v_acc)`: the target normal velocity is `-` this.
    pub bounce: T,
    /// The cone radius this step (`μ_s` sticking, `μ_d` sliding; 0 without friction).
    pub mu: T,
    pub friction: bool,
    /// Slides when the step begins (its clamped iterates go on the rim).
    pub sliding: bool,
    /// `Δq̇_t`.
    pub unit_total: T,
}

impl<T: Real> Rows<T> {
    /// Rows of nothing (both slots the world's entry 0, every number zero).
    pub fn empty() -> Self {
        Rows {
            bodies: [0; 2],
            basis: Matrix3::zeros(),
            angular: [Matrix3::zeros(); 2],
            inverse_mass: [T::zero(); 2],
            turn: [Matrix3::zeros(); 2],
            inverse: Matrix3::zeros(),
            normal_row: Vector3::zeros(),
            offset: Vector3::zeros(),
            bounce: T::zero(),
            mu: T::zero(),
            friction: false,
            sliding: false,
            unit_total: T::zero(),
        }
    }

    /// Sets every field in place for a contact with basis `basis` and no
    /// bodies yet (`world`: the world's solver body).
    #[inline(always)]
    pub fn reset(&mut self, world: usize, basis: Matrix3<T>) {
        self.bodies = [world; 2];
        self.basis = basis;
        self.angular = [Matrix3::zeros(); 2];
        self.inverse_mass = [T::zero(); 2];
        self.turn = [Matrix3::zeros(); 2];
        self.inverse = Matrix3::zeros();
        self.normal_row = Vector3::zeros();
        self.offset = Vector3::zeros();
        self.bounce = T::zero();
        self.mu = T::zero();
        self.friction = false;
        self.sliding = false;
        self.unit_total = T::zero();
    }

    /// The contact velocity the solver bodies give now, contact space.
    #[inline(always)]
    pub fn velocity(&self, bodies: &[SolverBody<T>]) -> Vector3<T> {
        let (b1, b2) = (&bodies[self.bodies[0]], &bodies[self.bodies[1]]);
        self.basis.tr_mul(&(b1.v - b2.v))
            + self.angular[0].tr_mul(&b1.w)
            + self.angular[1].tr_mul(&b2.w)
            + self.offset
    }

    /// [`Self::velocity`]'s normal component alone, the same bits: each
    /// component of `Aᵀx` is a column's dot product with `x`, and the four
    /// terms are added in the same order.
    #[inline(always)]
    pub fn normal_velocity(&self, bodies: &[SolverBody<T>]) -> T {
        let (b1, b2) = (&bodies[self.bodies[0]], &bodies[self.bodies[1]]);
        self.basis.column(0).dot(&(b1.v - b2.v))
            + self.angular[0].column(0).dot(&b1.w)
            + self.angular[1].column(0).dot(&b2.w)
            + self.offset.x
    }

    /// Applies the contact-space impulse `g`; returns the world impulse `C g`.
    #[inline(always)]
    pub fn apply(&self, bodies: &mut [SolverBody<T>], g: &Vector3<T>) -> Vector3<T> {
        let p = self.basis * g;
        for i in 0..2 {
            let b = &mut bodies[self.bodies[i]];
            b.v += p * self.inverse_mass[i];
            b.w += self.turn[i] * g;
        }
        p
    }
}

/// `[r × d, r × t₀, r × t₁]`, each column `r ×` the basis column.
fn arm_rows<T: Real>(r: &Vector3<T>, basis: &Matrix3<T>) -> Matrix3<T> {
    Matrix3::from_columns(&[
        r.cross(&basis.column(0).into_owned()),
        r.cross(&basis.column(1).into_owned()),
        r.cross(&basis.column(2).into_owned()),
    ])
}

/// `M⁻¹` of a symmetric 3×3 `M` (its lower triangle read) by cofactors,
/// `None` unless `M` is positive definite (Sylvester: `M₀₀`, the leading
/// 2×2 minor and `det M` positive), as a Cholesky factor would fail.
pub fn symmetric_inverse<T: Real>(m: &Matrix3<T>) -> Option<Matrix3<T>> {
    let (a, b, c) = (m[(0, 0)], m[(1, 0)], m[(2, 0)]);
    let (d, e, f) = (m[(1, 1)], m[(2, 1)], m[(2, 2)]);
    // Cofactors of [[a b c] [b d e] [c e f]].
    let c00 = d * f - e * e;
    let c01 = c * e - b * f;
    let c02 = b * e - c * d;
    let c11 = a * f - c * c;
    let c12 = b * c - a * e;
    let c22 = a * d - b * b;
    let det = a * c00 + b * c01 + c * c02;
    let definite = a > T::zero() && c22 > T::zero() && det > T::zero();
    definite.then(|| {
        let s = T::one() / det;
        let (c00, c01, c02, c11, c12, c22) = (c00 * s, c01 * s, c02 * s, c11 * s, c12 * s, c22 * s);
        Matrix3::new(c00, c01, c02, c01, c11, c12, c02, c12, c22)
    })
}

/// The solver bodies for `bodies` (and the world's entry, last).
pub fn solver_bodies<T: Real>(bodies: &[ResolverBody<T>], out: &mut Vec<SolverBody<T>>) {
    out.clear();
    out.extend(bodies.iter().map(|b| SolverBody {
        v: b.velocity,
        w: b.angular_velocity,
    }));
    out.push(SolverBody {
        v: Vector3::zeros(),
        w: Vector3::zeros(),
    });
}

/// Builds the rows of every prepared contact into `out` (`slip_speed`: the
/// stick/slip threshold), each offset from the solver bodies `solver`; each
/// friction matrix `M` (left zero by a sequential prepare) from the rows.
pub fn build<T: Real>(
    contacts: &[ResolverContact<T>],
    setups: &[ContactSetup<T>],
    bodies: &[ResolverBody<T>],
    friction: &mut [FrictionData<T>],
    solver: &[SolverBody<T>],
    slip_speed: T,
    out: &mut Vec<Rows<T>>,
) {
    let world = bodies.len();
    out.clear();
    out.extend(contacts.iter().zip(setups).map(|(k, setup)| {
        let mut rows = Rows {
            bodies: [world; 2],
            basis: k.basis,
            unit_total: setup.unit_total,
            ..Rows::empty()
        };
        for (i, slot) in k.bodies.iter().enumerate() {
            let Some(b) = *slot else { continue };
            let body = &bodies[b];
            let arm = arm_rows(&k.r[i], &k.basis);
            let signed = if i == 0 { arm } else { -arm };
            rows.bodies[i] = b;
            rows.inverse_mass[i] = if i == 0 {
                body.inverse_mass
            } else {
                -body.inverse_mass
            };
            rows.turn[i] = body.inverse_inertia_world * signed;
            rows.angular[i] = signed;
        }
        rows.inverse[(0, 0)] = T::one() / setup.unit_total;
        if let Some(f) = setup.friction {
            // M = Σ A_iᵀ T_i + Σ m_i⁻¹ 𝟙 (= Cᵀ(Σ -[r_i]× I_i⁻¹ [r_i]×)C + Σ m_i⁻¹ 𝟙).
            let linear = rows.inverse_mass[0] - rows.inverse_mass[1];
            let m = rows.angular[0].tr_mul(&rows.turn[0])
                + rows.angular[1].tr_mul(&rows.turn[1])
                + Matrix3::from_diagonal_element(linear);
            let data = &mut friction[f];
            // Kept for the reports; not factored (the rows hold M⁻¹).
            data.matrix.matrix = m;
            rows.friction = true;
            rows.sliding = setup.slip > slip_speed;
            rows.mu = if rows.sliding {
                data.dynamic_friction
            } else {
                data.static_friction
            };
            rows.normal_row = data.matrix.matrix.row(0).transpose();
            if let Some(m_inv) = symmetric_inverse(&m) {
                rows.inverse = m_inv;
            }
        }
        let (e, _) = applied_restitution(k.initial_velocity, k.restitution, k.velocity_limit);
        rows.bounce = e * (k.initial_velocity - k.velocity_from_acceleration);
        rows.offset = k.velocity - rows.velocity(solver);
        rows
    }));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_symmetric_inverse_inverts_and_refuses_what_cholesky_refuses() {
        let m: Matrix3<f64> = Matrix3::new(2.0, 0.5, 0.1, 0.5, 3.0, 0.2, 0.1, 0.2, 2.5);
        let inv = symmetric_inverse(&m).unwrap();
        assert!((m * inv - Matrix3::identity()).norm() < 1e-15, "{inv}");
        assert!((inv - m.cholesky().unwrap().inverse()).norm() < 1e-15);
        // Indefinite (a negative eigenvalue) and singular: no inverse.
        let indefinite = Matrix3::new(1.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 1.0);
        assert_eq!(symmetric_inverse(&indefinite), None);
        assert!(indefinite.cholesky().is_none());
        assert_eq!(symmetric_inverse(&Matrix3::<f64>::zeros()), None);
    }

    #[test]
    fn the_normal_velocity_is_the_whole_velocitys_first_component_bit_for_bit() {
        // Random rows and bodies over many magnitudes and both signs, a
        // world slot, zero and negative-zero entries.
        let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let bits = x;
            let m = 1.0 + (bits >> 12) as f64 / (1u64 << 52) as f64;
            let e = (bits % 41) as i32 - 20;
            match bits % 7 {
                0 => 0.0,
                1 => -0.0,
                _ if bits & 8 == 0 => -m * 2f64.powi(e),
                _ => m * 2f64.powi(e),
            }
        };
        for _ in 0..20_000 {
            let mut rows = Rows::empty();
            rows.bodies = [0, if next() > 0.0 { 1 } else { 2 }];
            rows.basis = Matrix3::from_fn(|_, _| next());
            rows.angular = [
                Matrix3::from_fn(|_, _| next()),
                Matrix3::from_fn(|_, _| next()),
            ];
            rows.offset = Vector3::from_fn(|_, _| next());
            let mut body = || SolverBody {
                v: Vector3::from_fn(|_, _| next()),
                w: Vector3::from_fn(|_, _| next()),
            };
            let bodies = [body(), body(), body()];
            let whole = rows.velocity(&bodies).x;
            assert_eq!(rows.normal_velocity(&bodies).to_bits(), whole.to_bits());
        }
    }
}
