//! The notes of the `checks` stage that say why a check came out as it did
//! (`physics::contact::causes`): every ✗ with its actual cause, and every result
//! that only round-off or the model's own rule explains.

use crate::physics::causes::Cause;
use crate::physics::checks::CheckKind;

/// A note and the numbers it quotes (as `{placeholders}`, filled from the
/// step's inputs, which are not part of the JSON contract).
pub struct Described {
    pub note: String,
    pub inputs: Vec<(&'static str, f64)>,
}

/// `prefix` keeps the placeholders of one check's note apart from another's.
fn round_off(prefix: &'static str, what: &str, condition: f64, allowance: f64) -> Described {
    let (c, a) = match prefix {
        "energy" => ("energy_condition", "energy_allowance"),
        "restitution" => ("restitution_condition", "restitution_allowance"),
        "slip" => ("slip_condition", "slip_allowance"),
        _ => ("cone_condition", "cone_allowance"),
    };
    let finite = condition.is_finite() && condition < f64::MAX && allowance < f64::MAX;
    let (solve, bound, inputs) = if finite {
        (
            format!("the 3×3 solve for g is ill-conditioned (κ(M) = {{{c}}}), so g is known only to about κ·ε of its size"),
            format!(" (up to {{{a}}})"),
            vec![(c, condition), (a, allowance)],
        )
    } else {
        (
            "M is numerically singular or indefinite at f64's precision, so g has no reliable digit".to_string(),
            String::new(),
            vec![],
        )
    };
    Described {
        note: format!("ROUND-OFF, NOT PHYSICS: {what} is within what round-off can produce here{bound}: {solve}. This is a limit of 64-bit arithmetic, not a defect of the model, so it is shown (·) but not counted as a failure."),
        inputs,
    }
}

/// The note for `cause` on a check of `kind`; `None` where the check's
/// existing wording already says it.
pub fn describe(kind: CheckKind, cause: &Cause<f64>, has_friction: bool) -> Option<Described> {
    let plain = |note: &str| {
        Some(Described {
            note: note.to_string(),
            inputs: vec![],
        })
    };
    let rose =
        "ENERGY ROSE: kinetic energy after ({energy_after}) exceeds before ({energy_before})";
    match (kind, *cause) {
        (CheckKind::Energy, Cause::RoundOff { condition, allowance }) => Some(round_off(
            "energy",
            "the energy change ({energy_change})",
            condition,
            allowance,
        )),
        (CheckKind::Energy, Cause::AccelerationCompensation { energy_without }) => Some(Described {
            note: format!("{rose} because of the acceleration compensation: last frame's acceleration gives v_acc = {{velocity_from_acceleration}} along d̂, and the target v_s′ = -c(v_s - v_acc) then asks the bodies to separate faster than restitution alone would. The compensation assumes the acceleration pushed the bodies together (a resting contact); here it points away from the contact. Without the acceleration the energy after would be {{energy_without}}."),
            inputs: vec![("energy_without", energy_without)],
        }),
        (CheckKind::Energy, Cause::Friction { .. }) => plain(&format!("{rose}. Newton's restitution (a velocity target) combined with friction can create energy — Kane's example (T. R. Kane, 1984) is the classic case; energetic restitution (Stronge) avoids it.")),
        (CheckKind::Energy, Cause::AccelerationAndFriction { energy_without }) => Some(Described {
            note: format!("{rose}: neither the acceleration compensation (v_acc = {{velocity_from_acceleration}}) nor friction (Kane's effect) alone raises it, both together do; without either the energy after would be {{energy_without}}."),
            inputs: vec![("energy_without", energy_without)],
        }),
        (CheckKind::Energy, _) if !has_friction => plain(&format!("{rose}; with restitution ≤ 1 and no friction this should not happen.")),
        (CheckKind::Energy, _) => plain(&format!("{rose}, and neither friction, the acceleration compensation nor round-off explains it: this should not happen.")),

        (CheckKind::Restitution, Cause::RoundOff { condition, allowance }) => Some(round_off(
            "restitution",
            "the miss of the separating velocity's target (v_s′ = {separating_velocity} for {separating_velocity_expected})",
            condition,
            allowance,
        )),
        (CheckKind::Restitution, Cause::KineticDirectionNormal) => plain("MISSED TARGET: the kinetic-direction model (the collisions lectures: Lecture IV Collisions; Pronost) takes the normal impulse from the closed form g_closed (the companion lectures' j), which knows neither the acceleration compensation nor the normal velocity that its own tangential impulse μ_d g_closed f̂ causes through M₀₁ and M₀₂; so v_s′ is not v_s + Δv. The model does not aim at this target: a defect of the model, not of the arithmetic."),
        (CheckKind::Restitution, _) => plain("MISSED TARGET: the separating velocity after the impulse is not v_s + Δv, and neither the friction model nor round-off explains it: this should not happen."),

        (CheckKind::Slip, Cause::NoFrictionWhileNotSliding) => plain("SLIDE STARTED: nothing slid before the impulse, so the kinetic-direction model has no direction f̂ and applies no friction at all; the normal impulse alone drives the contact point sideways (M₀₁, M₀₂ ≠ 0) and starts a slide of {slip_speed_after}. Static friction would have resisted it: the model cannot hold a contact, a defect of the model."),
        (CheckKind::Slip, Cause::PlanarAcceleration { planar }) => Some(Described {
            note: "SLIP FROM LAST FRAME'S ACCELERATION: as the reference engine does, the contact velocity that static friction removes includes the planar part of last frame's acceleration × duration ({slip_planar_acceleration}), so the contact point now slides by what one frame of that acceleration will add back, and sticks after the next step. The model's rule, not a defect, so it is shown (·) but not counted as a failure.".to_string(),
            inputs: vec![("slip_planar_acceleration", planar)],
        }),
        (CheckKind::Slip, Cause::FrictionlessFallback) => plain("NO FRICTION ACTED: the friction matrix M could not be factorised (SINGULAR), so the frictionless impulse was used and the normal impulse alone drove the contact point sideways. A limit of 64-bit arithmetic, not a defect of the model, so it is shown (·) but not counted as a failure."),
        (CheckKind::Slip, Cause::RoundOff { condition, allowance }) => Some(round_off(
            "slip",
            "the slip left after a sticking impulse ({slip_speed_after})",
            condition,
            allowance,
        )),

        (CheckKind::FrictionCone, Cause::KineticDirectionNormal) => plain("OUTSIDE THE CONE: the kinetic-direction model takes its normal impulse from the closed form g_closed = -(1 + c) v_s / (…) (the companion lectures' j), which knows nothing of the acceleration compensation; here the contact points do not close (v_s ≥ 0) while the compensation still asks for an impulse, so g_closed < 0 pulls the bodies together. A defect of the model."),
        (CheckKind::FrictionCone, Cause::VelocityScalingModel) => plain("OUTSIDE THE CONE: the friction lecture's (PSE Friction) velocity-scaling model sets the planar velocity (μ_d v_planar) rather than bounding the impulse, so the impulse it needs can exceed μ g_n. This is the model's rule, not Coulomb's law: a defect of the model."),
        (CheckKind::FrictionCone, Cause::RoundOff { condition, allowance }) => Some(round_off(
            "cone",
            "the step outside the cone",
            condition,
            allowance,
        )),
        (CheckKind::FrictionCone, _) => plain("OUTSIDE THE CONE: the clamped impulse exceeds μ g_n, and neither the friction model nor round-off explains it: this should not happen."),
        _ => None,
    }
}
