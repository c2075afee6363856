//! No verdict's label contradicts its numbers (issue 16, item 5): over every
//! check of every lesson contact, under every friction model, and over
//! random scenes, a label that says "rose" goes with numbers that rise, one
//! that says "inside the friction cone" with |g_planar| ≤ μ g_n, and so on.
//! The old label "slip speed does not rise" printed beside 1.99995 → 2.04599
//! is what this test forbids.

use crate::common;
use contact_lab::knobs::Choice;

use contact_lab::lesson::{Lesson, Overrides};
use contact_lab::physics::{solve, FrictionModel, RigidBody};
use contact_lab::trace::contact::{verdicts, ContactNames, SolvedContact};
use contact_lab::trace::{Step, Trace, Value, Verdict};
use proptest::prelude::*;

fn num(checks: &Step, name: &str) -> f64 {
    match checks.value(name) {
        Some(Value::Scalar(x)) => *x,
        other => panic!("checks value {name}: {other:?}"),
    }
}

/// `Err` with the reason when the label says something the values deny.
fn consistent(v: &Verdict, checks: &Step) -> Result<(), String> {
    let l = v.label.as_str();
    let failed = v.passed == Some(false);
    let err = |why: &str| Err(format!("«{}» ({:?}): {why}", l, v.passed));
    if l.contains("does not") || l.contains("doesn't") {
        return err("a label states what happened, not what should have");
    }
    let trend = |before: &str, after: &str| -> Result<(), String> {
        let (b, a) = (num(checks, before), num(checks, after));
        let ok = if l.ends_with("rose") {
            a > b
        } else if l.ends_with("fell") {
            a < b
        } else if l.ends_with("stayed the same") {
            a == b
        } else {
            false
        };
        if ok {
            Ok(())
        } else {
            Err(format!("«{l}» beside {b} → {a}"))
        }
    };
    if l.starts_with("kinetic energy") {
        trend("energy_before", "energy_after")?;
    } else if l.starts_with("slip speed") {
        trend("slip_speed_before", "slip_speed_after")?;
    } else if l.contains("friction cone") {
        let (t, lim) = (num(checks, "tangential_impulse"), num(checks, "cone_limit"));
        let inside = t <= lim;
        if l.contains("inside") != inside {
            return err(&format!("|g_planar| = {t}, μ g_n = {lim}"));
        }
        if v.detail.contains('≤') != inside || v.detail.contains('>') == inside {
            return err(&format!("detail {} for {t} vs {lim}", v.detail));
        }
        if l.contains("outside the friction cone") != failed {
            return err("outside the cone must be ✗ and only then");
        }
    } else if l.contains("target") {
        if l.contains("meets") == failed || l.contains("misses") != failed {
            return err("meets/misses against the verdict");
        }
    } else if l.contains("momentum") {
        if l.ends_with("conserved") == failed || l.ends_with("changed") != failed {
            return err("conserved/changed against the verdict");
        }
    } else if l.contains("unit quaternion") {
        if l.contains("is not") != failed {
            return err("is/is not against the verdict");
        }
    } else if !l.starts_with("penetration left") {
        return err("a label this test does not know: teach it");
    }
    Ok(())
}

fn all_consistent(t: &Trace) -> Result<(), String> {
    let Some(checks) = t.stage("checks") else {
        return Ok(());
    };
    t.verdicts.iter().try_for_each(|v| consistent(v, checks))
}

#[test]
fn no_label_contradicts_its_numbers_in_any_lesson_or_model() {
    let mut seen = 0;
    for id in contact_lab::lesson::embedded::ids() {
        for model in FrictionModel::ALL {
            let mut l = Lesson::load(id).unwrap();
            l.apply(&Overrides::from_pairs(&[("friction_model", model.name())]).unwrap());
            for k in 0..l.contacts.len() {
                let t = contact_lab::worked_solution(&l, k);
                seen += t.verdicts.len();
                if let Err(e) = all_consistent(&t) {
                    panic!("{id} #{k} ({}): {e}", model.name());
                }
            }
        }
    }
    assert!(seen > 100, "only {seen} verdicts looked at");
}

#[test]
fn a_rising_slip_is_labelled_as_rising() {
    // friction-cube's sliding contact under seed 004's model: slip rises.
    let mut found = false;
    for id in contact_lab::lesson::embedded::ids() {
        for model in FrictionModel::ALL {
            let mut l = Lesson::load(id).unwrap();
            l.apply(&Overrides::from_pairs(&[("friction_model", model.name())]).unwrap());
            for k in 0..l.contacts.len() {
                let t = contact_lab::worked_solution(&l, k);
                if t.verdicts.iter().any(|v| v.label == "slip speed rose") {
                    found = true;
                }
            }
        }
    }
    assert!(
        found,
        "no lesson shows a rising slip: the label is untested"
    );
}

#[test]
fn the_checker_catches_a_contradiction() {
    let l = Lesson::load("lecture-2").unwrap();
    let t = contact_lab::worked_solution(&l, 0);
    let checks = t.stage("checks").unwrap();
    let bad = Verdict {
        label: "kinetic energy rose".into(),
        passed: Some(true),
        detail: String::new(),
    };
    assert!(
        consistent(&bad, checks).is_err(),
        "31.25 → 28.91 did not rise"
    );
    let old = Verdict {
        label: "kinetic energy does not rise".into(),
        passed: Some(true),
        detail: String::new(),
    };
    assert!(consistent(&old, checks).is_err());
}

fn body() -> impl Strategy<Value = RigidBody<f64>> {
    common::random::body(-2.0..6.0, -3.0..3.0, 20.0)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 500, ..ProptestConfig::default() })]

    #[test]
    fn in_random_scenes_no_label_contradicts_its_numbers(
        b1 in body(),
        b2 in prop::option::of(body()),
        c in 0.0..1.0f64,
        mu in (0.0..1.5f64, 0.0..1.0f64),
        model in prop::sample::select(FrictionModel::ALL.to_vec()),
        penetration in prop::sample::select(vec![0.0, 0.01, 0.5]),
    ) {
        let p = common::random::floor_problem(b1, b2.clone(), c, mu, model, penetration, 0.01);
        let s = solve(&p);
        let names = ContactNames {
            bodies: [Some("a".into()), b2.map(|_| "b".into())],
            label: "0: a ↔ b".into(),
            ..ContactNames::default()
        };
        let solved = SolvedContact::new(&p, &s, &names);
        let checks = contact_lab::trace::contact::checks(&solved);
        for v in verdicts(&solved) {
            if let Err(e) = consistent(&v, &checks) {
                prop_assert!(false, "{}", e);
            }
        }
    }
}
