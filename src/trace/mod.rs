//! The trace: one description of a worked solution, built from the stage
//! records. Renderers (text, JSON, Markdown, LaTeX, SVG, TUI) read only this.
//!
//! - [`contact`]: one builder per stage of ONE contact, from a problem, its
//!   solution and the names to show (reusable per resolver iteration);
//! - `worked`: a lesson contact's whole [`Trace`] ([`build`]);
//! - [`latex`]: the Unicode formulas in LaTeX, converted when rendered;
//! - `scene`: what a picture of the contact needs ([`SceneView`]);
//! - `stage_names`: each stage's title, short label and why it exists;
//! - [`glossary`]: every symbol with its meaning, unit and stages;
//! - [`grade`]: a student's answer graded against a value (predict mode, exercises).

mod acceleration;
pub mod blow_up;
pub mod broad_search;
pub mod contact;
pub mod detect;
pub mod detect_mesh;
mod elided;
pub mod glossary;
pub mod movement;
pub mod previous_frame;

mod names;
mod plane;

pub mod resolver;
pub mod run;
mod scene;
mod stage_names;
pub mod step;
pub mod stop;
pub mod substeps;
pub mod symbols;
pub mod toi;
mod worked;

use std::borrow::Cow;

use nalgebra::{Matrix3, Quaternion, Vector3};

use crate::physics::StageId;

pub use acceleration::note_planar_acceleration;
pub use contact::impact_curves;
pub use plane::Plane;
pub use scene::{BodyView, ContactView, SceneView};
pub use worked::{build, build_of};

/// A value a stage takes in or produces.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Scalar(f64),
    Vector([f64; 3]),
    Quaternion([f64; 4]),
    /// Rows.
    Matrix([[f64; 3]; 3]),
    Text(String),
    /// A list of strings (the phases of an integrated impact).
    List(Vec<String>),
}

impl From<f64> for Value {
    fn from(x: f64) -> Self {
        Value::Scalar(x)
    }
}
impl From<Vector3<f64>> for Value {
    fn from(v: Vector3<f64>) -> Self {
        Value::Vector([v.x, v.y, v.z])
    }
}
impl From<Quaternion<f64>> for Value {
    fn from(q: Quaternion<f64>) -> Self {
        Value::Quaternion([q.w, q.i, q.j, q.k])
    }
}
impl From<Matrix3<f64>> for Value {
    fn from(m: Matrix3<f64>) -> Self {
        Value::Matrix([0, 1, 2].map(|r| [0, 1, 2].map(|c| m[(r, c)])))
    }
}
impl From<&str> for Value {
    fn from(s: &str) -> Self {
        Value::Text(s.to_string())
    }
}

impl Value {
    /// The numbers of the value, row by row.
    pub fn numbers(&self) -> Vec<f64> {
        match self {
            Value::Scalar(x) => vec![*x],
            Value::Vector(v) => v.to_vec(),
            Value::Quaternion(q) => q.to_vec(),
            Value::Matrix(m) => m.iter().flatten().copied().collect(),
            Value::Text(_) | Value::List(_) => vec![],
        }
    }
}

/// A trace's text: borrowed where it is fixed (formula sides, value names,
/// notes written out in the source), owned where a body's number or name is
/// put into it. It reads as a `&str` either way.
pub type Text = Cow<'static, str>;

/// One formula: symbols, then the numbers put into it, then the result.
#[derive(Debug, Clone, PartialEq)]
pub struct Formula {
    /// Left-hand side, e.g. `Δv`.
    pub lhs: Text,
    /// Symbolic right-hand side, e.g. `-(1 + c)·v_s`.
    pub rhs: Text,
    /// The right-hand side with `{name}` placeholders for numbers.
    pub substituted: Option<Text>,
    /// Name of the value (in `values` or `inputs`) that is the result.
    pub result: Option<Text>,
}

/// One stage of the worked solution.
#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    pub id: StageId,
    pub title: &'static str,
    /// Why the stage did not run, when it did not.
    pub skipped: Option<Text>,
    pub formulas: Vec<Formula>,
    /// Numbers the formulas take in (not part of the JSON contract).
    pub inputs: Vec<(Text, Value)>,
    /// Named results (the JSON contract, `docs/json.md`).
    pub values: Vec<(Text, Value)>,
    pub notes: Vec<Text>,
}

impl Step {
    /// A value or input by name.
    pub fn lookup(&self, name: &str) -> Option<&Value> {
        self.values
            .iter()
            .chain(self.inputs.iter())
            .find(|(n, _)| n == name)
            .map(|(_, v)| v)
    }

    pub fn value(&self, name: &str) -> Option<&Value> {
        self.values.iter().find(|(n, _)| n == name).map(|(_, v)| v)
    }
}

/// Pass / fail of one invariant, for the checks panel.
#[derive(Debug, Clone, PartialEq)]
pub struct Verdict {
    pub label: String,
    /// `None` for an informative measurement.
    pub passed: Option<bool>,
    pub detail: String,
}

impl Verdict {
    /// ✓ passed, ✗ failed, · informs.
    pub fn mark(&self) -> &'static str {
        Verdict::mark_of(self.passed)
    }

    /// The mark of a check that passed (`Some(true)`), failed or informs (`None`).
    pub fn mark_of(passed: Option<bool>) -> &'static str {
        match passed {
            Some(true) => "✓",
            Some(false) => "✗",
            None => "·",
        }
    }
}

/// A body's state after the contact is resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct AfterState {
    pub position: [f64; 3],
    pub orientation: [f64; 4],
    pub velocity: [f64; 3],
    pub angular_velocity: [f64; 3],
}

/// The worked solution of one contact.
#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    pub lesson: String,
    pub title: String,
    pub source: String,
    pub summary: String,
    pub contact: usize,
    pub contact_label: String,
    pub bodies: Vec<String>,
    pub stages: Vec<Step>,
    pub after: Vec<(String, AfterState)>,
    pub verdicts: Vec<Verdict>,
    pub warnings: Vec<String>,
    pub scene: SceneView,
    /// The impact integrated by the `exact_impact` stage, for the
    /// impulse-space figure; `None` when the stage did not run.
    pub impact: Option<ImpactCurves>,
}

/// The contact velocity against the normal impulse during an integrated
/// impact, and where its phases change.
#[derive(Debug, Clone, PartialEq)]
pub struct ImpactCurves {
    /// The restitution law's name (`stronge`, …).
    pub law: String,
    /// `(P_n, u_n, u_t0, u_t1)`, contact space; u is linear in P_n between
    /// consecutive points of a closed-form stretch.
    pub samples: Vec<[f64; 4]>,
    /// Where the phases change: `(P_n, what happens there)`, in order, one
    /// entry per P_n (coinciding events joined).
    pub events: Vec<(f64, String)>,
}

impl Trace {
    pub fn stage(&self, id: &str) -> Option<&Step> {
        self.stages.iter().find(|s| s.id.json_name() == id)
    }

    /// A stage's named value.
    pub fn value(&self, stage: &str, name: &str) -> Option<&Value> {
        self.stage(stage)?.value(name)
    }
}
