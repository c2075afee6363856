//! Stage 4: the impulse, before any friction clamp.
//!
//! Frictionless: `g = Δv / Δq̇_t` along the normal (lecture: "Calculating the
//! Impulse"). With friction (Millington and velocity-scaling models) the
//! sticking impulse `g = M⁻¹ (Δv, -v_y, -v_z)` that removes all sliding. The
//! companion lectures' closed form `j` is computed independently as a check.

use nalgebra::{Matrix3, Vector3};

use super::{ContactFrame, DesiredVelocity, UnitImpulse};
use crate::physics::{c, FrictionModel, Problem, Real};

/// How the 3×3 system `M g = rhs` was solved, and how well.
#[derive(Debug, Clone, PartialEq)]
pub struct MatrixSolve<T: Real> {
    pub rhs: Vector3<T>,
    /// κ(M) = λ_max / λ_min (M is symmetric positive-definite).
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
    let eig = m.symmetric_eigenvalues();
    let (lo, hi) = (eig.min(), eig.max());
    let condition_number = if lo > T::zero() {
        hi / lo
    } else {
        T::max_value().unwrap_or(hi)
    };
    let ill_conditioned = condition_number * T::default_epsilon() > c(1e-3);
    // κ ε ≥ 1 (or M numerically indefinite): no digit of g would be right,
    // and an LU solve of such an M can return anything up to inf.
    let hopeless = condition_number * T::default_epsilon() >= T::one();
    let mut used_lu = false;
    let solution = match m.cholesky() {
        _ if hopeless => None,
        Some(ch) => Some(ch.solve(&rhs)),
        None => {
            used_lu = true;
            m.lu().solve(&rhs)
        }
    }
    .filter(|g| g.iter().all(|x| x.is_finite()));
    let singular = solution.is_none();
    (
        solution,
        MatrixSolve {
            rhs,
            condition_number,
            ill_conditioned,
            used_lu,
            singular,
        },
    )
}

/// The closed form of the companion lectures (seeds 002/003), evaluated with
/// `(r×n)ᵀ I⁻¹ (r×n)` rather than the lecture's `((I⁻¹(r×n))×r)·n`.
pub fn closed_form_j<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
    desired: &DesiredVelocity<T>,
) -> T {
    let n = frame.normal();
    let mut denominator = T::zero();
    for (i, body) in problem.bodies.iter().enumerate() {
        if let (Some(b), Some(r)) = (body, frame.r[i]) {
            let u = r.cross(&n);
            denominator += b.inverse_mass + u.dot(&(b.inverse_inertia_world() * u));
        }
    }
    -(T::one() + desired.restitution) * desired.contact_velocity_world.dot(&n) / denominator
}

/// The impulse in contact coordinates for a desired Δv and contact velocity:
/// `(Δv / Δq̇_t, 0, 0)`, or with a sticking friction model the impulse
/// `M⁻¹ (Δv, -v_y, -v_z)` that removes all sliding (frictionless impulse if
/// `M` cannot be solved). The resolver calls this with its own bookkeeping.
pub fn impulse_contact<T: Real>(
    desired: T,
    contact_velocity: &Vector3<T>,
    total: T,
    matrix: Option<&Matrix3<T>>,
    sticking: bool,
) -> (Vector3<T>, Option<MatrixSolve<T>>) {
    let normal_only = Vector3::new(desired / total, T::zero(), T::zero());
    match (sticking, matrix) {
        (true, Some(m)) => {
            let v = contact_velocity;
            let rhs = Vector3::new(desired, -v.y, -v.z);
            let (g, solve) = solve_matrix(m, rhs);
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
    let normal_only = Vector3::new(desired.desired / unit.total, T::zero(), T::zero());
    let (impulse_contact, solve) = impulse_contact(
        desired.desired,
        &desired.contact_velocity,
        unit.total,
        unit.matrix.as_ref(),
        sticking_model(&problem.contact),
    );
    let closed_form_j = closed_form_j(problem, frame, desired);
    let scale = closed_form_j.abs().max(T::min_value().unwrap_or(T::zero()));
    let closed_form_relative_difference = if scale > T::zero() {
        (normal_only.x - closed_form_j).abs() / scale
    } else {
        (normal_only.x - closed_form_j).abs()
    };
    Impulse {
        impulse_contact,
        impulse_world: frame.to_world(&impulse_contact),
        solve,
        closed_form_j,
        closed_form_relative_difference,
    }
}
