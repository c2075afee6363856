//! The lesson file as written: serde types that keep each value's span so
//! validation can name the line and column of a bad value.

use serde::Deserialize;
use toml::Spanned;

pub type S<T> = Spanned<T>;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLesson {
    pub id: S<String>,
    pub title: String,
    #[serde(default)]
    pub source: String,
    #[serde(default)]
    pub summary: String,
    #[serde(default, rename = "body")]
    pub bodies: Vec<RawBody>,
    #[serde(default, rename = "contact")]
    pub contacts: Vec<RawContact>,
    #[serde(default)]
    pub settings: RawSettings,
    #[serde(default)]
    pub printed: Vec<RawPrinted>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBody {
    pub name: S<String>,
    pub mass: S<f64>,
    pub shape: Option<S<RawShape>>,
    pub inertia: Option<S<[[f64; 3]; 3]>>,
    pub position: S<[f64; 3]>,
    pub orientation: Option<S<[f64; 4]>>,
    pub velocity: Option<S<[f64; 3]>>,
    pub angular_velocity: Option<S<[f64; 3]>>,
    pub acceleration: Option<S<[f64; 3]>>,
}

/// `shape = { box = [x, y, z] }`, `{ sphere = r }`, `{ hollow_sphere = r }`,
/// `{ cylinder = { radius = r, height = h } }` (axis along body y), `"half_space"`.
#[derive(Debug, Clone, Copy, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum RawShape {
    Sphere(f64),
    HollowSphere(f64),
    Box([f64; 3]),
    Cylinder { radius: f64, height: f64 },
    HalfSpace,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawContact {
    pub name: Option<String>,
    pub bodies: S<Vec<S<String>>>,
    pub point: S<[f64; 3]>,
    pub normal: S<[f64; 3]>,
    pub penetration: Option<S<f64>>,
    pub restitution: S<f64>,
    pub friction: Option<S<f64>>,
    pub static_friction: Option<S<f64>>,
    pub dynamic_friction: Option<S<f64>>,
    pub friction_model: Option<S<String>>,
    pub settings: Option<RawSettings>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSettings {
    pub velocity_limit: Option<S<f64>>,
    pub angular_limit: Option<S<f64>>,
    pub relaxation: Option<S<f64>>,
    pub duration: Option<S<f64>>,
    pub projection: Option<S<String>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPrinted {
    #[serde(default)]
    pub contact: usize,
    pub stage: S<String>,
    pub value: S<String>,
    /// Component index for vectors (0-based) when only one component is printed.
    pub component: Option<usize>,
    pub printed: S<PrintedValue>,
    #[serde(rename = "where")]
    pub location: String,
    pub erratum: Option<String>,
}

/// A printed number keeps its text where given as a string (`"0.10"`), so its
/// last printed digit is known.
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[serde(untagged)]
pub enum PrintedNumber {
    Number(f64),
    Text(String),
}

#[derive(Debug, Clone, Deserialize, PartialEq)]
#[serde(untagged)]
pub enum PrintedValue {
    Scalar(PrintedNumber),
    Vector(Vec<PrintedNumber>),
    Matrix(Vec<Vec<PrintedNumber>>),
}
