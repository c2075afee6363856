//! What a traced XPBD step keeps of each substep: per active contact the
//! position iteration's C, w, λ_n, Δλ_n, α̃ and static friction, and the
//! velocity pass's dynamic friction and restitution (the glossary's names).

use super::passes::{PositionDone, VelocityDone};

/// One substep of a traced step.
#[derive(Debug, Clone, PartialEq)]
pub struct SubstepRecord {
    /// 1-based.
    pub substep: usize,
    /// h = Δt / substeps (s).
    pub h: f64,
    /// α̃ = α/h² (m/N·s⁻²: the compliance per substep).
    pub alpha_tilde: f64,
    /// The contacts the position iteration found penetrating, in file order.
    pub contacts: Vec<ContactRecord>,
}

impl SubstepRecord {
    pub fn new(substep: usize, h: f64, alpha_tilde: f64) -> Self {
        SubstepRecord {
            substep,
            h,
            alpha_tilde,
            contacts: Vec::new(),
        }
    }
}

/// One contact in one substep.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRecord {
    /// The contact's index (file order of the step's contacts).
    pub contact: usize,
    /// Position pass: C (the separation, < 0 penetrating), the generalized
    /// inverse mass w₁ + w₂ along n, λ_n and Δλ_n (kg·m).
    pub c: f64,
    pub w: f64,
    pub lambda: f64,
    pub delta_lambda: f64,
    /// Static friction: λ_t asked for, its bound μ_s λ_n, whether it held.
    pub lambda_t: f64,
    pub lambda_t_max: f64,
    pub sticks: bool,
    /// Velocity pass: v_n after the projection, ṽ_n before it, |v_t|, the
    /// speed dynamic friction removed, the restitution applied, Δv_n.
    pub vn: f64,
    pub vn_before: f64,
    pub slip: f64,
    pub friction_dv: f64,
    pub restitution: f64,
    pub restitution_dv: f64,
}

impl ContactRecord {
    pub(super) fn of_position(contact: usize, p: &PositionDone) -> Self {
        ContactRecord {
            contact,
            c: p.c,
            w: p.w,
            lambda: p.lambda_n,
            delta_lambda: p.delta_lambda_n,
            lambda_t: p.lambda_t,
            lambda_t_max: p.lambda_t_max,
            sticks: p.sticks,
            vn: 0.0,
            vn_before: 0.0,
            slip: 0.0,
            friction_dv: 0.0,
            restitution: 0.0,
            restitution_dv: 0.0,
        }
    }

    pub(super) fn add_velocity(&mut self, v: &VelocityDone) {
        self.vn = v.vn;
        self.vn_before = v.vn_before;
        self.slip = v.slip;
        self.friction_dv = v.friction_dv;
        self.restitution = v.restitution;
        self.restitution_dv = v.restitution_dv;
    }
}
