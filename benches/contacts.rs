//! Contact generation per pair kind: the analytic routine against GJK/EPA
//! and the clipped manifold (`narrow_phase = "gjk"`), on the same 64 seeded
//! overlapping placements of each pair (box–box, box–sphere, sphere–sphere,
//! and for scale hull–hull and cylinder–box, which have GJK only).
//! Criterion reports the time for all 64; divide by 64 for one pair.

#[path = "common/rng.rs"]
mod rng;
use rng::Rng;

use std::hint::black_box;
use std::sync::Arc;
use std::time::Duration;

use contact_lab::physics::collide::{collide_with, NarrowPhase, Options, Pose};
use contact_lab::physics::detect::ConvexHull;
use contact_lab::physics::Shape;
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::Vector3;

/// 64 placements of `a` overlapping `b` (at the origin): A's centre at a
/// random direction, a little nearer than the sum of the bounding radii
/// allows, so most pairs touch.
fn placements(a: &Shape, b: &Shape, seed: u64) -> Vec<(Pose<f64>, Pose<f64>)> {
    let mut rng = Rng(seed);
    let reach = 0.8 * (a.bounding_radius().unwrap() + b.bounding_radius().unwrap());
    (0..64)
        .map(|_| {
            let d = Vector3::new(
                rng.range(-1.0, 1.0),
                rng.range(-1.0, 1.0),
                rng.range(-1.0, 1.0),
            )
            .normalize();
            let pa = Pose::from_unit(d * reach * rng.range(0.6, 1.0), &rng.rotation());
            let pb = Pose::from_unit(Vector3::zeros(), &rng.rotation());
            (pa, pb)
        })
        .collect()
}

fn hull() -> Shape {
    // An octagonal prism, radius 0.5, height 0.6.
    let pts: Vec<[f64; 3]> = [-0.3, 0.3]
        .iter()
        .flat_map(|&y| {
            (0..8).map(move |k| {
                let t = std::f64::consts::TAU * k as f64 / 8.0;
                [0.5 * t.cos(), y, 0.5 * t.sin()]
            })
        })
        .collect();
    Shape::Hull(Arc::new(ConvexHull::new(&pts).unwrap()))
}

fn bench(c: &mut Criterion) {
    let cube = Shape::Box {
        sides: [1.0, 0.8, 1.2],
    };
    let ball = Shape::Sphere { radius: 0.5 };
    let can = Shape::Cylinder {
        radius: 0.4,
        height: 1.0,
    };
    let pairs = [
        ("box-box", cube.clone(), cube.clone(), true),
        ("box-sphere", cube.clone(), ball.clone(), true),
        ("sphere-sphere", ball.clone(), ball, true),
        ("cylinder-box", can, cube, false),
        ("hull-hull", hull(), hull(), false),
    ];
    let mut group = c.benchmark_group("contacts");
    group.measurement_time(Duration::from_secs(2));
    group.warm_up_time(Duration::from_millis(500));
    for (k, (name, a, b, analytic)) in pairs.iter().enumerate() {
        let poses = placements(a, b, 7 + k as u64);
        let phases: &[(&str, NarrowPhase)] = if *analytic {
            &[
                ("analytic", NarrowPhase::Analytic),
                ("gjk", NarrowPhase::Gjk),
            ]
        } else {
            &[("gjk", NarrowPhase::Gjk)]
        };
        for (label, phase) in phases {
            let options = Options {
                narrow_phase: *phase,
                ..Options::default()
            };
            let mut out = Vec::with_capacity(64);
            group.bench_function(format!("{name}/{label}"), |bench| {
                bench.iter(|| {
                    let mut n = 0;
                    for (pa, pb) in &poses {
                        out.clear();
                        n += collide_with((a, pa), (b, pb), &options, &mut out);
                    }
                    black_box(n)
                })
            });
        }
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
