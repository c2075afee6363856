//! Time of collision against the closed form t = gap / speed (a sphere moving
//! straight at a sphere, and at a thin wall's face): bisection within its
//! tolerance in exactly ⌈log₂(Δt / tol)⌉ tests; conservative advancement
//! within its tolerance in fewer; a bullet that crosses a thin wall inside
//! the step is invisible to bisection and found by advancement.

use nalgebra::{UnitQuaternion, Vector3};

use crate::physics::detect::toi::bounding_radius;
use crate::physics::detect::{
    toi, Convex, Motion, MovingPair, ToiEnd, ToiMethod, ToiOptions, ToiRecorder,
};

const DT: f64 = 1.0 / 60.0;

fn moving(x: f64, vx: f64) -> Motion<f64> {
    Motion {
        velocity: Vector3::new(vx, 0.0, 0.0),
        ..Motion::fixed(Vector3::new(x, 0.0, 0.0))
    }
}

fn options(tolerance: f64) -> ToiOptions<f64> {
    ToiOptions {
        tolerance,
        ..ToiOptions::default()
    }
}

fn expected_bisections(tol: f64) -> usize {
    (DT / tol).log2().ceil() as usize
}

/// The ball, its motion, the target, its motion, the closed-form time.
type Case = (Convex, Motion<f64>, Convex, Motion<f64>, f64);

fn cases() -> Vec<Case> {
    let ball = Convex::Sphere { radius: 0.05 };
    let mut out = Vec::new();
    // Sphere at a sphere of radius 0.5 at the origin: gap = x − 0.55.
    for (x, v) in [(1.0, 40.0), (0.9, 30.0), (2.0, 100.0)] {
        let gap: f64 = x - 0.55;
        out.push((
            ball.clone(),
            moving(x, -v),
            Convex::Sphere { radius: 0.5 },
            Motion::fixed(Vector3::zeros()),
            gap / v,
        ));
    }
    // Sphere at a thin wall (1 cm thick, face at x = 0.005), ending past it
    // only when fast: gap = x − 0.05 − 0.005.
    for (x, v) in [(0.1, 6.0), (0.5, 50.0), (1.2, 100.0)] {
        out.push((
            ball.clone(),
            moving(x, -v),
            Convex::Cuboid {
                half: [0.005, 2.0, 2.0],
            },
            Motion::fixed(Vector3::zeros()),
            (x - 0.055) / v,
        ));
    }
    out
}

#[test]
fn bisection_meets_gap_over_speed_in_log2_of_step_over_tolerance_tests() {
    for tol in [1e-4, 1e-6, 1e-8] {
        // One wall case ends inside the wall; the other two crossed it.
        let mut bisected_walls = 3;
        for (a, ma, b, mb, want) in cases() {
            let mut rec = ToiRecorder::default();
            let r = toi(
                ToiMethod::Bisection,
                &MovingPair::new(&a, &ma, &b, &mb),
                DT,
                &options(tol),
                &mut rec,
            );
            if r.end == ToiEnd::NoHitAtEnd {
                // The ball crossed the wall inside the step: bisection cannot bracket it.
                assert!(matches!(b, Convex::Cuboid { .. }), "{a:?} {ma:?}");
                bisected_walls -= 1;
                continue;
            }
            assert_eq!(r.end, ToiEnd::Converged);
            let t = r.time.unwrap();
            assert!(t <= want && want - t <= tol, "{t} vs {want}, tol {tol}");
            assert_eq!(r.iterations, expected_bisections(tol), "tol {tol}");
            assert_eq!(rec.steps.len(), r.iterations);
            // Every recorded interval brackets the closed form and halves.
            for s in &rec.steps {
                assert!(s.t0 <= want && want <= s.t1);
                assert_eq!(s.hit, s.trial >= want);
            }
        }
        assert_eq!(bisected_walls, 1);
    }
}

#[test]
fn conservative_advancement_meets_gap_over_speed_in_fewer_tests() {
    let tol = 1e-6;
    for (a, ma, b, mb, want) in cases() {
        let speed = ma.velocity.norm();
        let r = toi(
            ToiMethod::Conservative,
            &MovingPair::new(&a, &ma, &b, &mb),
            DT,
            &options(tol),
            &mut (),
        );
        assert_eq!(r.end, ToiEnd::Converged);
        let t = r.time.unwrap();
        // Never past the contact; the distance left ≤ tol, so the time ≤ tol / speed early.
        assert!(
            t <= want + 1e-12 && want - t <= tol / speed,
            "{t} vs {want}"
        );
        assert!(r.iterations < expected_bisections(tol), "{}", r.iterations);
        // Straight motion along the normal: d / μ is exact, one advance then the check.
        assert!(r.iterations <= 3, "{}", r.iterations);
    }
}

#[test]
fn a_bullet_through_a_thin_wall_is_missed_by_bisection_and_found_by_advancement() {
    let bullet = Convex::Sphere { radius: 0.01 };
    let wall = Convex::Cuboid {
        half: [0.01, 1.0, 1.0],
    };
    // 100 m/s at 60 Hz: 1.67 m in a step, from 0.5 m before the wall to 1.17 m past it.
    let ma = moving(0.5, -100.0);
    let mb = Motion::fixed(Vector3::zeros());
    let b = toi(
        ToiMethod::Bisection,
        &MovingPair::new(&bullet, &ma, &wall, &mb),
        DT,
        &options(1e-6),
        &mut (),
    );
    assert_eq!((b.end, b.time), (ToiEnd::NoHitAtEnd, None));
    let c = toi(
        ToiMethod::Conservative,
        &MovingPair::new(&bullet, &ma, &wall, &mb),
        DT,
        &options(1e-6),
        &mut (),
    );
    let want = (0.5 - 0.02) / 100.0;
    assert!((c.time.unwrap() - want).abs() <= 1e-8, "{c:?}");
}

#[test]
fn advancement_with_spin_stays_before_the_first_contact() {
    // A thin box spinning fast while falling onto a slab: μ includes |ω| ρ, so
    // every advance is safe; the box is apart at the time found, and bisection
    // (which brackets the first contact here: the end pose overlaps) agrees.
    let plank = Convex::Cuboid {
        half: [0.5, 0.02, 0.1],
    };
    let slab = Convex::Cuboid {
        half: [3.0, 0.1, 3.0],
    };
    let ma = Motion {
        position: Vector3::new(0.0, 0.7, 0.0),
        orientation: UnitQuaternion::identity(),
        velocity: Vector3::new(0.0, -30.0, 0.0),
        angular_velocity: Vector3::new(0.0, 0.0, 20.0),
    };
    let mb = Motion::fixed(Vector3::zeros());
    let tol = 1e-7;
    let mut rec = ToiRecorder::default();
    let c = toi(
        ToiMethod::Conservative,
        &MovingPair::new(&plank, &ma, &slab, &mb),
        DT,
        &options(tol),
        &mut rec,
    );
    let b = toi(
        ToiMethod::Bisection,
        &MovingPair::new(&plank, &ma, &slab, &mb),
        DT,
        &options(1e-9),
        &mut (),
    );
    let (tc, tb) = (c.time.unwrap(), b.time.unwrap());
    assert_eq!(c.end, ToiEnd::Converged);
    assert!(tc <= tb + 1e-9 && tb - tc < 1e-5, "{tc} vs {tb}");
    // The recorded distances shrink and the times grow.
    for w in rec.steps.windows(2) {
        assert!(w[1].trial > w[0].trial && w[1].distance < w[0].distance);
    }
    assert!(bounding_radius::<f64, _>(&plank) >= 0.5);
}
