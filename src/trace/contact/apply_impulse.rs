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
        b.input(slot!(i => "m" N), body.mass);
        b.input(slot!(i => "r" N), c.r(i));
        b.input(slot!(i => "v" N "_before"), body.velocity);
        b.input(slot!(i => "w" N "_before"), body.angular_velocity);
        b.input(
            slot!(i => "inverse_inertia_world" N),
            body.inverse_inertia_world(),
        );
        b.value(slot!(i => "impulse" N), change.impulse);
        b.value(slot!(i => "impulsive_torque" N), change.impulsive_torque);
        b.value(slot!(i => "dv" N), change.dv);
        b.value(slot!(i => "dw" N), change.dw);
        b.value(slot!(i => "v" N), change.v);
        b.value(slot!(i => "w" N), change.w);
        b.value(
            slot!(i => "dw" N "_degrees_per_second"),
            crate::physics::scale::stable_norm(&change.dw).to_degrees(),
        );
        b.f(
            slot!(i => "Δṗ" S),
            slot!(i => MINUS "g / m" S),
            Some(slot!(i => "{impulse" N "} / {m" N "}")),
            Some(slot!(i => "dv" N)),
        );
        b.f(
            slot!(i => "u" S),
            [slot!(i => "r" S " × g"), slot!(i => "r" S " × (-g)")][i],
            Some(slot!(i => "{r" N "} × {impulse" N "}")),
            Some(slot!(i => "impulsive_torque" N)),
        );
        b.f(
            slot!(i => "Δθ̇" S),
            slot!(i => "I" S "⁻¹ u" S),
            Some(slot!(i => "{inverse_inertia_world" N "} {impulsive_torque" N "}")),
            Some(slot!(i => "dw" N)),
        );
        b.f(
            slot!(i => "v" S "′"),
            slot!(i => "v" S " + Δṗ" S),
            Some(slot!(i => "{v" N "_before} + {dv" N "}")),
            Some(slot!(i => "v" N)),
        );
        b.f(
            slot!(i => "ω" S "′"),
            slot!(i => "ω" S " + Δθ̇" S),
            Some(slot!(i => "{w" N "_before} + {dw" N "}")),
            Some(slot!(i => "w" N)),
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
    if c.movable().count() == 2 {
        b.note("Both bodies receive the same impulse in opposite directions: body 2 gets -g.");
    }
    b.done()
}
