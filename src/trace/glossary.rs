//! The glossary: every symbol the worked solution uses, with its one
//! meaning, its unit and the stages that use it, and the companion lectures'
//! name where it differs. One table, read by `contact-lab glossary`, the
//! renderers (units on printed numbers) and, later, the TUI's help page.

use crate::physics::StageId;
use crate::physics::StageId::{
    ApplyImpulse as AI, Checks as CH, ContactFrame as CF, DesiredDeltaVelocity as DV,
    ExactImpact as EI, FrictionClamp as FC, Impulse as IM, NonlinearProjection as NP,
    OrientationUpdate as OU, UnitImpulse as UI,
};

/// One symbol. A trailing `ᵢ` stands for the body subscript (₁ or ₂).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Symbol {
    pub symbol: &'static str,
    pub meaning: &'static str,
    /// SI unit as printed after numbers; `""` for a pure number.
    pub unit: &'static str,
    pub stages: &'static [StageId],
    /// What the lectures call it where their name differs (`""` if the same).
    pub elsewhere: &'static str,
}

impl Symbol {
    /// The numbers of the stages that use the symbol, as the stepper counts
    /// them (1 = the first stage): "2, 4, 5".
    pub fn stage_numbers(&self) -> String {
        self.stages
            .iter()
            .map(|id| id.number().to_string())
            .collect::<Vec<_>>()
            .join(", ")
    }
}

const fn s(
    symbol: &'static str,
    meaning: &'static str,
    unit: &'static str,
    stages: &'static [StageId],
    elsewhere: &'static str,
) -> Symbol {
    Symbol {
        symbol,
        meaning,
        unit,
        stages,
        elsewhere,
    }
}

/// Every symbol, in the order the stages first use them (one line each).
#[rustfmt::skip]
pub const GLOSSARY: &[Symbol] = &[
    s("q", "contact point (world coordinates)", "m", &[CF, DV, CH], ""),
    s("d̂", "contact normal, unit vector pointing from body 2 toward body 1", "", &[CF, UI, DV, IM, FC, AI, NP, CH], "n in the collisions lectures"),
    s("â", "guess axis for the tangents: world x, or world y when the normal is closer to x", "", &[CF], ""),
    s("t₀", "first tangent of the contact plane, â × d̂ normalised", "", &[CF], ""),
    s("t₁", "second tangent, d̂ × t₀", "", &[CF], ""),
    s("C", "contact basis [d̂ t₀ t₁]: turns contact coordinates into world coordinates", "", &[CF, UI, DV, IM, FC], "M_C→W in COMP 476 Session 10"),
    s("x̂", "first axis of contact coordinates, (1, 0, 0): the normal direction", "", &[DV], ""),
    s("pᵢ", "position of body i's centre of mass", "m", &[CF, NP], ""),
    s("rᵢ", "arm from body i's centre to the contact point, q - pᵢ", "m", &[CF, UI, DV, AI, NP, CH], "q_rel in COMP 476 Session 10"),
    s("mᵢ", "mass of body i (∞ = immovable)", "kg", &[UI, AI, NP], ""),
    s("Iᵢ⁻¹", "inverse inertia tensor of body i in world coordinates", "kg⁻¹·m⁻²", &[UI, AI, NP], ""),
    s("Δṗ_d", "change of linear velocity per unit impulse along d̂: Σ 1/mᵢ", "(m/s)/(N·s)", &[UI], ""),
    s("u_dᵢ", "torque arm of a unit impulse along d̂: rᵢ × d̂", "m", &[UI], "u (for the unit impulse) in COMP 476 Session 10"),
    s("Δθ̇_dᵢ", "change of body i's angular velocity per unit impulse along d̂: Iᵢ⁻¹ u_dᵢ", "(rad/s)/(N·s)", &[UI, NP], "Δθ̇ (per unit impulse) in COMP 476 Session 10"),
    s("Δq̇ᵢ", "velocity change of the contact point from body i's turn, per unit impulse: Δθ̇_dᵢ × rᵢ", "(m/s)/(N·s)", &[UI], ""),
    s("Δq̇_dᵢ", "normal part of Δq̇ᵢ: Δq̇ᵢ · d̂", "(m/s)/(N·s)", &[UI, IM], ""),
    s("Δq̇_t", "total change of normal velocity per unit impulse: Δṗ_d + Σ Δq̇_dᵢ", "(m/s)/(N·s)", &[UI, IM], ""),
    s("[rᵢ]×", "cross-product matrix of rᵢ: [rᵢ]× x = rᵢ × x", "m", &[UI], "the skew matrix of q_rel in COMP 476 Session 10"),
    s("M", "velocity change in contact coordinates per unit impulse in contact coordinates (3×3)", "(m/s)/(N·s)", &[UI, IM, FC, EI], "the unit-impulse matrix of COMP 476 Session 10; K, the collision matrix, in Mirtich and Stronge"),
    s("M₀₀, M₀₁, M₀₂", "first row of M: normal velocity change per unit impulse along x, y, z of the contact", "(m/s)/(N·s)", &[FC], ""),
    s("𝟙", "3×3 identity matrix", "", &[UI], ""),
    s("vᵢ", "linear velocity of body i before the impulse", "m/s", &[DV, AI], "v_A-, v_B- in the collisions lectures"),
    s("ωᵢ", "angular velocity of body i before the impulse", "rad/s", &[DV, AI], ""),
    s("q̇ᵢ", "velocity of the contact point as a point of body i: ωᵢ × rᵢ + vᵢ", "m/s", &[DV], ""),
    s("v_c", "contact velocity in contact coordinates: Cᵀ (q̇₁ - q̇₂)", "m/s", &[DV, FC, EI], "u₀ in Stronge and Mirtich (at the start of the impact)"),
    s("v_s", "separating velocity, the normal part of v_c (negative: closing)", "m/s", &[DV, IM, FC, CH], "v_rel · n in the collisions lectures"),
    s("v_y, v_z", "sliding components of v_c along t₀ and t₁", "m/s", &[FC], ""),
    s("c", "coefficient of restitution (as applied)", "", &[DV, IM, EI], "C_R in the collisions lectures; e elsewhere"),
    s("aᵢ", "body i's acceleration during the last frame", "m/s²", &[DV], ""),
    s("Δt", "duration of the last frame", "s", &[DV], ""),
    s("v_acc", "normal velocity that last frame's acceleration built up", "m/s", &[DV], ""),
    s("Δv", "desired change of the normal velocity", "m/s", &[DV, IM, FC, CH], "Δv_s in COMP 476 Session 10"),
    s("g", "the impulse (a number along d̂ without friction; body 2 receives -g)", "N·s", &[IM, AI], "j n̂ in the collisions lectures"),
    s("g_contact", "the impulse in contact coordinates (g_x normal, g_y, g_z tangential)", "N·s", &[IM, FC, EI], ""),
    s("g_world", "the impulse in world coordinates: C g_contact", "N·s", &[IM, FC], ""),
    s("g_closed", "normal impulse from the companion lectures' closed form", "N·s", &[IM, FC], "j in the collisions lectures"),
    s("g_x, g_y, g_z", "components of the sticking impulse g_contact of stage 4", "N·s", &[FC], "g.x, g.y, g.z in COMP 476 Session 10"),
    s("|g_planar|", "size of the tangential part of an impulse", "N·s", &[FC, CH], "|g_planar| in COMP 476 Session 10"),
    s("g_max", "largest tangential impulse static friction can give: μ_s g_x", "N·s", &[FC], "|g_normal| μ in COMP 476 Session 10"),
    s("g_n", "normal impulse after the friction clamp", "N·s", &[FC, CH], "g_normal in COMP 476 Session 10"),
    s("μ_s", "static friction coefficient: decides whether the contact sticks", "", &[FC], ""),
    s("μ_d", "dynamic (sliding) friction coefficient: sizes the friction while sliding", "", &[FC], "μ_k in the collisions lectures"),
    s("μ", "friction coefficient of the cone test (μ_d while sliding, μ_s while sticking)", "", &[CH], ""),
    s("f̂", "unit direction of the friction impulse in the contact plane", "", &[FC], "-t̂ in the collisions lectures"),
    s("|v_planar|", "sliding speed in the contact plane (the friction lecture's model)", "m/s", &[FC], ""),
    s("v_max", "sliding speed below which the friction lecture's model sticks: -μ_s v_s", "m/s", &[FC], ""),
    s("Δṗᵢ", "change of body i's linear velocity: ±g / mᵢ", "m/s", &[AI], "Δṗ in COMP 476 Session 10"),
    s("uᵢ", "impulsive torque on body i: rᵢ × (±g)", "N·m·s", &[AI], "u in COMP 476 Session 10"),
    s("Δθ̇ᵢ", "change of body i's angular velocity: Iᵢ⁻¹ uᵢ", "rad/s", &[AI], "Δθ̇ in COMP 476 Session 10"),
    s("vᵢ′", "linear velocity of body i after the impulse", "m/s", &[AI, EI], ""),
    s("ωᵢ′", "angular velocity of body i after the impulse", "rad/s", &[AI, EI], ""),
    s("d_pen", "penetration depth along d̂", "m", &[NP, CH], ""),
    s("relaxation", "share of the penetration resolved in one projection, (0, 1]", "", &[NP], ""),
    s("d_res", "depth this projection resolves: d_pen · relaxation", "m", &[NP, CH], ""),
    s("I_lᵢ", "linear inertia of body i along d̂ for the projection: 1/mᵢ", "kg⁻¹", &[NP], "linearInertia in the reference code"),
    s("I_aᵢ", "angular inertia of body i along d̂: (Δθ̇_dᵢ × rᵢ) · d̂", "kg⁻¹", &[NP], "angularInertia in the reference code"),
    s("I_t", "total inertia along d̂: Σ (I_lᵢ + I_aᵢ)", "kg⁻¹", &[NP], ""),
    s("Δ_lᵢ", "linear move of body i along d̂", "m", &[NP], ""),
    s("Δ_aᵢ", "angular move: how far body i's turn moves the contact point along d̂", "m", &[NP], ""),
    s("angular_limit", "largest angular move per metre of arm across d̂ (setting)", "", &[NP], ""),
    s("Δ_maxᵢ", "largest angular move of body i: angular_limit · |rᵢ - (rᵢ · d̂) d̂|", "m", &[NP], ""),
    s("Δpᵢ", "change of body i's position: Δ_lᵢ d̂", "m", &[NP], ""),
    s("Δθᵢ", "rotation vector of body i's turn", "rad", &[NP, OU], ""),
    s("pᵢ′", "position of body i after the projection", "m", &[NP], ""),
    s("θᵢ", "orientation quaternion of body i, [w, x, y, z]", "", &[OU], ""),
    s("θᵢ′", "orientation after θᵢ + ½ [0, Δθᵢ] θᵢ, before normalising", "", &[OU], ""),
    s("δ", "the turn as a quaternion, (θᵢ′ / |θᵢ′|) θᵢ⁻¹, with scalar part δ_w and vector part δ_xyz", "", &[OU], ""),
    s("φᵢ", "angle body i turns", "°", &[OU], ""),
    s("q̇ᵢ′", "velocity of the contact point on body i after the impulse", "m/s", &[CH], ""),
    s("v_s′", "separating velocity after the impulse", "m/s", &[CH], "v_s′ in COMP 476 Session 10"),
    s("v_target", "separating velocity the impulse aims at: v_s + Δv", "m/s", &[CH], ""),
    s("qᵢ′", "the contact point carried by body i's move", "m", &[CH], ""),
    s("d_left", "penetration left after the finite moves", "m", &[CH], ""),
    s("κ(M)", "condition number of M: about log₁₀ κ digits are lost solving with it", "", &[IM], ""),
    s("E", "kinetic energy of the bodies, Σ ½ (m v² + ωᵀ I ω)", "J", &[CH, EI], ""),
    s("law", "restitution law of the integrated impact: Newton (kinematic), Poisson (kinetic) or Stronge (energetic)", "", &[EI], ""),
    s("P", "impulse accumulated during the integrated impact, contact coordinates", "N·s", &[EI], "P in Stronge and Mirtich"),
    s("P_n", "normal part of P: the integration variable", "N·s", &[EI], ""),
    s("v_c(P)", "contact velocity during the impact, as P grows: v_c + M P", "m/s", &[EI], "u(P) in Stronge and Mirtich"),
    s("v_n, v_t", "normal and tangential parts of the contact velocity during the impact", "m/s", &[EI], "u_n, u_t in Stronge and Mirtich"),
    s("v_n′", "normal contact velocity at the end of the impact", "m/s", &[EI], ""),
    s("v_n0", "normal contact velocity at the start of the impact (v_s)", "m/s", &[EI], ""),
    s("dP_t", "tangential impulse gained while P_n grows by dP_n", "N·s", &[EI], ""),
    s("s", "unit slip direction in the contact plane, v_t / |v_t|", "", &[EI], ""),
    s("τ", "tangential impulse per unit normal impulse while the contact sticks", "", &[EI], ""),
    s("P_c", "P_n at maximum compression (v_n = 0)", "N·s", &[EI], ""),
    s("P_n′", "P_n at the end of the impact", "N·s", &[EI], ""),
    s("W_c, W_r, W_t", "work of the normal impulse in compression and in restitution, and of friction", "J", &[EI], ""),
    s("P_world", "P in world coordinates: C P", "N·s", &[EI], ""),
    s("v_c′", "contact velocity after the integrated impact: v_c + M P", "m/s", &[EI], ""),
    s("E′", "kinetic energy after the integrated impact", "J", &[EI], ""),
    s("E′_clamp", "kinetic energy after the one-shot impulse of stages 4–6", "J", &[EI], ""),
];

/// One quantity a soft-step or XPBD trace prints (`simulate --trace-step`,
/// the TUI's substeps): its symbol, the key it has in JSON, the formula
/// that computes it, its meaning and unit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SolverSymbol {
    pub symbol: &'static str,
    /// The JSON key of the value (`""`: printed in text only).
    pub key: &'static str,
    /// How it is computed (`""`: an input or a record).
    pub formula: &'static str,
    pub meaning: &'static str,
    pub unit: &'static str,
    /// `"soft step"`, `"XPBD"` or `"both"`.
    pub solver: &'static str,
}

const fn q(
    symbol: &'static str,
    key: &'static str,
    formula: &'static str,
    meaning: &'static str,
    unit: &'static str,
    solver: &'static str,
) -> SolverSymbol {
    SolverSymbol {
        symbol,
        key,
        formula,
        meaning,
        unit,
        solver,
    }
}

/// Every quantity the soft-step and XPBD traces print.
#[rustfmt::skip]
pub const SOLVER_GLOSSARY: &[SolverSymbol] = &[
    q("Δt", "dt", "", "the step's duration", "s", "both"),
    q("substeps", "substeps", "", "how many substeps a step is cut into (knob `substeps`)", "", "both"),
    q("h", "h", "h = Δt / substeps", "the substep: the time one substep advances", "s", "both"),
    q("f", "contact_hertz", "", "the contact's stiffness as a frequency (knob `contact_hertz`)", "Hz", "soft step"),
    q("ζ", "contact_damping_ratio", "", "the contact's damping ratio (knob `contact_damping_ratio`)", "", "soft step"),
    q("ω", "", "ω = 2πf", "the contact spring's angular frequency", "rad/s", "soft step"),
    q("a₁", "", "a₁ = 2ζ + hω", "the soft constraint's first coefficient", "", "soft step"),
    q("a₂", "", "a₂ = hω·a₁", "the soft constraint's second coefficient", "", "soft step"),
    q("a₃", "", "a₃ = 1/(1 + a₂)", "the soft constraint's third coefficient", "", "soft step"),
    q("bias rate", "bias_rate", "ω/a₁", "the share of the separation the biased solve asks back per second: bias velocity = max(bias rate · s, -push-out speed)", "1/s", "soft step"),
    q("mass scale", "mass_scale", "a₂a₃", "the share of the rigid impulse the biased solve applies", "", "soft step"),
    q("impulse scale", "impulse_scale", "a₃", "the share of the accumulated impulse the biased solve takes back (the spring's softness)", "", "soft step"),
    q("push-out speed", "push_out_speed", "", "the fastest the biased solve pushes a penetrating contact apart (knob `push_out_speed`)", "m/s", "soft step"),
    q("relax", "relax_iterations", "", "sweeps per substep without bias after the positions move (knob `relax_iterations`): they remove the push-out speed the bias added", "", "soft step"),
    q("restitution threshold", "restitution_threshold", "", "a contact that closed slower than this gets no restitution (knob `restitution_threshold`)", "m/s", "soft step"),
    q("s", "penetration", "s = -penetration", "the contact's separation at the step's start (negative: penetrating); a contact still apart asks only s/h", "m", "soft step"),
    q("v_n", "relative_velocity", "", "the normal velocity before the solve (negative: closing)", "m/s", "soft step"),
    q("m_n", "normal_mass", "m_n = 1/(w₁ + w₂)", "the contact's effective mass along the normal", "kg", "soft step"),
    q("μ", "friction", "", "the contact's friction coefficient", "", "soft step"),
    q("e", "restitution", "", "the contact's restitution coefficient (as applied)", "", "both"),
    q("P_warm", "warm_impulse", "", "the normal impulse warm starting begins with (last step's)", "N·s", "soft step"),
    q("P_n", "normal_impulse", "", "the accumulated normal impulse (after a substep, or stored at the end)", "N·s", "soft step"),
    q("P_t", "tangent_impulse", "", "the accumulated friction impulse along the two tangents", "N·s", "soft step"),
    q("s_k", "separation", "", "the separation after substep k", "m", "soft step"),
    q("α", "compliance", "", "the contact's compliance, the inverse of its stiffness (0: rigid)", "m/N", "XPBD"),
    q("α̃", "alpha_tilde", "α̃ = α/h²", "the compliance per substep", "kg⁻¹", "XPBD"),
    q("C", "c", "", "the contact constraint: the separation along n (negative: penetrating)", "m", "XPBD"),
    q("w", "w", "w = w₁ + w₂, wᵢ = 1/mᵢ + (rᵢ × n)ᵀ Iᵢ⁻¹ (rᵢ × n)", "the generalized inverse mass along n", "kg⁻¹", "XPBD"),
    q("λ_n", "lambda", "λ_n += Δλ_n", "the normal multiplier accumulated in the substep (|f_n| = λ_n/h²)", "kg·m", "XPBD"),
    q("Δλ_n", "delta_lambda", "Δλ_n = (-C - α̃λ_n)/(w + α̃)", "the position iteration's change of λ_n", "kg·m", "XPBD"),
    q("λ_t", "lambda_t", "", "the tangential multiplier static friction asks for", "kg·m", "XPBD"),
    q("λ_t,max", "lambda_t_max", "μ_s λ_n", "the most static friction may hold", "kg·m", "XPBD"),
    q("sticks", "sticks", "λ_t ≤ μ_s λ_n", "whether static friction held", "", "XPBD"),
    q("ṽ_n", "vn_before", "", "the normal velocity before the substep's projection", "m/s", "XPBD"),
    q("v_n′", "vn", "", "the normal velocity after the projection (velocities from positions)", "m/s", "XPBD"),
    q("|v_t|", "slip", "", "the sliding speed the velocity pass starts from", "m/s", "XPBD"),
    q("Δv_t", "friction_dv", "min(μ_d λ_n w / h, |v_t|)", "the speed dynamic friction removes (corrected formula; the printed one drops w, see `check`)", "m/s", "XPBD"),
    q("Δv_n", "restitution_dv", "Δv_n = max(-e ṽ_n, 0) - v_n′", "the restitution's change of the normal velocity (e = 0 when |ṽ_n| ≤ 2|g|h)", "m/s", "XPBD"),
];

/// The solver quantity whose JSON key is `key`.
pub fn solver_symbol_by_key(key: &str) -> Option<&'static SolverSymbol> {
    SOLVER_GLOSSARY
        .iter()
        .find(|s| !s.key.is_empty() && s.key == key)
}

/// The symbols whose name appears in `text` (a formula, a note), each once,
/// in glossary order. Body subscripts ₁ ₂ match the glossary's ᵢ.
pub fn symbols_in(text: &str) -> Vec<&'static Symbol> {
    GLOSSARY
        .iter()
        .filter(|s| {
            s.symbol.split(", ").any(|name| {
                ["ᵢ", "₁", "₂"]
                    .iter()
                    .any(|sub| contains_symbol(text, &name.replace('ᵢ', sub)))
            })
        })
        .collect()
}

/// `name` occurs in `text` as a whole symbol: not inside a longer name.
fn contains_symbol(text: &str, name: &str) -> bool {
    let part = |c: char| {
        c.is_alphanumeric() || c == '_' || c == '′' || ('\u{300}'..='\u{36f}').contains(&c)
    };
    let mut from = 0;
    while let Some(at) = text[from..].find(name) {
        let start = from + at;
        let end = start + name.len();
        let before = text[..start].chars().next_back();
        let after = text[end..].chars().next();
        let name_last = name.chars().next_back();
        let subscripted = name_last.is_some_and(|c| "ᵢ₀₁₂".contains(c));
        let extends_after = after.is_some_and(|c| part(c) || (!subscripted && "ᵢ₀₁₂⁻".contains(c)));
        let extends_before = before.is_some_and(|c| part(c) && !"Δ".contains(c))
            || (name.starts_with(|c: char| c.is_alphabetic()) && before == Some('Δ'));
        if !extends_after && !extends_before {
            return true;
        }
        from = end;
    }
    false
}

/// The unit printed after value `name` of `step` (`""` for a pure number).
/// The body digit in a name (`r1`, `v2_before`) does not matter.
pub fn unit(step: &crate::trace::Step, name: &str) -> &'static str {
    let base = without_body_digit(name);
    let velocity_scaling = matches!(step.value("model"), Some(crate::trace::Value::Text(m)) if m == "velocity-scaling");
    match (step.id, base.as_str()) {
        (FC, "planar" | "limit") if velocity_scaling => "m/s",
        (FC, "planar" | "limit") => "N·s",
        (UI, "rotation") | (_, "rotation_per_unit") => "(rad/s)/(N·s)",
        (OU, "rotation") | (_, "angular_change") => "rad",
        (UI | IM, "linear" | "angular" | "total" | "velocity")
        | (_, "matrix" | "angular_matrix_world" | "m" | "normal_per_unit")
        | (_, "m00" | "m01" | "m02") => {
            if base == "m" {
                "kg"
            } else {
                "(m/s)/(N·s)"
            }
        }
        (_, "q" | "p" | "r" | "position" | "linear_change" | "skew_r" | "torque")
        | (_, "r_perp_length" | "d_pen" | "resolved_depth" | "linear_move" | "angular_move")
        | (_, "linear_move_unlimited" | "angular_move_unlimited" | "angular_limit")
        | (_, "depth_to_resolve" | "separation_gained" | "residual_penetration") => "m",
        (_, "inertia" | "shape_inertia") => "kg·m²",
        (_, "inverse_inertia_world") => "kg⁻¹·m⁻²",
        (_, "linear_inertia" | "angular_inertia" | "total_inertia") => "kg⁻¹",
        (
            _,
            "v" | "v_before" | "dv" | "point_velocity" | "normal_velocity" | "contact_velocity",
        )
        | (_, "separating_velocity" | "closing_velocity" | "velocity_from_acceleration")
        | (_, "desired" | "separating_velocity_before" | "separating_velocity_expected")
        | (_, "slip_speed_before" | "slip_speed_after" | "velocity_limit" | "vx" | "vy" | "vz")
        | (_, "point_velocity_after" | "slip_planar_acceleration")
        | (IM, "rhs") => "m/s",
        (_, "w" | "w_before" | "dw") => "rad/s",
        (_, "dw_degrees_per_second") => "°/s",
        (_, "a") => "m/s²",
        (_, "duration") => "s",
        (_, "impulse_contact" | "impulse_world" | "g" | "closed_form_j" | "impulse")
        | (_, "sticking" | "sticking_normal" | "sticking_y" | "sticking_z" | "normal_impulse")
        | (_, "tangential_impulse" | "cone_limit" | "friction_y" | "friction_z")
        | (_, "linear_momentum_error") => "N·s",
        (
            EI,
            "compression_normal_impulse" | "impulse_one_shot_contact" | "impulse_one_shot_world",
        )
        | (EI, "impulse_difference" | "impulse_difference_abs") => "N·s",
        (EI, "velocity_contact") => "m/s",
        (EI, "energy_after_one_shot" | "energy_difference")
        | (EI, "work_compression" | "work_restitution" | "work_friction") => "J",
        (_, "impulsive_torque" | "angular_momentum_error") => "N·m·s",
        (_, "rotation_degrees" | "rotation_vector_degrees" | "euler_zyx_degrees")
        | (_, "rotation_signed_degrees") => "°",
        (_, "energy_before" | "energy_after" | "energy_change" | "energy_without") => "J",
        _ => "",
    }
}

/// `name` without its body digit: `r1` → `r`, `v2_before` → `v_before`
/// (a 1 or 2 after a letter, at the end or before `_`; `m01` keeps its digits).
fn without_body_digit(name: &str) -> String {
    let chars: Vec<char> = name.chars().collect();
    chars
        .iter()
        .enumerate()
        .filter(|&(i, c)| {
            let body = matches!(c, '1' | '2')
                && i > 0
                && chars[i - 1].is_ascii_alphabetic()
                && chars.get(i + 1).is_none_or(|n| *n == '_');
            !body
        })
        .map(|(_, c)| *c)
        .collect()
}

/// The unit to print after placeholder `name` of `template`: `""` when the
/// template already writes it there (`{rotation_degrees1}°`).
pub fn unit_to_add(template: &str, name: &str, unit: &'static str) -> &'static str {
    let written = !unit.is_empty()
        && template
            .split(&format!("{{{name}}}"))
            .skip(1)
            .all(|after| after.trim_start().starts_with(unit));
    if written {
        ""
    } else {
        unit
    }
}

/// `number unit` as printed (`2.25 m/s`, `7.88°`, `0.8`).
pub fn with_unit(number: &str, unit: &str) -> String {
    match unit {
        "" => number.to_string(),
        "°" => format!("{number}°"),
        u => format!("{number} {u}"),
    }
}

/// The unit in LaTeX maths (`\,\mathrm{m/s}`), empty for a pure number.
pub fn unit_latex(unit: &str) -> String {
    if unit.is_empty() {
        return String::new();
    }
    if unit == "°" {
        // `{}` keeps 10^{-5}° from being a double superscript.
        return "{}^{\\circ}".to_string();
    }
    let body = unit
        .replace('·', "\\cdot ")
        .replace("⁻¹", "^{-1}")
        .replace("⁻²", "^{-2}")
        .replace('²', "^2");
    format!("\\,\\mathrm{{{body}}}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn symbols_are_found_whole_not_inside_longer_names() {
        let names = |t: &str| -> Vec<&str> { symbols_in(t).iter().map(|s| s.symbol).collect() };
        assert_eq!(names("u_d₁ = r₁ × d̂"), vec!["d̂", "rᵢ", "u_dᵢ"]);
        assert_eq!(names("Δv = -(1 + c) v_s"), vec!["v_s", "c", "Δv"]);
        assert!(!names("v_s′ = 1").contains(&"v_s"));
        assert!(!names("Δθ̇_d₁ = I₁⁻¹ u_d₁").contains(&"Δθ̇ᵢ"));
        assert!(names("g_max = μ_s g_x").contains(&"g_x, g_y, g_z"));
        assert!(!names("g_max = μ_s g_x").contains(&"g"));
    }

    #[test]
    fn units_print_with_their_numbers() {
        assert_eq!(with_unit("2.25", "m/s"), "2.25 m/s");
        assert_eq!(with_unit("7.9", "°"), "7.9°");
        assert_eq!(with_unit("0.8", ""), "0.8");
        assert_eq!(unit_latex("kg·m²"), "\\,\\mathrm{kg\\cdot m^2}");
    }
}
