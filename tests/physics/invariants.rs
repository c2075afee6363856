//! Physics checked against invariants on the lessons, not only snapshots.

use crate::common;

use common::{scalar, text, vector};

use contact_lab::lesson::{embedded, Lesson};
use contact_lab::trace::{Trace, Value};

fn trace(id: &str, k: usize) -> Trace {
    contact_lab::worked_solution(&Lesson::load(id).unwrap(), k)
}

#[test]
fn every_lesson_file_is_embedded_and_named_for_its_id() {
    fn toml_files(dir: &std::path::Path, prefix: &str, out: &mut Vec<String>) {
        for entry in std::fs::read_dir(dir).unwrap().flatten() {
            let name = entry.file_name().into_string().unwrap();
            if entry.path().is_dir() && name != "scenes" {
                toml_files(&entry.path(), &format!("{prefix}{name}/"), out);
            } else if name.ends_with(".toml") {
                out.push(format!("{prefix}{name}"));
            }
        }
    }
    let mut files = Vec::new();
    toml_files(
        std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/lessons")),
        "",
        &mut files,
    );
    files.sort();
    let mut embedded: Vec<String> = embedded::LESSONS
        .iter()
        .map(|(f, _)| f.to_string())
        .collect();
    embedded.sort();
    assert_eq!(
        files, embedded,
        "every lessons/*.toml must be listed in src/lesson/embedded.rs"
    );
    // Scenes live in lessons/scenes/ and in their own list.
    let mut scenes: Vec<String> =
        std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/lessons/scenes"))
            .unwrap()
            .flatten()
            .map(|e| format!("scenes/{}", e.file_name().into_string().unwrap()))
            .filter(|n| n.ends_with(".toml"))
            .collect();
    scenes.sort();
    let mut listed: Vec<String> = embedded::SCENES
        .iter()
        .map(|(f, _)| f.to_string())
        .collect();
    listed.sort();
    assert_eq!(
        scenes, listed,
        "every lessons/scenes/*.toml must be listed in SCENES"
    );
    for id in embedded::scene_ids() {
        assert_eq!(
            Lesson::load(id).unwrap().id,
            id,
            "file name of scene '{id}' must be its id"
        );
    }
    for lesson in common::all_lessons() {
        assert!(
            embedded::find(&lesson.id).is_some(),
            "file name of '{}' must be its id",
            lesson.id
        );
    }
}

#[test]
fn every_check_of_every_lesson_passes() {
    for lesson in common::all_lessons() {
        for k in 0..lesson.contacts.len() {
            let t = contact_lab::worked_solution(&lesson, k);
            for v in &t.verdicts {
                // Kane's example exists to show the energy check failing.
                let expected =
                    lesson.id == "kane-energy-gain" && v.label.starts_with("kinetic energy");
                assert_eq!(
                    v.passed == Some(false),
                    expected,
                    "{} contact {k}: {}",
                    lesson.id,
                    v.label
                );
            }
        }
    }
}

#[test]
fn sticking_leaves_no_tangential_contact_velocity() {
    for (id, k) in [("friction-cube", 0), ("spinning-ball", 0)] {
        let t = trace(id, k);
        assert_eq!(text(&t, "friction_clamp", "regime"), "static", "{id} {k}");
        let before = scalar(&t, "checks", "slip_speed_before");
        let after = scalar(&t, "checks", "slip_speed_after");
        assert!(before > 1.0, "{id}: the contact slid before ({before})");
        assert!(after <= 1e-12 * before, "{id}: slip after sticking {after}");
    }
}

#[test]
fn sliding_meets_the_normal_target_and_sits_on_the_cone() {
    for (id, k, mu_d) in [("friction-cube", 1, 0.25), ("spinning-ball", 1, 0.5)] {
        let t = trace(id, k);
        assert_eq!(text(&t, "friction_clamp", "regime"), "dynamic", "{id} {k}");
        let vs = scalar(&t, "desired_delta_velocity", "separating_velocity");
        let c = scalar(&t, "desired_delta_velocity", "restitution");
        let after = scalar(&t, "checks", "separating_velocity");
        assert!(
            (after - (-c * vs)).abs() <= 1e-12 * vs.abs(),
            "{id}: {after} vs {}",
            -c * vs
        );
        let g = vector(&t, "friction_clamp", "impulse_contact");
        let gt = (g[1] * g[1] + g[2] * g[2]).sqrt();
        assert!(
            (gt - mu_d * g[0]).abs() <= 1e-12 * g[0],
            "{id}: |g_t| = {gt}, μ_d g_n = {}",
            mu_d * g[0]
        );
    }
}

#[test]
fn friction_changes_the_normal_impulse_of_the_lecture_cube() {
    let frictionless = trace("lecture-2", 0);
    let sticks = trace("friction-cube", 0);
    let slides = trace("friction-cube", 1);
    let gn = |t: &Trace, s: &str| vector(t, s, "impulse_contact")[0];
    assert!((gn(&frictionless, "impulse") - 18.7337).abs() < 2e-4);
    assert!(gn(&sticks, "friction_clamp") > gn(&slides, "friction_clamp"));
    assert!(gn(&slides, "friction_clamp") > gn(&frictionless, "impulse"));
}

#[test]
fn projection_moves_sum_to_the_resolved_depth() {
    for lesson in common::all_lessons() {
        for k in 0..lesson.contacts.len() {
            let t = contact_lab::worked_solution(&lesson, k);
            let Some(p) = t
                .stage("nonlinear_projection")
                .filter(|s| s.skipped.is_none())
            else {
                continue;
            };
            let depth = scalar(&t, "nonlinear_projection", "resolved_depth");
            let mut sum = 0.0;
            for n in 1..=2 {
                if p.value(&format!("linear_move{n}")).is_some() {
                    let sign = if n == 1 { 1.0 } else { -1.0 };
                    sum += sign
                        * (scalar(&t, "nonlinear_projection", &format!("linear_move{n}"))
                            + scalar(&t, "nonlinear_projection", &format!("angular_move{n}")));
                    let limit = match t.value("nonlinear_projection", &format!("angular_limit{n}"))
                    {
                        Some(Value::Scalar(x)) => *x,
                        _ => f64::INFINITY,
                    };
                    let angular = scalar(&t, "nonlinear_projection", &format!("angular_move{n}"));
                    assert!(
                        angular.abs() <= limit * (1.0 + 1e-15),
                        "{} {k}: limit exceeded",
                        lesson.id
                    );
                }
            }
            assert!(
                (sum - depth).abs() <= 1e-14 * depth,
                "{} {k}: moves {sum} vs depth {depth}",
                lesson.id
            );
        }
    }
}

#[test]
fn the_angular_limit_moves_the_excess_to_the_linear_share() {
    let limited = trace("excessive-rotation", 0);
    let unlimited = trace("excessive-rotation", 1);
    let p = "nonlinear_projection";
    assert!((scalar(&limited, p, "angular_move1") - 0.4).abs() < 1e-12);
    let free = scalar(&unlimited, p, "angular_move1");
    assert!(free > 0.59 && free < 0.61, "{free}");
    let excess = free - 0.4;
    assert!(
        (scalar(&limited, p, "linear_move1") - (scalar(&unlimited, p, "linear_move1") + excess))
            .abs()
            < 1e-12
    );
    assert!(limited
        .stage(p)
        .unwrap()
        .notes
        .iter()
        .any(|n| n.contains("Excessive rotation")));
    // The unlimited turn is larger, and its linearised estimate is further off.
    let r_lim = scalar(&limited, "checks", "residual_penetration").abs();
    let r_free = scalar(&unlimited, "checks", "residual_penetration").abs();
    assert!(r_free > r_lim, "{r_free} vs {r_lim}");
}

#[test]
fn both_bodies_rotate_in_the_two_box_lesson() {
    let t = trace("two-boxes", 0);
    for n in 1..=2 {
        let dw = vector(&t, "apply_impulse", &format!("dw{n}"));
        assert!(dw[2].abs() > 0.1, "body {n} spins: {dw:?}");
        assert!(
            t.value("orientation_update", &format!("orientation{n}"))
                .is_some(),
            "body {n} turns"
        );
    }
    let dw1 = vector(&t, "apply_impulse", "dw1")[2];
    let dw2 = vector(&t, "apply_impulse", "dw2")[2];
    assert!(dw1 * dw2 < 0.0, "opposite senses: {dw1} {dw2}");
}

#[test]
fn kanes_example_gains_energy_and_says_so_loudly() {
    let t = trace("kane-energy-gain", 0);
    let (before, after) = (
        scalar(&t, "checks", "energy_before"),
        scalar(&t, "checks", "energy_after"),
    );
    assert!(after > 1.2 * before, "{before} → {after}");
    assert_eq!(text(&t, "friction_clamp", "regime"), "static");
    let notes = &t.stage("checks").unwrap().notes;
    assert!(
        notes
            .iter()
            .any(|n| n.starts_with("ENERGY ROSE") && n.contains("Kane")),
        "{notes:?}"
    );
}
