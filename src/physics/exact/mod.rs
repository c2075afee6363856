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
//! `dP_t = −μ_d s dP_n` with `s = u_t/|u_t|`; a contact at rest tangentially
//! sticks with `dP_t = τ dP_n`, `τ = −K_tt⁻¹ K_tn`, while `|τ| ≤ μ_s`, and
//! otherwise slips again along the consistent direction
//! ([`PhaseKind::SlipReverses`] in the planar case, [`PhaseKind::SlipResumes`] in 3D).
//! Compression ends where u_n reaches 0 (P_c, work W_c); restitution ends by
//! the chosen [`RestitutionLaw`]: Newton `u_n = −e u_n0`, Poisson
//! `P_n = (1 + e) P_c`, Stronge `W_r = −e² W_c`.
//!
//! **How.** While dP/dP_n is constant (frictionless; sticking; slipping along
//! an *invariant* direction, `K_tn − μ_d K_tt s ∥ s`, which covers the planar
//! case and any restart) u is linear in P_n and each stretch is solved in
//! closed form (`run.rs`): these results are exact to round-off. Only an
//! initial slip whose direction turns is integrated numerically
//! (`rotating.rs`): the slip-direction ODE, rescaled by `dP_n = |u_t| dσ` so
//! that slip halting is not a singularity, with Dormand–Prince 5(4) and event
//! location by false position on the step length. After a halt the direction
//! is again invariant (stick, or restart along an invariant direction), so
//! at most one stretch is numerical.
//!
//! **Error bound.** Each accepted step keeps the embedded error estimate,
//! RMS over the five state components `(P, W_n, W_t)`, below
//! `atol_i + rtol·|y_i|` with `atol = rtol·|u0|/K_nn` for impulses and
//! `rtol·|u0|²/K_nn` for works (`rtol` = [`Tolerance::rtol`], 1e-10 in f64);
//! the fifth-order solution is propagated. Events are located to the same
//! accuracy. Slip counts as halted below `rtol·|u0|` and the remaining
//! normal impulse, at most `rtol·|u0|/|λ|`, is added in closed form. The
//! global error is not bounded a priori (the slip-direction flow can diverge
//! from an unstable invariant direction), so it is measured: over 2 000
//! random turning impacts (`tests/exact_accuracy.rs`), the impulse at
//! `rtol = 1e-10` differs from a run at `rtol = 1e-13` by at most
//! 3e-10·|P| (Poisson and Stronge) and the energy residual
//! `|W_c + W_r + W_t − ΔE|` stays below 1e-9 of `|u0|²/K_nn`; forced through
//! the integrator, the planar closed forms are reproduced to 1e-9.
//!
//! Everything is generic over [`Real`](crate::physics::Real): the integrator
//! runs in f32 too, with `rtol` = 1.2e-4 by default.
//!
//! [`integrate`] is the kernel on contact-space data; [`exact_impact`] builds
//! its input from one contact with the existing stages and compares it with
//! the one-shot impulse of [`crate::physics::solve`].

mod contact;
mod input;
mod integrate;
mod outcome;
mod rk;
mod rotating;
mod run;
mod tangent;

pub use contact::{exact_impact, exact_impact_with, ExactImpact};
pub use input::{ExactError, ImpactInput, RestitutionLaw, Tolerance};
pub use integrate::integrate;
pub use outcome::{Cost, ImpactOutcome, Phase, PhaseKind, Regime, Sample};

#[cfg(test)]
mod tests;
