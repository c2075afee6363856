//! What continuous detection needs beyond the swept broad phase: the pairs
//! of a moving body and a half-space (a half-space has no bounds to sort,
//! and its swept test is a closed form, [`crate::physics::detect::PlanePair`]),
//! and a pair's contacts where it stands at its time of collision (the
//! narrow phase's, within the search's tolerance: a box face meeting a wall
//! or a floor gets its four corners, not one).

use nalgebra::Vector3;

use crate::physics::collide::{collide_with, ContactPoint, Options};
use crate::physics::detect::Convex;
use crate::physics::params::SimParams;
use crate::physics::pose::Pose;
use crate::physics::{c, Real, Shape, World};

/// Body `j`'s plane if it is a half-space: its unit outward normal and a
/// point of it (the body's position).
pub fn half_space<T: Real>(world: &World<T>, j: usize) -> Option<(Vector3<T>, Vector3<T>)> {
    match world.bodies[j].shape.as_ref()? {
        Shape::HalfSpace { normal } => Some((
            Vector3::new(c(normal[0]), c(normal[1]), c(normal[2])),
            world.bodies[j].state.position,
        )),
        _ => None,
    }
}

/// The pairs (body, half-space) whose movement can meet over `dt`: a
/// moving body with a convex shape whose bounding sphere (about its
/// origin, ρ) comes within ρ of the plane at either end of the step (its
/// centre moves straight, so its height above the plane is linear in t).
pub fn plane_pairs<T: Real>(
    world: &World<T>,
    moving: &[bool],
    dt: T,
    out: &mut Vec<(usize, usize)>,
) {
    out.clear();
    let planes: Vec<(usize, Vector3<T>, Vector3<T>)> = (0..world.bodies.len())
        .filter_map(|j| half_space(world, j).map(|(n, p)| (j, n, p)))
        .collect();
    if planes.is_empty() {
        return;
    }
    for (i, body) in world.bodies.iter().enumerate() {
        let Some(shape) = body.shape.as_ref().and_then(Convex::from_shape) else {
            continue;
        };
        if !moving[i] {
            continue;
        }
        let r: T = c(shape.bounding_radius());
        let s = &body.state;
        for &(j, n, p) in &planes {
            let h0 = n.dot(&(s.position - p));
            let h1 = h0 + n.dot(&s.velocity) * dt;
            if h0.min(h1) <= r {
                out.push((i, j));
            }
        }
    }
}

/// The narrow phase's contacts of bodies `i` (body 1) and `j` where they
/// stand, gaps up to `tolerance` included.
pub fn contacts_at<T: Real>(
    world: &World<T>,
    p: &SimParams<T>,
    (i, j): (usize, usize),
    tolerance: T,
) -> Vec<ContactPoint<T>> {
    let (Some(a), Some(b)) = (
        world.bodies[i].shape.as_ref(),
        world.bodies[j].shape.as_ref(),
    ) else {
        return Vec::new();
    };
    let pose = |k: usize| {
        let s = &world.bodies[k].state;
        Pose::new(s.position, &s.orientation)
    };
    let options = Options {
        box_box: p.box_box,
        tolerance,
        narrow_phase: p.narrow_phase,
        broad_phase: p.broad_phase,
        internal_edges: p.internal_edges,
    };
    let mut out = Vec::new();
    collide_with((a, &pose(i)), (b, &pose(j)), &options, &mut out);
    out
}
