//! Stage 4: the impulse, before any friction clamp.
//!
//! Frictionless: `g = Δv / Δq̇_t` along the normal (lecture: "Calculating the
//! Impulse"). With friction (Millington and velocity-scaling models) the
//! sticking impulse `g = M⁻¹ (Δv, -v_y, -v_z)` that removes all sliding. The
//! companion lectures' closed form `j` is computed independently as a check.

use nalgebra::{Cholesky, Matrix3, Vector3, LU, U3};

mod lean;

use super::{ContactFrame, DesiredVelocity, UnitImpulse};
use crate::physics::contact::problem::InverseInertias;
use crate::physics::{c, FrictionModel, Problem, Real};

/// How the 3×3 system `M g = rhs` was solved, and how well.
#[derive(Debug, Clone, PartialEq)]
pub struct MatrixSolve<T: Real> {
    pub rhs: Vector3<T>,
    /// The factor's κ(M): the upper bound `‖M‖_F ‖M⁻¹‖_F` (at most 3κ) where
    /// it already shows κ·ε < 1e-3, else the exact λ_max / λ_min. The
    /// exact κ that the trace and the causes show is [`condition_number`]
    /// of M, computed where it is shown (the stage path skips the eigenvalues).
    pub condition_number: T,
    /// True when κ·ε exceeds 1e-3: fewer than three digits of g can be trusted.
    pub ill_conditioned: bool,
    /// True when Cholesky failed (M not numerically positive-definite) and LU was used.
    pub used_lu: bool,
    /// True when no factorisation succeeded, or κ·ε ≥ 1 (no digit of g would
    /// be right): the frictionless impulse was used instead.
    pub singular: bool,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Impulse<T: Real> {
    pub impulse_contact: Vector3<T>,
    pub impulse_world: Vector3<T>,
    /// Present when the impulse came from the 3×3 friction matrix.
    pub solve: Option<MatrixSolve<T>>,
    /// Companion lectures' `j = -(1+e)(v_rel·n) / (Σ 1/m + Σ (r×n)ᵀ I⁻¹ (r×n))`.
    pub closed_form_j: T,
    /// `|g_x - j| / max(|j|, tiny)` (frictionless) — how well the two routes agree.
    pub closed_form_relative_difference: T,
}

/// Solves `M g = rhs` for symmetric positive-definite `M`, reporting conditioning.
pub fn solve_matrix<T: Real>(
    m: &Matrix3<T>,
    rhs: Vector3<T>,
) -> (Option<Vector3<T>>, MatrixSolve<T>) {
    FactoredMatrix::with_condition(*m).solve(rhs)
}

/// `M` factored once for any number of right-hand sides. The resolver
/// solves the same contact's `M` at every visit, so it factors it when it
/// prepares the contact ([`FactoredMatrix::new`]); a single contact's stage
/// factors it with the exact condition number it shows
/// ([`FactoredMatrix::with_condition`]). Both give the same `g` bit for bit.
#[derive(Debug, Clone)]
pub struct FactoredMatrix<T: Real> {
    pub matrix: Matrix3<T>,
    factor: Factor<T>,
    /// κ(M) = λ_max / λ_min, or with [`FactoredMatrix::new`] an upper bound
    /// of it (see there) when the bound already shows κ·ε < 1e-3.
    condition_number: T,
}

#[derive(Debug, Clone)]
enum Factor<T: Real> {
    Cholesky(Cholesky<T, U3>),
    /// M is not numerically positive-definite.
    Lu(LU<T, U3, U3>),
    /// κ·ε ≥ 1: no digit of g would be right.
    Hopeless,
}

/// The factor is a function of the matrix: equal matrices, equal factors.
impl<T: Real> PartialEq for FactoredMatrix<T> {
    fn eq(&self, other: &Self) -> bool {
        self.matrix == other.matrix
    }
}

/// κ(M) = λ_max / λ_min of a symmetric `M` (its symmetric eigenvalues; the
/// largest float when λ_min ≤ 0).
pub fn condition_number<T: Real>(m: &Matrix3<T>) -> T {
    let eig = m.symmetric_eigenvalues();
    let (lo, hi) = (eig.min(), eig.max());
    if lo > T::zero() {
        hi / lo
    } else {
        T::max_value().unwrap_or(hi)
    }
}

impl<T: Real> FactoredMatrix<T> {
    /// Factors `m` with its exact condition number (symmetric eigenvalues).
    pub fn with_condition(m: Matrix3<T>) -> Self {
        Self::factor(m, condition_number(&m))
    }

    /// Factors `m` for solving only: when `‖M‖_F ‖M⁻¹‖_F` (at most 3κ for a
    /// 3×3 matrix) already shows κ·ε < 1e-3, that bound stands in for κ and
    /// no eigenvalue is computed; otherwise as [`FactoredMatrix::with_condition`].
    /// Either way the same factorisation is chosen, so g is the same.
    /// Inlined: the stage path then builds it in place (no copy into its `Option`).
    #[inline]
    pub fn new(m: Matrix3<T>) -> Self {
        // Only a positive-definite M (Cholesky succeeds) may skip the eigenvalues:
        // an indefinite M is hopeless however small the bound.
        let cholesky = m.cholesky();
        let bound = m
            .try_inverse()
            .map(|inverse| m.norm() * inverse.norm())
            .filter(|b| b.is_finite() && *b * T::default_epsilon() <= c(1e-3));
        match (cholesky, bound) {
            (Some(ch), Some(b)) => FactoredMatrix {
                matrix: m,
                factor: Factor::Cholesky(ch),
                condition_number: b,
            },
            _ => Self::with_condition(m),
        }
    }

    /// Factors `m` for `M⁻¹` only (sequential impulses invert M once and
    /// never solve with it): the Cholesky factor where M is numerically
    /// positive-definite, no condition number (NaN, not to be reported).
    /// [`FactoredMatrix::cholesky_inverse`] gives the same `M⁻¹` bit for bit
    /// as from [`FactoredMatrix::new`].
    pub fn for_inverse(m: Matrix3<T>) -> Self {
        FactoredMatrix {
            matrix: m,
            factor: match m.cholesky() {
                Some(ch) => Factor::Cholesky(ch),
                None => Factor::Hopeless,
            },
            condition_number: c(f64::NAN),
        }
    }

    fn factor(m: Matrix3<T>, condition_number: T) -> Self {
        // κ ε ≥ 1 (or M numerically indefinite): no digit of g would be right,
        // and an LU solve of such an M can return anything up to inf.
        let factor = if condition_number * T::default_epsilon() >= T::one() {
            Factor::Hopeless
        } else {
            match m.cholesky() {
                Some(ch) => Factor::Cholesky(ch),
                None => Factor::Lu(m.lu()),
            }
        };
        FactoredMatrix {
            matrix: m,
            factor,
            condition_number,
        }
    }

    /// `M⁻¹` from the Cholesky factor (None when M is not numerically
    /// positive-definite), the factor already held where there is one.
    pub fn cholesky_inverse(&self) -> Option<Matrix3<T>> {
        match &self.factor {
            Factor::Cholesky(ch) => Some(ch.inverse()),
            _ => self.matrix.cholesky().map(|ch| ch.inverse()),
        }
    }

    /// `g = M⁻¹ rhs` (None when M cannot be solved or g is not finite).
    #[inline]
    pub fn solve(&self, rhs: Vector3<T>) -> (Option<Vector3<T>>, MatrixSolve<T>) {
        let solution = match &self.factor {
            Factor::Hopeless => None,
            Factor::Cholesky(ch) => Some(ch.solve(&rhs)),
            Factor::Lu(lu) => lu.solve(&rhs),
        }
        .filter(|g| g.iter().all(|x| x.is_finite()));
        (
            solution,
            MatrixSolve {
                rhs,
                condition_number: self.condition_number,
                ill_conditioned: self.condition_number * T::default_epsilon() > c(1e-3),
                used_lu: matches!(self.factor, Factor::Lu(_)),
                singular: solution.is_none(),
            },
        )
    }
}

/// The closed form of the companion lectures (the collisions lectures: Lecture IV Collisions; Pronost), evaluated with
/// `(r×n)ᵀ I⁻¹ (r×n)` rather than the lecture's `((I⁻¹(r×n))×r)·n`.
pub fn closed_form_j<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
    desired: &DesiredVelocity<T>,
) -> T {
    closed_form_j_with(problem, &problem.inverse_inertias(), frame, desired)
}

/// [`closed_form_j`] with each slot's world inverse inertia already at hand.
pub fn closed_form_j_with<T: Real>(
    problem: &Problem<T>,
    inverse_inertias: &InverseInertias<T>,
    frame: &ContactFrame<T>,
    desired: &DesiredVelocity<T>,
) -> T {
    let n = frame.normal();
    let mut denominator = T::zero();
    for (i, body) in problem.bodies.iter().enumerate() {
        if let (Some(b), Some(r), Some(inverse)) = (body, frame.r[i], &inverse_inertias[i]) {
            let u = r.cross(&n);
            denominator += b.inverse_mass + u.dot(&(inverse * u));
        }
    }
    -(T::one() + desired.restitution) * desired.contact_velocity_world.dot(&n) / denominator
}

/// The impulse in contact coordinates for a desired Δv and contact velocity:
/// `(Δv / Δq̇_t, 0, 0)`, or with a sticking friction model the impulse
/// `M⁻¹ (Δv, -v_y, -v_z)` that removes all sliding (frictionless impulse if
/// `M` cannot be solved). The resolver calls this with its own bookkeeping.
#[inline]
pub fn impulse_contact<T: Real>(
    desired: T,
    contact_velocity: &Vector3<T>,
    total: T,
    matrix: Option<&FactoredMatrix<T>>,
    sticking: bool,
) -> (Vector3<T>, Option<MatrixSolve<T>>) {
    let normal_only = Vector3::new(desired / total, T::zero(), T::zero());
    match (sticking, matrix) {
        (true, Some(m)) => {
            let v = contact_velocity;
            let rhs = Vector3::new(desired, -v.y, -v.z);
            let (g, solve) = m.solve(rhs);
            (g.unwrap_or(normal_only), Some(solve))
        }
        _ => (normal_only, None),
    }
}

/// Whether the contact's friction model starts from the sticking impulse.
pub fn sticking_model<T: Real>(contact: &crate::physics::ContactInput<T>) -> bool {
    contact.has_friction() && contact.friction_model != FrictionModel::KineticDirection
}

pub fn impulse<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
    unit: &UnitImpulse<T>,
    desired: &DesiredVelocity<T>,
) -> Impulse<T> {
    impulse_with(problem, &problem.inverse_inertias(), frame, unit, desired)
}

/// [`impulse`] with each slot's world inverse inertia already at hand.
pub fn impulse_with<T: Real>(
    problem: &Problem<T>,
    inverse_inertias: &InverseInertias<T>,
    frame: &ContactFrame<T>,
    unit: &UnitImpulse<T>,
    desired: &DesiredVelocity<T>,
) -> Impulse<T> {
    let factored = unit.matrix.map(FactoredMatrix::new);
    let mut impulse = Impulse::empty();
    impulse_factored_into(
        problem,
        inverse_inertias,
        frame,
        unit,
        desired,
        factored.as_ref(),
        &mut impulse,
    );
    impulse
}

impl<T: Real> Impulse<T> {
    /// A record to be written by [`impulse_factored_into`].
    pub fn empty() -> Self {
        Impulse {
            impulse_contact: Vector3::zeros(),
            impulse_world: Vector3::zeros(),
            solve: None,
            closed_form_j: T::zero(),
            closed_form_relative_difference: T::zero(),
        }
    }
}

/// [`impulse_with`] with `M` already factored (the stage path factors it
/// once for the impulse and the friction clamp), written into `out`.
#[inline]
pub fn impulse_factored_into<T: Real>(
    problem: &Problem<T>,
    inverse_inertias: &InverseInertias<T>,
    frame: &ContactFrame<T>,
    unit: &UnitImpulse<T>,
    desired: &DesiredVelocity<T>,
    factored: Option<&FactoredMatrix<T>>,
    out: &mut Impulse<T>,
) {
    let normal_only = Vector3::new(desired.desired / unit.total, T::zero(), T::zero());
    let (impulse_contact, solve) = impulse_contact(
        desired.desired,
        &desired.contact_velocity,
        unit.total,
        factored,
        sticking_model(&problem.contact),
    );
    let closed_form_j = closed_form_j_with(problem, inverse_inertias, frame, desired);
    let scale = closed_form_j.abs().max(T::min_value().unwrap_or(T::zero()));
    let closed_form_relative_difference = if scale > T::zero() {
        (normal_only.x - closed_form_j).abs() / scale
    } else {
        (normal_only.x - closed_form_j).abs()
    };
    out.impulse_contact = impulse_contact;
    out.impulse_world = frame.to_world(&impulse_contact);
    out.solve = solve;
    out.closed_form_j = closed_form_j;
    out.closed_form_relative_difference = closed_form_relative_difference;
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Rotation3;

    /// `R diag(λ) Rᵀ`: a symmetric matrix with chosen eigenvalues.
    pub(super) fn with_eigenvalues<T: Real>(l: [f64; 3], angle: f64) -> Matrix3<T> {
        let r = Rotation3::from_euler_angles(angle, 0.7 * angle, -0.3 * angle).into_inner();
        let m = r * Matrix3::from_diagonal(&Vector3::from(l)) * r.transpose();
        m.map(c::<T>)
    }

    fn same_g<T: Real>(m: Matrix3<T>, rhs: Vector3<T>) {
        let (fast, fast_solve) = FactoredMatrix::new(m).solve(rhs);
        let (exact, exact_solve) = FactoredMatrix::with_condition(m).solve(rhs);
        assert_eq!(fast, exact, "g of {m}");
        assert_eq!(fast_solve.singular, exact_solve.singular);
        assert_eq!(fast_solve.used_lu, exact_solve.used_lu);
        // Sequential impulses invert M from the factor held, or factor it afresh.
        let inverse = m.cholesky().map(|ch| ch.inverse());
        assert_eq!(FactoredMatrix::new(m).cholesky_inverse(), inverse);
        assert_eq!(FactoredMatrix::for_inverse(m).cholesky_inverse(), inverse);
        assert_eq!(
            FactoredMatrix::with_condition(m).cholesky_inverse(),
            inverse
        );
        // The fast factor's κ is an upper bound, at most 3κ, when it stands in.
        assert!(fast_solve.condition_number >= exact_solve.condition_number * c(0.999));
    }

    #[test]
    fn factoring_for_solving_gives_the_same_g_as_with_the_condition_number() {
        let rhs = Vector3::new(0.3, -1.2, 2.5);
        let cases = [
            [1.0, 2.0, 3.0],   // well-conditioned
            [1e-3, 1.0, 5.0],  // κ 5e3
            [1e-12, 1.0, 1.0], // ill-conditioned (κ ε ≈ 2e-4 .. 1e-3)
            [1e-14, 1.0, 2.0], // ill-conditioned beyond the bound's reach
            [1e-17, 1.0, 1.0], // hopeless: κ ε ≥ 1
            [-1.0, 1.0, 2.0],  // indefinite: hopeless however small the bound
            [0.0, 1.0, 1.0],   // singular
        ];
        for (i, l) in cases.iter().enumerate() {
            let angle = 0.4 + i as f64;
            same_g::<f64>(with_eigenvalues(*l, angle), rhs);
            same_g::<f32>(with_eigenvalues(*l, angle), rhs.map(c::<f32>));
        }
        // The lecture's own matrices are far from any boundary: the bound stands in.
        let m = with_eigenvalues::<f64>([1.0, 2.0, 3.0], 0.4);
        assert!(FactoredMatrix::new(m).solve(rhs).1.condition_number <= 9.0);
    }
}
