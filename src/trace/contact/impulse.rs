//! The `impulse` stage described: g = Δv / Δq̇_t without friction, the
//! sticking impulse M⁻¹ (Δv, -v_y, -v_z) with it, and the closed form j.

use super::builder::{skip_reason, SolvedContact, B};
use crate::physics::solve::Skip;
use crate::physics::StageId;
use crate::trace::Step;

/// The impulse before any friction clamp, contact and world space.
pub fn impulse(c: &SolvedContact) -> Step {
    let mut b = B::new(StageId::Impulse);
    let Some(g) = &c.solution.impulse else {
        return b.skipped(skip_reason(Skip::Separating));
    };
    let d = c.solution.frame.normal();
    b.input("d", d);
    b.input("desired", c.solution.desired.desired);
    b.input("total", c.solution.unit.total);
    b.input("contact_to_world", c.solution.frame.contact_to_world);
    b.value("impulse_contact", g.impulse_contact);
    b.value("impulse_world", g.impulse_world);
    match &g.solve {
        None => {
            b.input("g", g.impulse_contact.x);
            b.f("g", "Δv / Δq̇_t", Some("{desired} / {total}"), Some("g"));
            b.f(
                "g_contact",
                "(g, 0, 0)",
                Some("({g}, 0, 0)"),
                Some("impulse_contact"),
            );
            b.f(
                "g_world",
                "C g_contact = g d̂",
                Some("{g} {d}"),
                Some("impulse_world"),
            );
        }
        Some(solve) => {
            b.input("matrix", c.solution.unit.matrix.unwrap_or_default());
            b.input("rhs", solve.rhs);
            // κ(M) exactly (the stage path kept only the factor's bound).
            let kappa = c
                .solution
                .condition_number()
                .unwrap_or(solve.condition_number);
            b.value("condition_number", kappa);
            b.f(
                "g_contact",
                "M⁻¹ (Δv, -v_y, -v_z)",
                Some("{matrix}⁻¹ {rhs}"),
                Some("impulse_contact"),
            );
            b.f(
                "g_world",
                "C g_contact",
                Some("{contact_to_world} {impulse_contact}"),
                Some("impulse_world"),
            );
            b.note("This is the sticking impulse: it meets the normal target and removes all sliding. The friction clamp decides whether friction can supply it.");
            b.note("κ(M) = {condition_number}: about log₁₀ κ of the 16 significant digits of f64 are lost solving for g.");
            if solve.ill_conditioned {
                b.note("ILL-CONDITIONED: κ(M) · ε > 10⁻³, so fewer than three digits of g can be trusted (a huge mass with a tiny inertia, or the reverse).");
            }
            if solve.singular {
                b.note("SINGULAR: M could not be factorised, or κ(M) · ε ≥ 1 so no digit of g would be right; the frictionless impulse Δv / Δq̇_t is used instead.");
            } else if solve.used_lu {
                b.note("M is not numerically positive-definite (Cholesky failed); LU was used.");
            }
        }
    }
    b.value("closed_form_j", g.closed_form_j);
    b.value(
        "closed_form_relative_difference",
        g.closed_form_relative_difference,
    );
    b.input("restitution", c.solution.desired.restitution);
    b.input("separating_velocity", c.solution.desired.separating());
    let mut denominator = vec!["{linear}"];
    b.input("linear", c.solution.unit.linear);
    for i in c.movable() {
        b.input(
            slot!(i => "angular" N),
            c.solution.unit.bodies[i].as_ref().expect("movable").angular,
        );
        denominator.push(slot!(i => "{angular" N "}"));
    }
    b.f(
        "g_closed",
        "-(1 + c) v_s / (Σ 1/mᵢ + Σ (rᵢ × d̂)ᵀ Iᵢ⁻¹ (rᵢ × d̂))",
        Some(format!(
            "-(1 + {{restitution}})({{separating_velocity}}) / ({})",
            denominator.join(" + ")
        )),
        Some("closed_form_j"),
    );
    b.note("The collisions lectures (Lecture IV Collisions; Pronost) write this closed form as j = -(1 + C_R)(v_rel · n) / (…): their j is g here, n is d̂, v_rel · n is v_s and C_R is c. Each (rᵢ × d̂)ᵀ Iᵢ⁻¹ (rᵢ × d̂) equals Δq̇_dᵢ of stage 2.");
    if g.solve.is_some() {
        b.note("For comparison, without friction the closed form gives g_closed = {closed_form_j} along the normal.");
    } else if c.solution.desired.velocity_from_acceleration == 0.0 {
        b.note("The closed form g_closed = {closed_form_j} agrees with Δv / Δq̇_t to a relative {closed_form_relative_difference}: the same number by a different route ((r × d̂)ᵀ I⁻¹ (r × d̂) = ((I⁻¹(r × d̂)) × r) · d̂).");
    } else {
        b.note("The closed form g_closed = {closed_form_j} has no acceleration compensation, so it differs from Δv / Δq̇_t here (relative {closed_form_relative_difference}).");
    }
    b.done()
}
