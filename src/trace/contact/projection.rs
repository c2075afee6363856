//! The `nonlinear_projection` stage described: the penetration shared out
//! as linear and angular moves by each body's inertia along the normal.

use super::builder::{skip_reason, through_centre, SolvedContact, B, SUB};
use crate::physics::solve::Skip;
use crate::physics::{ProjectionMethod, StageId};
use crate::trace::Step;

/// Δ_l = (-1)^(i+1) d_pen I_l / I_t, Δ_a likewise, with the angular limit.
pub fn projection(c: &SolvedContact) -> Step {
    let mut b = B::new(StageId::NonlinearProjection);
    let Some(p) = &c.solution.projection else {
        return b.skipped(skip_reason(Skip::NoPenetration));
    };
    let settings = &c.problem.contact.settings;
    b.input("d", c.solution.frame.normal());
    b.input("d_pen", c.problem.contact.penetration);
    b.input("relaxation", settings.relaxation);
    b.input("angular_limit_setting", settings.angular_limit);
    b.value("method", p.method.name());
    b.value("resolved_depth", p.resolved_depth);
    let relaxed = settings.relaxation != 1.0;
    // One symbol for the depth this projection resolves: d_pen, or d_res when relaxed.
    let depth_symbol = if relaxed { "d_res" } else { "d_pen" };
    if relaxed {
        b.f(
            "d_res",
            "d_pen · relaxation",
            Some("{d_pen} · {relaxation}"),
            Some("resolved_depth"),
        );
    }
    let nonlinear = p.method == ProjectionMethod::Nonlinear;
    let mut total = Vec::new();
    for i in c.movable() {
        let n = i + 1;
        let s = SUB[i];
        let m = p.bodies[i].as_ref().expect("movable");
        b.input(format!("m{n}"), c.body(i).mass);
        b.input(format!("r{n}"), c.r(i));
        b.input(
            format!("inverse_inertia_world{n}"),
            c.body(i).inverse_inertia_world(),
        );
        b.value(format!("linear_inertia{n}"), m.linear_inertia);
        b.value(format!("angular_inertia{n}"), m.angular_inertia);
        b.f(
            &format!("I_l{s}"),
            &format!("1/m{s}"),
            Some(&format!("1/{{m{n}}}")),
            Some(&format!("linear_inertia{n}")),
        );
        if nonlinear {
            b.f(
                &format!("Δθ̇_d{s}"),
                &format!("I{s}⁻¹(r{s} × d̂)"),
                Some(&format!("{{inverse_inertia_world{n}}} ({{r{n}}} × {{d}})")),
                Some(&format!("rotation_per_unit{n}")),
            );
            b.f(
                &format!("I_a{s}"),
                &format!("(Δθ̇_d{s} × r{s}) · d̂"),
                Some(&format!("({{rotation_per_unit{n}}} × {{r{n}}}) · {{d}}")),
                Some(&format!("angular_inertia{n}")),
            );
            total.push(format!("{{linear_inertia{n}}} + {{angular_inertia{n}}}"));
        } else {
            total.push(format!("{{linear_inertia{n}}}"));
        }
    }
    b.value("total_inertia", p.total_inertia);
    b.f(
        "I_t",
        if nonlinear {
            "Σ (I_lᵢ + I_aᵢ)"
        } else {
            "Σ I_lᵢ"
        },
        Some(&total.join(" + ")),
        Some("total_inertia"),
    );
    let depth = if relaxed {
        "{resolved_depth}"
    } else {
        "{d_pen}"
    };
    for i in c.movable() {
        let n = i + 1;
        let s = SUB[i];
        let sign = if i == 0 { "" } else { "-" };
        let m = p.bodies[i].as_ref().expect("movable");
        b.input(format!("p{n}"), c.body(i).position);
        b.value(format!("linear_move{n}"), m.linear_move);
        b.value(format!("angular_move{n}"), m.angular_move);
        if m.angular_limit.is_finite() {
            b.value(format!("angular_limit{n}"), m.angular_limit);
        } else {
            b.value(format!("angular_limit{n}"), "none");
        }
        b.input(format!("r_perp_length{n}"), m.r_perp_length);
        b.value(format!("linear_change{n}"), m.linear_change);
        b.value(format!("rotation_per_unit{n}"), m.rotation_per_unit);
        b.value(format!("angular_change{n}"), m.angular_change);
        b.value(format!("position{n}"), m.position);
        let e = format!("(-1)^({n}+1)");
        // Before the limit; when it acts, the clamped moves follow below.
        b.input(
            format!("angular_move_unlimited{n}"),
            m.angular_move_unlimited,
        );
        b.input(format!("linear_move_unlimited{n}"), m.linear_move_unlimited);
        let (lin, ang) = if m.limited {
            (
                format!("linear_move_unlimited{n}"),
                format!("angular_move_unlimited{n}"),
            )
        } else {
            (format!("linear_move{n}"), format!("angular_move{n}"))
        };
        b.f(
            &format!("Δ_l{s}"),
            &format!("{e} {depth_symbol} I_l{s} / I_t"),
            Some(&format!(
                "{sign}{depth} · {{linear_inertia{n}}} / {{total_inertia}}"
            )),
            Some(&lin),
        );
        if !nonlinear {
            // Linear projection: no angular share, no limit, no turn.
            b.f(
                &format!("Δp{s}"),
                &format!("Δ_l{s} d̂"),
                Some(&format!("{{linear_move{n}}} {{d}}")),
                Some(&format!("linear_change{n}")),
            );
            b.f(
                &format!("p{s}′"),
                &format!("p{s} + Δp{s}"),
                Some(&format!("{{p{n}}} + {{linear_change{n}}}")),
                Some(&format!("position{n}")),
            );
            continue;
        }
        b.f(
            &format!("Δ_a{s}"),
            &format!("{e} {depth_symbol} I_a{s} / I_t"),
            Some(&format!(
                "{sign}{depth} · {{angular_inertia{n}}} / {{total_inertia}}"
            )),
            Some(&ang),
        );
        if !m.angular_limit.is_finite() {
            b.note("angular_limit = inf: the angular move is not limited.");
        } else {
            b.f(
                &format!("Δ_max{s}"),
                &format!("angular_limit · |r{s} - (r{s} · d̂) d̂|"),
                Some(&format!("{{angular_limit_setting}} · {{r_perp_length{n}}}")),
                Some(&format!("angular_limit{n}")),
            );
        }
        if m.limited {
            b.f(
                &format!("Δ_a{s} (limited)"),
                &format!("±Δ_max{s}"),
                None,
                Some(&format!("angular_move{n}")),
            );
            b.f(
                &format!("Δ_l{s} (limited)"),
                &format!("Δ_l{s} + (Δ_a{s} - Δ_a{s} (limited))"),
                Some(&format!("{{linear_move_unlimited{n}}} + ({{angular_move_unlimited{n}}} - {{angular_move{n}}})")),
                Some(&format!("linear_move{n}")),
            );
            b.note(format!(
                "Excessive rotation: {}'s angular move {{angular_move_unlimited{n}}} exceeds the limit Δ_max{s} = {{angular_limit{n}}}; it is cut to the limit and the excess moves to the linear share ({{linear_move_unlimited{n}}} → {{linear_move{n}}}).",
                c.name(i)
            ));
        }
        b.f(
            &format!("Δp{s}"),
            &format!("Δ_l{s} d̂"),
            Some(&format!("{{linear_move{n}}} {{d}}")),
            Some(&format!("linear_change{n}")),
        );
        if m.angular_inertia == 0.0 || m.angular_move == 0.0 {
            // Δ_a / I_a would be 0 / 0 or 0: no turn, said rather than divided.
            b.f(
                &format!("Δθ{s}"),
                "0",
                None,
                Some(&format!("angular_change{n}")),
            );
            b.note(format!(
                "{} takes no angular share (Δ_a{s} = 0), so it does not turn: Δθ{s} = 0.",
                c.name(i)
            ));
        } else {
            b.f(
                &format!("Δθ{s}"),
                &format!("(Δ_a{s} / I_a{s}) Δθ̇_d{s}"),
                Some(&format!(
                    "({{angular_move{n}}} / {{angular_inertia{n}}}) {{rotation_per_unit{n}}}"
                )),
                Some(&format!("angular_change{n}")),
            );
        }
        b.f(
            &format!("p{s}′"),
            &format!("p{s} + Δp{s}"),
            Some(&format!("{{p{n}}} + {{linear_change{n}}}")),
            Some(&format!("position{n}")),
        );
        let d = c.solution.frame.normal();
        if through_centre(&c.r(i), &d) {
            b.note(format!(
                "{}'s contact arm lies along the normal (r × d̂ ≈ 0): its angular inertia is (all but) zero, so it (all but) only translates.",
                c.name(i)
            ));
        }
    }
    if p.method == ProjectionMethod::Linear {
        b.note("Linear projection: each body moves along the normal in proportion to its inverse mass; nothing rotates.");
    }
    b.note(format!(
        "The moves of all bodies add up to the depth resolved: Σ (|Δ_lᵢ| + |Δ_aᵢ|) = {depth_symbol} = {depth}."
    ));
    b.done()
}
