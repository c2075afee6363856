//! Contacts that the resolver cannot put right and must not pass over in
//! silence: a body wholly inside another (the penetration is at least the
//! smaller body's width along the normal, so the contact's normal says
//! nothing about which way is out), and a body that the position phase is
//! about to push out through the far side of a thin body (last step it was
//! on the other side of that body's centre: it crossed it, and projection
//! along this normal finishes the tunnel instead of undoing it).

use nalgebra::Vector3;

use crate::physics::{to_f64, BodyId, Contact, Real, Shape, World};

/// The width of a body along the world direction `n` (`None`: a half-space
/// or a body without a shape, unbounded).
pub fn width_along<T: Real>(world: &World<T>, id: BodyId, n: &Vector3<f64>) -> Option<f64> {
    let body = world.body(id);
    let shape = body.shape.as_ref().filter(|s| s.is_finite())?;
    let r = body.state.rotation();
    let r = r.map(to_f64);
    let local = r.transpose() * n;
    let far = shape.support(&local)?;
    let near = shape.support(&-local)?;
    Some((far - near).dot(&local))
}

/// A lower bound on a body's width along any direction: a sphere's
/// diameter, a box's smallest side, a cylinder's smaller of diameter and
/// height (infinite for a half-space or a body without a shape).
fn thinnest<T: Real>(world: &World<T>, id: BodyId) -> f64 {
    match world.body(id).shape {
        Some(Shape::Sphere { radius }) | Some(Shape::HollowSphere { radius }) => 2.0 * radius,
        Some(Shape::Box { sides }) => sides.iter().fold(f64::INFINITY, |m, s| m.min(*s)),
        Some(Shape::Cylinder { radius, height }) => (2.0 * radius).min(height),
        Some(Shape::Capsule { radius, .. }) => 2.0 * radius,
        Some(Shape::Hull(ref hull)) => 2.0 * hull.inner_radius(),
        // A closed mesh: the ball inside it about its centroid; an open
        // mesh (a surface) has no inside for a body to be wholly in.
        Some(Shape::Mesh(ref mesh)) => mesh.inner_radius().map_or(f64::INFINITY, |r| 2.0 * r),
        Some(Shape::HalfSpace { .. }) | None => f64::INFINITY,
    }
}

/// Whether a contact's penetration reaches the smaller body's width along
/// its normal: one body is wholly inside the other. Returns that width.
pub fn wholly_inside<T: Real>(world: &World<T>, k: &Contact<T>) -> Option<f64> {
    wholly_inside_below(world, k, thinnest_of_pair(world, k))
}

/// The smaller of a contact's two bodies' [`thinnest`] widths (the same for
/// every contact of a pair).
pub fn thinnest_of_pair<T: Real>(world: &World<T>, k: &Contact<T>) -> f64 {
    let thin = k.body2.map_or(f64::INFINITY, |b| thinnest(world, b));
    thinnest(world, k.body1).min(thin)
}

/// [`wholly_inside`], the pair's [`thinnest_of_pair`] given.
pub fn wholly_inside_below<T: Real>(world: &World<T>, k: &Contact<T>, thin: f64) -> Option<f64> {
    // Cheap test first: shallower than either body's thinnest width.
    let depth = to_f64(k.input.penetration);
    if depth < thin {
        return None;
    }
    let n = k.input.normal.map(to_f64);
    let w1 = width_along(world, k.body1, &n);
    let w2 = k.body2.and_then(|b| width_along(world, b, &n));
    let smaller = match (w1, w2) {
        (Some(a), Some(b)) => a.min(b),
        (a, b) => a.or(b)?,
    };
    (to_f64(k.input.penetration) >= smaller).then_some(smaller)
}

/// Whether the position phase would push body 1 out through the far side
/// of body 2 (or body 2 through body 1): both finite, and a step ago (the
/// centres moved back by `velocity × dt`) body 1's centre lay behind body
/// 2's along the normal that now points from body 2 toward body 1. Returns
/// (the body pushed through, the body it goes through: the thinner one).
pub fn pushed_through<T: Real>(
    world: &World<T>,
    k: &Contact<T>,
    dt: T,
) -> Option<(BodyId, BodyId)> {
    let b2 = k.body2?;
    let n = k.input.normal;
    let (s1, s2) = (&world.body(k.body1).state, &world.body(b2).state);
    let before = (s1.position - s1.velocity * dt) - (s2.position - s2.velocity * dt);
    if before.dot(&n) >= T::zero() {
        return None;
    }
    let nf = n.map(to_f64);
    let w1 = width_along(world, k.body1, &nf)?;
    let w2 = width_along(world, b2, &nf)?;
    Some(if w2 <= w1 {
        (k.body1, b2)
    } else {
        (b2, k.body1)
    })
}
