//! One pair over one step, as `detect --toi` shows it: its movement bounds,
//! its time-of-collision search (the one continuous detection runs, with
//! its tolerance), and its two normals: EPA's where the pair overlaps at the
//! step's end (the poses moved by v Δt, what a discrete step detects), and
//! the one from the closest points at the step's start, one frame earlier
//! ("Lecture IV Collisions": for fast motion, take the normal from the
//! previous frame, when the pair was still apart).

use nalgebra::Vector3;

use super::previous_frame::apart_normal;
use super::substep::search_options;
use super::swept::{motion_of, spheres_meet, swept_aabb, swept_sphere};
use crate::physics::detect::toi_sweep::{closing_bound, swept_toi};
use crate::physics::detect::{
    query, Convex, EpaOptions, GjkOptions, Motion, MovingPair, QueryOptions, Toi, ToiMethod,
    ToiObserver,
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
/// not yet updated) over `dt`; `None` when either has no convex shape.
pub fn search_pair<T: Real, O: ToiObserver<T> + ?Sized>(
    world: &World<T>,
    moving: &[bool],
    (i, j): (usize, usize),
    dt: T,
    method: ToiMethod,
    observer: &mut O,
) -> Option<PairSearch<T>> {
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
