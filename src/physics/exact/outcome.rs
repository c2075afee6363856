//! What the impact integration returns: the impulse, the final velocity, the
//! works, the phases the impact went through and sampled curves.

use nalgebra::{Vector2, Vector3};

use super::RestitutionLaw;
use crate::physics::Real;

/// What happens over a stretch of normal impulse (or at one value of it).
/// Directions are unit 2-vectors in the tangent plane (t0, t1) of contact space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PhaseKind<T: Real> {
    /// No friction at all (μ_s = μ_d = 0): the tangential motion is free.
    Frictionless,
    /// The contact slips; friction `-μ_d s dP_n` opposes the slip direction s.
    /// `rotating` is true when s turned (integrated numerically); otherwise s
    /// was constant and the stretch was solved in closed form.
    Slides {
        direction: Vector2<T>,
        end_direction: Vector2<T>,
        rotating: bool,
    },
    /// The contact sticks (u_t = 0): friction supplies `dP_t = τ dP_n`,
    /// `τ = -K_tt⁻¹ K_tn`, inside the cone `|τ| ≤ μ_s`.
    Sticks { ratio: Vector2<T> },
    /// Instant: the slip speed reaches zero.
    SlipHalts,
    /// Instant: after halting, the contact cannot stick and slips back the way it came.
    SlipReverses { direction: Vector2<T> },
    /// Instant: after halting, the contact cannot stick and slips in a new
    /// direction (3D), neither the old one nor its reverse.
    SlipResumes { direction: Vector2<T> },
    /// Instant: the contact starts at rest (u_t = 0), cannot stick, and starts to slip.
    SlipStarts { direction: Vector2<T> },
    /// Instant: the normal velocity reaches zero; compression ends, restitution begins.
    MaxCompression,
}

impl<T: Real> PhaseKind<T> {
    /// A short stable name (`slides`, `sticks`, `slip_halts`, …).
    pub fn name(&self) -> &'static str {
        match self {
            PhaseKind::Frictionless => "frictionless",
            PhaseKind::Slides { .. } => "slides",
            PhaseKind::Sticks { .. } => "sticks",
            PhaseKind::SlipHalts => "slip_halts",
            PhaseKind::SlipReverses { .. } => "slip_reverses",
            PhaseKind::SlipResumes { .. } => "slip_resumes",
            PhaseKind::SlipStarts { .. } => "slip_starts",
            PhaseKind::MaxCompression => "max_compression",
        }
    }

    /// True for the kinds that happen at one value of P_n.
    pub fn is_instant(&self) -> bool {
        !matches!(
            self,
            PhaseKind::Frictionless | PhaseKind::Slides { .. } | PhaseKind::Sticks { .. }
        )
    }
}

/// One phase: an interval `[from_pn, to_pn]` of the normal impulse, or an
/// instant (`from_pn == to_pn`). Intervals are split at maximum compression.
#[derive(Debug, Clone, PartialEq)]
pub struct Phase<T: Real> {
    pub kind: PhaseKind<T>,
    pub from_pn: T,
    pub to_pn: T,
    /// Contact velocity (contact space) at `from_pn` and at `to_pn`.
    pub u_from: Vector3<T>,
    pub u_to: Vector3<T>,
}

/// One point of the impulse-space curves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample<T: Real> {
    /// Impulse so far (contact space); `p.x` is P_n.
    pub p: Vector3<T>,
    /// Contact velocity `u0 + K p`: `u.x` is u_n, `u.y`, `u.z` are u_t0, u_t1.
    pub u: Vector3<T>,
    /// Work of the normal impulse so far, `∫ u_n dP_n`.
    pub work_normal: T,
}

/// What the numerical part cost (all zero when every stretch was closed form).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Cost {
    /// Evaluations of the right-hand side.
    pub rhs_evals: usize,
    pub accepted_steps: usize,
    pub rejected_steps: usize,
    /// Trial steps spent locating events inside a step.
    pub event_steps: usize,
}

impl Cost {
    /// Steps of every kind, counted against the budget.
    pub fn steps(&self) -> usize {
        self.accepted_steps + self.rejected_steps + self.event_steps
    }
}

/// How the tangential motion went, read from the phases.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Regime {
    /// The contact was not closing: nothing happens.
    Separating,
    Frictionless,
    /// Stuck from the first impulse to the last.
    SticksThroughout,
    /// Slipped in one constant direction throughout.
    SlidesThroughout,
    /// At rest tangentially at first, could not stick, and slipped along the
    /// consistent direction throughout.
    StartsSliding,
    /// Slipped in one direction, halted and stuck.
    HaltsAndSticks,
    /// Slipped, halted and slipped again (reversed or, in 3D, resumed elsewhere).
    Reverses,
    /// The slip direction turned during the impact (integrated numerically).
    Rotating,
}

impl Regime {
    pub fn name(self) -> &'static str {
        match self {
            Regime::Separating => "separating",
            Regime::Frictionless => "frictionless",
            Regime::SticksThroughout => "sticks throughout",
            Regime::SlidesThroughout => "slides throughout",
            Regime::StartsSliding => "starts sliding",
            Regime::HaltsAndSticks => "halts and sticks",
            Regime::Reverses => "reverses",
            Regime::Rotating => "rotating direction",
        }
    }
}

/// The integrated impact.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactOutcome<T: Real> {
    pub law: RestitutionLaw,
    /// False when `u0.x ≥ 0`: no impulse, no phases.
    pub closing: bool,
    /// Total impulse P (contact space) on body 1; body 2 receives -P.
    pub impulse: Vector3<T>,
    /// Contact velocity after the impact, `u0 + K P`.
    pub velocity: Vector3<T>,
    /// Normal impulse at maximum compression, P_c.
    pub compression_pn: T,
    /// Work of the normal impulse during compression, `W_c = ∫₀^{P_c} u_n dP_n ≤ 0`.
    pub work_compression: T,
    /// Work of the normal impulse during restitution, W_r.
    pub work_restitution: T,
    /// Work of friction, `W_t = ∫ u_t · dP_t ≤ 0`.
    pub work_friction: T,
    /// Kinetic-energy change `ΔE = P·u0 + ½ Pᵀ K P` (exact for an impulse in
    /// contact space); equals `W_c + W_r + W_t` up to the integration error.
    pub energy_change: T,
    pub phases: Vec<Phase<T>>,
    /// Curves for an impulse-space figure: every phase boundary and every
    /// integration step (u is linear in P_n between consecutive samples of a closed-form stretch).
    pub samples: Vec<Sample<T>>,
    pub cost: Cost,
}

impl<T: Real> ImpactOutcome<T> {
    /// `W_c + W_r + W_t`: the energy change as the integration accumulated it.
    pub fn work_total(&self) -> T {
        self.work_compression + self.work_restitution + self.work_friction
    }

    /// `|W_c + W_r + W_t - ΔE|`: zero up to round-off for closed-form
    /// stretches, the integration error otherwise.
    pub fn energy_residual(&self) -> T {
        (self.work_total() - self.energy_change).abs()
    }

    /// The regime, read from the phases.
    pub fn regime(&self) -> Regime {
        if !self.closing {
            return Regime::Separating;
        }
        let has = |f: &dyn Fn(&PhaseKind<T>) -> bool| self.phases.iter().any(|p| f(&p.kind));
        if has(&|k| matches!(k, PhaseKind::Slides { rotating: true, .. })) {
            Regime::Rotating
        } else if has(&|k| {
            matches!(
                k,
                PhaseKind::SlipReverses { .. } | PhaseKind::SlipResumes { .. }
            )
        }) {
            Regime::Reverses
        } else if has(&|k| matches!(k, PhaseKind::SlipStarts { .. })) {
            Regime::StartsSliding
        } else if has(&|k| matches!(k, PhaseKind::SlipHalts)) {
            Regime::HaltsAndSticks
        } else if has(&|k| matches!(k, PhaseKind::Sticks { .. })) {
            Regime::SticksThroughout
        } else if has(&|k| matches!(k, PhaseKind::Frictionless)) {
            Regime::Frictionless
        } else {
            Regime::SlidesThroughout
        }
    }
}
