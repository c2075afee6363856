//! Cost of contact generation: each pair function, and broad + narrow phase
//! over piles of 50 to 2,000 spheres on a floor, sort-and-sweep against all
//! pairs.

use std::hint::black_box;
use std::time::Duration;

use contact_lab::physics::collide::{
    all_pairs, collide, Aabb, BoxBoxMode, BroadPhase, ContactGenerator, ContactPoint, Options, Pose,
};
use contact_lab::physics::Shape;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use nalgebra::{UnitQuaternion, Vector3};

fn pose(p: [f64; 3], turn: UnitQuaternion<f64>) -> Pose<f64> {
    Pose::from_unit(Vector3::from(p), &turn)
}

/// A named pair: body A, body B, box–box mode.
type Case<'a> = (
    &'a str,
    (&'a Shape, Pose<f64>),
    (&'a Shape, Pose<f64>),
    BoxBoxMode,
);

fn pairs(c: &mut Criterion) {
    let floor = Shape::HalfSpace {
        normal: [0.0, 1.0, 0.0],
    };
    let ball = Shape::Sphere { radius: 0.5 };
    let cube = Shape::Box { sides: [1.0; 3] };
    let can = Shape::Cylinder {
        radius: 0.5,
        height: 1.0,
    };
    let level = UnitQuaternion::identity();
    let tilt = UnitQuaternion::from_euler_angles(0.3, 0.5, 0.2);
    let edge_a = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::FRAC_PI_4);
    let edge_b = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_4);
    let origin = pose([0.0; 3], level);
    let cases: [Case; 9] = [
        (
            "sphere_sphere",
            (&ball, pose([0.0, 0.99, 0.0], level)),
            (&ball, origin),
            BoxBoxMode::Single,
        ),
        (
            "sphere_plane",
            (&ball, pose([0.0, 0.49, 0.0], level)),
            (&floor, origin),
            BoxBoxMode::Single,
        ),
        (
            "box_plane_flat",
            (&cube, pose([0.0, 0.49, 0.0], level)),
            (&floor, origin),
            BoxBoxMode::Single,
        ),
        (
            "box_sphere",
            (&cube, pose([0.0, 0.0, 0.0], tilt)),
            (&ball, pose([0.6, 0.7, 0.1], level)),
            BoxBoxMode::Single,
        ),
        (
            "cylinder_plane",
            (&can, pose([0.0, 0.49, 0.0], tilt)),
            (&floor, origin),
            BoxBoxMode::Single,
        ),
        (
            "box_box_face_single",
            (&cube, pose([0.1, 0.98, 0.2], level)),
            (&cube, origin),
            BoxBoxMode::Single,
        ),
        (
            "box_box_face_manifold",
            (&cube, pose([0.1, 0.98, 0.2], level)),
            (&cube, origin),
            BoxBoxMode::Manifold,
        ),
        (
            "box_box_edge_edge",
            (&cube, pose([0.0, 1.4, 0.0], edge_a)),
            (&cube, pose([0.0; 3], edge_b)),
            BoxBoxMode::Manifold,
        ),
        (
            "box_box_separated",
            (&cube, pose([0.2, 1.2, 0.3], tilt)),
            (&cube, origin),
            BoxBoxMode::Manifold,
        ),
    ];
    let mut group = c.benchmark_group("pair");
    let mut out: Vec<ContactPoint<f64>> = Vec::with_capacity(16);
    for (name, (sa, pa), (sb, pb), mode) in cases {
        let n = collide((sa, &pa), (sb, &pb), mode, &mut out);
        eprintln!("{name}: {n} contacts");
        group.bench_function(name, |b| {
            b.iter(|| {
                out.clear();
                collide((black_box(sa), black_box(&pa)), (sb, &pb), mode, &mut out)
            })
        });
    }
    // The same tilted face contact in f32.
    let cast = |p: &Pose<f64>| Pose::<f32> {
        position: p.position.cast(),
        rotation: p.rotation.cast(),
    };
    let (pa, pb) = (cast(&pose([0.1, 0.98, 0.2], tilt)), cast(&origin));
    let mut out32: Vec<ContactPoint<f32>> = Vec::with_capacity(16);
    group.bench_function("box_box_manifold_f32", |b| {
        b.iter(|| {
            out32.clear();
            collide(
                (black_box(&cube), black_box(&pa)),
                (&cube, &pb),
                BoxBoxMode::Manifold,
                &mut out32,
            )
        })
    });
    group.finish();
}

/// `n` spheres (radius 0.5) in four layers of a square grid, 0.99 apart, the
/// bottom layer 0.01 into the floor (body 0): each touches its neighbours.
fn pile(n: usize) -> (Vec<Option<Shape>>, Vec<Pose<f64>>, Vec<bool>) {
    let side = ((n as f64 / 4.0).sqrt().ceil() as usize).max(1);
    let mut shapes = vec![Some(Shape::HalfSpace {
        normal: [0.0, 1.0, 0.0],
    })];
    let mut poses = vec![Pose::at(Vector3::zeros())];
    for i in 0..n {
        let (x, z, y) = (i % side, i / side % side, i / (side * side));
        shapes.push(Some(Shape::Sphere { radius: 0.5 }));
        poses.push(Pose::at(
            Vector3::new(x as f64, y as f64, z as f64) * 0.99 + Vector3::y() * 0.49,
        ));
    }
    let movable = (0..=n).map(|i| i > 0).collect();
    (shapes, poses, movable)
}

/// The broad phase alone on a pile's bounds: sort and sweep (state kept from
/// call to call) against testing all pairs.
fn broad(c: &mut Criterion) {
    let mut group = c.benchmark_group("broad");
    for n in [50, 200, 1000, 2000] {
        let (shapes, poses, _) = pile(n);
        let bounds: Vec<Option<Aabb<f64>>> = shapes
            .iter()
            .zip(&poses)
            .map(|(s, p)| Aabb::of(s.as_ref().unwrap(), p, 0.0))
            .collect();
        let mut out = Vec::new();
        let mut sweep = BroadPhase::new();
        group.bench_with_input(BenchmarkId::new("sweep", n), &n, |b, _| {
            b.iter(|| sweep.candidate_pairs(black_box(&bounds), &[0], &mut out))
        });
        group.bench_with_input(BenchmarkId::new("all_pairs", n), &n, |b, _| {
            b.iter(|| all_pairs(black_box(&bounds), &[0], &mut out))
        });
    }
    group.finish();
}

fn scenes(c: &mut Criterion) {
    let mut group = c.benchmark_group("pile");
    for n in [50, 200, 1000, 2000] {
        let (shapes, poses, movable) = pile(n);
        let options = Options::default();
        for brute_force in [false, true] {
            let mut generator = ContactGenerator::new();
            generator.brute_force = brute_force;
            let mut out = Vec::new();
            generator.generate(&shapes, &poses, &movable, &options, &mut out);
            let label = if brute_force { "all_pairs" } else { "sweep" };
            eprintln!(
                "pile {n} {label}: {} candidate pairs, {} contacts",
                generator.pairs().len(),
                out.len()
            );
            group.bench_with_input(BenchmarkId::new(label, n), &n, |b, _| {
                b.iter(|| {
                    generator.generate(black_box(&shapes), &poses, &movable, &options, &mut out)
                })
            });
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30).measurement_time(Duration::from_secs(2)).warm_up_time(Duration::from_millis(500));
    targets = pairs, broad, scenes
}
criterion_main!(benches);
