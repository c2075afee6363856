//! Time per step of `simulate`, with no trace recorded: the resting box, the
//! 5-box stack, and piles of spheres on a floor (50 … 2,000 bodies).

use contact_lab::lesson::Lesson;
use contact_lab::physics::params::Material;
use contact_lab::physics::step::{SimParams, Simulation};
use contact_lab::physics::{Body, RigidBody, Shape, World};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use nalgebra::{Matrix3, Quaternion, Vector3};

/// A scene's simulation, warmed up by `warm` steps, with sleep off so every
/// step does the full work.
fn scene(id: &str, warm: usize) -> Simulation<f64> {
    let lesson = Lesson::load(id).unwrap();
    let mut params = lesson.sim_params().unwrap();
    params.sleep.enabled = false;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    for _ in 0..warm {
        sim.advance().unwrap();
    }
    sim
}

/// `n` spheres of radius 0.5 in layers of a square grid, resting on a floor.
fn pile(n: usize) -> Simulation<f64> {
    let side = (n as f64).sqrt().ceil() as usize / 2 + 1;
    let mut bodies = Vec::new();
    for i in 0..n {
        let layer = i / (side * side);
        let (x, z) = ((i % side) as f64, ((i / side) % side) as f64);
        let m = 1.0;
        let inertia = 0.4 * m * 0.25;
        bodies.push(Body {
            state: RigidBody {
                mass: m,
                inverse_mass: 1.0 / m,
                inertia_body: Matrix3::identity() * inertia,
                inverse_inertia_body: Matrix3::identity() / inertia,
                position: Vector3::new(x * 1.001, 0.5 + layer as f64 * 1.001, z * 1.001),
                orientation: Quaternion::identity(),
                velocity: Vector3::zeros(),
                angular_velocity: Vector3::zeros(),
                acceleration: Vector3::zeros(),
            },
            shape: Some(Shape::Sphere { radius: 0.5 }),
            movable: true,
        });
    }
    bodies.push(Body::immovable(
        Vector3::zeros(),
        Quaternion::identity(),
        Some(Shape::HalfSpace {
            normal: [0.0, 1.0, 0.0],
        }),
    ));
    let materials = vec![
        Material {
            restitution: 0.1,
            static_friction: 0.4,
            dynamic_friction: 0.4,
        };
        bodies.len()
    ];
    let mut params = SimParams::<f64>::default();
    params.sleep.enabled = false;
    let world = World {
        bodies,
        contacts: Vec::new(),
        step: Default::default(),
    };
    let mut sim = Simulation::new(world, params, materials);
    for _ in 0..30 {
        sim.advance().unwrap();
    }
    sim
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("simulate_step");
    g.sample_size(20);
    for id in ["resting-box", "stack-5"] {
        let mut sim = scene(id, 60);
        g.bench_function(id, |b| b.iter(|| sim.advance().unwrap()));
    }
    for n in [50usize, 200, 1000, 2000] {
        let mut sim = pile(n);
        g.bench_with_input(BenchmarkId::new("sphere_pile", n), &n, |b, _| {
            b.iter(|| sim.advance().unwrap())
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
