//! Load warnings where a lesson is probably wrong though valid: a contact
//! point deeper inside one of its bodies than the stated penetration, and a
//! normal that points from body 1 toward body 2 (the convention is from
//! body 2 toward body 1), and the places of printed values that are all
//! zeros (`check` and the commands warn when the computed value there is
//! not). A lesson marks a warning it means with `deliberate = [...]` on the
//! contact or the printed entry (lessons/README.md).

use std::ops::Range;

use nalgebra::Vector3;

use super::Validator;
use crate::lesson::raw::{RawContact, RawPrinted, S};
use crate::lesson::source::Note;
use crate::lesson::{BodyDef, ContactDef, Shape};

/// The marks a contact may carry, and the one a printed entry may.
pub const CONTACT_MARKS: [&str; 2] = ["point-inside-body", "normal-into-body"];
pub const PRINTED_MARKS: [&str; 1] = ["printed-zero"];

/// How deep `q` lies inside `body` (positive inside, ≤ 0 outside), and the
/// body's size; `None` for a shape this test does not measure.
fn depth(body: &BodyDef, q: &Vector3<f64>) -> Option<(f64, f64)> {
    let local = body.orientation_local(q);
    Some(match *body.shape.as_ref()? {
        // Sphere: r − |q − p|.
        Shape::Sphere { radius } | Shape::HollowSphere { radius } => {
            (radius - local.norm(), radius)
        }
        // Box: the least distance to a face, min_i (hᵢ − |xᵢ|).
        Shape::Box { sides } => {
            let d = (0..3)
                .map(|i| sides[i] / 2.0 - local[i].abs())
                .fold(f64::INFINITY, f64::min);
            (d, sides.iter().fold(0.0, |a: f64, s| a.max(*s)) / 2.0)
        }
        // Capsule: r − the distance to its segment along body y.
        Shape::Capsule { radius, height } => {
            let y = local.y.clamp(-height / 2.0, height / 2.0);
            (
                radius - (local - Vector3::new(0.0, y, 0.0)).norm(),
                radius + height / 2.0,
            )
        }
        // Half-space: −(q − p)·n.
        Shape::HalfSpace { normal } => (-(q - body.position).dot(&Vector3::from(normal)), 1.0),
        _ => return None,
    })
}

impl BodyDef {
    /// `q` in the body's frame: Rᵀ (q − p).
    fn orientation_local(&self, q: &Vector3<f64>) -> Vector3<f64> {
        let r = nalgebra::UnitQuaternion::from_quaternion(self.orientation);
        r.inverse_transform_vector(&(q - self.position))
    }
}

/// The marks of a `deliberate` list, each checked against `allowed`.
fn marks(v: &mut Validator, list: &Option<S<Vec<S<String>>>>, allowed: &[&str]) -> Vec<String> {
    let Some(list) = list else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for m in list.get_ref() {
        if allowed.contains(&m.get_ref().as_str()) {
            out.push(m.get_ref().clone());
        } else {
            v.err(
                m.span(),
                format!(
                    "deliberate: unknown warning \"{}\" (here: {})",
                    crate::lesson::snippet::printable(m.get_ref().clone()),
                    allowed.join(", ")
                ),
            );
        }
    }
    out
}

impl Validator {
    /// Warns about a contact whose point or normal is probably wrong.
    pub(super) fn plausible_contact(
        &mut self,
        raw: &RawContact,
        c: &ContactDef,
        bodies: &[BodyDef],
    ) {
        let marked = marks(self, &raw.deliberate, &CONTACT_MARKS);
        let name = |i: usize| bodies.get(i).map_or("?", |b| b.name.as_str());
        if !marked.iter().any(|m| m == "point-inside-body") {
            for i in std::iter::once(c.bodies.0).chain(c.bodies.1) {
                let Some((d, size)) = bodies.get(i).and_then(|b| depth(b, &c.point)) else {
                    continue;
                };
                // Lecture numbers are rounded: a thousandth of the body's size is allowed.
                if d > c.penetration + 1e-3 * size + 1e-9 {
                    self.warnings.push(Note::new(
                        format!(
                            "the contact point lies {} inside '{}', deeper than the stated penetration {}: the point or the body's shape or position is probably wrong (mark it `deliberate = [\"point-inside-body\"]` if meant)",
                            crate::format::Fmt::new(4).num(d),
                            name(i),
                            crate::format::exact(c.penetration)
                        ),
                        raw.point.span(),
                    ));
                }
            }
        }
        if !marked.iter().any(|m| m == "normal-into-body") {
            let Some(b1) = bodies.get(c.bodies.0) else {
                return;
            };
            let arm = b1.position - c.point;
            let along = arm.dot(&c.normal);
            if along < -1e-3 * arm.norm() {
                self.warnings.push(Note::new(
                    format!(
                        "the contact normal points from body 1 '{}' toward body 2 ((p₁ - q)·n = {} < 0): moving '{}' along it drives it into the other body. The normal points from body 2 toward body 1; swap the bodies or negate the normal (mark it `deliberate = [\"normal-into-body\"]` if meant)",
                        name(c.bodies.0),
                        crate::format::Fmt::new(4).num(along),
                        name(c.bodies.0)
                    ),
                    raw.normal.span(),
                ));
            }
        }
    }

    /// The span of a printed value that is all zeros and not marked
    /// deliberate, for the warning `check` gives when the computed value
    /// is not zero.
    pub(super) fn printed_zero(&mut self, raw: &RawPrinted) -> Option<Range<usize>> {
        let marked = marks(self, &raw.deliberate, &PRINTED_MARKS);
        let p = crate::lesson::Printed::from_raw(raw).ok()?;
        let zero = p.printed.numbers().iter().all(|n| n.value == 0.0);
        (zero && marked.is_empty()).then(|| raw.printed.span())
    }
}
