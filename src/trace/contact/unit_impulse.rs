//! The `unit_impulse` stage described: the velocity change per unit impulse
//! along the normal, and with friction the 3×3 matrix M in contact space.

use super::builder::{through_centre, SolvedContact, B};
use crate::physics::contact::stages::unit_impulse::angular_matrix;
use crate::physics::frame::skew;
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
        if let Some(body) = &c.problem.bodies[i] {
            b.input(slot!(i => "m" N), body.mass);
            parts.push(slot!(i => "1/{m" N "}"));
        } else if c.names.bodies[i].is_some() {
            parts.push("1/∞");
        }
    }
    b.value("linear", u.linear);
    b.f("Δṗ_d", "Σ 1/mᵢ", Some(parts.join(" + ")), Some("linear"));
    let mut total_parts = vec!["{linear}"];
    for i in c.movable() {
        let r = u.bodies[i].as_ref().expect("movable");
        b.input(slot!(i => "r" N), c.r(i));
        b.value(slot!(i => "inertia" N), c.body(i).inertia_body);
        if let Some(t) = c.names.written.shape_inertia[i] {
            b.value(slot!(i => "shape_inertia" N), t);
        }
        b.value(
            slot!(i => "inverse_inertia_world" N),
            c.body(i).inverse_inertia_world(),
        );
        b.value(slot!(i => "torque" N), r.torque_per_unit_impulse);
        b.value(slot!(i => "rotation" N), r.rotation_per_unit_impulse);
        b.value(slot!(i => "velocity" N), r.velocity_per_unit_impulse);
        b.value(slot!(i => "angular" N), r.angular);
        b.f(
            slot!(i => "u_d" S),
            slot!(i => "r" S " × d̂"),
            Some(slot!(i => "{r" N "} × {d}")),
            Some(slot!(i => "torque" N)),
        );
        b.f(
            slot!(i => "Δθ̇_d" S),
            slot!(i => "I" S "⁻¹ u_d" S),
            Some(slot!(i => "{inverse_inertia_world" N "} {torque" N "}")),
            Some(slot!(i => "rotation" N)),
        );
        b.f(
            slot!(i => "Δq̇" S),
            slot!(i => "Δθ̇_d" S " × r" S),
            Some(slot!(i => "{rotation" N "} × {r" N "}")),
            Some(slot!(i => "velocity" N)),
        );
        b.f(
            slot!(i => "Δq̇_d" S),
            slot!(i => "Δq̇" S " · d̂"),
            Some(slot!(i => "{velocity" N "} · {d}")),
            Some(slot!(i => "angular" N)),
        );
        total_parts.push(slot!(i => "{angular" N "}"));
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
        Some(total_parts.join(" + ")),
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
        // `[r]×` and `-[r]× I⁻¹ [r]×` from the body, by the functions the
        // stage summed into M (the record keeps only M).
        let skew_r = skew(&c.r(i));
        let angular = angular_matrix(&skew_r, &c.body(i).inverse_inertia_world());
        b.value(slot!(i => "skew_r" N), skew_r);
        b.f(
            slot!(i => "[r" S "]×"),
            "",
            None::<&str>,
            Some(slot!(i => "skew_r" N)),
        );
        b.value(slot!(i => "angular_matrix_world" N), angular);
        b.f(
            slot!(i => "-[r" S "]× I" S "⁻¹ [r" S "]×"),
            "",
            Some(slot!(i => "-{skew_r" N "} {inverse_inertia_world" N "} {skew_r" N "}")),
            Some(slot!(i => "angular_matrix_world" N)),
        );
    }
    b.value("matrix", m);
    b.input("contact_to_world", c.solution.frame.contact_to_world);
    let sum = c
        .movable()
        .map(|i| slot!(i => "{angular_matrix_world" N "}"))
        .collect::<Vec<_>>()
        .join(" + ");
    let sum = if sum.is_empty() { "0".to_string() } else { sum };
    b.f(
        "M",
        "Cᵀ (Σ -[rᵢ]× Iᵢ⁻¹ [rᵢ]×) C + (Σ 1/mᵢ) 𝟙",
        Some(format!(
            "{{contact_to_world}}ᵀ ({sum}) {{contact_to_world}} + {{linear}} 𝟙"
        )),
        Some("matrix"),
    );
    b.note("With friction all three contact directions matter: M maps an impulse in contact coordinates to the velocity change it causes. M[0][0] equals Δq̇_t.");
    b.note("The lecture writes M_C→W (…) M_C→Wᵀ; converting a world matrix into contact space takes Cᵀ (…) C (as the reference code does).");
}
