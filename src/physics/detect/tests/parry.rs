//! Against a peer implementation: parry3d (f64) on 10,000 random pairs of
//! every shape (sphere, box, cylinder, capsule, hull, hollow sphere; seeded).
//! The intersection verdicts agree (pairs within 1e-6 of touching would be
//! counted, not judged); distances agree to 1e-9 relative where both sides
//! are exact (no cylinder or capsule) and 1e-5 absolute where parry's GJK
//! approaches a curved surface; EPA depths to 1e-9 (polyhedra and spheres)
//! and 1e-5 (curved). Depths from the margins (sphere and capsule cores
//! apart) are closed forms; parry's capsule depths stray from them by up to
//! ~1e-3, so those are held to 2e-3 only.

use nalgebra::{UnitQuaternion, Vector3};
use parry3d_f64::math::{Pose as PPose, Rotation, Vector as PVec};
use parry3d_f64::query;
use parry3d_f64::shape::{Ball, Capsule, ConvexPolyhedron, Cuboid, Cylinder, Shape as PShape};

use super::Rng;
use crate::physics::detect::{query as detect, Convex, EpaEnd, PenetrationSource, QueryOptions};
use crate::physics::pose::Pose;

fn vec(v: &Vector3<f64>) -> PVec {
    PVec::new(v.x, v.y, v.z)
}

/// The same shape for parry.
pub(super) fn peer_shape(shape: &Convex) -> Box<dyn PShape> {
    match shape {
        Convex::Sphere { radius } => Box::new(Ball::new(*radius)),
        Convex::Cuboid { half } => Box::new(Cuboid::new(PVec::new(half[0], half[1], half[2]))),
        Convex::Cylinder {
            radius,
            half_height,
        } => Box::new(Cylinder::new(*half_height, *radius)),
        Convex::Capsule(c) => Box::new(Capsule::new_y(c.height / 2.0, c.radius)),
        Convex::Hull(h) => {
            let pts: Vec<PVec> = h.vertices().iter().map(vec).collect();
            Box::new(ConvexPolyhedron::from_convex_hull(&pts).expect("parry takes the hull"))
        }
    }
}

fn peer_pose(at: &Vector3<f64>, q: &UnitQuaternion<f64>) -> PPose {
    PPose::from_parts(vec(at), Rotation::from_xyzw(q.i, q.j, q.k, q.w))
}

/// Pairs where parry's answer is itself iterative on a curved surface
/// (cylinders, and capsules, which parry runs whole rather than as a segment).
fn is_round(shape: &Convex) -> bool {
    matches!(shape, Convex::Cylinder { .. } | Convex::Capsule(_))
}

#[test]
fn ten_thousand_random_pairs_agree_with_parry() {
    let mut rng = Rng::new(40);
    let (mut near, mut separated, mut overlapping) = (0, 0, 0);
    let (mut worst_distance, mut worst_depth) = (0.0f64, 0.0f64);
    let mut capped = 0;
    let mut worst_round = 0.0f64;
    let mut worst_margins = 0.0f64;
    let (mut gjk_iterations, mut epa_iterations) = (Vec::new(), Vec::new());
    for k in 0..10_000u64 {
        let (a, b) = (rng.shape(k), rng.shape(k / 6));
        let (xa, qa) = (rng.vector(1.6), rng.rotation());
        let (xb, qb) = (rng.vector(1.6), rng.rotation());
        let (pa, pb) = (Pose::from_unit(xa, &qa), Pose::from_unit(xb, &qb));
        let ours = detect(&a, &pa, &b, &pb, &QueryOptions::default(), &mut (), &mut ());
        let (sa, sb) = (peer_shape(&a), peer_shape(&b));
        let (ppa, ppb) = (peer_pose(&xa, &qa), peer_pose(&xb, &qb));
        let theirs = query::distance(&ppa, &*sa, &ppb, &*sb)
            .expect("parry supports the pair")
            .distance;
        let contact = query::contact(&ppa, &*sa, &ppb, &*sb, 0.0).expect("parry supports the pair");
        let depth = ours.penetration.map_or(0.0, |p| p.depth);
        gjk_iterations.push(ours.gjk.iterations);
        if let Some(e) = ours.epa {
            epa_iterations.push(e.iterations);
        }
        if ours.gjk.distance < 1e-6 && depth < 1e-6 {
            near += 1;
            continue;
        }
        let round = is_round(&a) || is_round(&b);
        if let Some(p) = ours.penetration {
            overlapping += 1;
            assert_eq!(
                theirs, 0.0,
                "pair {k} ({a:?}, {b:?}): parry finds them apart"
            );
            let c = contact.expect("parry finds the contact");
            if ours.epa.is_some_and(|e| e.end == EpaEnd::IterationCap) {
                capped += 1;
            }
            let err = (p.depth + c.dist).abs();
            if p.source == PenetrationSource::Margins {
                // Ours is the closed form m_A + m_B − |v| (tested in
                // closed_forms); parry's capsule depth strays by up to ~1e-3.
                worst_margins = worst_margins.max(err);
                assert!(
                    err <= 2e-3,
                    "pair {k} ({a:?}, {b:?}): depth {} vs {}",
                    p.depth,
                    -c.dist
                );
                continue;
            }
            worst_depth = worst_depth.max(err);
            let tol = if round { 1e-5 } else { 1e-9 };
            assert!(
                err <= tol,
                "pair {k} ({a:?}, {b:?}): {:?} depth {} vs {}",
                ours.epa,
                p.depth,
                -c.dist
            );
            // Parry's normal1 points out of A; ours from B toward A.
            let n2 = Vector3::new(c.normal2.x, c.normal2.y, c.normal2.z);
            if !round {
                assert!(
                    (p.normal - n2).norm() < 1e-6 || err < 1e-9,
                    "pair {k}: normal"
                );
            }
        } else {
            separated += 1;
            // Relative for exact pairs; absolute (shapes are 0.3–1.5 across) for curved ones.
            let err =
                (ours.gjk.distance - theirs).abs() / if round { 1.0 } else { theirs.max(1e-12) };
            worst_distance = worst_distance.max(if round { 0.0 } else { err });
            let tol = if round { 1e-5 } else { 1e-9 };
            worst_round = worst_round.max(if round { err } else { 0.0 });
            assert!(
                err <= tol,
                "pair {k} ({a:?}, {b:?}): {:?} distance {} vs {theirs}",
                ours.gjk.end,
                ours.gjk.distance
            );
        }
    }
    eprintln!(
        "parry: {separated} separated, {overlapping} overlapping, {near} within 1e-6 of touching; \
         worst relative distance error {worst_distance:.1e} (exact shapes), {worst_round:.1e} (curved, absolute), worst EPA depth error {worst_depth:.1e}, parry off the closed-form margin depth by {worst_margins:.1e}, \
         EPA capped {capped}"
    );
    let stats = |v: &[usize]| {
        let mean = v.iter().sum::<usize>() as f64 / v.len().max(1) as f64;
        (mean, v.iter().max().copied().unwrap_or(0))
    };
    eprintln!(
        "iterations (mean, max): GJK {:?}; EPA {:?} over {} runs",
        stats(&gjk_iterations),
        stats(&epa_iterations),
        epa_iterations.len()
    );
    assert!(
        separated > 2500 && overlapping > 2500,
        "{separated} {overlapping}"
    );
}
