//! Scenes the simulation benches share: an embedded scene and a pile of
//! spheres, with sleep off so every step does the full work, the resolver
//! settings given by the caller, warmed up before timing; and a timer that
//! restarts a scene every `span` steps, so a stack is timed while it stands
//! (the lecture's resolver lets `stack-5` fall after about 19 s without sleep,
//! and a fallen stack is far cheaper than a standing one).

use std::time::{Duration, Instant};

use contact_lab::lesson::Lesson;
use contact_lab::physics::params::Material;
use contact_lab::physics::step::{SimParams, Simulation};
use contact_lab::physics::{Body, ResolverParams, RigidBody, Shape, World};
use nalgebra::{Matrix3, Quaternion, Vector3};

fn warmed(mut sim: Simulation<f64>, warm: usize) -> Simulation<f64> {
    for _ in 0..warm {
        sim.advance().unwrap();
    }
    sim
}

/// The embedded scene `id`, warmed up by `warm` steps.
pub fn scene(id: &str, warm: usize, resolver: impl Fn(&mut ResolverParams)) -> Simulation<f64> {
    let lesson = Lesson::load(id).unwrap();
    let mut params = lesson.sim_params().unwrap();
    params.sleep.enabled = false;
    resolver(&mut params.resolver);
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    warmed(
        Simulation::new(world, params, lesson.simulation.unwrap().materials),
        warm,
    )
}

/// `n` spheres of radius 0.5 in layers of a square grid on a floor, warmed
/// up by 30 steps.
pub fn pile(n: usize, resolver: impl Fn(&mut ResolverParams)) -> Simulation<f64> {
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
    let material = Material {
        restitution: 0.1,
        static_friction: 0.4,
        dynamic_friction: 0.4,
    };
    let materials = vec![material; bodies.len()];
    let mut params = SimParams::<f64>::default();
    params.sleep.enabled = false;
    resolver(&mut params.resolver);
    let world = World {
        bodies,
        contacts: Vec::new(),
        step: Default::default(),
    };
    warmed(Simulation::new(world, params, materials), 30)
}

/// Times `iters` steps of `start`, started again from a copy every `span`
/// steps (the copies are not timed): for `Bencher::iter_custom`.
pub fn time_steps(start: &Simulation<f64>, span: usize, iters: u64) -> Duration {
    let mut total = Duration::ZERO;
    let mut left = iters;
    while left > 0 {
        let mut sim = start.clone();
        let n = left.min(span as u64);
        let t = Instant::now();
        for _ in 0..n {
            sim.advance().unwrap();
        }
        total += t.elapsed();
        left -= n;
    }
    total
}
