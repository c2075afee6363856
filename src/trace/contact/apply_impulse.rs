//! The `apply_impulse` stage described: each movable body's velocity and
//! spin after the impulse (body 2 receives -g).

use nalgebra::Vector3;

use super::builder::{about_one_axis, sense, skip_reason, through_centre, SolvedContact, B, SUB};
use crate::physics::solve::Skip;
use crate::physics::StageId;
use crate::trace::Step;

/// v′ = v + Δṗ, ω′ = ω + I⁻¹ (r × g) per movable body.
pub fn apply_impulse(c: &SolvedContact) -> Step {
    let mut b = B::new(StageId::ApplyImpulse);
    let Some(a) = &c.solution.applied else {
        return b.skipped(skip_reason(Skip::Separating));
    };
    for i in c.movable() {
        let n = i + 1;
        let s = SUB[i];
        let body = c.body(i);
        let change = a.bodies[i].as_ref().expect("movable");
        b.input(format!("m{n}"), body.mass);
        b.input(format!("r{n}"), c.r(i));
        b.input(format!("v{n}_before"), body.velocity);
        b.input(format!("w{n}_before"), body.angular_velocity);
        b.input(
            format!("inverse_inertia_world{n}"),
            body.inverse_inertia_world(),
        );
        b.value(format!("impulse{n}"), change.impulse);
        b.value(format!("impulsive_torque{n}"), change.impulsive_torque);
        b.value(format!("dv{n}"), change.dv);
        b.value(format!("dw{n}"), change.dw);
        b.value(format!("v{n}"), change.v);
        b.value(format!("w{n}"), change.w);
        b.value(
            format!("dw{n}_degrees_per_second"),
            crate::physics::scale::stable_norm(&change.dw).to_degrees(),
        );
        let g = if i == 0 { "g" } else { "-g" };
        b.f(
            &format!("Δṗ{s}"),
            &format!("{g} / m{s}"),
            Some(&format!("{{impulse{n}}} / {{m{n}}}")),
            Some(&format!("dv{n}")),
        );
        b.f(
            &format!("u{s}"),
            &format!("r{s} × {}", if i == 0 { "g" } else { "(-g)" }),
            Some(&format!("{{r{n}}} × {{impulse{n}}}")),
            Some(&format!("impulsive_torque{n}")),
        );
        b.f(
            &format!("Δθ̇{s}"),
            &format!("I{s}⁻¹ u{s}"),
            Some(&format!(
                "{{inverse_inertia_world{n}}} {{impulsive_torque{n}}}"
            )),
            Some(&format!("dw{n}")),
        );
        b.f(
            &format!("v{s}′"),
            &format!("v{s} + Δṗ{s}"),
            Some(&format!("{{v{n}_before}} + {{dv{n}}}")),
            Some(&format!("v{n}")),
        );
        b.f(
            &format!("ω{s}′"),
            &format!("ω{s} + Δθ̇{s}"),
            Some(&format!("{{w{n}_before}} + {{dw{n}}}")),
            Some(&format!("w{n}")),
        );
        // The impulse (with friction, not only its normal part) passes
        // through the centre: any spin left is the data's rounding.
        let rounding = through_centre(&c.r(i), &change.impulse.normalize());
        if rounding && change.dw != Vector3::zeros() {
            b.note(format!(
                "{}'s spin changes by only {{dw{n}_degrees_per_second}} °/s: the impulse passes through its centre to within the data's rounding, so this is what the rounding leaves, not a real spin-up.",
                c.name(i)
            ));
        } else if let Some((axis, ccw)) = about_one_axis(&change.dw) {
            b.note(format!(
                "{}'s spin changes by |Δθ̇{s}| = {{dw{n}_degrees_per_second}} °/s, {} about the {axis}-axis (seen from +{axis}).",
                c.name(i),
                sense(ccw)
            ));
        }
    }
    if c.movable().len() == 2 {
        b.note("Both bodies receive the same impulse in opposite directions: body 2 gets -g.");
    }
    b.done()
}
