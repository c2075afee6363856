//! Cost of the exact impact integration per restitution law against the
//! one-shot `physics::solve`, one contact each: frictionless, sticking
//! throughout, sliding then sticking, sliding throughout, slip reversing
//! (closed form, no integration) and slip turning in 3D (Dormand–Prince).

use contact_lab::knobs::Choice;
use std::hint::black_box;

use contact_lab::lesson::Lesson;
use contact_lab::physics::exact::{
    exact_impact, integrate, ImpactInput, RestitutionLaw, Tolerance,
};
use contact_lab::physics::{solve, ContactInput, ContactParams, FrictionModel, Problem, RigidBody};
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::{Matrix3, UnitQuaternion, Vector3};

/// The 45° rod of `tests/physics/exact_impact.rs`: its end slides, halts and slides back.
fn rod() -> Problem<f64> {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let inertia = Matrix3::from_diagonal(&Vector3::new(1.0 / 3.0, 0.01, 1.0 / 3.0));
    let turn = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), -std::f64::consts::FRAC_PI_4);
    Problem {
        bodies: [
            Some(RigidBody {
                mass: 1.0,
                inverse_mass: 1.0,
                inertia_body: inertia,
                inverse_inertia_body: inertia.try_inverse().unwrap(),
                position: Vector3::new(h, h, 0.0),
                orientation: *turn.quaternion(),
                velocity: Vector3::new(0.55, -1.0, 0.0),
                angular_velocity: Vector3::zeros(),
                acceleration: Vector3::zeros(),
            }),
            None,
        ],
        contact: ContactInput {
            point: Vector3::zeros(),
            normal: Vector3::y(),
            penetration: 0.0,
            restitution: 0.5,
            static_friction: 0.5,
            dynamic_friction: 0.5,
            friction_model: FrictionModel::Millington,
            settings: ContactParams::default(),
        },
        duration: 0.01,
    }
}

fn lesson(id: &str, k: usize) -> Problem<f64> {
    Lesson::load(id).unwrap().problem::<f64>(k)
}

fn bench(c: &mut Criterion) {
    let mut turning = lesson("friction-cube", 0);
    turning.bodies[0].as_mut().unwrap().velocity.z += 1.0;
    let cases = [
        ("exact-frictionless", lesson("lecture-2", 0)),
        ("exact-sticks", lesson("two-boxes", 0)),
        ("exact-halts-and-sticks", lesson("friction-cube", 0)),
        ("exact-slides", lesson("friction-cube", 1)),
        ("exact-reverses", rod()),
        ("exact-turning", turning),
    ];
    for (name, problem) in cases {
        let mut group = c.benchmark_group(name);
        group.bench_function("one_shot", |b| b.iter(|| solve(black_box(&problem))));
        let input = exact_impact(&problem, RestitutionLaw::Poisson)
            .unwrap()
            .input;
        for law in RestitutionLaw::ALL {
            let input = ImpactInput {
                law,
                tolerance: Tolerance::default(),
                ..input.clone()
            };
            group.bench_function(format!("integrate_{}", Some(law).name()), |b| {
                b.iter(|| integrate(black_box(&input)).unwrap())
            });
        }
        group.bench_function("exact_impact_poisson", |b| {
            b.iter(|| exact_impact(black_box(&problem), RestitutionLaw::Poisson).unwrap())
        });
        group.finish();
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(50).measurement_time(std::time::Duration::from_secs(2)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
criterion_main!(benches);
