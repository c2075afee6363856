//! The `checks` stage described: the invariants physics measured, given
//! their JSON value names here, and the pass/fail verdicts of the checks panel.

use super::builder::{SolvedContact, B};
use crate::physics::checks::{CheckItem, CheckKind, Measured};
use crate::physics::StageId;
use crate::trace::{Step, Verdict};

/// The named values of one check (`CheckItem::named_values`).
pub fn check_values(item: &CheckItem<f64>) -> Vec<(&'static str, f64)> {
    item.named_values()
}

/// Every check's values, with the formulas of the restitution target and
/// the residual penetration, a note naming the cause of each ✗ (or of a
/// result only round-off explains), and a note when slip rose while sliding.
pub fn checks(c: &SolvedContact) -> Step {
    let mut b = B::new(StageId::Checks);
    let checks = &c.solution.checks;
    for item in &checks.items {
        for (name, v) in check_values(item) {
            b.value(name, v);
        }
    }
    if checks.get(CheckKind::Restitution).is_some() {
        b.input("desired", c.solution.desired.desired);
        // The contact point's velocity on each body after the impulse,
        // q̇ᵢ′ = ωᵢ′ × rᵢ + vᵢ′, from the applied record (as stage 3 did before).
        let d = c.solution.frame.normal();
        b.input("d", d);
        let mut diff = Vec::new();
        if let Some(applied) = &c.solution.applied {
            for i in c.movable() {
                let change = applied.bodies[i].as_ref().expect("movable");
                b.input(
                    slot!(i => "point_velocity_after" N),
                    change.w.cross(&c.r(i)) + change.v,
                );
                diff.push(slot!(i => "{point_velocity_after" N "}"));
            }
        }
        let substituted = match (diff.len(), c.movable().next()) {
            (2, _) => Some(format!("({} - {}) · {{d}}", diff[0], diff[1])),
            (1, Some(1)) => Some(format!("(-{}) · {{d}}", diff[0])),
            (1, _) => Some(format!("{} · {{d}}", diff[0])),
            _ => None,
        };
        b.f(
            "v_s′",
            "(q̇₁′ - q̇₂′) · d̂",
            substituted,
            Some("separating_velocity"),
        );
        b.f(
            "v_target",
            "v_s + Δv",
            Some("{separating_velocity_before} + {desired}"),
            Some("separating_velocity_expected"),
        );
    }
    // Why each check came out as it did, where a cause is known.
    b.input(
        "velocity_from_acceleration",
        c.solution.desired.velocity_from_acceleration,
    );
    let friction = c.problem.contact.has_friction();
    for item in &checks.items {
        let Some(cause) = &item.cause else { continue };
        if let Some(d) = super::causes::describe(item.kind(), cause, friction) {
            for (name, v) in d.inputs {
                b.input(name, v);
            }
            b.note(d.note);
        }
    }
    let rose = |c: &crate::physics::checks::CheckItem<f64>| matches!(c.measured, Measured::Slip { before, after } if after > before);
    if checks
        .get(CheckKind::Slip)
        .is_some_and(|c| c.passed.is_none() && c.cause.is_none() && rose(c))
    {
        b.note("The slip speed rose ({slip_speed_before} → {slip_speed_after}) while sliding: the normal impulse itself drives the contact point sideways (M₀₁, M₀₂ ≠ 0), more than friction capped at μ g_n can take away. This is Coulomb friction working as intended, not an error.");
    }
    if checks.get(CheckKind::ResidualPenetration).is_some() {
        let depth_symbol = if c.problem.contact.settings.relaxation != 1.0 {
            "d_res"
        } else {
            "d_pen"
        };
        b.f(
            "d_left",
            format!("{depth_symbol} - Σ (-1)^(i+1) (qᵢ′ - q) · d̂"),
            Some("{depth_to_resolve} - {separation_gained}"),
            Some("residual_penetration"),
        );
        b.note("Residual penetration = depth to resolve - separation actually gained when each body's contact point is carried by its finite move (new position and normalised rotation). It measures how far the linearised estimate is off.");
    }
    b.done()
}

/// One verdict per check: a label that states what the numbers show (it
/// never claims "does not rise" beside numbers that rise), pass/fail (or
/// informs), and a detail whose `{name}` placeholders are values of the
/// `checks` stage.
pub fn verdicts(c: &SolvedContact) -> Vec<Verdict> {
    c.solution
        .checks
        .items
        .iter()
        .map(|item| {
            let failed = item.passed == Some(false);
            let (label, detail) = match (item.kind(), &item.measured) {
                (CheckKind::LinearMomentum, _) => (
                    if failed {
                        "linear momentum changed"
                    } else {
                        "linear momentum conserved"
                    }
                    .to_string(),
                    "error {linear_momentum_error}".to_string(),
                ),
                (CheckKind::AngularMomentum(i), _) => (
                    format!(
                        "angular momentum of {} about q {}",
                        c.name(i),
                        if failed { "changed" } else { "conserved" }
                    ),
                    format!("error {{angular_momentum_error{}}}", i + 1),
                ),
                (CheckKind::Restitution, _) => (
                    if failed {
                        "separating velocity misses the target"
                    } else {
                        "separating velocity meets the target"
                    }
                    .to_string(),
                    "v_s′ = {separating_velocity}, v_target = {separating_velocity_expected}"
                        .to_string(),
                ),
                (CheckKind::Energy, Measured::Energy { before, after, .. }) => (
                    format!("kinetic energy {}", trend(*before, *after)),
                    "{energy_before} → {energy_after}".to_string(),
                ),
                (
                    CheckKind::FrictionCone,
                    Measured::FrictionCone {
                        tangential, limit, ..
                    },
                ) => {
                    let inside = tangential <= limit;
                    (
                        match (inside, failed) {
                            (true, _) => "impulse inside the friction cone",
                            (false, false) => "impulse on the friction cone's edge (outside by round-off only)",
                            (false, true) => "impulse outside the friction cone",
                        }
                        .to_string(),
                        format!(
                            "g_n = {{normal_impulse}}, |g_planar| = {{tangential_impulse}} {} μ g_n = {{cone_limit}}",
                            if inside { "≤" } else { ">" }
                        ),
                    )
                }
                (CheckKind::Slip, Measured::Slip { before, after }) => (
                    format!("slip speed {}", trend(*before, *after)),
                    "{slip_speed_before} → {slip_speed_after}".to_string(),
                ),
                (CheckKind::ResidualPenetration, _) => (
                    "penetration left after the finite move".to_string(),
                    "{residual_penetration} of {depth_to_resolve}".to_string(),
                ),
                (CheckKind::UnitQuaternion(i), _) => (
                    format!(
                        "{}'s orientation {} a unit quaternion",
                        c.name(i),
                        if failed { "is not" } else { "is" }
                    ),
                    format!("| |θ′| - 1 | = {{orientation_norm_error{}}}", i + 1),
                ),
                (kind, measured) => unreachable!("{kind:?} measured as {measured:?}"),
            };
            Verdict {
                label,
                passed: item.passed,
                detail,
            }
        })
        .collect()
}

/// "rose", "fell" or "stayed the same": what a measured quantity did.
pub fn trend(before: f64, after: f64) -> &'static str {
    if after > before {
        "rose"
    } else if after < before {
        "fell"
    } else {
        "stayed the same"
    }
}
