//! What each exercise asks, question by question, and the short answers
//! each question asks for: one table, read by the sheet (questions), the
//! answer key, `--answer-template` and the grader, so a quantity a question
//! names (v_c, g in contact coordinates, M, …) is in all four.

use super::Kind;
use crate::trace::{Trace, Value};

/// One question of a sheet and the keys of the short answers it asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Question {
    pub text: &'static str,
    pub asks: &'static [&'static str],
}

const fn q(text: &'static str, asks: &'static [&'static str]) -> Question {
    Question { text, asks }
}

const VELOCITIES: [&str; 4] = ["v1", "w1", "v2", "w2"];

/// The questions of an exercise of `kind`; a penetration exercise whose
/// bodies also close (the trace's impulse stage ran) asks for the impulse too.
pub fn questions(kind: Kind, t: &Trace) -> Vec<Question> {
    const DESIRED: Question = q(
        "Find the contact velocity v_c (in contact coordinates), the separating velocity v_s and the desired change in velocity Δv.",
        &["v_c", "v_s", "dv"],
    );
    match kind {
        Kind::Frictionless => vec![
            DESIRED,
            q(
                "Find the velocity change per unit impulse along the normal, Δq̇_t.",
                &["dq_t"],
            ),
            q(
                "Find the impulse g, in contact and in world coordinates.",
                &["g_contact", "g_world"],
            ),
            q(
                "Find each movable body's velocity v′ and angular velocity ω′ after the impulse.",
                &VELOCITIES,
            ),
        ],
        Kind::StaticFriction | Kind::DynamicFriction => vec![
            DESIRED,
            q(
                "Build the matrix M of velocity change per unit impulse in contact coordinates (M₀₀ = Δq̇_t).",
                &["M", "dq_t"],
            ),
            q(
                "Find the impulse that stops all sliding (in contact coordinates), its planar part and the most static friction can supply, and decide: does the contact stick or slide?",
                &["g_sticking", "g_planar", "g_max", "regime"],
            ),
            q(
                "Find the impulse in world coordinates and each movable body's v′ and ω′ after it.",
                &["g_world", "v1", "w1", "v2", "w2"],
            ),
        ],
        Kind::Penetration => {
            let mut qs = vec![
                q(
                    "Find each movable body's linear and angular inertia along the normal, and the total inertia I_t.",
                    &["I_l1", "I_a1", "I_l2", "I_a2", "I_t"],
                ),
                q(
                    "Share the penetration d_pen: find each body's linear move Δ_l and angular move Δ_a.",
                    &["move_l1", "move_a1", "move_l2", "move_a2"],
                ),
                q(
                    "Find the new positions, the rotation Δθ of each body, and the updated, normalised orientation quaternions.",
                    &["p1", "p2", "turn1", "turn2", "theta1", "theta2"],
                ),
            ];
            if closing(t) {
                qs.push(q(
                    "The bodies are also closing: find the impulse g in world coordinates and the velocities v′ and ω′ after it.",
                    &["g_world", "v1", "w1", "v2", "w2"],
                ));
            }
            qs
        }
    }
}

/// Whether the contact closes: its impulse stage ran.
fn closing(t: &Trace) -> bool {
    t.stage("impulse").is_some_and(|s| s.skipped.is_none())
}

/// A short answer's label on the sheet and where the trace has it:
/// (label, stage, value name).
fn answer(kind: Kind, key: &str) -> Option<(&'static str, &'static str, &'static str)> {
    let friction = matches!(kind, Kind::StaticFriction | Kind::DynamicFriction);
    let (dv, p) = ("desired_delta_velocity", "nonlinear_projection");
    Some(match key {
        "v_c" => ("v_c (contact coordinates)", dv, "contact_velocity"),
        "v_s" => ("v_s", dv, "separating_velocity"),
        "dv" => ("Δv", dv, "desired"),
        "dq_t" => ("Δq̇_t", "unit_impulse", "total"),
        "M" => ("M (contact coordinates)", "unit_impulse", "matrix"),
        "g_contact" => ("g_contact", "impulse", "impulse_contact"),
        "g_sticking" => ("sticking impulse g_contact", "impulse", "impulse_contact"),
        "g_planar" => ("|g_planar|", "friction_clamp", "planar"),
        "g_max" => ("g_max = μ_s g_x", "friction_clamp", "limit"),
        "regime" => ("regime (static or dynamic)", "friction_clamp", "regime"),
        "g_world" if friction => ("g_world", "friction_clamp", "impulse_world"),
        "g_world" => ("g_world", "impulse", "impulse_world"),
        "v1" => ("v₁′", "apply_impulse", "v1"),
        "w1" => ("ω₁′", "apply_impulse", "w1"),
        "v2" => ("v₂′", "apply_impulse", "v2"),
        "w2" => ("ω₂′", "apply_impulse", "w2"),
        "I_l1" => ("I_l₁", p, "linear_inertia1"),
        "I_a1" => ("I_a₁", p, "angular_inertia1"),
        "I_l2" => ("I_l₂", p, "linear_inertia2"),
        "I_a2" => ("I_a₂", p, "angular_inertia2"),
        "I_t" => ("I_t", p, "total_inertia"),
        "move_l1" => ("Δ_l₁", p, "linear_move1"),
        "move_a1" => ("Δ_a₁", p, "angular_move1"),
        "move_l2" => ("Δ_l₂", p, "linear_move2"),
        "move_a2" => ("Δ_a₂", p, "angular_move2"),
        "p1" => ("p₁′", p, "position1"),
        "p2" => ("p₂′", p, "position2"),
        "turn1" => ("Δθ₁", p, "angular_change1"),
        "turn2" => ("Δθ₂", p, "angular_change2"),
        "theta1" => ("θ₁′ / |θ₁′|", "orientation_update", "orientation1"),
        "theta2" => ("θ₂′ / |θ₂′|", "orientation_update", "orientation2"),
        _ => return None,
    })
}

/// One short answer: the key a student's answer file uses, the label on the
/// sheet, and where the trace has it.
pub struct ShortAnswer<'a> {
    pub key: &'static str,
    pub label: &'static str,
    pub step: &'a crate::trace::Step,
    pub name: &'static str,
    pub value: &'a Value,
}

/// The short answers of an exercise, question by question, where the
/// trace has them (a body that is immovable has no v₂′): the answer key,
/// the template and the grader all read this list.
pub fn short_answers(kind: Kind, t: &Trace) -> Vec<ShortAnswer<'_>> {
    let mut keys: Vec<&'static str> = Vec::new();
    for q in questions(kind, t) {
        for key in q.asks {
            if !keys.contains(key) {
                keys.push(key);
            }
        }
    }
    keys.into_iter()
        .filter_map(|key| {
            let (label, stage, name) = answer(kind, key)?;
            let step = t.stage(stage).filter(|s| s.skipped.is_none())?;
            Some(ShortAnswer {
                key,
                label,
                step,
                name,
                value: step.value(name)?,
            })
        })
        .collect()
}

/// Every key the questions of an exercise ask for that the trace has a
/// value for, in order (what the sheet asks, for tests and the TUI).
pub fn asked(kind: Kind, t: &Trace) -> Vec<&'static str> {
    short_answers(kind, t).iter().map(|a| a.key).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_a_question_asks_for_has_an_answer() {
        for kind in Kind::ALL {
            let e = &crate::exercise::generate(3, Some(kind), 1).unwrap()[0];
            for q in questions(kind, &e.trace) {
                for key in q.asks {
                    assert!(answer(kind, key).is_some(), "{kind:?}: {key}");
                }
            }
        }
    }
}
