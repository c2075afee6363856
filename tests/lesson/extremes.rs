//! The extremes suite: every extreme lesson gives finite results whose
//! invariants hold within the checks' tolerance (10⁴ ε of the size of the
//! terms each check adds: ~100 roundings of ε each, with a factor 100 to
//! spare, while a real error is O(1)), or a clear diagnostic.

use crate::common;

use contact_lab::format::Fmt;
use contact_lab::lesson::Lesson;
use contact_lab::render;
use contact_lab::trace::{Trace, Value};

fn extremes() -> Vec<Lesson> {
    common::all_lessons()
        .into_iter()
        .filter(|l| l.id.starts_with("extreme-"))
        .collect()
}

fn traces(id: &str) -> Vec<Trace> {
    let l = Lesson::load(id).unwrap();
    (0..l.contacts.len())
        .map(|k| contact_lab::worked_solution(&l, k))
        .collect()
}

#[test]
fn the_suite_covers_what_the_issue_lists() {
    let ids: Vec<String> = extremes().into_iter().map(|l| l.id).collect();
    for id in [
        "extreme-mass-ratio",
        "extreme-far-from-origin",
        "extreme-velocities",
        "extreme-penetrations",
        "extreme-normals",
        "extreme-inertia",
    ] {
        assert!(ids.iter().any(|i| i == id), "{id} missing");
    }
}

#[test]
fn no_nan_or_inf_is_ever_printed_and_every_check_holds() {
    for lesson in extremes() {
        for k in 0..lesson.contacts.len() {
            let t = contact_lab::worked_solution(&lesson, k);
            let text = render::contact::text::render(&t, &Fmt::default());
            let json = render::contact::json::render(&t);
            for bad in ["NaN", "inf"] {
                assert!(!text.contains(bad), "{} #{k}: text shows {bad}", lesson.id);
            }
            // JSON writes a non-finite number as null; the only nulls allowed are "skipped": null.
            assert_eq!(
                json.matches("null").count(),
                json.matches("\"skipped\": null").count(),
                "{} #{k}",
                lesson.id
            );
            for v in &t.verdicts {
                assert_ne!(
                    v.passed,
                    Some(false),
                    "{} #{k}: {} failed",
                    lesson.id,
                    v.label
                );
            }
        }
    }
}

#[test]
fn a_near_singular_friction_matrix_is_diagnosed() {
    let t = &traces("extreme-inertia")[1];
    let impulse = t.stage("impulse").unwrap();
    let kappa = match impulse.value("condition_number") {
        Some(Value::Scalar(k)) => *k,
        other => panic!("{other:?}"),
    };
    assert!(kappa > 1e14, "κ = {kappa}");
    assert!(impulse
        .notes
        .iter()
        .any(|n| n.starts_with("ILL-CONDITIONED")));
    // The well-conditioned lecture cube has no such note.
    let cube = &traces("friction-cube")[0];
    assert!(!cube
        .stage("impulse")
        .unwrap()
        .notes
        .iter()
        .any(|n| n.contains("ILL-CONDITIONED")));
}

#[test]
fn an_ill_conditioned_inertia_tensor_is_warned_about() {
    let l = Lesson::load("extreme-inertia").unwrap();
    assert!(
        l.warnings
            .iter()
            .any(|w| w.message.contains("condition number is 1e12")),
        "{:?}",
        l.warnings
    );
}

#[test]
fn far_from_the_origin_the_digits_left_are_stated_and_the_answer_kept() {
    let far = &traces("extreme-far-from-origin")[0];
    let near = &traces("lecture-2")[0];
    let frame = far.stage("contact_frame").unwrap();
    assert!(frame.notes.iter().any(|n| n.contains("significant digits")));
    assert_eq!(frame.lookup("r1_digits"), Some(&Value::Scalar(8.0)));
    assert!(near
        .stage("contact_frame")
        .unwrap()
        .lookup("r1_digits")
        .is_none());
    let g = |t: &Trace| t.value("impulse", "impulse_world").unwrap().numbers()[1];
    assert!(
        (g(far) - g(near)).abs() <= 1e-7 * g(near),
        "{} vs {}",
        g(far),
        g(near)
    );
}

#[test]
fn every_normal_gets_an_orthonormal_right_handed_basis() {
    for t in traces("extreme-normals") {
        let Some(Value::Matrix(c)) = t.value("contact_frame", "contact_to_world") else {
            panic!()
        };
        let m = nalgebra::Matrix3::from_fn(|r, col| c[r][col]);
        assert!(
            (m.transpose() * m - nalgebra::Matrix3::identity()).norm() < 1e-14,
            "{}",
            t.contact_label
        );
        assert!((m.determinant() - 1.0).abs() < 1e-14, "{}", t.contact_label);
        assert!(
            t.stage("impulse").unwrap().skipped.is_none(),
            "{}: every box strikes",
            t.contact_label
        );
    }
}

#[test]
fn tiny_and_huge_velocities_scale_exactly() {
    let t = traces("extreme-velocities");
    let g = |t: &Trace| {
        t.value("friction_clamp", "impulse_world")
            .unwrap()
            .numbers()
    };
    let (slow, fast) = (g(&t[0]), g(&t[1]));
    for i in 0..3 {
        assert!(
            (slow[i] * 1e20 - fast[i]).abs() <= 1e-12 * fast[i].abs().max(1.0),
            "{slow:?} {fast:?}"
        );
    }
}

#[test]
fn tiny_and_huge_penetrations_resolve() {
    let t = traces("extreme-penetrations");
    let depth = |t: &Trace| t.value("checks", "depth_to_resolve").unwrap().numbers()[0];
    let residual = |t: &Trace| t.value("checks", "residual_penetration").unwrap().numbers()[0];
    assert!(residual(&t[0]).abs() <= 1e-2 * depth(&t[0]));
    assert!(residual(&t[1]).abs() <= 1e-2 * depth(&t[1]));
    assert!(t[1]
        .stage("nonlinear_projection")
        .unwrap()
        .notes
        .iter()
        .any(|n| n.contains("Excessive rotation")));
}

#[test]
fn huge_mass_ratios_conserve_momentum() {
    for t in traces("extreme-mass-ratio") {
        let e = t
            .value("checks", "linear_momentum_error")
            .unwrap()
            .numbers()[0];
        assert!(e == 0.0 || e < 1e-3, "{}: {e}", t.contact_label);
        assert!(t.verdicts.iter().all(|v| v.passed != Some(false)));
    }
}
