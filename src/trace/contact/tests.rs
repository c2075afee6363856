//! The stage builders on hand-made problems (no lesson): order, names,
//! skip reasons, notes about immovable bodies, check value names.

use nalgebra::{Matrix3, Quaternion, Vector3};

use super::*;
use crate::physics::checks::Measured;
use crate::physics::stages::FrictionRegime;
use crate::physics::{solve, ContactInput, ContactParams, FrictionModel, RigidBody};
use crate::trace::Value;

fn body(mass: f64, inertia: f64, position: [f64; 3], velocity: [f64; 3]) -> RigidBody<f64> {
    let tensor = Matrix3::from_diagonal_element(inertia);
    RigidBody {
        mass,
        inverse_mass: 1.0 / mass,
        inertia_body: tensor,
        inverse_inertia_body: tensor.try_inverse().unwrap(),
        position: position.into(),
        orientation: Quaternion::identity(),
        velocity: velocity.into(),
        angular_velocity: Vector3::zeros(),
        acceleration: Vector3::zeros(),
    }
}

fn contact(point: [f64; 3], penetration: f64, mu: f64) -> ContactInput<f64> {
    ContactInput {
        point: point.into(),
        normal: Vector3::y(),
        penetration,
        restitution: 0.8,
        static_friction: mu,
        dynamic_friction: mu,
        friction_model: FrictionModel::Millington,
        settings: ContactParams::default(),
    }
}

/// The lecture's second example: a cube's corner hits the immovable floor.
fn cube_on_floor() -> Problem<f64> {
    Problem {
        bodies: [
            Some(body(
                10.0,
                240.0,
                [20.1966, 16.1966, 0.0],
                [2.165, -1.25, 0.0],
            )),
            None,
        ],
        contact: contact([22.3932, 8.0, 0.0], 0.0, 0.0),
        duration: 0.01,
    }
}

/// Two movable bodies, sliding with friction and interpenetrating.
fn two_bodies() -> Problem<f64> {
    Problem {
        bodies: [
            Some(body(2.0, 1.0, [0.0, 1.0, 0.0], [3.0, -2.0, 0.0])),
            Some(body(4.0, 3.0, [0.0, -1.0, 0.0], [0.0, 0.0, 0.0])),
        ],
        contact: contact([1.0, 0.0, 0.0], 0.5, 0.1),
        duration: 0.01,
    }
}

fn names(one: &str, two: Option<&str>) -> ContactNames {
    ContactNames {
        bodies: [Some(one.to_string()), two.map(str::to_string)],
        label: "contact 3, iteration 7".to_string(),
        written: AsWritten::default(),
        previous_normal: None,
    }
}

fn step(steps: &[Step], id: StageId) -> &Step {
    steps.iter().find(|s| s.id == id).expect("stage present")
}

fn vector(s: &Step, name: &str) -> [f64; 3] {
    match s.value(name) {
        Some(Value::Vector(v)) => *v,
        other => panic!("{name}: {other:?}"),
    }
}

fn scalar(s: &Step, name: &str) -> f64 {
    match s.value(name) {
        Some(Value::Scalar(x)) => *x,
        other => panic!("{name}: {other:?}"),
    }
}

#[test]
fn every_stage_comes_in_order_with_its_title() {
    let p = cube_on_floor();
    let s = solve(&p);
    let steps = build(&p, &s, &names("cube", Some("floor")));
    let ids: Vec<_> = steps.iter().map(|s| s.id).collect();
    assert_eq!(ids, StageId::ALL.to_vec());
    for st in &steps {
        assert_eq!(st.title, st.id.title());
    }
    // One stage alone is the same as that stage of the whole build.
    let n = names("cube", Some("floor"));
    let c = SolvedContact::new(&p, &s, &n);
    assert_eq!(stage(StageId::Impulse, &c), steps[3]);
}

#[test]
fn the_lecture_cube_gives_the_lectures_numbers() {
    let p = cube_on_floor();
    let s = solve(&p);
    let steps = build(&p, &s, &names("cube", Some("floor")));
    let g = vector(step(&steps, StageId::Impulse), "impulse_world");
    assert!(g[0].abs() < 1e-12 && (g[1] - 18.7337).abs() < 1e-4, "{g:?}");
    assert!((scalar(step(&steps, StageId::UnitImpulse), "total") - 0.120104).abs() < 1e-6);
    assert!((scalar(step(&steps, StageId::DesiredDeltaVelocity), "desired") - 2.25).abs() < 1e-12);
    let r1 = vector(step(&steps, StageId::ContactFrame), "r1");
    assert!((r1[0] - 2.1966).abs() < 1e-12 && (r1[1] + 8.1966).abs() < 1e-12);
    assert!(step(&steps, StageId::ContactFrame).value("r2").is_none());
    // The body's tensor as the stages use it.
    match step(&steps, StageId::UnitImpulse).value("inertia1") {
        Some(Value::Matrix(m)) => assert_eq!(m[1][1], 240.0),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_named_immovable_body_is_noted_and_counts_as_infinite_mass() {
    let p = cube_on_floor();
    let s = solve(&p);
    let steps = build(&p, &s, &names("cube", Some("floor")));
    let frame = step(&steps, StageId::ContactFrame);
    assert!(frame
        .notes
        .iter()
        .any(|n| n == "floor is immovable (m = ∞): it has no r and contributes nothing."));
    let unit = step(&steps, StageId::UnitImpulse);
    assert_eq!(
        unit.formulas[0].substituted.as_deref(),
        Some("1/{m1} + 1/∞")
    );
    assert!(unit
        .notes
        .iter()
        .any(|n| n.starts_with("floor is immovable: 1/m = 0")));
    let after = after(&p, &s, &names("cube", Some("floor")));
    assert_eq!(after.len(), 1);
    assert_eq!(after[0].0, "cube");
    let v: [f64; 3] = s.after(&p, 0).unwrap().velocity.into();
    assert_eq!(after[0].1.velocity, v);
}

#[test]
fn an_empty_slot_is_the_world_and_adds_no_term() {
    let p = cube_on_floor();
    let s = solve(&p);
    let steps = build(&p, &s, &names("cube", None));
    let unit = step(&steps, StageId::UnitImpulse);
    assert_eq!(unit.formulas[0].substituted.as_deref(), Some("1/{m1}"));
    assert!(!steps
        .iter()
        .flat_map(|s| &s.notes)
        .any(|n| n.contains("immovable")));
}

#[test]
fn skipped_stages_say_why() {
    let p = cube_on_floor();
    let s = solve(&p);
    let steps = build(&p, &s, &names("cube", Some("floor")));
    let why = |id| step(&steps, id).skipped.clone().unwrap_or_default();
    assert!(why(StageId::FrictionClamp).starts_with("no friction (μ = 0)"));
    assert!(why(StageId::NonlinearProjection).starts_with("no penetration (d_pen ≤ 0)"));
    assert_eq!(
        why(StageId::OrientationUpdate),
        "no penetration (d_pen ≤ 0): no projection, so no body turns"
    );
    assert!(step(&steps, StageId::Impulse).skipped.is_none());
    // A separating contact: no impulse, nothing applied.
    let mut p = cube_on_floor();
    p.bodies[0].as_mut().unwrap().velocity = Vector3::new(0.0, 1.0, 0.0);
    let s = solve(&p);
    let steps = build(&p, &s, &names("cube", Some("floor")));
    for id in [
        StageId::Impulse,
        StageId::ApplyImpulse,
        StageId::FrictionClamp,
    ] {
        assert!(step(&steps, id)
            .skipped
            .as_deref()
            .is_some_and(|w| w.starts_with("the contact is separating")));
    }
}

#[test]
fn the_checks_stage_names_what_physics_measured() {
    let p = cube_on_floor();
    let s = solve(&p);
    let steps = build(&p, &s, &names("cube", Some("floor")));
    let checks = step(&steps, StageId::Checks);
    let names: Vec<&str> = checks.values.iter().map(|(n, _)| n.as_ref()).collect();
    assert_eq!(
        names,
        [
            "angular_momentum_error1",
            "separating_velocity_before",
            "separating_velocity",
            "separating_velocity_expected",
            "energy_before",
            "energy_after",
            "energy_change",
        ]
    );
    let Measured::Energy { before, after, .. } = s.checks.items[2].measured else {
        panic!("{:?}", s.checks.items[2]);
    };
    assert_eq!(scalar(checks, "energy_before"), before);
    assert_eq!(scalar(checks, "energy_after"), after);
    // The restitution target: -c v_s = 0.8 × 1.25 after the impulse.
    assert!((scalar(checks, "separating_velocity") - 1.0).abs() < 1e-9);
}

#[test]
fn verdicts_name_the_bodies_and_point_at_check_values() {
    let p = two_bodies();
    let s = solve(&p);
    let n = names("cube", Some("ball"));
    let c = SolvedContact::new(&p, &s, &n);
    let verdicts = verdicts(&c);
    assert_eq!(verdicts.len(), s.checks.items.len());
    let labels: Vec<&str> = verdicts.iter().map(|v| v.label.as_str()).collect();
    assert!(labels.contains(&"angular momentum of ball about q conserved"));
    assert!(labels.contains(&"cube's orientation is a unit quaternion"));
    let checks = checks(&c);
    for v in &verdicts {
        let wanted = v
            .detail
            .split('{')
            .skip(1)
            .map(|s| s.split('}').next().unwrap());
        for name in wanted {
            assert!(checks.value(name).is_some(), "{} needs {name}", v.label);
        }
    }
}

#[test]
fn two_bodies_slide_separate_and_turn() {
    let p = two_bodies();
    let s = solve(&p);
    assert_eq!(s.regime(), Some(FrictionRegime::Dynamic));
    let steps = build(&p, &s, &names("cube", Some("ball")));
    let friction = step(&steps, StageId::FrictionClamp);
    assert_eq!(friction.value("regime"), Some(&Value::from("dynamic")));
    assert_eq!(friction.value("model"), Some(&Value::from("millington")));
    let applied = step(&steps, StageId::ApplyImpulse);
    assert!(applied
        .notes
        .iter()
        .any(|n| n.starts_with("Both bodies receive the same impulse")));
    let g = s.final_impulse_world().unwrap();
    assert_eq!(vector(applied, "impulse1"), <[f64; 3]>::from(g));
    assert_eq!(vector(applied, "impulse2"), <[f64; 3]>::from(-g));
    let projection = step(&steps, StageId::NonlinearProjection);
    let moved = s.projection.as_ref().unwrap().bodies[1].as_ref().unwrap();
    assert_eq!(
        vector(projection, "position2"),
        <[f64; 3]>::from(moved.position)
    );
    let orientation = step(&steps, StageId::OrientationUpdate);
    assert!(orientation.skipped.is_none());
    assert!(orientation.value("orientation1").is_some());
    assert!(orientation.value("orientation2").is_some());
    // The arm (1, -1, 0) and d̂ = y turn body 1 about z.
    assert_eq!(
        orientation.value("rotation_world_axis1"),
        Some(&Value::from("z"))
    );
}

#[test]
fn what_the_scene_wrote_is_noted() {
    let p = cube_on_floor();
    let s = solve(&p);
    let mut n = names("cube", Some("floor"));
    n.written.normal_length = 1.0001;
    n.written.shape_inertia[0] = Some(Matrix3::from_diagonal_element(240.0));
    let steps = build(&p, &s, &n);
    let frame = step(&steps, StageId::ContactFrame);
    match frame.lookup("normal_length_deviation") {
        Some(Value::Scalar(x)) => assert!((x - 1e-4).abs() < 1e-12),
        other => panic!("{other:?}"),
    }
    assert!(frame
        .notes
        .iter()
        .any(|n| n.starts_with("The normal as written")));
    assert!(step(&steps, StageId::UnitImpulse)
        .value("shape_inertia1")
        .is_some());
    // Nothing written: nothing noted.
    let plain = build(&p, &s, &names("cube", Some("floor")));
    assert!(step(&plain, StageId::ContactFrame)
        .lookup("normal_length_deviation")
        .is_none());
    assert!(step(&plain, StageId::UnitImpulse)
        .value("shape_inertia1")
        .is_none());
}
