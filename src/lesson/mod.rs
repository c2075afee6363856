//! Lesson files: one scene per TOML file (format in `lessons/README.md`),
//! validated into a [`Lesson`] with spans for every error.

pub mod characters;
pub mod edit;
pub mod embedded;
pub mod knob_value;
pub mod mesh;
pub mod overflow;
pub mod printed;
pub mod ranges;
pub mod raw;
pub mod read;
pub mod shape;
pub mod snippet;
pub mod source;
pub mod syntax;
pub mod validate;

use nalgebra::{Matrix3, Quaternion, Vector3};

use crate::knobs::{Knob, Level, Value};
pub use crate::physics::params::Material;
use crate::physics::params::{ContactSettings, SceneSettings};
use crate::physics::step::SimParams;
pub use crate::physics::Shape;
use crate::physics::{
    c, Body, BodyId, Contact, ContactInput, Problem, Real, ResolverParams, RigidBody, StepParams,
    World,
};
pub use printed::Printed;
pub use source::{LessonDiagnostic, LessonError};

/// A validated lesson: every number finite, every reference resolved.
#[derive(Debug, Clone)]
pub struct Lesson {
    pub id: String,
    pub title: String,
    pub source: String,
    pub summary: String,
    /// File path, or `lessons/NAME.toml (embedded)`.
    pub origin: String,
    pub bodies: Vec<BodyDef>,
    pub contacts: Vec<ContactDef>,
    pub printed: Vec<Printed>,
    /// The lesson's `[settings]` table as validated, defaults where absent: a contact's knobs.
    pub settings: ContactSettings,
    /// Time stepping, when the lesson has `[world]`, `[step]` or `[sleep]`.
    pub simulation: Option<SceneSettings>,
    /// How `resolve` resolves the contacts together (`[settings]`, defaults where absent).
    pub resolver: ResolverParams,
    /// Non-fatal findings (normalised normal, shape vs tensor, …).
    pub warnings: Vec<LessonDiagnostic>,
    /// `[figure]`: how the pictures correct the lesson's geometry, if at all.
    pub figure: Option<FigureDef>,
    /// Every scene-wide knob the file sets (`[settings]`, `[world]`,
    /// `[step]`, `[sleep]`): its table, the knob and the key as the file
    /// spells it (the knob's name or an old one: `[sleep] enabled`), so that
    /// what is written back into the file replaces the same key.
    pub spellings: Vec<(crate::knobs::Table, &'static str, String)>,
}

/// A lesson's text as contact-lab shows it: the Unicode minus sign (U+2212)
/// written as ASCII `-`, the one kind of minus sign of every output (so a
/// copied number or formula pastes into a calculator).
pub fn ascii_minus(s: &str) -> String {
    s.replace('\u{2212}', "-")
}

/// A figure-only correction of a lesson's geometry: the pictures (SVG, TUI,
/// LaTeX) draw these shapes and orientations and quote the note; the stages
/// compute with the lesson's own values.
#[derive(Debug, Clone, PartialEq)]
pub struct FigureDef {
    pub note: String,
    pub bodies: Vec<DrawnBody>,
}

/// One body as a [`FigureDef`] draws it.
#[derive(Debug, Clone, PartialEq)]
pub struct DrawnBody {
    /// Index into [`Lesson::bodies`].
    pub body: usize,
    pub shape: Option<Shape>,
    /// Unit quaternion `[w, x, y, z]`.
    pub orientation: Option<[f64; 4]>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct BodyDef {
    pub name: String,
    /// `f64::INFINITY` for an immovable body.
    pub mass: f64,
    pub shape: Option<Shape>,
    /// Body-frame tensor used by the stages (explicit, else from the shape).
    pub inertia: Option<Matrix3<f64>>,
    /// Tensor the shape formula gives, when a shape is named.
    pub shape_inertia: Option<Matrix3<f64>>,
    pub position: Vector3<f64>,
    /// Unit quaternion `[w, x, y, z]`.
    pub orientation: Quaternion<f64>,
    pub velocity: Vector3<f64>,
    pub angular_velocity: Vector3<f64>,
    pub acceleration: Vector3<f64>,
}

impl BodyDef {
    pub fn movable(&self) -> bool {
        self.mass.is_finite()
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct ContactDef {
    pub name: Option<String>,
    /// Indices into `Lesson::bodies`; the second is `None` against the world.
    pub bodies: (usize, Option<usize>),
    pub point: Vector3<f64>,
    /// Unit normal, from body 2 toward body 1.
    pub normal: Vector3<f64>,
    /// Length of the normal as written (1 unless it was normalised).
    pub normal_length: f64,
    pub penetration: f64,
    pub restitution: f64,
    pub static_friction: f64,
    pub dynamic_friction: f64,
    /// `[settings]` with this contact's `settings` table over it (and its
    /// own `friction_model`).
    pub settings: ContactSettings,
    /// A scene step's penetrating contact: the normal from the closest
    /// points one frame earlier (t − Δt), when the pair was apart then
    /// (physics/step/previous_frame.rs). Never written in a file.
    pub previous_normal: Option<Vector3<f64>>,
}

impl Lesson {
    /// Every knob's value: the lesson's `[settings]`, its resolver's and its
    /// scene's (defaults for a lesson without one).
    pub fn knobs(&self) -> crate::physics::Settings {
        crate::physics::Settings {
            contact: self.settings,
            resolver: self.resolver,
            scene: self.simulation.clone().unwrap_or_default(),
        }
    }

    /// Sets `knob`: a contact's knob on `[settings]` and on every contact.
    pub fn set_knob(&mut self, knob: &Knob, value: Value) {
        let mut all = self.knobs();
        (knob.set)(&mut all, value);
        self.settings = all.contact;
        self.resolver = all.resolver;
        if let Some(sim) = &mut self.simulation {
            *sim = all.scene;
        }
        if knob.level == Level::Contact {
            for contact in &mut self.contacts {
                let mut own = crate::physics::Settings {
                    contact: contact.settings,
                    ..Default::default()
                };
                (knob.set)(&mut own, value);
                contact.settings = own.contact;
            }
        }
    }

    /// The parameters of the lesson's simulation: its scene tables, with the
    /// `[settings]` of every generated contact.
    pub fn sim_params(&self) -> Option<SimParams<f64>> {
        self.simulation.as_ref()?;
        Some(self.knobs().sim_params())
    }
}

/// Command-line or TUI overrides: knobs set on the lesson after it is read
/// (a contact's knob on every contact).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Overrides(pub Vec<(&'static Knob, Value)>);

impl Overrides {
    /// Sets `knob`, replacing an earlier value of it.
    pub fn set(&mut self, knob: &'static Knob, value: Value) {
        self.0.retain(|(k, _)| k.name != knob.name);
        self.0.push((knob, value));
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Overrides from knob names and values as text (`("dt", "0.01")`),
    /// each checked by its rule.
    pub fn from_pairs(pairs: &[(&str, &str)]) -> Result<Overrides, String> {
        let mut o = Overrides::default();
        for (name, text) in pairs {
            let knob =
                crate::knobs::find(name).ok_or_else(|| format!("no knob is named '{name}'"))?;
            o.set(knob, knob_value::from_text(knob, text)?);
        }
        Ok(o)
    }

    /// The value given for `knob`, if any.
    pub fn get(&self, knob: &Knob) -> Option<Value> {
        self.0
            .iter()
            .find(|(k, _)| k.name == knob.name)
            .map(|(_, v)| *v)
    }
}

impl Lesson {
    /// Loads a lesson by embedded id or by path (any file name the OS
    /// allows, UTF-8 or not).
    pub fn load(name: impl AsRef<std::ffi::OsStr>) -> Result<Lesson, LessonError> {
        let name = name.as_ref();
        if let Some(text) = name.to_str().and_then(embedded::find) {
            return validate::parse(&embedded::origin(name.to_str().unwrap_or_default()), text);
        }
        let path = std::path::Path::new(name);
        // Messages show the name escaped: it may hold control characters.
        let shown = crate::output_file::shown(path);
        let bytes = read::read(path, &shown)?;
        if bytes.len() > validate::MAX_BYTES {
            return Err(validate::too_large(&shown));
        }
        validate::parse_bytes(&shown, &bytes)
    }

    /// Names of the contact's two slots (the second may be absent).
    pub fn contact_body_names(&self, k: usize) -> Vec<String> {
        let (a, b) = self.contacts[k].bodies;
        std::iter::once(a)
            .chain(b)
            .map(|i| self.bodies[i].name.clone())
            .collect()
    }

    /// A short label: `0: ball ↔ floor`.
    pub fn contact_label(&self, k: usize) -> String {
        let names = self.contact_body_names(k);
        let pair = if names.len() == 1 {
            format!("{} ↔ world", names[0])
        } else {
            names.join(" ↔ ")
        };
        match &self.contacts[k].name {
            Some(n) => format!("{k}: {n} ({pair})"),
            None => format!("{k}: {pair}"),
        }
    }

    /// Applies overrides (a contact's knob to every contact).
    pub fn apply(&mut self, o: &Overrides) {
        for (knob, value) in &o.0 {
            self.set_knob(knob, *value);
        }
    }

    /// Slot indices into `bodies` for contact `k`: `[body 1, body 2]`, `None`
    /// where the slot is empty.
    pub fn slots(&self, k: usize) -> [Option<usize>; 2] {
        let (a, b) = self.contacts[k].bodies;
        [Some(a), b]
    }

    /// The physics input of contact `k` with the scene moved (in f64) so the
    /// contact point is the origin. Every stage depends only on `r = q - p`,
    /// so this keeps f32 runs precise far from the origin; positions after
    /// the projection are then relative to q.
    pub fn problem_centred<T: Real>(&self, k: usize) -> Problem<T> {
        let mut moved = self.clone();
        let q = moved.contacts[k].point;
        for b in &mut moved.bodies {
            b.position -= q;
        }
        moved.contacts[k].point = Vector3::zeros();
        moved.problem(k)
    }

    /// The physics input of contact `k`, in float type `T`: a view of the
    /// lesson's world. Immovable bodies become empty slots.
    pub fn problem<T: Real>(&self, k: usize) -> Problem<T> {
        // Only the contact's own bodies are built (not the whole world: a
        // check of every contact would otherwise cost contacts × bodies).
        let contact = self.contact::<T>(k);
        let body = |id: Option<BodyId>| {
            let b = self.bodies[id?.0].body::<T>();
            b.dynamic().cloned()
        };
        Problem {
            bodies: [body(Some(contact.body1)), body(contact.body2)],
            duration: contact.duration.unwrap_or(c(self.settings.duration)),
            contact: contact.input,
        }
    }

    /// Contact `k` as the world holds it, in float type `T`.
    fn contact<T: Real>(&self, k: usize) -> Contact<T> {
        let def = &self.contacts[k];
        Contact {
            body1: BodyId(def.bodies.0),
            body2: def.bodies.1.map(BodyId),
            input: ContactInput {
                point: def.point.map(c),
                normal: def.normal.map(c),
                penetration: c(def.penetration),
                restitution: c(def.restitution),
                static_friction: c(def.static_friction),
                dynamic_friction: c(def.dynamic_friction),
                friction_model: def.settings.friction_model,
                settings: def.settings.contact_params(),
            },
            duration: (def.settings.duration != self.settings.duration)
                .then(|| c(def.settings.duration)),
        }
    }

    /// The lesson as a world of bodies by id (the same indices as `bodies`)
    /// and contacts between them, in float type `T`.
    pub fn world<T: Real>(&self) -> World<T> {
        let bodies = self.bodies.iter().map(BodyDef::body).collect();
        let contacts = (0..self.contacts.len()).map(|k| self.contact(k)).collect();
        World {
            bodies,
            contacts,
            step: StepParams {
                duration: c(self.settings.duration),
                ..StepParams::default()
            },
        }
    }
}

impl BodyDef {
    /// The physics body, in float type `T`.
    fn body<T: Real>(&self) -> Body<T> {
        let position = self.position.map(c);
        let orientation = Quaternion::from(self.orientation.coords.map(c));
        if !self.movable() {
            return Body::immovable(position, orientation, self.shape.clone());
        }
        let inertia = self.inertia.unwrap_or_else(Matrix3::identity);
        // Validated tensors invert (`ranges::inertia`); scaled first so a
        // determinant out of f64's range cannot make one look singular.
        let inverse = crate::physics::scale::stable_inverse(&inertia)
            .expect("a validated inertia tensor is invertible");
        Body {
            state: RigidBody {
                mass: c(self.mass),
                inverse_mass: c(1.0 / self.mass),
                inertia_body: inertia.map(c),
                inverse_inertia_body: inverse.map(c),
                position,
                orientation,
                velocity: self.velocity.map(c),
                angular_velocity: self.angular_velocity.map(c),
                acceleration: self.acceleration.map(c),
            },
            shape: self.shape.clone(),
            movable: true,
        }
    }
}

#[cfg(test)]
mod problem_tests {
    use super::*;

    /// `problem(k)` builds only contact k's bodies; it is the world's view.
    #[test]
    fn a_contacts_problem_is_the_worlds_view_of_it() {
        for id in embedded::ids() {
            let lesson = Lesson::load(id).unwrap();
            let world = lesson.world::<f64>();
            for k in 0..lesson.contacts.len() {
                assert_eq!(
                    lesson.problem::<f64>(k),
                    world.problem(k),
                    "{id} contact {k}"
                );
            }
        }
    }
}
