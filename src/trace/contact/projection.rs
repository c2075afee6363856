//! The `nonlinear_projection` stage described: the penetration shared out
//! as linear and angular moves by each body's inertia along the normal.

use super::builder::{skip_reason, through_centre, SolvedContact, B, SUB};
use crate::knobs::Choice;
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
        let m = p.bodies[i].as_ref().expect("movable");
        b.input(slot!(i => "m" N), c.body(i).mass);
        b.input(slot!(i => "r" N), c.r(i));
        b.input(
            slot!(i => "inverse_inertia_world" N),
            c.body(i).inverse_inertia_world(),
        );
        b.value(slot!(i => "linear_inertia" N), m.linear_inertia);
        b.value(slot!(i => "angular_inertia" N), m.angular_inertia);
        b.f(
            slot!(i => "I_l" S),
            slot!(i => "1/m" S),
            Some(slot!(i => "1/{m" N "}")),
            Some(slot!(i => "linear_inertia" N)),
        );
        if nonlinear {
            b.f(
                slot!(i => "Δθ̇_d" S),
                slot!(i => "I" S "⁻¹(r" S " × d̂)"),
                Some(slot!(i => "{inverse_inertia_world" N "} ({r" N "} × {d})")),
                Some(slot!(i => "rotation_per_unit" N)),
            );
            b.f(
                slot!(i => "I_a" S),
                slot!(i => "(Δθ̇_d" S " × r" S ") · d̂"),
                Some(slot!(i => "({rotation_per_unit" N "} × {r" N "}) · {d}")),
                Some(slot!(i => "angular_inertia" N)),
            );
            total.push(slot!(i => "{linear_inertia" N "} + {angular_inertia" N "}"));
        } else {
            total.push(slot!(i => "{linear_inertia" N "}"));
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
        Some(total.join(" + ")),
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
        let m = p.bodies[i].as_ref().expect("movable");
        b.input(slot!(i => "p" N), c.body(i).position);
        b.value(slot!(i => "linear_move" N), m.linear_move);
        b.value(slot!(i => "angular_move" N), m.angular_move);
        if m.angular_limit.is_finite() {
            b.value(slot!(i => "angular_limit" N), m.angular_limit);
        } else {
            b.value(slot!(i => "angular_limit" N), "none");
        }
        b.input(slot!(i => "r_perp_length" N), m.r_perp_length);
        b.value(slot!(i => "linear_change" N), m.linear_change);
        b.value(slot!(i => "rotation_per_unit" N), m.rotation_per_unit);
        b.value(slot!(i => "angular_change" N), m.angular_change);
        b.value(slot!(i => "position" N), m.position);
        // Before the limit; when it acts, the clamped moves follow below.
        b.input(
            slot!(i => "angular_move_unlimited" N),
            m.angular_move_unlimited,
        );
        b.input(
            slot!(i => "linear_move_unlimited" N),
            m.linear_move_unlimited,
        );
        let (lin, ang) = if m.limited {
            (
                slot!(i => "linear_move_unlimited" N),
                slot!(i => "angular_move_unlimited" N),
            )
        } else {
            (slot!(i => "linear_move" N), slot!(i => "angular_move" N))
        };
        b.f(
            slot!(i => "Δ_l" S),
            if relaxed {
                slot!(i => "(-1)^(" N "+1) d_res I_l" S " / I_t")
            } else {
                slot!(i => "(-1)^(" N "+1) d_pen I_l" S " / I_t")
            },
            Some(if relaxed {
                slot!(i => MINUS "{resolved_depth} · {linear_inertia" N "} / {total_inertia}")
            } else {
                slot!(i => MINUS "{d_pen} · {linear_inertia" N "} / {total_inertia}")
            }),
            Some(lin),
        );
        if !nonlinear {
            // Linear projection: no angular share, no limit, no turn.
            b.f(
                slot!(i => "Δp" S),
                slot!(i => "Δ_l" S " d̂"),
                Some(slot!(i => "{linear_move" N "} {d}")),
                Some(slot!(i => "linear_change" N)),
            );
            b.f(
                slot!(i => "p" S "′"),
                slot!(i => "p" S " + Δp" S),
                Some(slot!(i => "{p" N "} + {linear_change" N "}")),
                Some(slot!(i => "position" N)),
            );
            continue;
        }
        b.f(
            slot!(i => "Δ_a" S),
            if relaxed {
                slot!(i => "(-1)^(" N "+1) d_res I_a" S " / I_t")
            } else {
                slot!(i => "(-1)^(" N "+1) d_pen I_a" S " / I_t")
            },
            Some(if relaxed {
                slot!(i => MINUS "{resolved_depth} · {angular_inertia" N "} / {total_inertia}")
            } else {
                slot!(i => MINUS "{d_pen} · {angular_inertia" N "} / {total_inertia}")
            }),
            Some(ang),
        );
        if !m.angular_limit.is_finite() {
            b.note("angular_limit = inf: the angular move is not limited.");
        } else {
            b.f(
                slot!(i => "Δ_max" S),
                slot!(i => "angular_limit · |r" S " - (r" S " · d̂) d̂|"),
                Some(slot!(i => "{angular_limit_setting} · {r_perp_length" N "}")),
                Some(slot!(i => "angular_limit" N)),
            );
        }
        if m.limited {
            b.f(
                slot!(i => "Δ_a" S " (limited)"),
                slot!(i => "±Δ_max" S),
                None::<&str>,
                Some(slot!(i => "angular_move" N)),
            );
            b.f(
                slot!(i => "Δ_l" S " (limited)"),
                slot!(i => "Δ_l" S " + (Δ_a" S " - Δ_a" S " (limited))"),
                Some(slot!(i => "{linear_move_unlimited" N "} + ({angular_move_unlimited" N "} - {angular_move" N "})")),
                Some(slot!(i => "linear_move" N)),
            );
            b.note(format!(
                "Excessive rotation: {}'s angular move {{angular_move_unlimited{n}}} exceeds the limit Δ_max{s} = {{angular_limit{n}}}; it is cut to the limit and the excess moves to the linear share ({{linear_move_unlimited{n}}} → {{linear_move{n}}}).",
                c.name(i)
            ));
        }
        b.f(
            slot!(i => "Δp" S),
            slot!(i => "Δ_l" S " d̂"),
            Some(slot!(i => "{linear_move" N "} {d}")),
            Some(slot!(i => "linear_change" N)),
        );
        if m.angular_inertia == 0.0 || m.angular_move == 0.0 {
            // Δ_a / I_a would be 0 / 0 or 0: no turn, said rather than divided.
            b.f(
                slot!(i => "Δθ" S),
                "0",
                None::<&str>,
                Some(slot!(i => "angular_change" N)),
            );
            b.note(format!(
                "{} takes no angular share (Δ_a{s} = 0), so it does not turn: Δθ{s} = 0.",
                c.name(i)
            ));
        } else {
            b.f(
                slot!(i => "Δθ" S),
                slot!(i => "(Δ_a" S " / I_a" S ") Δθ̇_d" S),
                Some(slot!(i => "({angular_move" N "} / {angular_inertia" N "}) {rotation_per_unit" N "}")),
                Some(slot!(i => "angular_change" N)),
            );
        }
        b.f(
            slot!(i => "p" S "′"),
            slot!(i => "p" S " + Δp" S),
            Some(slot!(i => "{p" N "} + {linear_change" N "}")),
            Some(slot!(i => "position" N)),
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
