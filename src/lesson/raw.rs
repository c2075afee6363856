//! The lesson file as written: serde types that keep each value's span so
//! validation can name the line and column of a bad value.

use std::collections::BTreeMap;

use serde::Deserialize;
use toml::Spanned;

pub type S<T> = Spanned<T>;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLesson {
    pub id: S<String>,
    pub title: S<String>,
    pub source: Option<S<String>>,
    pub summary: Option<S<String>>,
    #[serde(default, rename = "body")]
    pub bodies: Vec<RawBody>,
    #[serde(default, rename = "contact")]
    pub contacts: Vec<RawContact>,
    #[serde(default)]
    pub settings: KnobTable,
    #[serde(default)]
    pub printed: Vec<RawPrinted>,
    /// Time stepping (`simulate`): forces, the step, sleep.
    pub world: Option<KnobTable>,
    pub step: Option<KnobTable>,
    pub sleep: Option<KnobTable>,
    /// What the pictures draw differently from the numbers.
    pub figure: Option<RawFigure>,
}

/// `[figure]`: a figure-only correction of the lesson's geometry (where the
/// lecture's own shapes or poses are wrong, the numbers staying the
/// lecture's), and the note that says so.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFigure {
    pub note: S<String>,
    #[serde(default, rename = "body")]
    pub bodies: Vec<RawFigureBody>,
}

/// `[[figure.body]]`: the shape or orientation a body is drawn with.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFigureBody {
    pub name: S<String>,
    pub shape: Option<S<RawShape>>,
    #[serde(default, deserialize_with = "exact::some")]
    pub orientation: Option<S<[f64; 4]>>,
}

/// A table of knobs (`[settings]`, a contact's `settings`, `[world]`,
/// `[step]`, `[sleep]`) as written: each key and value with its span, read
/// against the knob table (`knobs`) by the validator.
pub type KnobTable = BTreeMap<S<String>, S<toml::Value>>;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBody {
    pub name: S<String>,
    pub mass: S<f64>,
    pub shape: Option<S<RawShape>>,
    #[serde(default, deserialize_with = "exact::some")]
    pub inertia: Option<S<[[f64; 3]; 3]>>,
    #[serde(deserialize_with = "exact::spanned")]
    pub position: S<[f64; 3]>,
    #[serde(default, deserialize_with = "exact::some")]
    pub orientation: Option<S<[f64; 4]>>,
    #[serde(default, deserialize_with = "exact::some")]
    pub velocity: Option<S<[f64; 3]>>,
    #[serde(default, deserialize_with = "exact::some")]
    pub angular_velocity: Option<S<[f64; 3]>>,
    #[serde(default, deserialize_with = "exact::some")]
    pub acceleration: Option<S<[f64; 3]>>,
    /// A half-space's outward normal (world frame).
    #[serde(default, deserialize_with = "exact::some")]
    pub normal: Option<S<[f64; 3]>>,
    /// Coefficients of the contacts generated for this body (`simulate`).
    pub restitution: Option<S<f64>>,
    pub friction: Option<S<f64>>,
    pub static_friction: Option<S<f64>>,
    pub dynamic_friction: Option<S<f64>>,
}

/// `shape = { box = [x, y, z] }`, `{ sphere = r }`, `{ hollow_sphere = r }`,
/// `{ cylinder = { radius = r, height = h } }` (axis along body y),
/// `{ capsule = { radius = r, height = h } }`, `{ convex = [[x, y, z], …] }`
/// (the hull of the points, body frame), `{ mesh = … }` ([`RawMesh`]),
/// `"half_space"`.
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum RawShape {
    Sphere(f64),
    HollowSphere(f64),
    #[serde(deserialize_with = "exact::array")]
    Box([f64; 3]),
    Cylinder {
        radius: f64,
        height: f64,
    },
    Capsule {
        radius: f64,
        height: f64,
    },
    #[serde(deserialize_with = "exact::array")]
    Convex(Vec<[f64; 3]>),
    /// `{ mesh = { vertices = [[x, y, z], …], triangles = [[i, j, k], …] } }`
    /// or `{ mesh = "file.obj" }` (relative to the lesson file).
    Mesh(RawMesh),
    HalfSpace,
}

/// A mesh written inline, or the path of an OBJ file.
#[derive(Debug, Clone, Deserialize, PartialEq)]
#[serde(untagged)]
pub enum RawMesh {
    File(String),
    Inline {
        vertices: Vec<[f64; 3]>,
        triangles: Vec<[usize; 3]>,
    },
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawContact {
    pub name: Option<S<String>>,
    pub bodies: S<Vec<S<String>>>,
    #[serde(deserialize_with = "exact::spanned")]
    pub point: S<[f64; 3]>,
    #[serde(deserialize_with = "exact::spanned")]
    pub normal: S<[f64; 3]>,
    pub penetration: Option<S<f64>>,
    pub restitution: S<f64>,
    pub friction: Option<S<f64>>,
    pub static_friction: Option<S<f64>>,
    pub dynamic_friction: Option<S<f64>>,
    /// A knob of the contact's own (`knobs`, table `[[contact]]`).
    pub friction_model: Option<S<toml::Value>>,
    pub settings: Option<KnobTable>,
    /// Load warnings the lesson means (`"normal-into-body"`,
    /// `"point-inside-body"`): not shown.
    pub deliberate: Option<S<Vec<S<String>>>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPrinted {
    pub contact: Option<S<usize>>,
    pub stage: S<String>,
    pub value: S<String>,
    /// Component index for vectors (0-based) when only one component is printed.
    pub component: Option<S<usize>>,
    pub printed: S<PrintedValue>,
    #[serde(rename = "where")]
    pub location: S<String>,
    pub erratum: Option<S<String>>,
    /// Load warnings the lesson means (`"printed-zero"`): not shown.
    pub deliberate: Option<S<Vec<S<String>>>>,
    /// `stage = "resolver"`: the body whose state after the resolver is printed.
    pub body: Option<S<String>>,
    /// `stage = "resolver"`: the solver it is resolved under (the lesson's when left out).
    pub solver: Option<S<String>>,
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

/// Fixed-size arrays that refuse extra elements. serde reads `[T; N]` as the
/// first N elements and ignores the rest, so `velocity = [2.165, -1, 25, 0]`
/// (a decimal comma, as in the lecture's own typos) would pass as a 3-vector.
mod exact {
    use serde::de::{Deserialize, DeserializeOwned, Deserializer, Error};

    use super::S;

    /// An array read as a list, then checked for its exact length.
    pub trait Exact: Sized {
        type List: DeserializeOwned;
        fn exact(list: Self::List) -> Result<Self, String>;
    }

    fn length<T, const N: usize>(list: Vec<T>) -> Result<[T; N], String> {
        let n = list.len();
        list.try_into()
            .map_err(|_| format!("expected an array of {N} numbers, got {n}"))
    }

    impl<const N: usize> Exact for [f64; N] {
        type List = Vec<f64>;
        fn exact(list: Vec<f64>) -> Result<Self, String> {
            length(list)
        }
    }

    /// A list of points, each of exactly 3 numbers (a convex hull's).
    impl Exact for Vec<[f64; 3]> {
        type List = Vec<Vec<f64>>;
        fn exact(rows: Vec<Vec<f64>>) -> Result<Self, String> {
            rows.into_iter()
                .enumerate()
                .map(|(i, p)| length(p).map_err(|e| format!("point {i}: {e}")))
                .collect()
        }
    }

    impl Exact for [[f64; 3]; 3] {
        type List = Vec<Vec<f64>>;
        fn exact(rows: Vec<Vec<f64>>) -> Result<Self, String> {
            let n = rows.len();
            let rows: Vec<[f64; 3]> = rows
                .into_iter()
                .map(length)
                .collect::<Result<_, _>>()
                .map_err(|e| format!("a 3×3 tensor row: {e}"))?;
            rows.try_into()
                .map_err(|_| format!("expected a 3×3 tensor (3 rows), got {n} rows"))
        }
    }

    pub fn array<'de, D: Deserializer<'de>, T: Exact>(d: D) -> Result<T, D::Error> {
        T::exact(T::List::deserialize(d)?).map_err(D::Error::custom)
    }

    pub fn spanned<'de, D: Deserializer<'de>, T: Exact>(d: D) -> Result<S<T>, D::Error> {
        let list = S::<T::List>::deserialize(d)?;
        let span = list.span();
        let value = T::exact(list.into_inner()).map_err(D::Error::custom)?;
        Ok(S::new(span, value))
    }

    pub fn some<'de, D: Deserializer<'de>, T: Exact>(d: D) -> Result<Option<S<T>>, D::Error> {
        spanned(d).map(Some)
    }
}
