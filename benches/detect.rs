//! GJK and EPA per pair against parry3d (f64) on the same pairs: 64 seeded
//! random placements of each kind of pair, separated (GJK distance against
//! `parry::query::distance`) and overlapping (GJK + EPA, or the margins,
//! against `parry::query::contact`). Criterion reports the time for all 64;
//! divide by 64 for one pair.

#[path = "common/rng.rs"]
mod rng;
use rng::Rng;

use std::hint::black_box;
use std::time::Duration;

use contact_lab::physics::collide::Pose;
use contact_lab::physics::detect::{
    gjk, query, Capsule, Convex, ConvexHull, GjkOptions, QueryOptions,
};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::{UnitQuaternion, Vector3};
use parry3d_f64::math::{Pose as PPose, Rotation, Vector as PVec};
use parry3d_f64::shape::{
    Ball, Capsule as PCapsule, ConvexPolyhedron, Cuboid, Cylinder, Shape as PShape,
};

fn peer(shape: &Convex) -> Box<dyn PShape> {
    match shape {
        Convex::Sphere { radius } => Box::new(Ball::new(*radius)),
        Convex::Cuboid { half } => Box::new(Cuboid::new(PVec::new(half[0], half[1], half[2]))),
        Convex::Cylinder {
            radius,
            half_height,
        } => Box::new(Cylinder::new(*half_height, *radius)),
        Convex::Capsule(c) => Box::new(PCapsule::new_y(c.height / 2.0, c.radius)),
        Convex::Hull(h) => {
            let pts: Vec<PVec> = h
                .vertices()
                .iter()
                .map(|v| PVec::new(v.x, v.y, v.z))
                .collect();
            Box::new(ConvexPolyhedron::from_convex_hull(&pts).unwrap())
        }
    }
}

/// One placed pair, for both libraries.
struct Case {
    a: Convex,
    b: Convex,
    pa: Pose<f64>,
    pb: Pose<f64>,
    sa: Box<dyn PShape>,
    sb: Box<dyn PShape>,
    qa: PPose,
    qb: PPose,
}

fn place(x: &Vector3<f64>, q: &UnitQuaternion<f64>) -> (Pose<f64>, PPose) {
    (
        Pose::from_unit(*x, q),
        PPose::from_parts(
            PVec::new(x.x, x.y, x.z),
            Rotation::from_xyzw(q.i, q.j, q.k, q.w),
        ),
    )
}

/// 64 placements of `make()` pairs that are apart (`overlap` false) or overlap.
fn cases(seed: u64, make: &dyn Fn(&mut Rng) -> (Convex, Convex), overlap: bool) -> Vec<Case> {
    let mut rng = Rng(seed);
    let mut out = Vec::new();
    while out.len() < 64 {
        let (a, b) = make(&mut rng);
        let (xa, ra) = (rng.vector(1.5), rng.rotation());
        let (pa, qa) = place(&xa, &ra);
        let (pb, qb) = place(&Vector3::zeros(), &rng.rotation());
        let r = gjk(&a, &pa, &b, &pb, &GjkOptions::default(), &mut ());
        if (r.distance == 0.0) == overlap && (overlap || r.distance > 1e-3) {
            let (sa, sb) = (peer(&a), peer(&b));
            out.push(Case {
                a,
                b,
                pa,
                pb,
                sa,
                sb,
                qa,
                qb,
            });
        }
    }
    out
}

fn cuboid(rng: &mut Rng) -> Convex {
    Convex::Cuboid {
        half: [
            rng.range(0.3, 1.0),
            rng.range(0.3, 1.0),
            rng.range(0.3, 1.0),
        ],
    }
}

fn hull(rng: &mut Rng) -> Convex {
    let pts: Vec<[f64; 3]> = (0..16).map(|_| rng.vector(0.8).into()).collect();
    Convex::hull(ConvexHull::new(&pts).unwrap())
}

fn cylinder(rng: &mut Rng) -> Convex {
    Convex::Cylinder {
        radius: rng.range(0.3, 0.8),
        half_height: rng.range(0.3, 0.8),
    }
}

fn capsule(rng: &mut Rng) -> Convex {
    Convex::Capsule(Capsule {
        radius: rng.range(0.2, 0.5),
        height: rng.range(0.5, 1.5),
    })
}

fn pairs(c: &mut Criterion) {
    type Make = fn(&mut Rng) -> (Convex, Convex);
    let kinds: [(&str, Make); 5] = [
        ("box_box", |r| (cuboid(r), cuboid(r))),
        ("hull_hull", |r| (hull(r), hull(r))),
        ("cylinder_box", |r| (cylinder(r), cuboid(r))),
        ("capsule_capsule", |r| (capsule(r), capsule(r))),
        ("sphere_hull", |r| {
            (
                Convex::Sphere {
                    radius: r.range(0.3, 0.8),
                },
                hull(r),
            )
        }),
    ];
    let mut group = c.benchmark_group("detect_64_pairs");
    let options = QueryOptions::default();
    for (k, (name, make)) in kinds.iter().enumerate() {
        let apart = cases(100 + k as u64, make, false);
        let deep = cases(200 + k as u64, make, true);
        group.bench_function(format!("{name}/distance/ours"), |bench| {
            bench.iter(|| {
                for x in &apart {
                    black_box(gjk(&x.a, &x.pa, &x.b, &x.pb, &options.gjk, &mut ()).distance);
                }
            })
        });
        group.bench_function(format!("{name}/distance/parry"), |bench| {
            bench.iter(|| {
                for x in &apart {
                    black_box(parry3d_f64::query::distance(&x.qa, &*x.sa, &x.qb, &*x.sb).unwrap());
                }
            })
        });
        group.bench_function(format!("{name}/penetration/ours"), |bench| {
            bench.iter(|| {
                for x in &deep {
                    black_box(
                        query(&x.a, &x.pa, &x.b, &x.pb, &options, &mut (), &mut ()).penetration,
                    );
                }
            })
        });
        group.bench_function(format!("{name}/penetration/parry"), |bench| {
            bench.iter(|| {
                for x in &deep {
                    black_box(
                        parry3d_f64::query::contact(&x.qa, &*x.sa, &x.qb, &*x.sb, 0.0).unwrap(),
                    );
                }
            })
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).measurement_time(Duration::from_secs(2)).warm_up_time(Duration::from_millis(300));
    targets = pairs
}
criterion_main!(benches);
