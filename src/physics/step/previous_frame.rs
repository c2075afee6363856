//! The normal from the previous frame ("Lecture IV Collisions", the time
//! issue): for fast motion the least penetration at t (EPA's normal, or the
//! analytic routine's) can point sideways or even backwards; the closest
//! points one frame earlier, at t − Δt, when the pair was still apart, give
//! the direction it came from. A step keeps each body's pose at the start
//! of the last step (the previous frame of this step's contacts).

use nalgebra::{Quaternion, Vector3};

use crate::physics::detect::{gjk, Convex, GjkOptions, GjkVerdict, Support};
use crate::physics::pose::Pose;
use crate::physics::{Body, Contact, Real, World};

/// A body's position and orientation.
pub type PoseOf<T> = (Vector3<T>, Quaternion<T>);

/// The unit vector from b's closest point toward a's, when the two shapes
/// at these poses are apart (GJK's closest points); `None` when they touch
/// or overlap.
pub fn apart_normal<T: Real>(
    a: &Convex,
    pa: &Pose<T>,
    b: &Convex,
    pb: &Pose<T>,
) -> Option<Vector3<T>> {
    let g = gjk(a, pa, b, pb, &GjkOptions::default(), &mut ());
    if g.verdict != GjkVerdict::Separated {
        return None;
    }
    (g.closest_a - g.closest_b).try_normalize(T::zero())
}

/// The normal from the previous frame of a penetrating contact between two
/// convex bodies: from body 2's closest point toward body 1's at the poses
/// `previous` (each body's, one frame earlier). `None` when the contact
/// does not penetrate, a body has no convex shape (a half-space's normal
/// is the plane's at any time), there is no previous frame, or the pair
/// already touched then.
pub fn previous_normal<T: Real>(
    world: &World<T>,
    previous: &[PoseOf<T>],
    contact: &Contact<T>,
) -> Option<Vector3<T>> {
    if contact.input.penetration <= T::zero() {
        return None;
    }
    pair_normal(&world.bodies, previous, contact.body1.0, contact.body2?.0)
}

/// Bodies `i` (body 1) and `j`'s normal from the previous frame (see
/// [`previous_normal`]), whatever their penetration now.
pub fn pair_normal<T: Real>(
    bodies: &[Body<T>],
    previous: &[PoseOf<T>],
    i: usize,
    j: usize,
) -> Option<Vector3<T>> {
    let shape = |k: usize| Convex::from_shape(bodies[k].shape.as_ref()?);
    let pose = |k: usize| {
        let (x, q) = previous.get(k)?;
        Some(Pose::new(*x, q))
    };
    apart_normal(&shape(i)?, &pose(i)?, &shape(j)?, &pose(j)?)
}

/// The depth of bodies `i` (body 1) and `j`'s overlap along the unit `n`
/// (from j toward i) where they are now: how far i must move along n to
/// clear j, max over j of x·n minus min over i of x·n, from the support
/// mappings (the `normal_from = previous` contact's penetration).
pub fn depth_along<T: Real>(bodies: &[Body<T>], i: usize, j: usize, n: &Vector3<T>) -> Option<T> {
    let shape = |k: usize| Convex::from_shape(bodies[k].shape.as_ref()?);
    let pose = |k: usize| {
        let s = &bodies[k].state;
        Pose::new(s.position, &s.orientation)
    };
    let (a, b) = (shape(i)?, shape(j)?);
    let deepest_of_b = b.support(&pose(j), n).dot(n);
    let lowest_of_a = a.support(&pose(i), &-n).dot(n);
    Some(deepest_of_b - lowest_of_a)
}

/// The angle between two unit normals (radians): acos(d̂₁·d̂₂), the dot
/// product clamped to [−1, 1].
pub fn angle_between<T: Real>(a: &Vector3<T>, b: &Vector3<T>) -> T {
    a.dot(b).max(-T::one()).min(T::one()).acos()
}
