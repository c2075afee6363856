//! Contacts of a whole set of bodies: broad phase, then the pair functions,
//! with the buffers kept from step to step.

use super::broad::{all_pairs, Aabb};
use super::partition::{BroadCounts, PairFinder};
use super::{c, collide_with, ContactPoint, NarrowPhase, Options, Pose, Real, Shape};
use crate::physics::{Body, BodyId};

/// A generated contact between bodies `body1` and `body2` (indices into the
/// slices given to [`ContactGenerator::generate`], or into the world's
/// bodies); the normal points from body 2 toward body 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyContact<T: Real> {
    pub body1: BodyId,
    pub body2: BodyId,
    pub contact: ContactPoint<T>,
}

/// Runs the broad and the narrow phase over a set of bodies. Keep one per
/// scene: its buffers (bounds, pairs, sweep order) are reused.
#[derive(Debug, Clone)]
pub struct ContactGenerator<T: Real> {
    /// Test every pair of bounds instead of sweeping (for comparison).
    pub brute_force: bool,
    broad: PairFinder,
    bounds: Vec<Option<Aabb<T>>>,
    half_spaces: Vec<usize>,
    pairs: Vec<(usize, usize)>,
    points: Vec<ContactPoint<T>>,
    /// A world's bodies as slices (for `generate_world`).
    shapes: Vec<Option<Shape>>,
    poses: Vec<Pose<T>>,
    movable: Vec<bool>,
}

impl<T: Real> Default for ContactGenerator<T> {
    fn default() -> Self {
        ContactGenerator {
            brute_force: false,
            broad: PairFinder::new(),
            bounds: Vec::new(),
            half_spaces: Vec::new(),
            pairs: Vec::new(),
            points: Vec::new(),
            shapes: Vec::new(),
            poses: Vec::new(),
            movable: Vec::new(),
        }
    }
}

impl<T: Real> ContactGenerator<T> {
    pub fn new() -> Self {
        Self::default()
    }

    /// Replaces `out` with the contacts of the bodies: body i has shape
    /// `shapes[i]` (`None`: no shape, no contacts), pose `poses[i]` and is
    /// movable when `movable[i]`. Pairs of immovable bodies generate nothing.
    /// A pair's lower index is body 1 unless only the higher one is movable
    /// (then body 2 is the immovable one, as the resolver expects). Contacts
    /// come in pair order (sorted by index pair), then in the pair function's
    /// order: deterministic.
    pub fn generate(
        &mut self,
        shapes: &[Option<Shape>],
        poses: &[Pose<T>],
        movable: &[bool],
        options: &Options<T>,
        out: &mut Vec<BodyContact<T>>,
    ) {
        assert!(
            shapes.len() == poses.len() && shapes.len() == movable.len(),
            "one shape, pose and movable flag per body"
        );
        out.clear();
        // Bounds grown by half the tolerance each: bodies nearer than the
        // tolerance have overlapping bounds.
        let margin = options.tolerance.max(T::zero()) * c::<T>(0.5);
        self.bounds.clear();
        self.half_spaces.clear();
        for (i, (shape, pose)) in shapes.iter().zip(poses).enumerate() {
            if let Some(Shape::HalfSpace { .. }) = shape {
                self.half_spaces.push(i);
            }
            self.bounds
                .push(shape.as_ref().and_then(|s| Aabb::of(s, pose, margin)));
        }
        if self.brute_force {
            all_pairs(&self.bounds, &self.half_spaces, &mut self.pairs);
        } else {
            self.broad.candidate_pairs(
                options.broad_phase,
                &self.bounds,
                &self.half_spaces,
                &mut self.pairs,
            );
        }
        for &(i, j) in &self.pairs {
            let (body1, body2) = match (movable[i], movable[j]) {
                (false, false) => continue,
                (false, true) => (j, i),
                _ => (i, j),
            };
            let (Some(s1), Some(s2)) = (&shapes[body1], &shapes[body2]) else {
                continue;
            };
            if spheres_apart(s1, &poses[body1], s2, &poses[body2], options) {
                continue;
            }
            self.points.clear();
            collide_with(
                (s1, &poses[body1]),
                (s2, &poses[body2]),
                options,
                &mut self.points,
            );
            out.extend(self.points.iter().map(|&contact| BodyContact {
                body1: BodyId(body1),
                body2: BodyId(body2),
                contact,
            }));
        }
    }

    /// [`generate`](Self::generate) for a world's bodies (their shapes,
    /// positions, orientations and movable flags).
    pub fn generate_world(
        &mut self,
        bodies: &[Body<T>],
        options: &Options<T>,
        out: &mut Vec<BodyContact<T>>,
    ) {
        let (mut shapes, mut poses, mut movable) = (
            std::mem::take(&mut self.shapes),
            std::mem::take(&mut self.poses),
            std::mem::take(&mut self.movable),
        );
        shapes.clear();
        poses.clear();
        movable.clear();
        for body in bodies {
            shapes.push(body.shape.clone());
            poses.push(Pose::new(body.state.position, &body.state.orientation));
            movable.push(body.movable);
        }
        self.generate(&shapes, &poses, &movable, options, out);
        (self.shapes, self.poses, self.movable) = (shapes, poses, movable);
    }

    /// The candidate pairs of the last [`generate`](Self::generate).
    pub fn pairs(&self) -> &[(usize, usize)] {
        &self.pairs
    }

    /// What the last [`generate`](Self::generate)'s broad phase did (not
    /// updated by `brute_force`).
    pub fn broad_counts(&self) -> BroadCounts {
        self.broad.counts()
    }

    /// The boxes of the last call (grown by half the tolerance), by body.
    pub fn bounds(&self) -> &[Option<Aabb<T>>] {
        &self.bounds
    }
}

/// Two spheres whose centres are farther apart than their radii and the
/// tolerance: sphere–sphere's own rejection (`|d|² > (r_A + r_B + tol)²`,
/// the same numbers whichever body is first), taken before the pair
/// function's dispatch (a settled pile's candidate pairs are mostly
/// diagonal neighbours that do not touch). False for anything else.
fn spheres_apart<T: Real>(
    s1: &Shape,
    p1: &Pose<T>,
    s2: &Shape,
    p2: &Pose<T>,
    options: &Options<T>,
) -> bool {
    let radius = |s: &Shape| match *s {
        Shape::Sphere { radius } | Shape::HollowSphere { radius } => Some(c::<T>(radius)),
        _ => None,
    };
    let (Some(r1), Some(r2)) = (radius(s1), radius(s2)) else {
        return false;
    };
    if options.narrow_phase != NarrowPhase::Analytic {
        return false;
    }
    let reach = r1 + r2 + options.tolerance;
    reach < T::zero() || (p1.position - p2.position).norm_squared() > reach * reach
}
