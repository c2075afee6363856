//! The lecture's deepest-first resolver against sequential impulses (with
//! and without warm start), µs per simulate step at the same budget
//! (8 contact visits per contact per phase): the 5-box stack and a pile of
//! 200 spheres, sleep off so every step does the full work.

use contact_lab::lesson::Lesson;
use contact_lab::physics::params::Material;
use contact_lab::physics::step::{SimParams, Simulation};
use contact_lab::physics::{Body, ResolverParams, RigidBody, Shape, Solver, World};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use nalgebra::{Matrix3, Quaternion, Vector3};

const SOLVERS: [(&str, Solver, bool); 3] = [
    ("deepest_first", Solver::DeepestFirst, false),
    ("sequential_impulse", Solver::SequentialImpulse, false),
    ("sequential_impulse+warm", Solver::SequentialImpulse, true),
];

fn with_solver(p: &mut ResolverParams, solver: Solver, warm: bool) {
    p.solver = solver;
    p.warm_start = warm;
}

/// stack-5, warmed up by 60 steps.
fn stack(solver: Solver, warm: bool) -> Simulation<f64> {
    let lesson = Lesson::load("stack-5").unwrap();
    let mut params = lesson.sim_params().unwrap();
    params.sleep.enabled = false;
    with_solver(&mut params.resolver, solver, warm);
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    for _ in 0..60 {
        sim.advance().unwrap();
    }
    sim
}

/// `n` spheres of radius 0.5 in layers of a square grid on a floor, warmed up by 30 steps.
fn pile(n: usize, solver: Solver, warm: bool) -> Simulation<f64> {
    let side = (n as f64).sqrt().ceil() as usize / 2 + 1;
    let inertia = 0.4 * 0.25;
    let mut bodies: Vec<Body<f64>> = (0..n)
        .map(|i| {
            let layer = i / (side * side);
            let (x, z) = ((i % side) as f64, ((i / side) % side) as f64);
            Body {
                state: RigidBody {
                    mass: 1.0,
                    inverse_mass: 1.0,
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
            }
        })
        .collect();
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
    with_solver(&mut params.resolver, solver, warm);
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
    let mut g = c.benchmark_group("solver_step");
    g.sample_size(20);
    for (name, solver, warm) in SOLVERS {
        let mut sim = stack(solver, warm);
        g.bench_with_input(BenchmarkId::new("stack-5", name), &name, |b, _| {
            b.iter(|| sim.advance().unwrap())
        });
        let mut sim = pile(200, solver, warm);
        g.bench_with_input(BenchmarkId::new("sphere_pile_200", name), &name, |b, _| {
            b.iter(|| sim.advance().unwrap())
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
