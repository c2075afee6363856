//! The `unit_impulse` stage described: the velocity change per unit impulse
//! along the normal, and with friction the 3×3 matrix M in contact space.

use super::builder::{through_centre, SolvedContact, B, SUB};
use crate::physics::StageId;
use crate::trace::Step;

/// Δq̇_t = Σ 1/mᵢ + Σ ((Iᵢ⁻¹(rᵢ × d̂)) × rᵢ) · d̂, and M when friction needs it.
pub fn unit_impulse(c: &SolvedContact) -> Step {
    let mut b = B::new(StageId::UnitImpulse);
    let u = &c.solution.unit;
    let d = c.solution.frame.normal();
    b.input("d", d);
    let mut parts = Vec::new();
    for i in 0..2 {
        let n = i + 1;
        if let Some(body) = &c.problem.bodies[i] {
            b.input(format!("m{n}"), body.mass);
            parts.push(format!("1/{{m{n}}}"));
        } else if c.names.bodies[i].is_some() {
            parts.push("1/∞".to_string());
        }
    }
    b.value("linear", u.linear);
    b.f("Δṗ_d", "Σ 1/mᵢ", Some(&parts.join(" + ")), Some("linear"));
    let mut total_parts = vec!["{linear}".to_string()];
    for i in c.movable() {
        let n = i + 1;
        let s = SUB[i];
        let r = u.bodies[i].as_ref().expect("movable");
        b.input(format!("r{n}"), c.r(i));
        b.value(format!("inertia{n}"), c.body(i).inertia_body);
        if let Some(t) = c.names.written.shape_inertia[i] {
            b.value(format!("shape_inertia{n}"), t);
        }
        b.value(format!("inverse_inertia_world{n}"), r.inverse_inertia_world);
        b.value(format!("torque{n}"), r.torque_per_unit_impulse);
        b.value(format!("rotation{n}"), r.rotation_per_unit_impulse);
        b.value(format!("velocity{n}"), r.velocity_per_unit_impulse);
        b.value(format!("angular{n}"), r.angular);
        b.f(
            &format!("u_d{s}"),
            &format!("r{s} × d̂"),
            Some(&format!("{{r{n}}} × {{d}}")),
            Some(&format!("torque{n}")),
        );
        b.f(
            &format!("Δθ̇_d{s}"),
            &format!("I{s}⁻¹ u_d{s}"),
            Some(&format!("{{inverse_inertia_world{n}}} {{torque{n}}}")),
            Some(&format!("rotation{n}")),
        );
        b.f(
            &format!("Δq̇{s}"),
            &format!("Δθ̇_d{s} × r{s}"),
            Some(&format!("{{rotation{n}}} × {{r{n}}}")),
            Some(&format!("velocity{n}")),
        );
        b.f(
            &format!("Δq̇_d{s}"),
            &format!("Δq̇{s} · d̂"),
            Some(&format!("{{velocity{n}}} · {{d}}")),
            Some(&format!("angular{n}")),
        );
        total_parts.push(format!("{{angular{n}}}"));
        if through_centre(&c.r(i), &d) {
            b.note(format!(
                "For {} the normal passes through the centre of mass (r × d̂ ≈ 0), so the angular term is zero: only the linear term resists the impulse.",
                c.name(i)
            ));
        }
    }
    b.value("total", u.total);
    b.f(
        "Δq̇_t",
        "Δṗ_d + Σ Δq̇_dᵢ",
        Some(&total_parts.join(" + ")),
        Some("total"),
    );
    for i in c.immovable_named() {
        b.note(format!(
            "{} is immovable: 1/m = 0 and I⁻¹ = 0, so it adds nothing.",
            c.name(i)
        ));
    }
    if let Some(m) = u.matrix {
        matrix(c, &mut b, m);
    }
    b.done()
}

/// The friction matrix M = Cᵀ (Σ -[rᵢ]× Iᵢ⁻¹ [rᵢ]×) C + (Σ 1/mᵢ) 𝟙.
fn matrix(c: &SolvedContact, b: &mut B, m: nalgebra::Matrix3<f64>) {
    for i in c.movable() {
        let n = i + 1;
        let r = c.solution.unit.bodies[i].as_ref().expect("movable");
        let s = SUB[i];
        b.value(format!("skew_r{n}"), r.skew_r);
        b.f(&format!("[r{s}]×"), "", None, Some(&format!("skew_r{n}")));
        if let Some(a) = r.angular_matrix_world {
            b.value(format!("angular_matrix_world{n}"), a);
            b.f(
                &format!("-[r{s}]× I{s}⁻¹ [r{s}]×"),
                "",
                Some(&format!(
                    "-{{skew_r{n}}} {{inverse_inertia_world{n}}} {{skew_r{n}}}"
                )),
                Some(&format!("angular_matrix_world{n}")),
            );
        }
    }
    b.value("matrix", m);
    b.input("contact_to_world", c.solution.frame.contact_to_world);
    let sum = c
        .movable()
        .into_iter()
        .filter(|&i| {
            let r = c.solution.unit.bodies[i].as_ref().expect("movable");
            r.angular_matrix_world.is_some()
        })
        .map(|i| format!("{{angular_matrix_world{}}}", i + 1))
        .collect::<Vec<_>>()
        .join(" + ");
    let sum = if sum.is_empty() { "0".to_string() } else { sum };
    b.f(
        "M",
        "Cᵀ (Σ -[rᵢ]× Iᵢ⁻¹ [rᵢ]×) C + (Σ 1/mᵢ) 𝟙",
        Some(&format!(
            "{{contact_to_world}}ᵀ ({sum}) {{contact_to_world}} + {{linear}} 𝟙"
        )),
        Some("matrix"),
    );
    b.note("With friction all three contact directions matter: M maps an impulse in contact coordinates to the velocity change it causes. M[0][0] equals Δq̇_t.");
    b.note("The lecture writes M_C→W (…) M_C→Wᵀ; converting a world matrix into contact space takes Cᵀ (…) C (as the reference code does).");
}
