//! The `orientation_update` stage described: θ′ = θ + ½ [0, Δθ] θ, the
//! normalised quaternion and the turn it makes.

use super::builder::{about_one_axis, sense, skip_reason, through_centre, SolvedContact, B, SUB};
use crate::physics::solve::Skip;
use crate::physics::StageId;
use crate::trace::Step;

/// Each turned body's quaternion before and after normalising.
pub fn orientation(c: &SolvedContact) -> Step {
    let mut b = B::new(StageId::OrientationUpdate);
    let Some(o) = &c.solution.orientation else {
        return match c.solution.skip(StageId::OrientationUpdate) {
            Some(Skip::NoPenetration) => {
                b.skipped("no penetration (d_pen ≤ 0): no projection, so no body turns")
            }
            other => b.skipped(skip_reason(other.unwrap_or(Skip::NoRotation))),
        };
    };
    for i in c.movable() {
        let Some(u) = &o.bodies[i] else { continue };
        let n = i + 1;
        let s = SUB[i];
        let turn = u.turn();
        b.input(slot!(i => "before" N), u.before);
        b.input(slot!(i => "rotation" N), u.rotation);
        b.value(slot!(i => "orientation" N "_unnormalised"), u.unnormalised);
        b.value(slot!(i => "orientation" N), u.normalised);
        b.value(slot!(i => "rotation_degrees" N), turn.angle_degrees);
        b.value(slot!(i => "rotation_axis" N), turn.axis);
        b.value(
            slot!(i => "rotation_vector_degrees" N),
            turn.rotation_vector_degrees,
        );
        b.value(slot!(i => "euler_zyx_degrees" N), turn.euler_zyx_degrees);
        b.f(
            slot!(i => "θ" S "′"),
            slot!(i => "θ" S " + ½ [0, Δθ" S "] θ" S),
            Some(slot!(i => "{before" N "} + ½ [0, {rotation" N "}] {before" N "}")),
            Some(slot!(i => "orientation" N "_unnormalised")),
        );
        b.input(slot!(i => "norm" N), u.unnormalised.norm());
        b.f(
            slot!(i => "θ" S "′ / |θ" S "′|"),
            "",
            Some(slot!(i => "{orientation" N "_unnormalised} / {norm" N "}")),
            Some(slot!(i => "orientation" N)),
        );
        b.f(
            slot!(i => "φ" S),
            slot!(i => "2 atan2(|δ_xyz|, δ_w), δ = (θ" S "′ / |θ" S "′|) θ" S "⁻¹"),
            None::<&str>,
            Some(slot!(i => "rotation_degrees" N)),
        );
        let name = c.name(i);
        if let Some((axis, ccw)) = about_one_axis(&u.rotation) {
            let signed = if ccw {
                turn.angle_degrees
            } else {
                -turn.angle_degrees
            };
            b.value(slot!(i => "rotation_signed_degrees" N), signed);
            b.value(
                slot!(i => "rotation_world_axis" N),
                axis.to_string().as_str(),
            );
        }
        let rounding = through_centre(&c.r(i), &c.solution.frame.normal());
        match about_one_axis(&u.rotation) {
            _ if rounding => b.note(format!(
                "{name} turns only φ{s} = {{rotation_degrees{n}}}°: its contact arm lies along the normal to within the data's rounding, so this is what the rounding leaves."
            )),
            Some((axis, ccw)) => b.note(format!(
                "{name} turns φ{s} = {{rotation_degrees{n}}}° {} about the {axis}-axis (seen from +{axis}); |Δθ{s}| = {{rotation_vector_degrees{n}}}° is the small-angle estimate of the same turn.",
                sense(ccw)
            )),
            None => b.note(format!("{name} turns φ{s} = {{rotation_degrees{n}}}° about the axis {{rotation_axis{n}}}.")),
        }
        b.note(slot!(i => "Euler angles of the new orientation, intrinsic z-y′-x″ (yaw, pitch, roll): {euler_zyx_degrees" N "}°."));
    }
    b.note("Adding ½[0, Δθ]θ is a first-order step: the sum is not unit length, so it is normalised; the turn it represents is slightly smaller than |Δθ|.");
    b.done()
}
