//! What a picture of the contact needs: bodies with shapes and states before
//! and after, the contact point, the normal, the arms and the impulse.

use crate::lesson::{Lesson, Shape};
use crate::physics::solve::Solution;

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ShapeView {
    Sphere {
        radius: f64,
    },
    /// Full side lengths along the body axes.
    Box {
        sides: [f64; 3],
    },
    /// Axis along body y.
    Cylinder {
        radius: f64,
        height: f64,
    },
    /// The plane through the contact point, perpendicular to the normal.
    HalfSpace,
    /// No shape given: drawn as a marker.
    Marker,
}

#[derive(Debug, Clone, PartialEq)]
pub struct BodyView {
    pub name: String,
    pub movable: bool,
    /// 1 or 2: the body's slot in the contact; 0 when not in this contact.
    pub slot: usize,
    pub shape: ShapeView,
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
    pub point: [f64; 3],
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

pub(super) fn scene(lesson: &Lesson, k: usize, solution: &Solution<f64>) -> SceneView {
    let contact = &lesson.contacts[k];
    let problem = lesson.problem::<f64>(k);
    let slots = lesson.slots(k);
    let bodies = lesson
        .bodies
        .iter()
        .enumerate()
        .map(|(index, b)| {
            let slot = slots.iter().position(|s| *s == Some(index));
            let after = slot.and_then(|s| solution.after(&problem, s));
            let shape = match b.shape {
                Some(Shape::Sphere { radius: r }) | Some(Shape::HollowSphere { radius: r }) => {
                    ShapeView::Sphere { radius: r }
                }
                Some(Shape::Box { sides }) => ShapeView::Box { sides },
                Some(Shape::Cylinder { radius, height }) => ShapeView::Cylinder { radius, height },
                Some(Shape::HalfSpace { .. }) => ShapeView::HalfSpace,
                None => ShapeView::Marker,
            };
            BodyView {
                name: b.name.clone(),
                movable: b.movable(),
                slot: slot.map_or(0, |s| s + 1),
                shape,
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
    SceneView {
        bodies,
        point: arr(contact.point),
        normal: arr(contact.normal),
        penetration: contact.penetration,
        impulse: solution.final_impulse_world().map(arr),
    }
}
