//! A collision continuous detection found, resolved where it happens: the
//! bodies advanced along the motion the search assumed
//! ([`advance_along`]), the pair's contacts there (the narrow phase's
//! within the search's tolerance, or the closest points) resolved together
//! by the velocity phase, and whether the pair can meet again in the step
//! ([`apart_for_good`]).

use nalgebra::{UnitQuaternion, Vector3};

use super::ccd_pairs;
use super::energy;
use super::report::ToiEvent;
use super::simulation::contacts::contact_input;
use crate::physics::detect::{
    plane_depth, query, Convex, EpaOptions, GjkOptions, QueryOptions, ToiMethod,
};
use crate::physics::params::{Material, ResolverParams, RestitutionFrom, SimParams};
use crate::physics::pose::Pose;
use crate::physics::resolver::{Implementation, Resolver, Silent};
use crate::physics::{c, to_f64, BodyId, Contact, Real, Solver, World};

pub(super) fn shape<T: Real>(world: &World<T>, i: usize) -> Option<Convex> {
    Convex::from_shape(world.bodies[i].shape.as_ref()?)
}

pub(super) fn to3<T: Real>(v: &Vector3<T>) -> [f64; 3] {
    [to_f64(v.x), to_f64(v.y), to_f64(v.z)]
}

/// x ← x + v dt, q ← exp(ω dt) q for every moving body: the motion the
/// searches assume, so a body advanced to a time of collision stands where
/// its search found it (the integrator's q + ½ [0, ω dt] q turns less: by
/// 2 atan(|ω| dt / 2), not |ω| dt, far apart for a fast spin).
pub(super) fn advance_along<T: Real>(world: &mut World<T>, moving: &[bool], dt: T) {
    for (body, moves) in world.bodies.iter_mut().zip(moving) {
        if *moves {
            let s = &mut body.state;
            s.position += s.velocity * dt;
            let turn = UnitQuaternion::from_scaled_axis(s.angular_velocity * dt);
            s.orientation = (turn * UnitQuaternion::new_normalize(s.orientation)).into_inner();
        }
    }
}

/// Whether the gap of a pair just resolved with `hit` cannot shrink over
/// the rest of the step: along the contact's normal the bodies separate
/// faster than any of their points can turn back, (v₁ − v₂)·n ≥
/// |ω₁| ρ₁ + |ω₂| ρ₂ (the plane through the contact along n then keeps
/// them apart). Otherwise the pair is searched again (a spinning hull whose
/// next vertex comes round).
pub(super) fn apart_for_good<T: Real>(world: &World<T>, hit: &ToiEvent) -> bool {
    let n = Vector3::new(c::<T>(hit.normal[0]), c(hit.normal[1]), c(hit.normal[2]));
    let body = |b: BodyId| {
        let s = &world.bodies[b.0].state;
        let r = shape(world, b.0).map_or(T::zero(), |sh| c(sh.bounding_radius()));
        (s.velocity, s.angular_velocity.norm() * r)
    };
    let (v1, spin1) = body(hit.body1);
    let (v2, spin2) = body(hit.body2);
    (v1 - v2).dot(&n) >= spin1 + spin2
}

/// The closest points of bodies `i` and `j` where they are now, as one
/// contact (GJK's, or EPA's if the pair overlaps; a half-space's: the
/// shape's deepest point, the plane's normal): where the narrow phase finds
/// nothing within the tolerance.
fn closest<T: Real>(world: &World<T>, i: usize, j: usize) -> Option<(Vector3<T>, Vector3<T>, T)> {
    let pose = |k: usize| {
        let s = &world.bodies[k].state;
        Pose::new(s.position, &s.orientation)
    };
    let a = shape(world, i)?;
    if let Some((normal, point)) = ccd_pairs::half_space(world, j) {
        let (deepest, depth) = plane_depth(&a, &pose(i), &normal, &point);
        return Some((deepest + normal * (depth * c::<T>(0.5)), normal, depth));
    }
    let b = shape(world, j)?;
    let q = query(
        &a,
        &pose(i),
        &b,
        &pose(j),
        &QueryOptions {
            gjk: GjkOptions::default(),
            epa: EpaOptions::default(),
        },
        &mut (),
        &mut (),
    );
    match q.penetration {
        Some(pen) => Some((pen.point, pen.normal, pen.depth)),
        None => {
            let gap = q.gjk.closest_a - q.gjk.closest_b;
            let d = gap.norm();
            (d > T::zero()).then(|| {
                (
                    (q.gjk.closest_a + q.gjk.closest_b) * c::<T>(0.5),
                    gap / d,
                    -d,
                )
            })
        }
    }
}

/// The contacts of bodies `i` and `j` where they are now (the narrow
/// phase's within twice the search's `tolerance`, or their closest points),
/// resolved together by the velocity phase of the scene's resolver as one
/// impact (each contact's restitution from its closing speed here). Body 1 is a movable one. The
/// event's point is the contact closing fastest; `None` when none closes.
pub(super) fn resolve_at<T: Real>(
    world: &mut World<T>,
    p: &SimParams<T>,
    materials: &[Material],
    i: usize,
    j: usize,
    tolerance: f64,
) -> Option<ToiEvent> {
    let (i, j) = if world.bodies[i].movable {
        (i, j)
    } else {
        (j, i)
    };
    let mut points: Vec<(Vector3<T>, Vector3<T>, T)> =
        ccd_pairs::contacts_at(world, p, (i, j), c(2.0 * tolerance))
            .iter()
            .map(|k| (k.point, k.normal, k.penetration))
            .collect();
    if points.is_empty() {
        points.extend(closest(world, i, j));
    }
    let normal_speed = |w: &World<T>, point: &Vector3<T>, normal: &Vector3<T>| {
        let v = |k: usize| {
            let s = &w.bodies[k].state;
            s.point_velocity(&(point - s.position))
        };
        to_f64((v(i) - v(j)).dot(normal))
    };
    let (first, closing) = points
        .iter()
        .enumerate()
        .map(|(k, (point, normal, _))| (k, -normal_speed(world, point, normal)))
        .fold(None, |best: Option<(usize, f64)>, (k, s)| match best {
            Some((_, b)) if b >= s => best,
            _ => Some((k, s)),
        })?;
    if closing <= 0.0 {
        // Met but not closing (a grazing or turning-away pair): nothing to resolve.
        return None;
    }
    let m = materials[i].combine(&materials[j]);
    let contacts = points
        .iter()
        .map(|&(point, normal, penetration)| Contact {
            body1: BodyId(i),
            body2: Some(BodyId(j)),
            input: contact_input(p, &m, point, normal, penetration),
            duration: (!p.acceleration_compensation).then(T::zero),
        })
        .collect();
    let (point, normal, _) = points[first];
    let kinetic_before = to_f64(energy::kinetic(world));
    let kept = std::mem::replace(&mut world.contacts, contacts);
    // One impact of the whole manifold: every contact's restitution
    // target from its closing speed at the time of collision, and, for
    // several contacts, impulses accumulated until they hold together
    // (sequential impulses). Taken one after another, each from what the
    // others left (the lecture's deepest first), a box landing flat left
    // at 0.65 e v spinning at 22 rad/s; one contact is the same either way.
    let resolving = ResolverParams {
        restitution_from: RestitutionFrom::Initial,
        solver: if points.len() > 1 {
            Solver::SequentialImpulse
        } else {
            p.resolver.solver
        },
        warm_start: false,
        ..p.resolver
    };
    let mut resolver = Resolver::prepare(world, &resolving);
    resolver.velocity_phase(Implementation::Indexed, &mut Silent);
    resolver.write_back(world);
    world.contacts = kept;
    Some(ToiEvent {
        body1: BodyId(i),
        body2: BodyId(j),
        method: ToiMethod::Conservative,
        time: 0.0,
        tests: 0,
        point: to3(&point),
        normal: to3(&normal),
        closing,
        separating: normal_speed(world, &point, &normal),
        kinetic_before,
        kinetic_after: to_f64(energy::kinetic(world)),
    })
}
