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
        b.input(format!("before{n}"), u.before);
        b.input(format!("rotation{n}"), u.rotation);
        b.value(format!("orientation{n}_unnormalised"), u.unnormalised);
        b.value(format!("orientation{n}"), u.normalised);
        b.value(format!("rotation_degrees{n}"), u.angle_degrees);
        b.value(format!("rotation_axis{n}"), u.axis);
        b.value(
            format!("rotation_vector_degrees{n}"),
            u.rotation_vector_degrees,
        );
        b.value(format!("euler_zyx_degrees{n}"), u.euler_zyx_degrees);
        b.f(
            &format!("θ{s}′"),
            &format!("θ{s} + ½ [0, Δθ{s}] θ{s}"),
            Some(&format!(
                "{{before{n}}} + ½ [0, {{rotation{n}}}] {{before{n}}}"
            )),
            Some(&format!("orientation{n}_unnormalised")),
        );
        b.input(format!("norm{n}"), u.unnormalised.norm());
        b.f(
            &format!("θ{s}′ / |θ{s}′|"),
            "",
            Some(&format!("{{orientation{n}_unnormalised}} / {{norm{n}}}")),
            Some(&format!("orientation{n}")),
        );
        b.f(
            &format!("φ{s}"),
            &format!("2 atan2(|δ_xyz|, δ_w), δ = (θ{s}′ / |θ{s}′|) θ{s}⁻¹"),
            None,
            Some(&format!("rotation_degrees{n}")),
        );
        let name = c.name(i);
        if let Some((axis, ccw)) = about_one_axis(&u.rotation) {
            let signed = if ccw {
                u.angle_degrees
            } else {
                -u.angle_degrees
            };
            b.value(format!("rotation_signed_degrees{n}"), signed);
            b.value(format!("rotation_world_axis{n}"), axis.to_string().as_str());
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
        b.note(format!("Euler angles of the new orientation, intrinsic z-y′-x″ (yaw, pitch, roll): {{euler_zyx_degrees{n}}}°."));
    }
    b.note("Adding ½[0, Δθ]θ is a first-order step: the sum is not unit length, so it is normalised; the turn it represents is slightly smaller than |Δθ|.");
    b.done()
}
