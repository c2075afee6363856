//! What a picture of the contact needs: bodies with shapes and states before
//! and after, the contact point, the normal, the arms and the impulse. A
//! figure of several contacts takes bodies and a list of [`ContactView`]s.

use crate::lesson::{FigureDef, Lesson};
use crate::physics::solve::Solution;
use crate::physics::{Problem, Shape};

#[derive(Debug, Clone, PartialEq)]
pub struct BodyView {
    pub name: String,
    pub movable: bool,
    /// 1 or 2: the body's slot in the contact; 0 when not in this contact.
    pub slot: usize,
    /// `None` when the lesson gives no shape (drawn as a marker).
    pub shape: Option<Shape>,
    pub position: [f64; 3],
    pub orientation: [f64; 4],
    pub position_after: [f64; 3],
    pub orientation_after: [f64; 4],
    pub velocity: [f64; 3],
    pub velocity_after: [f64; 3],
    pub angular_velocity: [f64; 3],
    pub angular_velocity_after: [f64; 3],
}

#[derive(Debug, Clone, PartialEq)]
pub struct SceneView {
    pub bodies: Vec<BodyView>,
    /// The contact's number in the lesson (from 0).
    pub contact: usize,
    pub point: [f64; 3],
    pub normal: [f64; 3],
    pub penetration: f64,
    /// The impulse body 1 receives (world), when one is applied.
    pub impulse: Option<[f64; 3]>,
    /// Set when the bodies are drawn with the lesson's `[figure]` geometry
    /// (shapes, orientations) rather than its own: the lesson's note.
    pub corrected: Option<String>,
}

impl SceneView {
    /// The contact, its bodies by index into `bodies`.
    pub fn contact_view(&self) -> ContactView {
        let slot = |n: usize| self.bodies.iter().position(|b| b.slot == n);
        ContactView {
            number: self.contact,
            bodies: [slot(1), slot(2)],
            point: self.point,
            normal: self.normal,
            penetration: self.penetration,
            impulse: self.impulse,
        }
    }
}

/// One contact of a scene, between bodies given by index into a list of
/// [`BodyView`]s (their `slot` is not used).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactView {
    /// Its number in the scene (file order, from 0).
    pub number: usize,
    /// Body 1 and body 2 (`None` against the immovable world).
    pub bodies: [Option<usize>; 2],
    pub point: [f64; 3],
    /// Unit normal, from body 2 toward body 1.
    pub normal: [f64; 3],
    pub penetration: f64,
    /// The impulse body 1 receives (world), when one is applied.
    pub impulse: Option<[f64; 3]>,
}

fn arr(v: nalgebra::Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

fn quat(q: nalgebra::Quaternion<f64>) -> [f64; 4] {
    [q.w, q.i, q.j, q.k]
}

pub(super) fn scene(
    lesson: &Lesson,
    k: usize,
    problem: &Problem<f64>,
    solution: &Solution<f64>,
) -> SceneView {
    let contact = &lesson.contacts[k];
    let slots = lesson.slots(k);
    let bodies = lesson
        .bodies
        .iter()
        .enumerate()
        .map(|(index, b)| {
            let slot = slots.iter().position(|s| *s == Some(index));
            let after = slot.and_then(|s| solution.after(problem, s));
            BodyView {
                name: b.name.clone(),
                movable: b.movable(),
                slot: slot.map_or(0, |s| s + 1),
                shape: b.shape.clone(),
                position: arr(b.position),
                orientation: quat(b.orientation),
                position_after: after.as_ref().map_or(arr(b.position), |a| arr(a.position)),
                orientation_after: after
                    .as_ref()
                    .map_or(quat(b.orientation), |a| quat(a.orientation)),
                velocity: arr(b.velocity),
                velocity_after: after.as_ref().map_or(arr(b.velocity), |a| arr(a.velocity)),
                angular_velocity: arr(b.angular_velocity),
                angular_velocity_after: after
                    .as_ref()
                    .map_or(arr(b.angular_velocity), |a| arr(a.angular_velocity)),
            }
        })
        .collect();
    let mut scene = SceneView {
        bodies,
        contact: k,
        point: arr(contact.point),
        normal: arr(contact.normal),
        penetration: contact.penetration,
        impulse: solution.final_impulse_world().map(arr),
        corrected: None,
    };
    if let Some(f) = &lesson.figure {
        correct(&mut scene.bodies, f);
        scene.corrected = Some(f.note.clone());
    }
    scene
}

/// Draws the bodies with the `[figure]` shapes and orientations; a body the
/// projection turns is drawn turned by the same rotation from its drawn
/// orientation (q′ = (q′_l q_l⁻¹) q_drawn).
fn correct(bodies: &mut [BodyView], figure: &FigureDef) {
    use nalgebra::{Quaternion, UnitQuaternion};
    let unit =
        |q: [f64; 4]| UnitQuaternion::from_quaternion(Quaternion::new(q[0], q[1], q[2], q[3]));
    for d in &figure.bodies {
        let Some(b) = bodies.get_mut(d.body) else {
            continue;
        };
        if let Some(shape) = &d.shape {
            b.shape = Some(shape.clone());
        }
        if let Some(q) = d.orientation {
            if b.orientation_after != b.orientation {
                let turn = unit(b.orientation_after) * unit(b.orientation).inverse();
                b.orientation_after = quat((turn * unit(q)).into_inner());
            } else {
                b.orientation_after = q;
            }
            b.orientation = q;
        }
    }
}
