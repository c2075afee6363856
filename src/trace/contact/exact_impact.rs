//! The `exact_impact` stage described: the impact integrated in the
//! normal-impulse domain under one restitution law, its phases, and the
//! one-shot impulse beside it with the differences.

use crate::knobs::Choice;
use nalgebra::{Vector2, Vector3};

use super::builder::{skip_reason, SolvedContact, B};
use crate::physics::exact::{ExactImpact, Phase, PhaseKind, RestitutionLaw};
use crate::physics::solve::Skip;
use crate::physics::StageId;
use crate::trace::{Step, Value};

/// The law's name as the stage shows it, and its end condition.
fn law_text(law: RestitutionLaw) -> (&'static str, &'static str, &'static str) {
    match law {
        RestitutionLaw::Newton => ("Newton (kinematic)", "v_n′", "-c v_n0"),
        RestitutionLaw::Poisson => ("Poisson (kinetic)", "P_n′", "(1 + c) P_c"),
        RestitutionLaw::Stronge => ("Stronge (energetic)", "W_r", "-c² W_c"),
    }
}

/// The phase as one line of the JSON `phases` list: its name and where it
/// happens in P_n, at full precision.
pub fn phase_line(p: &Phase<f64>) -> String {
    if p.kind.is_instant() {
        format!("{} at P_n = {}", p.kind.name(), p.from_pn)
    } else {
        format!("{} from P_n = {} to {}", p.kind.name(), p.from_pn, p.to_pn)
    }
}

/// What a phase says in the notes; `{pn_from_i}`, `{pn_to_i}`, `{dir_i}` are
/// its inputs.
fn phase_note(kind: &PhaseKind<f64>, i: usize) -> String {
    let range = format!("P_n = {{pn_from_{i}}} → {{pn_to_{i}}}");
    let at = format!("at P_n = {{pn_from_{i}}}");
    match kind {
        PhaseKind::Frictionless => format!("{range}: no friction, the tangential motion is free."),
        PhaseKind::Slides { rotating, .. } => {
            let how = if *rotating {
                "its direction turns (integrated numerically), starting along"
            } else {
                "along"
            };
            format!("{range}: slides, {how} {{dir_{i}}}; friction μ_d dP_n opposes the slip.")
        }
        PhaseKind::Sticks { .. } => format!(
            "{range}: sticks (v_t = 0); friction supplies τ dP_n with |τ| = {{ratio_{i}}} ≤ μ_s."
        ),
        PhaseKind::SlipHalts => format!("{at}: the slip halts (v_t = 0)."),
        PhaseKind::SlipReverses { .. } => format!(
            "{at}: the cone cannot hold the contact, so it slips back the way it came, along {{dir_{i}}}."
        ),
        PhaseKind::SlipResumes { .. } => {
            format!("{at}: the contact cannot stick and slips again along {{dir_{i}}}.")
        }
        PhaseKind::SlipStarts { .. } => format!(
            "{at}: at rest tangentially but the cone cannot hold it: it starts to slip along {{dir_{i}}}."
        ),
        PhaseKind::MaxCompression => {
            format!("{at}: maximum compression (v_n = 0); restitution begins.")
        }
    }
}

/// A tangent-plane direction (t0, t1 components) in world space.
fn world_direction(c: &SolvedContact, d: &Vector2<f64>) -> Vector3<f64> {
    c.solution.frame.to_world(&Vector3::new(0.0, d.x, d.y))
}

/// The direction a phase shows, if any.
fn direction(kind: &PhaseKind<f64>) -> Option<Vector2<f64>> {
    match kind {
        PhaseKind::Slides { direction, .. }
        | PhaseKind::SlipReverses { direction }
        | PhaseKind::SlipResumes { direction }
        | PhaseKind::SlipStarts { direction } => Some(*direction),
        _ => None,
    }
}

/// The integrated impulse, velocities and energies, the phases, and the one-shot beside them.
pub fn exact_impact(c: &SolvedContact) -> Step {
    let mut b = B::new(StageId::ExactImpact);
    if let Some(Err(e)) = &c.solution.exact {
        return b.skipped(format!("the integration failed: {e}"));
    }
    if let Some(skip) = c.solution.skip(StageId::ExactImpact) {
        return b.skipped(skip_reason(skip));
    }
    let Some(Ok(x)) = &c.solution.exact else {
        return b.skipped(skip_reason(Skip::NotAsked));
    };
    let o = &x.outcome;
    let (law_name, end_lhs, end_rhs) = law_text(o.law);
    b.input("law_name", law_name);
    b.input("e", x.input.restitution);
    b.input("mu_s", x.input.static_friction);
    b.input("mu_d", x.input.dynamic_friction);
    b.input("u0", x.input.u0);
    b.input("matrix", x.input.k);
    b.input("contact_to_world", x.frame.contact_to_world);
    b.value("law", Some(o.law).name());
    b.value("regime", o.regime().name());
    b.value(
        "phases",
        Value::List(o.phases.iter().map(phase_line).collect()),
    );
    b.value("compression_normal_impulse", o.compression_pn);
    b.value("impulse_contact", o.impulse);
    b.value("impulse_world", x.impulse_world);
    b.value("velocity_contact", o.velocity);
    b.f("law", "", Some("{law_name}"), None::<&str>);
    b.f(
        "v_c(P)",
        "v_c + M P",
        Some("{u0} + {matrix} P"),
        None::<&str>,
    );
    b.f("dP_t", "-μ_d s dP_n", None::<&str>, None::<&str>);
    b.f(end_lhs, end_rhs, None::<&str>, None::<&str>);
    b.f(
        "P_c",
        "P_n where v_n = 0",
        None::<&str>,
        Some("compression_normal_impulse"),
    );
    b.f("P", "∫ dP", None::<&str>, Some("impulse_contact"));
    b.f(
        "P_world",
        "C P",
        Some("{contact_to_world} {impulse_contact}"),
        Some("impulse_world"),
    );
    b.f("v_c′", "v_c + M P", None::<&str>, Some("velocity_contact"));
    for i in c.movable() {
        let after = x.applied.bodies[i].as_ref().expect("movable");
        b.value(slot!(i => "v" N), after.v);
        b.value(slot!(i => "w" N), after.w);
        b.f(
            slot!(i => "v" S "′"),
            "",
            None::<&str>,
            Some(slot!(i => "v" N)),
        );
        b.f(
            slot!(i => "ω" S "′"),
            "",
            None::<&str>,
            Some(slot!(i => "w" N)),
        );
    }
    energies(&mut b, x);
    one_shot(&mut b, x);
    for (i, p) in o.phases.iter().enumerate() {
        b.input(format!("pn_from_{i}"), p.from_pn);
        b.input(format!("pn_to_{i}"), p.to_pn);
        if let Some(d) = direction(&p.kind) {
            b.input(format!("dir_{i}"), world_direction(c, &d));
        }
        if let PhaseKind::Sticks { ratio } = p.kind {
            b.input(format!("ratio_{i}"), ratio.norm());
        }
        b.note(phase_note(&p.kind, i));
    }
    b.note("Friction while slipping is dP_t = -μ_d s dP_n with s = v_t/|v_t| the slip direction; while stuck it is τ dP_n with τ = -M_tt⁻¹ M_tn, as long as |τ| ≤ μ_s. g_contact is the one-shot impulse of the stages above (the friction clamp's, or the impulse stage's without friction). Each stretch ends at an event: the slip halts, maximum compression, or the law's end.");
    let k = &x.input.k;
    let coupling = k[(0, 1)].hypot(k[(0, 2)]);
    let frictional = x.input.static_friction > 0.0 || x.input.dynamic_friction > 0.0;
    if frictional && coupling <= 1e-12 * k[(0, 0)] {
        b.note("M has no normal–tangential coupling (M_nt = 0, as for a ball): friction does not change the normal velocity and the contact never needs to slip back, so the three laws agree and the one-shot impulse is the exact one.");
    }
    gain_notes(&mut b, x);
    b.note("The integration applies nothing: the bodies after this contact are the one-shot's. Restitution here is the contact's c applied to the actual normal velocity (no velocity limit, no acceleration compensation).");
    b.done()
}

/// Energy before and after, and the works that make up the change.
fn energies(b: &mut B, x: &ExactImpact<f64>) {
    let o = &x.outcome;
    b.value("energy_before", x.energy_before);
    b.value("energy_after", x.energy_after);
    b.value("energy_change", x.energy_change());
    b.value("work_compression", o.work_compression);
    b.value("work_restitution", o.work_restitution);
    b.value("work_friction", o.work_friction);
    b.f("E", "", None::<&str>, Some("energy_before"));
    b.f("E′", "", None::<&str>, Some("energy_after"));
    b.f(
        "E′ - E",
        "W_c + W_r + W_t",
        Some("{work_compression} + {work_restitution} + {work_friction}"),
        Some("energy_change"),
    );
}

/// The one-shot impulse of the stages beside the integrated one.
fn one_shot(b: &mut B, x: &ExactImpact<f64>) {
    b.value("impulse_one_shot_contact", x.one_shot_contact);
    b.value("impulse_one_shot_world", x.one_shot_world);
    b.value("impulse_difference", x.impulse_difference());
    b.value("impulse_difference_abs", x.impulse_difference_abs());
    b.value(
        "impulse_difference_relative",
        x.impulse_difference_relative(),
    );
    b.value("energy_after_one_shot", x.energy_after_one_shot);
    b.value("energy_difference", x.energy_difference());
    b.f(
        "g_contact",
        "",
        None::<&str>,
        Some("impulse_one_shot_contact"),
    );
    b.f(
        "P - g_contact",
        "",
        Some("{impulse_contact} - {impulse_one_shot_contact}"),
        Some("impulse_difference"),
    );
    b.f(
        "|P - g_contact|",
        "",
        None::<&str>,
        Some("impulse_difference_abs"),
    );
    b.f(
        "|P - g_contact| / |P|",
        "",
        None::<&str>,
        Some("impulse_difference_relative"),
    );
    b.f("E′_clamp", "", None::<&str>, Some("energy_after_one_shot"));
    b.f(
        "E′_clamp - E′",
        "",
        Some("{energy_after_one_shot} - {energy_after}"),
        Some("energy_difference"),
    );
}

/// A note for energy gained by the integrated law or by the one-shot, and why.
fn gain_notes(b: &mut B, x: &ExactImpact<f64>) {
    let relative = |after: f64| {
        if x.energy_before > 0.0 {
            100.0 * (after - x.energy_before) / x.energy_before
        } else {
            0.0
        }
    };
    b.input("gain_percent", relative(x.energy_after));
    b.input("gain_percent_one_shot", relative(x.energy_after_one_shot));
    if x.gains_energy() {
        let why = match x.outcome.law {
            RestitutionLaw::Newton => "Newton's law fixes the final normal velocity whatever work the normal impulse does; with friction coupling the normal and tangential motion (M_nt ≠ 0), reaching -c v_n0 can take a normal impulse that does more work in restitution than compression absorbed. Newton's law with friction is not energetically consistent.",
            RestitutionLaw::Poisson => "Poisson's law fixes the restitution impulse c P_c; when friction (slip halting or reversing) makes v_n rise faster in restitution than it fell in compression, that impulse does more work than compression absorbed. Poisson's law with friction is not energetically consistent either.",
            RestitutionLaw::Stronge => "Stronge's law bounds the restitution work by c² of the compression work, so this is the integration's error, not the law.",
        };
        b.note(format!(
            "ENERGY GAIN: the integrated impulse raises the kinetic energy by {{gain_percent}} %. {why}"
        ));
    } else if x.outcome.law == RestitutionLaw::Stronge {
        b.note(
            "Stronge's law never gains energy: W_r = -c² W_c ≤ -W_c and friction's work W_t ≤ 0.",
        );
    }
    if x.one_shot_gains_energy() {
        b.note("ENERGY GAIN: the one-shot impulse raises the kinetic energy by {gain_percent_one_shot} %: it removes all sliding at once and applies Newton's restitution to the normal velocity, which with friction coupling is not energetically consistent.");
    }
}
