//! From TOML text to a validated [`Lesson`]. Every error names the span of the
//! offending value; all errors of a file are reported together.

mod body;
mod figure;
mod knobs;
mod plausible;
mod printed;
mod simulation;

use std::collections::HashMap;

use nalgebra::{Matrix3, Quaternion, Vector3};

use super::raw::{self, RawBody, RawContact, RawLesson, S};
use super::source::{LessonDiagnostic, LessonError, Note};
use super::syntax;
use super::{BodyDef, ContactDef, Lesson, Shape};
use crate::knobs::Table;
use crate::physics::params::ContactSettings;

/// Rules shared by the file validator and the TUI's edit form: each returns
/// the reason a value is refused.
pub mod rules;

/// Reads raw bytes (refusing non-UTF-8 with the position of the first bad byte).
pub fn parse_bytes(origin: &str, bytes: &[u8]) -> Result<Lesson, LessonError> {
    match std::str::from_utf8(bytes) {
        Ok(text) => parse(origin, text),
        Err(e) => {
            let valid = String::from_utf8_lossy(&bytes[..e.valid_up_to()]).into_owned();
            let at = valid.len();
            let mut text = valid;
            text.push(' ');
            let utf16 = bytes.starts_with(&[0xFF, 0xFE]) || bytes.starts_with(&[0xFE, 0xFF]);
            let help = if utf16 {
                "it starts like UTF-16 text: save the lesson as UTF-8 TOML"
            } else {
                "save the lesson as UTF-8 TOML; see lessons/README.md"
            };
            let note = Note::new(
                "the file is not UTF-8 text (a lesson is a TOML file)",
                at..at + 1,
            )
            .help(help);
            Err(invalid(origin, &text, vec![note]))
        }
    }
}

/// Lesson files larger than this are refused unread (a lesson is a few KB).
pub const MAX_BYTES: usize = 16 << 20;

/// The error for a file larger than [`MAX_BYTES`].
pub fn too_large(origin: &str) -> LessonError {
    let note = Note::new(
        format!(
            "the file is larger than {} MiB: a lesson is a small TOML file",
            MAX_BYTES >> 20
        ),
        0..0,
    );
    invalid(origin, "", vec![note])
}

/// At most this many errors of one file are reported; the rest are counted.
pub const MAX_ERRORS: usize = 20;

fn invalid(origin: &str, text: &str, mut notes: Vec<Note>) -> LessonError {
    let omitted = notes.len().saturating_sub(MAX_ERRORS);
    notes.truncate(MAX_ERRORS);
    LessonError::Invalid {
        path: origin.to_string(),
        diagnostics: LessonDiagnostic::resolve(origin, text, notes),
        omitted,
    }
}

pub fn parse(origin: &str, text: &str) -> Result<Lesson, LessonError> {
    if text.trim().is_empty() {
        let note = Note::new("the lesson file is empty", 0..0)
            .help("a lesson needs at least `id`, `title`, one [[body]] and one [[contact]]; see lessons/README.md");
        return Err(invalid(origin, text, vec![note]));
    }
    let raw: RawLesson =
        toml::from_str(text).map_err(|e| invalid(origin, text, vec![syntax::note(&e, text)]))?;
    let mut v = Validator {
        origin: origin.to_string(),
        ..Validator::default()
    };
    let lesson = v.lesson(raw, origin);
    if v.errors.is_empty() {
        // What the stages compute from valid inputs must fit in f64 too.
        for (k, span) in v.contact_spans.clone().into_iter().enumerate() {
            if let Err(e) = super::overflow::check(&lesson, k) {
                v.err(span, e);
            }
        }
    }
    if v.errors.is_empty() {
        let mut lesson = lesson;
        lesson.warnings = LessonDiagnostic::resolve(origin, text, v.warnings);
        for (i, span) in v.printed_zero {
            lesson.printed[i].zero_at = Some(super::source::line_column(text, span.start));
        }
        Ok(lesson)
    } else {
        Err(invalid(origin, text, v.errors))
    }
}

#[derive(Default)]
struct Validator {
    errors: Vec<Note>,
    warnings: Vec<Note>,
    /// Where each contact's `bodies` is, for errors about a whole contact.
    contact_spans: Vec<std::ops::Range<usize>>,
    /// Printed values that are all zeros, by index into the lesson's
    /// printed entries: where they stand.
    printed_zero: Vec<(usize, std::ops::Range<usize>)>,
    /// The scene-wide knobs set so far (`[settings]`, `[world]`, `[step]`,
    /// `[sleep]`) and the table each was set in: a knob set in two of them
    /// is said, since the table read last silently wins.
    /// The key as the file spells it comes third.
    scene_knobs: Vec<(&'static str, crate::knobs::Table, String)>,
    /// The lesson's origin (its path, or `… (embedded)`): where a mesh's
    /// OBJ file is looked for.
    origin: String,
}

fn v3(a: [f64; 3]) -> Vector3<f64> {
    Vector3::from(a)
}

fn mat(a: [[f64; 3]; 3]) -> Matrix3<f64> {
    Matrix3::from_fn(|r, c| a[r][c])
}

impl Validator {
    fn err(&mut self, span: std::ops::Range<usize>, message: impl Into<String>) {
        self.errors.push(Note::new(message, span));
    }

    fn rule(&mut self, what: &str, value: &S<f64>, rule: fn(f64) -> Result<(), String>) -> f64 {
        if let Err(e) = rule(*value.get_ref()) {
            self.err(value.span(), format!("{what}: {e}"));
        }
        *value.get_ref()
    }

    fn finite<const N: usize>(&mut self, what: &str, value: &S<[f64; N]>) -> [f64; N] {
        let names: &[&str] = if N == 4 {
            &["w", "x", "y", "z"]
        } else {
            &["x", "y", "z"]
        };
        let bad = value
            .get_ref()
            .iter()
            .zip(names)
            .find(|(x, _)| !rules::in_range(**x));
        if let Some((x, axis)) = bad {
            let message = if x.is_finite() && x.abs() < rules::MIN_MAGNITUDE {
                format!("{what}: {} (in {axis})", super::ranges::too_small(*x))
            } else if x.is_finite() {
                format!("{what}: every component must be a finite number within ±1e60, {x:e} is outside ±1e60 in {axis}")
            } else {
                format!("{what}: every component must be a finite number within ±1e60, got {x} in {axis}")
            };
            self.err(value.span(), message);
        }
        *value.get_ref()
    }

    /// A direction (normal, orientation): finite and within ±1e60, but any
    /// length, since it is normalised; tiny components of the unit vector
    /// are then set to 0 (`ranges::flush_tiny`).
    fn finite_direction<const N: usize>(&mut self, what: &str, value: &S<[f64; N]>) -> [f64; N] {
        let v = *value.get_ref();
        if v.iter()
            .all(|x| x.is_finite() && x.abs() <= rules::MAX_MAGNITUDE)
        {
            return v;
        }
        self.finite(what, value)
    }

    fn opt_vec(&mut self, what: &str, value: &Option<S<[f64; 3]>>) -> Vector3<f64> {
        value
            .as_ref()
            .map_or(Vector3::zeros(), |v| v3(self.finite(what, v)))
    }

    fn lesson(&mut self, raw: RawLesson, origin: &str) -> Lesson {
        if let Err(e) = rules::name(raw.id.get_ref()) {
            self.err(raw.id.span(), format!("id {e}"));
        }
        let texts = [("title", Some(&raw.title)), ("source", raw.source.as_ref())];
        for (what, value) in texts {
            if let Some(Err(e)) = value.map(|v| rules::line(v.get_ref())) {
                self.err(value.map_or(0..0, |v| v.span()), format!("{what} {e}"));
            }
        }
        if let Some(Err(e)) = raw.summary.as_ref().map(|v| rules::text(v.get_ref())) {
            let span = raw.summary.as_ref().map_or(0..0, |v| v.span());
            self.err(span, format!("summary {e}"));
        }
        let bodies: Vec<BodyDef> = raw.bodies.iter().map(|b| self.body(b)).collect();
        let mut index = HashMap::new();
        for (i, b) in raw.bodies.iter().enumerate() {
            if index.insert(b.name.get_ref().as_str(), i).is_some() {
                self.err(
                    b.name.span(),
                    format!("body name '{}' is used twice", b.name.get_ref()),
                );
            }
        }
        // Contacts refer to the first body of a name.
        for (i, b) in raw.bodies.iter().enumerate().rev() {
            index.insert(b.name.get_ref().as_str(), i);
        }
        if raw.bodies.is_empty() {
            self.err(0..0, "the lesson has no [[body]]");
        }
        let (all, mut simulation) = self.knobs(&raw);
        if let Some(scene) = &simulation {
            self.mesh_pairs(&raw, &bodies, scene);
        }
        self.body_materials(&raw, simulation.as_mut());
        if raw.contacts.is_empty() && simulation.is_none() {
            self.err(
                0..0,
                "the lesson has no [[contact]] (a scene that generates its contacts needs a [world] or [step] table)",
            );
        }
        let defaults = all.contact;
        let resolver = all.resolver;
        let contacts = raw
            .contacts
            .iter()
            .map(|c| {
                let def = self.contact(c, (&index, &raw.bodies), &bodies, defaults);
                self.plausible_contact(c, &def, &bodies);
                def
            })
            .collect();
        let mut printed = Vec::new();
        for p in &raw.printed {
            if let Some(entry) = self.printed(p, raw.contacts.len(), &index) {
                if let Some(span) = self.printed_zero(p) {
                    self.printed_zero.push((printed.len(), span));
                }
                printed.push(entry);
            }
        }
        let figure = raw.figure.as_ref().map(|f| self.figure(f, &index));
        Lesson {
            id: raw.id.into_inner(),
            title: super::ascii_minus(raw.title.get_ref()),
            source: raw
                .source
                .map(|s| super::ascii_minus(s.get_ref()))
                .unwrap_or_default(),
            summary: raw
                .summary
                .map(|s| super::ascii_minus(s.get_ref().trim()))
                .unwrap_or_default(),
            origin: origin.to_string(),
            bodies,
            contacts,
            printed,
            settings: defaults,
            simulation,
            resolver,
            warnings: Vec::new(),
            figure,
            spellings: self
                .scene_knobs
                .iter()
                .map(|(knob, table, key)| (*table, *knob, key.clone()))
                .collect(),
        }
    }

    fn contact(
        &mut self,
        raw: &RawContact,
        (by_name, raw_bodies): (&HashMap<&str, usize>, &[RawBody]),
        bodies: &[BodyDef],
        defaults: ContactSettings,
    ) -> ContactDef {
        self.contact_spans.push(raw.bodies.span());
        if let Some(n) = &raw.name {
            if let Err(e) = rules::name(n.get_ref()) {
                self.err(n.span(), format!("contact name {e}"));
            }
        }
        let names = raw.bodies.get_ref();
        let mut index = Vec::new();
        for n in names {
            match by_name.get(n.get_ref().as_str()) {
                Some(&i) => index.push(i),
                None => self.err(
                    n.span(),
                    format!(
                        "unknown body '{}' (bodies: {})",
                        n.get_ref(),
                        body_list(raw_bodies)
                    ),
                ),
            }
        }
        if names.is_empty() || names.len() > 2 {
            self.err(
                raw.bodies.span(),
                format!("a contact names one or two bodies, got {}", names.len()),
            );
        }
        if names.len() == 2 && names[0].get_ref() == names[1].get_ref() {
            self.err(
                names[1].span(),
                format!(
                    "a contact needs two different bodies, got '{}' twice",
                    names[1].get_ref()
                ),
            );
        }
        if !index.is_empty()
            && index.len() == names.len()
            && index.iter().all(|&i| bodies[i].mass == f64::INFINITY)
        {
            self.err(
                raw.bodies.span(),
                "a contact needs at least one movable body (mass < inf)",
            );
        }
        let point = v3(self.finite("contact point", &raw.point));
        // A direction: any non-zero length will do (scaled before squaring,
        // so a length of 1e-170 is not taken for zero).
        let given = v3(self.finite_direction("contact normal", &raw.normal));
        let normal_length = crate::physics::scale::stable_norm(&given);
        let normal = if !normal_length.is_finite() {
            Vector3::y()
        } else if normal_length == 0.0 {
            self.err(
                raw.normal.span(),
                "contact normal must be non-zero (its length is 0)",
            );
            Vector3::y()
        } else {
            if (normal_length - 1.0).abs() > 1e-4 {
                self.warnings.push(Note::new(
                    format!(
                        "contact normal has length {}; it was normalised to unit length",
                        crate::format::exact(normal_length)
                    ),
                    raw.normal.span(),
                ));
            }
            super::ranges::flush_tiny(given / normal_length)
        };
        let penetration = raw
            .penetration
            .as_ref()
            .map_or(0.0, |p| self.rule("penetration", p, rules::finite));
        let restitution = self.rule("contact", &raw.restitution, rules::restitution);
        let material = self.material(
            "contact",
            crate::physics::params::Material::default(),
            (
                &None,
                &raw.friction,
                &raw.static_friction,
                &raw.dynamic_friction,
            ),
        );
        let (mu_s, mu_d) = (material.static_friction, material.dynamic_friction);
        if mu_d > mu_s {
            if let Some(span) = raw.dynamic_friction.as_ref().map(|f| f.span()) {
                self.warnings.push(Note::new(
                    format!("dynamic friction {} exceeds static friction {}: sliding would grip harder than sticking", crate::format::exact(mu_d), crate::format::exact(mu_s)),
                    span,
                ));
            }
        }
        let mut own = crate::physics::Settings {
            contact: defaults,
            ..Default::default()
        };
        if let Some(m) = &raw.friction_model {
            let mut table = raw::KnobTable::new();
            table.insert(S::new(m.span(), "friction_model".into()), m.clone());
            self.knob_table(Table::Contact, &table, &mut own, &[]);
        }
        if let Some(s) = &raw.settings {
            self.knob_table(Table::ContactSettings, s, &mut own, &[]);
        }
        let settings = own.contact;
        ContactDef {
            name: raw.name.as_ref().map(|n| n.get_ref().clone()),
            bodies: (index.first().copied().unwrap_or(0), index.get(1).copied()),
            point,
            normal,
            normal_length,
            penetration,
            restitution,
            static_friction: mu_s,
            dynamic_friction: mu_d,
            settings,
            previous_normal: None,
        }
    }
}

/// The body names, for "unknown body" (the first ten of a long list).
fn body_list(bodies: &[RawBody]) -> String {
    let names: Vec<&str> = bodies
        .iter()
        .take(10)
        .map(|b| b.name.get_ref().as_str())
        .collect();
    match bodies.len() {
        n if n > names.len() => format!("{}, … {n} in all", names.join(", ")),
        _ => names.join(", "),
    }
}

/// A tensor as rows, through the one formatter.
fn tensor(m: &Matrix3<f64>) -> String {
    let f = crate::format::Fmt::default();
    let rows: Vec<String> = (0..3)
        .map(|r| format!("[{}]", f.list(&[m[(r, 0)], m[(r, 1)], m[(r, 2)]])))
        .collect();
    format!("[{}]", rows.join(", "))
}
