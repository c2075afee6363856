//! One pair over one step, as `detect --toi` shows it: its movement bounds,
//! its time-of-collision search (the one continuous detection runs, with
//! its tolerance), and its two normals: EPA's where the pair overlaps at the
//! step's end (the poses moved by v Δt, what a discrete step detects), and
//! the one from the closest points at the step's start, one frame earlier
//! ("Lecture IV Collisions": for fast motion, take the normal from the
//! previous frame, when the pair was still apart).

use nalgebra::Vector3;

use super::ccd_pairs::half_space;
use super::previous_frame::apart_normal;
use super::substep::{search_options, search_options_for};
use super::swept::{motion_of, spheres_meet, swept_aabb, swept_sphere};
use crate::physics::detect::toi_sweep::{closing_bound, swept_toi};
use crate::physics::detect::{
    query, Convex, EpaOptions, GjkOptions, Motion, MovingPair, PlanePair, QueryOptions, Toi,
    ToiMethod, ToiObserver,
};
use crate::physics::{c, Real, World};

/// What the search of one pair found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairSearch<T: Real> {
    pub aabbs_overlap: bool,
    pub spheres_meet: bool,
    pub toi: Toi<T>,
    /// EPA's normal (from j toward i) and depth at the step's end, if they overlap.
    pub at_end: Option<(Vector3<T>, T)>,
    /// The unit vector from j's closest point toward i's at the step's start, if apart.
    pub previous_frame: Option<Vector3<T>>,
}

/// Bodies `i` and `j` of `world` (the step's contacts resolved, positions
/// not yet updated) over `dt`; `None` when either has no convex shape and
/// is not a half-space (or both are half-spaces).
pub fn search_pair<T: Real, O: ToiObserver<T> + ?Sized>(
    world: &World<T>,
    moving: &[bool],
    (i, j): (usize, usize),
    dt: T,
    method: ToiMethod,
    observer: &mut O,
) -> Option<PairSearch<T>> {
    if let Some(plane) = half_space(world, j) {
        return search_plane(world, moving, i, plane, dt, method, observer);
    }
    if let Some(plane) = half_space(world, i) {
        return search_plane(world, moving, j, plane, dt, method, observer);
    }
    let (sa, sb) = (
        world.bodies[i].shape.as_ref()?,
        world.bodies[j].shape.as_ref()?,
    );
    let (a, b) = (Convex::from_shape(sa)?, Convex::from_shape(sb)?);
    let (ma, mb) = (
        motion_of(world, i, moving[i]),
        motion_of(world, j, moving[j]),
    );
    let aabbs_overlap = match (swept_aabb(sa, &ma, dt), swept_aabb(sb, &mb, dt)) {
        (Some(x), Some(y)) => x.overlaps(&y),
        _ => false,
    };
    let spheres = |s: &Convex, m: &Motion<T>| swept_sphere(c(s.bounding_radius()), m, dt);
    let spheres_meet = spheres_meet(spheres(&a, &ma), spheres(&b, &mb));
    let pair = MovingPair::new(&a, &ma, &b, &mb);
    let options = search_options(method, &a, &b, closing_bound(&pair));
    let toi = swept_toi(method, &pair, dt, &options, observer);
    let end = query(
        &a,
        &ma.pose_at(dt),
        &b,
        &mb.pose_at(dt),
        &QueryOptions {
            gjk: GjkOptions::default(),
            epa: EpaOptions::default(),
        },
        &mut (),
        &mut (),
    );
    let at_end = end.penetration.map(|p| (p.normal, p.depth));
    let previous_frame = apart_normal(&a, &ma.pose_at(T::zero()), &b, &mb.pose_at(T::zero()));
    Some(PairSearch {
        aabbs_overlap,
        spheres_meet,
        toi,
        at_end,
        previous_frame,
    })
}

/// Body `i` against the half-space `(normal, point)`: the closed form
/// ([`PlanePair`]). The movement bounds are the body's bounding sphere
/// swept along its path against the plane (both flags say whether it comes
/// within its radius of the plane); the normal at either end is the plane's.
fn search_plane<T: Real, O: ToiObserver<T> + ?Sized>(
    world: &World<T>,
    moving: &[bool],
    i: usize,
    (normal, point): (Vector3<T>, Vector3<T>),
    dt: T,
    method: ToiMethod,
    observer: &mut O,
) -> Option<PairSearch<T>> {
    let a = Convex::from_shape(world.bodies[i].shape.as_ref()?)?;
    let ma = motion_of(world, i, moving[i]);
    let radius: T = c(a.bounding_radius());
    let h0 = normal.dot(&(ma.position - point));
    let h1 = h0 + normal.dot(&ma.velocity) * dt;
    let reaches = h0.min(h1) <= radius;
    let pair = PlanePair::new(&a, &ma, normal, point);
    let options = search_options_for(method, a.bounding_radius(), closing_bound(&pair));
    let toi = swept_toi(method, &pair, dt, &options, observer);
    let (_, end) = pair.signed_distance(dt);
    let (_, start) = pair.signed_distance(T::zero());
    Some(PairSearch {
        aabbs_overlap: reaches,
        spheres_meet: reaches,
        toi,
        at_end: (end < T::zero()).then_some((normal, -end)),
        previous_frame: (start > T::zero()).then_some(normal),
    })
}
