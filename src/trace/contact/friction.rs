//! The `friction_clamp` stage described: whether the contact sticks or
//! slides, under the friction model the contact uses.

use super::builder::{skip_reason, SolvedContact, B};
use crate::knobs::Choice;
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
            b.input("sticking_y", g.impulse_contact.y);
            b.input("sticking_z", g.impulse_contact.z);
            b.f(
                "|g_planar|",
                "√(g_y² + g_z²)",
                Some("√(({sticking_y})² + ({sticking_z})²)"),
                Some("planar"),
            );
            b.f(
                "g_max",
                "μ_s g_x",
                Some("{mu_s} · {sticking_normal}"),
                Some("limit"),
            );
            if f.regime == FrictionRegime::Static {
                b.note("|g_planar| ≤ g_max = μ_s g_x: static friction can supply the sticking impulse, so the contact sticks and the impulse is unchanged. μ_s decided the regime.");
            } else if f.issue == Some(FrictionIssue::Jamming) {
                b.note("JAMMING: M₀₀ + μ_d(M₀₁ f̂_y + M₀₂ f̂_z) ≤ 0, friction would need a negative normal impulse; the frictionless impulse is used instead.");
            } else {
                b.input("matrix", c.solution.unit.matrix.unwrap_or_default());
                b.value("direction", f.direction);
                b.value("normal_per_unit", f.normal_per_unit);
                b.value("normal_impulse", f.impulse_contact.x);
                let m = c.solution.unit.matrix.unwrap_or_default();
                b.input("m00", m[(0, 0)]);
                b.input("m01", m[(0, 1)]);
                b.input("m02", m[(0, 2)]);
                b.input("fy", f.direction.y);
                b.input("fz", f.direction.z);
                b.input("friction_y", f.impulse_contact.y);
                b.input("friction_z", f.impulse_contact.z);
                b.f(
                    "f̂",
                    "(0, g_y, g_z) / |g_planar|",
                    Some("(0, {sticking_y}, {sticking_z}) / {planar}"),
                    Some("direction"),
                );
                b.f(
                    "M₀₀ + μ_d (M₀₁ f̂_y + M₀₂ f̂_z)",
                    "",
                    Some("{m00} + {mu_d} · (({m01}) · ({fy}) + ({m02}) · ({fz}))"),
                    Some("normal_per_unit"),
                );
                b.f(
                    "g_n",
                    "Δv / (M₀₀ + μ_d (M₀₁ f̂_y + M₀₂ f̂_z))",
                    Some("{desired} / {normal_per_unit}"),
                    Some("normal_impulse"),
                );
                b.f(
                    "g_contact",
                    "(g_n, μ_d g_n f̂_y, μ_d g_n f̂_z)",
                    Some("({normal_impulse}, {mu_d} · {normal_impulse} · ({fy}), {mu_d} · {normal_impulse} · ({fz}))"),
                    Some("impulse_contact"),
                );
                b.note("|g_planar| > g_max = μ_s g_x: the contact slides. μ_s decided the regime; μ_d = {mu_d} sizes the tangential impulse μ_d g_n along the sticking impulse's direction f̂, and g_n is recomputed so the normal velocity target Δv still holds.");
            }
        }
        FrictionModel::VelocityScaling => {
            let v = c.solution.desired.contact_velocity;
            b.input("vx", v.x);
            b.input("vy", v.y);
            b.input("vz", v.z);
            b.f(
                "|v_planar|",
                "√(v_y² + v_z²)",
                Some("√(({vy})² + ({vz})²)"),
                Some("planar"),
            );
            b.f("v_max", "-μ_s v_s", Some("-{mu_s} · ({vx})"), Some("limit"));
            if f.regime == FrictionRegime::Static {
                b.note("The friction lecture's model (PSE Friction): |v_planar| ≤ v_max = -μ_s v_s, so all planar velocity is removed (the sticking impulse). Here planar and limit are velocities, not impulses.");
            } else {
                b.input("matrix", c.solution.unit.matrix.unwrap_or_default());
                b.f(
                    "g_contact",
                    "M⁻¹ (Δv, -μ_d v_y, -μ_d v_z)",
                    Some("{matrix}⁻¹ ({desired}, -{mu_d} · ({vy}), -{mu_d} · ({vz}))"),
                    Some("impulse_contact"),
                );
                b.note("The friction lecture's model (PSE Friction): |v_planar| > v_max = -μ_s v_s, so the planar velocity is reduced by μ_d·v_planar rather than removed. This is not Coulomb's law: the impulse may leave the friction cone.");
            }
        }
        FrictionModel::KineticDirection => {
            let v = c.solution.desired.contact_velocity;
            b.input("direction", f.direction);
            b.input("vy", v.y);
            b.input("vz", v.z);
            b.input("closed_form_j", g.closed_form_j);
            b.f(
                "f̂",
                "(0, -v_y, -v_z) / √(v_y² + v_z²)",
                Some("(0, -({vy}), -({vz})) / √(({vy})² + ({vz})²)"),
                Some("direction"),
            );
            b.f(
                "g_contact",
                "g_closed ((1, 0, 0) + μ_d f̂)",
                Some("{closed_form_j} ((1, 0, 0) + {mu_d} {direction})"),
                Some("impulse_contact"),
            );
            if f.issue == Some(FrictionIssue::UndefinedDirection) {
                b.note("The collisions lectures' model (Lecture IV Collisions; Pronost; they write j (n + μ_k t): j is g_closed of stage 4, n is d̂, μ_k is μ_d): the slip direction is undefined because nothing slides (the relative velocity is along d̂); the model applies no friction impulse.");
            } else {
                b.note("The collisions lectures' model (Lecture IV Collisions; Pronost; they write j (n + μ_k t): j is g_closed of stage 4, n is d̂, μ_k is μ_d): friction μ_d g_closed acts along f̂, against the sliding direction, whatever the sliding speed, so it may reverse the slip. These lectures write t along the sliding velocity; friction must oppose it, so f̂ = -t.");
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
