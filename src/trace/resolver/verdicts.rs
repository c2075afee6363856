//! The verdicts of a scene's resolution: momentum, energy, the penetration
//! and the closing velocity left, each with its numbers (what `resolve`
//! prints under "Checks").

use nalgebra::Vector3;

use super::super::Verdict;
use super::arr;
use crate::physics::resolver::checks::SceneChecks;
use crate::physics::resolver::PhaseOutcome;

pub(super) fn verdicts(
    names: &[String],
    c: &SceneChecks<f64>,
    position: &PhaseOutcome<f64>,
    velocity: &PhaseOutcome<f64>,
    contacts: usize,
) -> Vec<Verdict> {
    let f = crate::format::Fmt::default();
    let v = |x: &Vector3<f64>| format!("({})", f.list(&arr(x)));
    let mut out = vec![];
    if c.free_bodies.is_empty() {
        out.push(Verdict {
            label: "linear momentum".into(),
            passed: None,
            detail: "every body touches the world or an immovable body (directly or through others): the world's impulses change their momentum".into(),
        });
    } else {
        let names: Vec<&str> = c
            .free_bodies
            .iter()
            .map(|b| names.get(b.0).map_or("?", String::as_str))
            .collect();
        out.push(Verdict {
            label: "linear momentum".into(),
            passed: Some(c.momentum_conserved),
            detail: format!(
                "Σ m v of the bodies that touch nothing immovable ({}): before {}, after {}, relative error {}",
                names.join(", "),
                v(&c.momentum_before),
                v(&c.momentum_after),
                f.num(c.momentum_error)
            ),
        });
    }
    let change = c.energy_after - c.energy_before;
    let percent = if c.energy_before > 0.0 {
        format!(" ({}%)", f.num(100.0 * change / c.energy_before))
    } else {
        String::new()
    };
    out.push(Verdict {
        label: "kinetic energy".into(),
        passed: Some(c.energy_not_gained),
        detail: format!(
            "before {}, after {}: change {}{percent}",
            f.num(c.energy_before),
            f.num(c.energy_after),
            f.num(change)
        ),
    });
    if contacts == 0 {
        for label in ["penetration left", "closing velocity left"] {
            out.push(Verdict {
                label: label.into(),
                passed: Some(true),
                detail: "no contacts".into(),
            });
        }
        return out;
    }
    out.push(Verdict {
        label: "penetration left".into(),
        passed: Some(c.penetration_left.0 <= position.epsilon),
        detail: format!(
            "deepest {} at contact {} (position_epsilon {})",
            f.num(c.penetration_left.0),
            c.penetration_left.1,
            f.num(position.epsilon)
        ),
    });
    let closing = if c.closing_left.0 > 0.0 {
        format!(
            "largest closing speed {} at contact {}",
            f.num(c.closing_left.0),
            c.closing_left.1
        )
    } else {
        "no contact is closing".into()
    };
    out.push(Verdict {
        label: "closing velocity left".into(),
        passed: Some(velocity.max_after <= velocity.epsilon),
        detail: format!(
            "{closing}; largest desired Δv {} at contact {} (velocity_epsilon {})",
            f.num(velocity.max_after),
            velocity.max_after_contact,
            f.num(velocity.epsilon)
        ),
    });
    out
}
