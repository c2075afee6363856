//! Live edits of a validated lesson (the TUI's edit form): which inputs of a
//! contact and its bodies may change, and setting them through the same
//! [`rules`] the file validator uses. A refused value leaves the lesson as it was.

use nalgebra::Vector3;

use super::knob_value::{self, echo};
use super::validate::rules;
use super::Lesson;
use crate::format::exact;
use crate::knobs::{self, Kind as KnobKind, Knob, Level, Offered, Spelling, Value};

/// What an editable field holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Key {
    Restitution,
    StaticFriction,
    DynamicFriction,
    Penetration,
    /// A knob of the table (`knobs`).
    Knob(&'static Knob),
    Mass,
    Velocity,
    AngularVelocity,
    Acceleration,
}

/// How a field is entered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// One number.
    Number,
    /// Three numbers `x, y, z`.
    Vector,
    /// One of a fixed list of names; entering cycles through them.
    Choice(&'static [Spelling]),
}

/// One editable input of contact `k`: a contact field, or a field of the body
/// `body` (an index into `Lesson::bodies`).
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    pub key: Key,
    pub body: Option<usize>,
    /// e.g. `restitution`, `cube: velocity`.
    pub label: String,
}

const FLAG: &[Spelling] = &[
    Spelling {
        name: "true",
        aliases: &[],
        doc: "",
    },
    Spelling {
        name: "false",
        aliases: &[],
        doc: "",
    },
];

impl Field {
    pub fn kind(&self) -> Kind {
        match self.key {
            Key::Velocity | Key::AngularVelocity | Key::Acceleration => Kind::Vector,
            Key::Knob(knob) => match knob.kind {
                KnobKind::Choice { choices } => Kind::Choice(choices),
                KnobKind::Flag => Kind::Choice(FLAG),
                KnobKind::Vector => Kind::Vector,
                _ => Kind::Number,
            },
            _ => Kind::Number,
        }
    }
}

const CONTACT_FIELDS: [(Key, &str); 4] = [
    (Key::Restitution, "restitution"),
    (Key::StaticFriction, "static friction μ_s"),
    (Key::DynamicFriction, "dynamic friction μ_d"),
    (Key::Penetration, "penetration"),
];

const BODY_FIELDS: [(Key, &str); 4] = [
    (Key::Mass, "mass"),
    (Key::Velocity, "velocity"),
    (Key::AngularVelocity, "angular velocity"),
    (Key::Acceleration, "acceleration"),
];

/// The editable fields of contact `k`: the contact's own, its knobs (and a
/// scene's other knobs, which change the run), then those of each movable
/// body in it (an immovable body has nothing to edit).
pub fn fields(lesson: &Lesson, k: usize) -> Vec<Field> {
    let scene = lesson.simulation.is_some();
    let mut out: Vec<Field> = CONTACT_FIELDS
        .iter()
        .map(|&(key, label)| Field {
            key,
            body: None,
            label: label.to_string(),
        })
        .collect();
    out.extend(
        knobs::KNOBS
            .iter()
            .filter(|knob| knob.edit == Offered::Yes && (scene || knob.level == Level::Contact))
            .map(|knob| Field {
                key: Key::Knob(knob),
                body: None,
                label: knob.name.to_string(),
            }),
    );
    for b in lesson.slots(k).into_iter().flatten() {
        if !lesson.bodies[b].movable() {
            continue;
        }
        for &(key, label) in &BODY_FIELDS {
            out.push(Field {
                key,
                body: Some(b),
                label: format!("{}: {label}", lesson.bodies[b].name),
            });
        }
    }
    out
}

fn vector_text(v: &Vector3<f64>) -> String {
    format!("{}, {}, {}", exact(v.x), exact(v.y), exact(v.z))
}

/// A knob's value for contact `k`: its own settings for a contact's knob,
/// the lesson's for the others.
fn knob_value_of(lesson: &Lesson, k: usize, knob: &Knob) -> Value {
    let mut all = lesson.knobs();
    if knob.level == Level::Contact {
        all.contact = lesson.contacts[k].settings;
    }
    (knob.get)(&all)
}

/// The field's current value as editable text (full precision, so that
/// entering it again changes nothing).
pub fn get(lesson: &Lesson, k: usize, field: &Field) -> String {
    let c = &lesson.contacts[k];
    let body = field.body.map(|b| &lesson.bodies[b]);
    match (field.key, body) {
        (Key::Restitution, _) => exact(c.restitution),
        (Key::StaticFriction, _) => exact(c.static_friction),
        (Key::DynamicFriction, _) => exact(c.dynamic_friction),
        (Key::Penetration, _) => exact(c.penetration),
        (Key::Knob(knob), _) => knob_value::text(knob_value_of(lesson, k, knob)),
        (Key::Mass, Some(b)) => exact(b.mass),
        (Key::Velocity, Some(b)) => vector_text(&b.velocity),
        (Key::AngularVelocity, Some(b)) => vector_text(&b.angular_velocity),
        (Key::Acceleration, Some(b)) => vector_text(&b.acceleration),
        (_, None) => String::new(),
    }
}

/// The next name of a choice field, after the current one.
pub fn next_choice(lesson: &Lesson, k: usize, field: &Field) -> Option<String> {
    let Kind::Choice(names) = field.kind() else {
        return None;
    };
    let now = get(lesson, k, field);
    let i = names.iter().position(|n| n.name == now).unwrap_or(0);
    Some(names[(i + 1) % names.len()].name.to_string())
}

fn number(text: &str) -> Result<f64, String> {
    let t = text.trim();
    let t = if t == "∞" { "inf" } else { t };
    t.parse::<f64>()
        .map_err(|_| format!("'{}' is not a number", echo(text.trim())))
}

fn vector(text: &str) -> Result<Vector3<f64>, String> {
    let parts: Vec<&str> = text
        .trim()
        .trim_start_matches(['(', '['])
        .trim_end_matches([')', ']'])
        .split([',', ' '])
        .filter(|s| !s.trim().is_empty())
        .collect();
    if parts.len() != 3 {
        return Err(format!(
            "expected three numbers x, y, z, got {} ('{}')",
            parts.len(),
            echo(text.trim())
        ));
    }
    let mut v = Vector3::zeros();
    for (i, p) in parts.iter().enumerate() {
        v[i] = number(p)?;
        rules::finite(v[i]).map_err(|e| format!("{} component {e}", ["x", "y", "z"][i]))?;
    }
    Ok(v)
}

/// Sets `field` of contact `k` from `text`, checked by the validator's rules.
/// On success returns a short description of the change (`restitution 0.8 → 0.5`);
/// on refusal returns why, and the lesson is unchanged.
pub fn set(lesson: &mut Lesson, k: usize, field: &Field, text: &str) -> Result<String, String> {
    let before = get(lesson, k, field);
    let backup = lesson.clone();
    apply(lesson, k, field, text).map_err(|e| format!("{}: {e}", field.label))?;
    // As when the file is read: what the stages compute must fit in f64.
    if let Err(e) = super::overflow::check_all(lesson) {
        *lesson = backup;
        return Err(format!("{}: {e}", field.label));
    }
    let after = get(lesson, k, field);
    let mut said = format!("{} {before} → {after}", field.label);
    if field.key == Key::Mass {
        said.push_str(" (inertia scaled with it: same shape, same mass distribution)");
    }
    Ok(said)
}

fn apply(lesson: &mut Lesson, k: usize, field: &Field, text: &str) -> Result<(), String> {
    let checked = |rule: fn(f64) -> Result<(), String>| {
        let x = number(text)?;
        rule(x)?;
        Ok::<f64, String>(x)
    };
    if let Some(b) = field.body {
        let body = &mut lesson.bodies[b];
        match field.key {
            Key::Mass => {
                let m = checked(rules::mass)?;
                if !m.is_finite() {
                    return Err(
                        "a movable body keeps a finite mass here; make a body immovable in the lesson file".into(),
                    );
                }
                let scale = m / body.mass;
                // The scaled tensor must still be one the stages can use.
                if let Some(t) = body.inertia {
                    rules::inertia(&(t * scale))
                        .map_err(|e| format!("the inertia tensor scaled with it: {e}"))?;
                }
                body.inertia = body.inertia.map(|t| t * scale);
                body.shape_inertia = body.shape_inertia.map(|t| t * scale);
                body.mass = m;
            }
            Key::Velocity => body.velocity = vector(text)?,
            Key::AngularVelocity => body.angular_velocity = vector(text)?,
            Key::Acceleration => body.acceleration = vector(text)?,
            _ => return Err("not a body field".into()),
        }
        return Ok(());
    }
    if let Key::Knob(knob) = field.key {
        let value = knob_value::from_text(knob, text).map_err(|e| {
            // The rule names the knob; the form already shows it.
            e.strip_prefix(knob.name)
                .map(|rest| rest.trim_start_matches(':').trim().to_string())
                .unwrap_or(e)
        })?;
        if knob.level == Level::Contact {
            let mut own = crate::physics::Settings {
                contact: lesson.contacts[k].settings,
                ..Default::default()
            };
            (knob.set)(&mut own, value);
            lesson.contacts[k].settings = own.contact;
        } else {
            lesson.set_knob(knob, value);
        }
        return Ok(());
    }
    let c = &mut lesson.contacts[k];
    match field.key {
        Key::Restitution => c.restitution = checked(rules::restitution)?,
        Key::StaticFriction => c.static_friction = checked(rules::friction)?,
        Key::DynamicFriction => c.dynamic_friction = checked(rules::friction)?,
        Key::Penetration => c.penetration = checked(rules::finite)?,
        _ => return Err("not a contact field".into()),
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lecture2() -> Lesson {
        Lesson::load("lecture-2").unwrap()
    }

    fn field(l: &Lesson, label: &str) -> Field {
        fields(l, 0)
            .into_iter()
            .find(|f| f.label == label)
            .unwrap_or_else(|| panic!("no field {label}"))
    }

    /// Sets the field labelled `label` of contact 0.
    fn put(l: &mut Lesson, label: &str, text: &str) -> Result<String, String> {
        let f = field(l, label);
        set(l, 0, &f, text)
    }

    #[test]
    fn immovable_bodies_have_no_fields() {
        let l = lecture2();
        let labels: Vec<String> = fields(&l, 0).into_iter().map(|f| f.label).collect();
        assert!(labels.contains(&"cube: mass".to_string()));
        assert!(!labels.iter().any(|f| f.starts_with("floor")));
    }

    #[test]
    fn refused_values_keep_the_old_value() {
        let mut l = lecture2();
        let before = l.clone();
        let mass = field(&l, "cube: mass");
        for bad in ["NaN", "-1", "0", "inf", "ten", ""] {
            let e = set(&mut l, 0, &mass, bad).unwrap_err();
            assert!(e.starts_with("cube: mass: "), "{e}");
        }
        let e = put(&mut l, "restitution", "1.5").unwrap_err();
        assert!(e.contains("[0, 1]"), "{e}");
        let e = put(&mut l, "restitution", "nan").unwrap_err();
        assert!(e.contains("[0, 1]"), "{e}");
        let e = put(&mut l, "cube: velocity", "1, NaN, 0").unwrap_err();
        assert!(e.contains("finite"), "{e}");
        let e = put(&mut l, "cube: velocity", "1, 2").unwrap_err();
        assert!(e.contains("three numbers"), "{e}");
        // A share knob (in (0, 1]) refuses 0.
        let share = crate::knobs::KNOBS
            .iter()
            .find(|k| k.kind.range() == Some(crate::knobs::Range::Share))
            .unwrap();
        let e = put(&mut l, share.name, "0").unwrap_err();
        assert!(e.contains("(0, 1]"), "{e}");
        assert_eq!(l.contacts, before.contacts);
        assert_eq!(l.bodies, before.bodies);
    }

    #[test]
    fn an_edit_whose_products_overflow_is_refused_and_undone() {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/invalid_lessons/product-overflows-under-another-model.toml"
        ))
        .unwrap();
        // Valid with a modest friction; μ_d = 1e54 overflows under kinetic-direction.
        let text = text.replace("static_friction = 1.1449294629583569e54", "friction = 0.5");
        let mut l = super::super::validate::parse("t.toml", &text).unwrap();
        let before = l.clone();
        let mu = fields(&l, 0)
            .into_iter()
            .find(|f| f.label == "dynamic friction μ_d")
            .expect("a dynamic friction field");
        let e = set(&mut l, 0, &mu, "1.1449294629583569e54").unwrap_err();
        assert!(e.contains("overflow a 64-bit float"), "{e}");
        assert_eq!(l.contacts, before.contacts);
        set(&mut l, 0, &mu, "0.8").unwrap();
    }

    #[test]
    fn accepted_values_change_the_lesson() {
        let mut l = lecture2();
        let said = put(&mut l, "restitution", " 0.5 ").unwrap();
        assert_eq!(said, "restitution 0.8 → 0.5");
        assert_eq!(l.contacts[0].restitution, 0.5);
        put(&mut l, "cube: velocity", "(1, -2, 0.5)").unwrap();
        assert_eq!(l.bodies[0].velocity, Vector3::new(1.0, -2.0, 0.5));
        put(&mut l, "cube: mass", "20").unwrap();
        assert_eq!(l.bodies[0].mass, 20.0);
        assert_eq!(l.bodies[0].inertia.unwrap()[(0, 0)], 480.0);
        put(&mut l, "angular_limit", "inf").unwrap();
        assert!(l.contacts[0].settings.angular_limit.is_infinite());
    }

    #[test]
    fn text_round_trips() {
        let l = lecture2();
        for f in fields(&l, 0) {
            let mut m = l.clone();
            let text = get(&l, 0, &f);
            set(&mut m, 0, &f, &text).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(m.contacts, l.contacts, "{}", f.label);
            assert_eq!(m.bodies, l.bodies, "{}", f.label);
        }
    }

    #[test]
    fn choices_cycle() {
        let mut l = lecture2();
        let f = field(&l, "friction_model");
        let next = next_choice(&l, 0, &f).unwrap();
        assert_eq!(next, "kinetic-direction");
        set(&mut l, 0, &f, &next).unwrap();
        assert_eq!(
            l.contacts[0].settings.friction_model,
            crate::physics::FrictionModel::KineticDirection
        );
        let f = field(&l, "exact");
        assert_eq!(get(&l, 0, &f), "none");
        for law in ["newton", "poisson", "stronge", "none"] {
            let next = next_choice(&l, 0, &f).unwrap();
            assert_eq!(next, law);
            set(&mut l, 0, &f, &next).unwrap();
            assert_eq!(
                crate::knobs::Choice::name(l.contacts[0].settings.exact),
                law
            );
        }
        let e = put(&mut l, "exact", "hooke").unwrap_err();
        assert!(
            e.contains(r#"one of "none", "newton", "poisson", "stronge""#),
            "{e}"
        );
    }
}
