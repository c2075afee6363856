//! Input of the impact integration (collision matrix, contact velocity,
//! coefficients, restitution law, tolerance), its validation and its errors.

use nalgebra::{Matrix3, Vector3};

use crate::physics::{c, to_f64, Real};

/// How the restitution phase ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RestitutionLaw {
    /// Kinematic: the normal velocity at separation is `u_n' = -e u_n0`.
    Newton,
    /// Kinetic: the total normal impulse is `(1 + e)` times the normal
    /// impulse at maximum compression, `P_n' = (1 + e) P_c`.
    Poisson,
    /// Energetic: the work of the normal impulse in restitution is `-e²`
    /// times its work in compression, `W_r = -e² W_c`.
    Stronge,
}

impl RestitutionLaw {
    pub const ALL: [RestitutionLaw; 3] = [
        RestitutionLaw::Newton,
        RestitutionLaw::Poisson,
        RestitutionLaw::Stronge,
    ];
}

/// Accuracy and budget of the integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance<T: Real> {
    /// Relative tolerance of each Runge–Kutta step (absolute parts scale
    /// with the frictionless impulse `|u0|/K_nn` and `|u0|²/K_nn`); also the
    /// slip speed, relative to `|u0|`, below which slip counts as halted.
    /// (default: max(1e-10, 1000 ε): 1e-10 in f64, 1.2e-4 in f32)
    pub rtol: T,
    /// Runge–Kutta steps (accepted, rejected and event-location steps) before
    /// the integration gives up with [`ExactError::BudgetExceeded`]. (default: 10 000)
    pub max_steps: usize,
    /// Integrate the initial slip numerically to its end even where its
    /// direction is constant or has settled and the closed form applies: for
    /// testing the integrator and measuring its cost. (default: false)
    pub always_integrate: bool,
}

impl<T: Real> Default for Tolerance<T> {
    fn default() -> Self {
        Tolerance {
            rtol: c::<T>(1e-10).max(T::default_epsilon() * c(1e3)),
            max_steps: 10_000,
            always_integrate: false,
        }
    }
}

/// One single-contact impact in contact space: x along the normal, y and z
/// along the tangents t0 and t1.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactInput<T: Real> {
    /// Collision matrix: contact velocity change per unit impulse, `u = u0 + K P`
    /// (the friction stage's 3×3 matrix). Symmetric positive-definite.
    pub k: Matrix3<T>,
    /// Contact velocity before the impact; `u0.x < 0` when closing.
    pub u0: Vector3<T>,
    /// μ_s: the contact sticks when the ratio `|τ|` that keeps it stuck is at most this.
    pub static_friction: T,
    /// μ_d: friction while slipping, `|dP_t| = μ_d dP_n`.
    pub dynamic_friction: T,
    /// e in [0, 1], read by `law`.
    pub restitution: T,
    pub law: RestitutionLaw,
    pub tolerance: Tolerance<T>,
}

/// Why an integration stopped without a result. It never returns NaN instead.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExactError {
    #[error("impact integration: {what} is not finite")]
    NonFinite { what: &'static str },
    #[error(
        "impact integration: the collision matrix K is not symmetric positive-definite ({reason})"
    )]
    NotPositiveDefinite { reason: &'static str },
    #[error("impact integration: {what} = {value} is outside {range}")]
    OutOfRange {
        what: &'static str,
        value: f64,
        range: &'static str,
    },
    #[error("impact integration did not finish within its budget of {budget} steps (stopped at P_n = {p_n:e} while {during})")]
    BudgetExceeded {
        budget: usize,
        p_n: f64,
        during: &'static str,
    },
    #[error("impact integration never ends: no event lies ahead at P_n = {p_n:e} ({during})")]
    NoTermination { p_n: f64, during: &'static str },
    #[error("impact integration overflowed at P_n = {p_n:e}")]
    Overflow { p_n: f64 },
}

/// Checks the input; returns K made exactly symmetric.
pub(super) fn validate<T: Real>(input: &ImpactInput<T>) -> Result<Matrix3<T>, ExactError> {
    let finite = |x: &T| x.is_finite();
    if !input.k.iter().all(finite) {
        return Err(ExactError::NonFinite { what: "K" });
    }
    if !input.u0.iter().all(finite) {
        return Err(ExactError::NonFinite { what: "u0" });
    }
    let coefficients = [
        ("μ_s", input.static_friction, "[0, ∞)"),
        ("μ_d", input.dynamic_friction, "[0, ∞)"),
        ("e", input.restitution, "[0, 1]"),
    ];
    for (what, value, range) in coefficients {
        let bad = !value.is_finite() || value < T::zero() || (what == "e" && value > T::one());
        if bad {
            let value = to_f64(value);
            return Err(if value.is_finite() {
                ExactError::OutOfRange { what, value, range }
            } else {
                ExactError::NonFinite { what }
            });
        }
    }
    let tol = input.tolerance.rtol;
    if !(tol > T::zero() && tol < c(0.1)) {
        return Err(ExactError::OutOfRange {
            what: "rtol",
            value: to_f64(tol),
            range: "(0, 0.1)",
        });
    }
    let k = input.k;
    let asymmetry = (k - k.transpose()).amax();
    if asymmetry > k.amax() * T::default_epsilon() * c(1e3) {
        return Err(ExactError::NotPositiveDefinite {
            reason: "not symmetric",
        });
    }
    let k = (k + k.transpose()) * c::<T>(0.5);
    if k.cholesky().is_none() || k[(0, 0)] <= T::zero() {
        return Err(ExactError::NotPositiveDefinite {
            reason: "Cholesky factorisation failed",
        });
    }
    Ok(k)
}
