//! What a stage's named value is called in the worked solution: the
//! left-hand side of the formula that computes it (`desired` → `Δv`,
//! `impulse_contact` → `g_contact`), or, for the few values no formula
//! computes, the lectures' symbol. `check` names its rows this way, so an
//! instructor reads `Δv` where the JSON keeps the key `desired`.

use super::{StageId, Trace};

/// Values that no formula's left-hand side names, by (stage, key).
const NAMED: &[(&str, &str, &str)] = &[
    ("desired_delta_velocity", "closing_velocity", "-v_s"),
    ("desired_delta_velocity", "contact_velocity", "v_c"),
    ("desired_delta_velocity", "restitution", "c"),
    ("unit_impulse", "inertia1", "I₁"),
    ("unit_impulse", "inertia2", "I₂"),
    ("unit_impulse", "shape_inertia1", "I₁ of the shape"),
    ("unit_impulse", "shape_inertia2", "I₂ of the shape"),
    ("unit_impulse", "matrix", "M"),
    ("apply_impulse", "dw1_degrees_per_second", "Δθ̇₁ (°/s)"),
    ("apply_impulse", "dw2_degrees_per_second", "Δθ̇₂ (°/s)"),
];

impl Trace {
    /// The symbol of a stage's value, `None` when the stage has no such
    /// value and no formula names it.
    pub fn symbol(&self, stage: &str, value: &str) -> Option<String> {
        let from_formula = self.stage(stage).and_then(|s| {
            s.formulas
                .iter()
                .find(|f| f.result.as_deref() == Some(value))
                .map(|f| f.lhs.to_string())
        });
        from_formula.or_else(|| {
            NAMED
                .iter()
                .find(|(s, v, _)| *s == stage && *v == value)
                .map(|(_, _, symbol)| symbol.to_string())
        })
    }
}

/// "stage 3, desired Δv" for a stage's JSON name; `None` for an unknown one.
pub fn stage_words(stage: &str) -> Option<String> {
    StageId::ALL
        .iter()
        .find(|s| s.json_name() == stage)
        .map(|s| format!("stage {}, {}", s.number(), s.label_in_text()))
}
