//! Exact impact integration: the accuracy reference of the single-contact stepper.
//!
//! The lecture's friction stage computes one impulse that removes all sliding
//! and clamps it to the Coulomb cone. Here the impact is integrated instead,
//! in the normal-impulse domain (Routh's method; Keller 1986; Mirtich's
//! thesis ch. 4; Stronge, *Impact Mechanics*, ch. 4–5): as the normal impulse
//! P_n grows from 0, the contact velocity follows
//!
//! `u(P) = u0 + K P`
//!
//! with K the collision matrix in contact space (x normal, y/z tangents t0/t1,
//! the friction stage's 3×3 matrix). Friction opposes the current slip,
//! `dP_t = -μ_d s dP_n` with `s = u_t/|u_t|`; a contact at rest tangentially
//! sticks with `dP_t = τ dP_n`, `τ = -K_tt⁻¹ K_tn`, while `|τ| ≤ μ_s`, and
//! otherwise slips again along the consistent direction
//! ([`PhaseKind::SlipReverses`] in the planar case, [`PhaseKind::SlipResumes`] in 3D).
//! Compression ends where u_n reaches 0 (P_c, work W_c); restitution ends by
//! the chosen [`RestitutionLaw`]: Newton `u_n = -e u_n0`, Poisson
//! `P_n = (1 + e) P_c`, Stronge `W_r = -e² W_c`.
//!
//! **How.** While dP/dP_n is constant (frictionless; sticking; slipping along
//! an *invariant* direction, `K_tn - μ_d K_tt s ∥ s`, which covers the planar
//! case and any restart) u is linear in P_n and each stretch is solved in
//! closed form (`run.rs`): these results are exact to round-off. Only an
//! initial slip whose direction turns is integrated numerically
//! (`rotating.rs`): the slip-direction ODE, rescaled by `dP_n = |u_t| dσ` so
//! that slip halting is not a singularity, with Dormand–Prince 5(4) and event
//! location by false position on the step length. After a halt the direction
//! is again invariant (stick, or restart along an invariant direction), so
//! at most one stretch is numerical.
//!
//! At rest tangentially, the contact sticks when `|τ| ≤ μ_s`. When
//! `μ_s < |τ| ≤ μ_d` no slip direction is consistent (kinetic friction
//! would stop any slip at once) and it sticks too, with `|τ| > μ_s`.
//!
//! **Error bound.** Each accepted step keeps the embedded error estimate
//! (RMS) below 1 against `atol_i + rtol·|y_i|` for the state `(P, W_n, W_t)`,
//! with `atol = rtol·|u0|/K_nn` for impulses and `rtol·|u0|²/K_nn` for
//! works (`rtol` = [`Tolerance::rtol`], 1e-10 in f64), and the tangential
//! velocity error against `rtol·|u0|/100 + |u_t|/1000`, so that the slip
//! speed stays resolved well below the halt threshold `rtol·|u0|`. The
//! fifth-order solution is propagated; events are located on the step
//! length to `rtol/1000` of the step. Below the threshold the last
//! `|u_t|/|λ| ≤ rtol·|u0|/|λ|` of normal impulse before the halt is done in
//! closed form, as is the rest of a slip whose direction has settled on a
//! stable invariant direction (to within θ with `θ|u_t| ≤ rtol·|u0|`, or
//! θ ≤ rtol while the slip grows). The global error has no a-priori bound
//! (the direction flow can leave an unstable invariant direction), so it is
//! measured (`tests/exact_accuracy.rs`, 400 random contacts × 3 laws each):
//! against runs at rtol = 1e-13 the impulse differs by 2e-11·|P| (median),
//! 2.3e-9·|P| at most; settling against integrating on, by 2.1e-10·|P| at
//! most; planar impacts forced through the integrator reproduce the closed
//! forms to 3.2e-10·|P|; the energy residual `|W_c + W_r + W_t - ΔE|`
//! stays below 2.1e-9 of the collision energy `½ u0ᵀK⁻¹u0` there (one
//! random case proptest found, μ_s = 0 < μ_d with a turning slip, reaches
//! 2.0e-8: `tests/exact_impact.rs`). In short: the
//! impulse to about 1e-9 relative, closed-form stretches to round-off.
//!
//! Everything is generic over [`Real`](crate::physics::Real): the integrator
//! runs in f32 too, with `rtol` = 1.2e-4 by default.
//!
//! [`integrate`] is the kernel on contact-space data; [`exact_impact`] builds
//! its input from one contact with the existing stages and compares it with
//! the one-shot impulse of [`crate::physics::solve`].

mod alone;
mod contact;
mod input;
mod integrate;
mod outcome;
mod rk;
mod rotating;
mod run;
mod tangent;

pub use alone::{exact_impact, exact_impact_with};
pub use contact::{exact_impact_beside, ExactImpact};
pub use input::{ExactError, ImpactInput, RestitutionLaw, Tolerance};
pub use integrate::integrate;
pub use outcome::{Cost, ImpactOutcome, Phase, PhaseKind, Regime, Sample};

#[cfg(test)]
mod tests;
