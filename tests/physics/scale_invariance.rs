//! Results do not depend on the units (issue 17, item 2): every lesson, and
//! random scenes, scaled by 10^k — velocities, lengths or masses — take the
//! same regimes (stick or slide, separating, restitution limited, angular
//! move limited, friction issues) and the same verdicts, wherever the scaled
//! lesson is still within contact-lab's accepted range (1e-60 to 1e60).

use crate::common;

use contact_lab::lesson::validate::rules;
use contact_lab::lesson::Lesson;
use contact_lab::physics::checks::CheckKind;
use contact_lab::physics::solve;
use proptest::prelude::*;

/// What a lesson is scaled by.
#[derive(Debug, Clone, Copy)]
enum Units {
    /// Velocities, angular velocities, accelerations (time is kept).
    Velocity,
    /// Lengths; velocities with them (so ω is kept), inertia with their square.
    Length,
    /// Masses and inertia.
    Mass,
}

fn scaled(lesson: &Lesson, units: Units, s: f64) -> Lesson {
    let mut l = lesson.clone();
    let (v, len, m) = match units {
        Units::Velocity => (s, 1.0, 1.0),
        Units::Length => (s, s, 1.0),
        Units::Mass => (1.0, 1.0, s),
    };
    // ω = v / length.
    let w = v / len;
    for b in &mut l.bodies {
        b.mass *= m;
        b.inertia = b.inertia.map(|t| t * m * len * len);
        b.shape_inertia = b.shape_inertia.map(|t| t * m * len * len);
        b.position *= len;
        b.velocity *= v;
        b.angular_velocity *= w;
        b.acceleration *= v;
    }
    for c in &mut l.contacts {
        c.point *= len;
        c.penetration *= len;
        c.settings.velocity_limit *= v;
    }
    l
}

/// Every number of the scaled lesson is one contact-lab accepts.
fn accepted(l: &Lesson) -> bool {
    let ok = |x: f64| rules::in_range(x);
    l.bodies.iter().all(|b| {
        (!b.movable() || (ok(b.mass) && ok(1.0 / b.mass)))
            && b.inertia
                .is_none_or(|t| t.iter().all(|x| ok(*x)) && rules::inertia(&t).is_ok())
            && [b.position, b.velocity, b.angular_velocity, b.acceleration]
                .iter()
                .all(|v| v.iter().all(|x| ok(*x)))
    }) && l.contacts.iter().all(|c| {
        c.point.iter().all(|x| ok(*x)) && ok(c.penetration) && ok(c.settings.velocity_limit)
    })
}

/// The regimes and verdicts of contact `k`: everything that must not change with the units.
fn signature(l: &Lesson, k: usize) -> Vec<String> {
    let s = solve(&l.problem::<f64>(k));
    let mut out = vec![
        format!("closing {}", s.impulse.is_some()),
        format!("restitution limited {}", s.desired.restitution_limited),
    ];
    if let Some(f) = &s.friction {
        out.push(format!("friction {:?} {:?}", f.regime, f.issue));
    }
    if let Some(g) = s.impulse.as_ref().and_then(|g| g.solve.as_ref()) {
        out.push(format!("singular {}", g.singular));
    }
    if let Some(p) = &s.projection {
        for b in p.bodies.iter().flatten() {
            // A normal through the centre leaves an angular share of order
            // ε², whose limit is round-off too: not a regime.
            if b.angular_inertia > 1e-12 * b.linear_inertia {
                out.push(format!("angular move limited {}", b.limited));
            } else {
                out.push("angular share round-off".into());
            }
        }
    }
    // A body turns when its rotation is more than round-off: a normal
    // through the centre (r × d̂ ≈ 0, e.g. sphere-row) leaves an angular share
    // of order ε whose presence depends on how r rounds, not on the units.
    let turning: Vec<usize> = s
        .orientation
        .iter()
        .flat_map(|o| o.bodies.iter().enumerate())
        .filter(|(_, b)| {
            b.as_ref()
                .is_some_and(|b| b.turn().rotation_vector_degrees > 1e-9)
        })
        .map(|(i, _)| i)
        .collect();
    out.push(format!("turns {:?}", turning));
    for item in &s.checks.items {
        if let CheckKind::UnitQuaternion(i) = item.kind() {
            if !turning.contains(&i) {
                continue;
            }
        }
        out.push(format!("{:?} {:?}", item.kind(), item.passed));
    }
    out
}

/// Scales `lesson` by 10^e for every even e in −58..=58 that keeps it in
/// range; returns how many scalings were tried.
fn assert_invariant(lesson: &Lesson, units: Units) -> usize {
    let mut tried = 0;
    for k in 0..lesson.contacts.len() {
        let base = signature(lesson, k);
        for e in (-58..=58).step_by(2) {
            let l = scaled(lesson, units, 10f64.powi(e));
            if !accepted(&l) {
                continue;
            }
            tried += 1;
            assert_eq!(
                signature(&l, k),
                base,
                "{} contact {k}, {units:?} × 1e{e}",
                lesson.id
            );
        }
    }
    tried
}

#[test]
fn every_lesson_takes_the_same_regimes_and_verdicts_in_any_units() {
    for lesson in common::all_lessons() {
        for units in [Units::Velocity, Units::Length, Units::Mass] {
            let tried = assert_invariant(&lesson, units);
            assert!(
                tried >= 10 * lesson.contacts.len(),
                "{} {units:?}: only {tried} scalings were in range",
                lesson.id
            );
        }
    }
}

/// Small-speed sliding: the friction cube's sliding contact at 1e-58 of its
/// speed, with a 1e-40 kg cube whose 1e-20 lengths make M ~ 1e60 — the
/// impulse (~1e-120) squared underflowed, so `√(g_y² + g_z²)` was 0 and the
/// contact was called sticking.
#[test]
fn a_sliding_contact_slides_at_tiny_impulses() {
    let lesson = Lesson::load("friction-cube").unwrap();
    let base = signature(&lesson, 1);
    assert!(
        base.contains(&"friction Dynamic None".to_string()),
        "{base:?}"
    );
    let l = scaled(&lesson, Units::Velocity, 1e-58);
    let l = scaled(&l, Units::Mass, 1e-41);
    assert!(accepted(&l));
    assert_eq!(signature(&l, 1), base);
}

/// The stages themselves decide on scaled norms, beyond the range a lesson
/// may hold: the friction cube's sliding contact with its velocities scaled
/// by 1e-170 still slides (√(g_y² + g_z²) underflowed to 0 and called it
/// sticking), and its checks say the same — all but the energy, whose
/// 1e-340 joules f64 cannot hold.
#[test]
fn the_stages_decide_regimes_on_scaled_norms_beyond_the_lesson_range() {
    let l = Lesson::load("friction-cube").unwrap();
    let base = solve(&l.problem::<f64>(1));
    let verdicts = |s: &contact_lab::physics::Solution<f64>| -> Vec<String> {
        s.checks
            .items
            .iter()
            .filter(|i| i.kind() != contact_lab::physics::checks::CheckKind::Energy)
            .map(|i| format!("{:?} {:?}", i.kind(), i.passed))
            .collect()
    };
    for e in [-200, -170, -160, 100, 150] {
        let mut p = l.problem::<f64>(1);
        for b in p.bodies.iter_mut().flatten() {
            b.velocity *= 10f64.powi(e);
            b.angular_velocity *= 10f64.powi(e);
        }
        let s = solve(&p);
        let f = s.friction.as_ref().unwrap();
        assert_eq!(f.regime, base.friction.as_ref().unwrap().regime, "1e{e}");
        assert_eq!(verdicts(&s), verdicts(&base), "1e{e}");
    }
}

/// A normal or an orientation is a direction: a length of 1e-170 (whose
/// square underflowed, so it was called "zero") or 1e60 is normalised with a
/// warning in scientific notation, and solves exactly like the unit one.
#[test]
fn directions_of_any_length_are_normalised_not_called_zero() {
    let lesson = |normal: &str, orientation: &str| {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/lessons/lecture-2.toml"
        ))
        .unwrap()
        .replace("normal = [0.0, 1.0, 0.0]", &format!("normal = {normal}"))
        .replace(
            "orientation = [0.9659258262890683, 0.0, 0.0, -0.25881904510252074]",
            &format!("orientation = {orientation}"),
        );
        contact_lab::lesson::validate::parse("scaled.toml", &text)
    };
    let unit = lesson("[0.0, 1.0, 0.0]", "[1.0, 0.0, 0.0, 0.0]").unwrap();
    for (normal, orientation, shown) in [
        ("[0.0, 1e-170, 0.0]", "[1e-170, 0.0, 0.0, 0.0]", "1e-170"),
        ("[0.0, 1e60, 0.0]", "[1e60, 0.0, 0.0, 0.0]", "1e60"),
    ] {
        let l = lesson(normal, orientation).unwrap_or_else(|e| panic!("{normal}: {e}"));
        let warnings: Vec<String> = l.warnings.iter().map(|w| w.to_string()).collect();
        assert!(
            warnings
                .iter()
                .any(|w| w.contains(&format!("contact normal has length {shown};"))),
            "{warnings:?}"
        );
        assert!(
            warnings
                .iter()
                .any(|w| w.contains(&format!("orientation has length {shown};"))),
            "{warnings:?}"
        );
        assert_eq!(l.contacts[0].normal, unit.contacts[0].normal);
        assert_eq!(signature(&l, 0), signature(&unit, 0));
    }
}

/// A scene's half-space normal is a direction too: 1e-170 and 1e60 long it
/// is normalised (not refused as zero), its tiny components set to 0.
#[test]
fn a_half_space_normal_of_any_length_is_normalised() {
    let scene = |normal: &str| {
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/lessons/scenes/ball-drop.toml"
        ))
        .unwrap()
        .replace("normal = [0, 1, 0]", &format!("normal = {normal}"));
        contact_lab::lesson::validate::parse("scene.toml", &text)
            .unwrap_or_else(|e| panic!("{normal}: {e}"))
    };
    let floor = |l: &Lesson| match l.bodies[1].shape.clone() {
        Some(contact_lab::physics::Shape::HalfSpace { normal }) => normal,
        other => panic!("{other:?}"),
    };
    let unit = floor(&scene("[0, 1, 0]"));
    assert_eq!(unit, [0.0, 1.0, 0.0]);
    for normal in ["[0, 1e-170, 0]", "[0, 1e60, 0]", "[1e-70, 1e-170, 0]"] {
        let n = floor(&scene(normal));
        let expected = if normal.starts_with("[1e-70") {
            [1.0, 0.0, 0.0]
        } else {
            unit
        };
        assert_eq!(n, expected, "{normal}");
    }
}

mod random {
    use super::*;
    use contact_lab::lesson::validate;

    /// A one-body lesson with friction, from a few drawn numbers.
    fn lesson(
        (vx, vy, wz): (f64, f64, f64),
        (px, py): (f64, f64),
        (mu, c, pen): (f64, f64, f64),
        model: &str,
    ) -> Lesson {
        let text = format!(
            r#"id = "random"
title = "random"
[[body]]
name = "box"
mass = 2.0
shape = {{ box = [1.0, 2.0, 1.5] }}
orientation = [0.9, 0.1, -0.2, 0.3]
position = [{px}, {py}, 0.1]
velocity = [{vx}, {vy}, 0.3]
angular_velocity = [0.2, -0.4, {wz}]
[[contact]]
bodies = ["box"]
point = [0.0, 0.0, 0.0]
normal = [0.1, 1.0, -0.05]
restitution = {c}
friction = {mu}
friction_model = "{model}"
penetration = {pen}
"#
        );
        validate::parse("random.toml", &text).expect("the random lesson is valid")
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

        #[test]
        fn random_scenes_take_the_same_regimes_and_verdicts_in_any_units(
            v in (-3.0..3.0f64, -3.0..-0.1f64, -2.0..2.0f64),
            p in (-1.0..1.0f64, 0.2..2.0f64),
            coeffs in (0.0..1.2f64, 0.0..1.0f64, 0.0..0.3f64),
            model in prop::sample::select(vec!["millington", "kinetic-direction", "velocity-scaling"]),
            units in prop::sample::select(vec![Units::Velocity, Units::Length, Units::Mass]),
            e in -55..55i32,
        ) {
            let base = lesson(v, p, coeffs, model);
            let l = scaled(&base, units, 10f64.powi(e));
            prop_assume!(accepted(&l));
            prop_assert_eq!(signature(&l, 0), signature(&base, 0), "{:?} × 1e{}", units, e);
        }
    }
}
