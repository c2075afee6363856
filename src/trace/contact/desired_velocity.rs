//! The `desired_delta_velocity` stage described: the contact velocity, the
//! separating velocity and the change Δv the impulse must make.

use super::builder::{SolvedContact, B};
use crate::physics::StageId;
use crate::trace::Step;

/// The name of the stage's velocity-limit value, present when the limit
/// forced restitution to 0 (the TUI's edit message reads it).
pub const VELOCITY_LIMIT: &str = "velocity_limit";

/// v_c = Cᵀ (q̇₁ - q̇₂) and Δv = -v_acc - (1 + c)(v_s - v_acc).
pub fn desired_velocity(c: &SolvedContact) -> Step {
    let mut b = B::new(StageId::DesiredDeltaVelocity);
    let dv = &c.solution.desired;
    let d = c.solution.frame.normal();
    b.input("d", d);
    let mut diff = Vec::new();
    for i in c.movable() {
        let body = c.body(i);
        b.input(slot!(i => "r" N), c.r(i));
        b.input(slot!(i => "v" N), body.velocity);
        b.input(slot!(i => "w" N), body.angular_velocity);
        let pv = dv.point_velocity[i].unwrap_or_default();
        b.value(slot!(i => "point_velocity" N), pv);
        b.value(slot!(i => "normal_velocity" N), pv.dot(&d));
        b.f(
            slot!(i => "q̇" S),
            slot!(i => "ω" S " × r" S " + v" S),
            Some(slot!(i => "{w" N "} × {r" N "} + {v" N "}")),
            Some(slot!(i => "point_velocity" N)),
        );
        b.f(
            slot!(i => "q̇" S " · d̂"),
            "",
            Some(slot!(i => "{point_velocity" N "} · {d}")),
            Some(slot!(i => "normal_velocity" N)),
        );
        diff.push(slot!(i => "{point_velocity" N "}"));
    }
    b.value("contact_velocity", dv.contact_velocity);
    b.value("separating_velocity", dv.separating());
    b.value("closing_velocity", -dv.separating());
    let world = if diff.len() == 2 {
        format!("Cᵀ ({} - {})", diff[0], diff[1])
    } else if c.movable().eq([1]) {
        format!("Cᵀ (-{})", diff[0])
    } else {
        format!("Cᵀ {}", diff[0])
    };
    b.f("v_c", "Cᵀ (q̇₁ - q̇₂)", Some(world), Some("contact_velocity"));
    b.f(
        "v_s",
        "v_c · x̂",
        Some("{contact_velocity} · (1, 0, 0)"),
        Some("separating_velocity"),
    );
    b.input("c_given", dv.restitution_given);
    b.value("restitution", dv.restitution);
    b.value("velocity_from_acceleration", dv.velocity_from_acceleration);
    if dv.velocity_from_acceleration != 0.0 {
        let mut acc = Vec::new();
        for i in c.movable() {
            let n = i + 1;
            b.input(slot!(i => "a" N), c.body(i).acceleration);
            acc.push(format!("{}{{a{n}}}", if i == 1 { "- " } else { "" }));
        }
        b.input("duration", c.problem.duration);
        b.f(
            "v_acc",
            "(a₁ - a₂)·d̂ Δt",
            Some(format!("({})·{{d}} × {{duration}}", acc.join(" "))),
            Some("velocity_from_acceleration"),
        );
        b.f("Δv", "-v_acc - (1 + c)(v_s - v_acc)", Some("-{velocity_from_acceleration} - (1 + {restitution})({separating_velocity} - {velocity_from_acceleration})"), Some("desired"));
        b.note("Remove accelerated velocity: the velocity last frame's acceleration built up ({velocity_from_acceleration}) is not bounced back, so resting contacts do not vibrate. (This is the lecture's form; -v_s - c(v_s - v_acc), the reference code's, is the same number.)");
    } else {
        b.f(
            "Δv",
            "-(1 + c) v_s",
            Some("-(1 + {restitution})({separating_velocity})"),
            Some("desired"),
        );
    }
    b.value("desired", dv.desired);
    if dv.restitution_limited {
        b.input(VELOCITY_LIMIT, c.problem.contact.settings.velocity_limit);
        b.note("The closing speed |v_s| is below velocity_limit ({velocity_limit}), so restitution is forced from {c_given} to 0: a slow contact does not bounce.");
    }
    if dv.separating() < 0.0 {
        b.note("v_s < 0: the contact points are closing at {closing_velocity}.");
    } else {
        b.note("v_s ≥ 0: the contact points are separating or at rest; no impulse is needed.");
    }
    let (vy, vz) = (dv.contact_velocity.y, dv.contact_velocity.z);
    if crate::physics::scale::stable_hypot(vy, vz)
        > 1e-12 * crate::physics::scale::stable_norm(&dv.contact_velocity)
    {
        b.note("The y and z components of v_c are sliding velocity in the contact plane; only friction acts on them.");
    }
    b.done()
}
