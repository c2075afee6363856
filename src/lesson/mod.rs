//! Lesson files: one scene per TOML file (format in `lessons/README.md`),
//! validated into a [`Lesson`] with spans for every error.

pub mod characters;
pub mod edit;
pub mod embedded;
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

use crate::physics::{
    c, ContactInput, FrictionModel, Problem, ProjectionMethod, Real, RigidBody, Settings,
};
pub use printed::Printed;
pub use shape::Shape;
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
    /// Non-fatal findings (normalised normal, shape vs tensor, …).
    pub warnings: Vec<LessonDiagnostic>,
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
    pub friction_model: FrictionModel,
    pub settings: Settings<f64>,
}

/// Command-line or TUI overrides applied to every contact before solving.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Overrides {
    pub friction_model: Option<FrictionModel>,
    pub projection: Option<ProjectionMethod>,
    pub relaxation: Option<f64>,
    pub angular_limit: Option<f64>,
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

    /// Applies overrides to every contact.
    pub fn apply(&mut self, o: &Overrides) {
        for contact in &mut self.contacts {
            if let Some(m) = o.friction_model {
                contact.friction_model = m;
            }
            if let Some(p) = o.projection {
                contact.settings.projection = p;
            }
            if let Some(r) = o.relaxation {
                contact.settings.relaxation = r;
            }
            if let Some(a) = o.angular_limit {
                contact.settings.angular_limit = a;
            }
        }
    }

    /// Slot indices into `bodies` for contact `k`: `[body 1, body 2]`, `None`
    /// where the slot is empty.
    pub fn slots(&self, k: usize) -> [Option<usize>; 2] {
        let (a, b) = self.contacts[k].bodies;
        [Some(a), b]
    }

    /// The physics input of contact `k` with the scene moved (in f64) so the
    /// contact point is the origin. Every stage depends only on `r = q − p`,
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

    /// The physics input of contact `k`, in float type `T`. Immovable bodies
    /// become empty slots.
    pub fn problem<T: Real>(&self, k: usize) -> Problem<T> {
        let def = &self.contacts[k];
        let body = |i: Option<usize>| {
            let b = &self.bodies[i?];
            if !b.movable() {
                return None;
            }
            let inertia = b.inertia.unwrap_or_else(Matrix3::identity);
            // Validated tensors invert (`ranges::inertia`); scaled first so a
            // determinant out of f64's range cannot make one look singular.
            let inverse = crate::physics::scale::stable_inverse(&inertia)
                .expect("a validated inertia tensor is invertible");
            Some(RigidBody {
                mass: c(b.mass),
                inverse_mass: c(1.0 / b.mass),
                inertia_body: inertia.map(c),
                inverse_inertia_body: inverse.map(c),
                position: b.position.map(c),
                orientation: Quaternion::from(b.orientation.coords.map(c)),
                velocity: b.velocity.map(c),
                angular_velocity: b.angular_velocity.map(c),
                acceleration: b.acceleration.map(c),
            })
        };
        let s = def.settings;
        Problem {
            bodies: [body(Some(def.bodies.0)), body(def.bodies.1)],
            contact: ContactInput {
                point: def.point.map(c),
                normal: def.normal.map(c),
                penetration: c(def.penetration),
                restitution: c(def.restitution),
                static_friction: c(def.static_friction),
                dynamic_friction: c(def.dynamic_friction),
                friction_model: def.friction_model,
                settings: Settings {
                    velocity_limit: c(s.velocity_limit),
                    angular_limit: c(s.angular_limit),
                    relaxation: c(s.relaxation),
                    duration: c(s.duration),
                    projection: s.projection,
                },
            },
        }
    }
}
