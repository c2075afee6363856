//! The `friction_clamp` stage described: whether the contact sticks or
//! slides, under the friction model the contact uses.

use super::builder::{skip_reason, SolvedContact, B};
use crate::physics::stages::friction::FrictionIssue;
use crate::physics::stages::FrictionRegime;
use crate::physics::{FrictionModel, StageId};
use crate::trace::Step;

/// The regime's JSON value: `"static"` (sticks) or `"dynamic"` (slides).
pub fn regime_name(regime: FrictionRegime) -> &'static str {
    match regime {
        FrictionRegime::Static => "static",
        FrictionRegime::Dynamic => "dynamic",
    }
}

/// The regime, the Coulomb limit and the impulse after the clamp.
pub fn friction(c: &SolvedContact) -> Step {
    let mut b = B::new(StageId::FrictionClamp);
    if let Some(skip) = c.solution.skip(StageId::FrictionClamp) {
        return b.skipped(skip_reason(skip));
    }
    let f = c.solution.friction.as_ref().expect("friction ran");
    let g = c.solution.impulse.as_ref().expect("impulse ran");
    let contact = &c.problem.contact;
    b.input("mu_s", contact.static_friction);
    b.input("mu_d", contact.dynamic_friction);
    b.input("sticking", g.impulse_contact);
    b.input("sticking_normal", g.impulse_contact.x);
    b.input("desired", c.solution.desired.desired);
    b.input("contact_to_world", c.solution.frame.contact_to_world);
    b.value("model", f.model.name());
    b.value("regime", regime_name(f.regime));
    let (decided_by, sized_by) = match (f.model, f.regime) {
        (FrictionModel::KineticDirection, _) => ("none (always sliding)", "dynamic_friction"),
        (_, FrictionRegime::Static) => ("static_friction", "none (the sticking impulse)"),
        (_, FrictionRegime::Dynamic) => ("static_friction", "dynamic_friction"),
    };
    b.value("decided_by", decided_by);
    b.value("sized_by", sized_by);
    b.value("planar", f.planar);
    b.value("limit", f.limit);
    b.value("impulse_contact", f.impulse_contact);
    b.value("impulse_world", f.impulse_world);
    match f.model {
        FrictionModel::Millington => {
            b.f("|g_planar|", "√(g_y² + g_z²)", None, Some("planar"));
            b.f(
                "limit",
                "μ_s g_n",
                Some("{mu_s} × {sticking_normal}"),
                Some("limit"),
            );
            if f.regime == FrictionRegime::Static {
                b.note("|g_planar| ≤ μ_s g_n: static friction can supply the sticking impulse, so the contact sticks and the impulse is unchanged. μ_s decided the regime.");
            } else if f.issue == Some(FrictionIssue::Jamming) {
                b.note("JAMMING: M₀₀ + μ_d(M₀₁u_y + M₀₂u_z) ≤ 0, friction would need a negative normal impulse; the frictionless impulse is used instead.");
            } else {
                b.input("matrix", c.solution.unit.matrix.unwrap_or_default());
                b.value("direction", f.direction);
                b.value("normal_per_unit", f.normal_per_unit);
                b.value("normal_impulse", f.impulse_contact.x);
                b.f("u", "(0, g_y, g_z) / |g_planar|", None, Some("direction"));
                b.f(
                    "M₀₀ + μ_d (M₀₁ u_y + M₀₂ u_z)",
                    "",
                    None,
                    Some("normal_per_unit"),
                );
                b.f(
                    "g_n",
                    "Δv / (M₀₀ + μ_d (M₀₁ u_y + M₀₂ u_z))",
                    Some("{desired} / {normal_per_unit}"),
                    Some("normal_impulse"),
                );
                b.f(
                    "g",
                    "(g_n, μ_d g_n u_y, μ_d g_n u_z)",
                    None,
                    Some("impulse_contact"),
                );
                b.note("|g_planar| > μ_s g_n: the contact slides. μ_s decided the regime; μ_d = {mu_d} sizes the tangential impulse μ_d g_n along the sticking impulse's direction u, and g_n is recomputed so the normal velocity target Δv still holds.");
            }
        }
        FrictionModel::VelocityScaling => {
            b.f("|v_planar|", "√(v_y² + v_z²)", None, Some("planar"));
            b.f("limit", "v_c μ_s", None, Some("limit"));
            if f.regime == FrictionRegime::Static {
                b.note("Seed 004's model: |v_planar| ≤ v_c μ_s, so all planar velocity is removed (the sticking impulse). Here planar and limit are velocities, not impulses.");
            } else {
                b.f(
                    "g",
                    "M⁻¹ (Δv, −μ_d v_y, −μ_d v_z)",
                    None,
                    Some("impulse_contact"),
                );
                b.note("Seed 004's model: |v_planar| > v_c μ_s, so the planar velocity is reduced by μ_d·v_planar rather than removed. This is not Coulomb's law: the impulse may leave the friction cone.");
            }
        }
        FrictionModel::KineticDirection => {
            b.f("g", "j (n + μ_k t)", None, Some("impulse_world"));
            if f.issue == Some(FrictionIssue::UndefinedDirection) {
                b.note("Seeds 002/003's model: t = (n × v_rel) × n / |…| is undefined because nothing slides (v_rel ∥ n); the model applies no friction impulse.");
            } else {
                b.note("Seeds 002/003's model: friction μ_k j acts against the sliding direction t, whatever the sliding speed, so it may reverse the slip. The seeds write t along the sliding velocity; friction must oppose it, so contact-lab uses −t.");
            }
        }
    }
    b.f(
        "g_world",
        "C g_contact",
        Some("{contact_to_world} {impulse_contact}"),
        Some("impulse_world"),
    );
    b.done()
}
