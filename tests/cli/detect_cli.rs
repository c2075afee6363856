//! `contact-lab detect` through the binary: each detection lesson shows what
//! its summary says; the JSON's depth and normal are the contact the step
//! generates; `--pair`, `--step`, `--figure` and the human formats.

use assert_cmd::Command;
use contact_lab::lesson::Lesson;
use contact_lab::physics::collide::{ContactGenerator, Options};
use serde_json::Value;

use crate::common;

fn run(args: &[&str]) -> std::process::Output {
    Command::cargo_bin("contact-lab")
        .unwrap()
        .arg("detect")
        .args(args)
        .output()
        .unwrap()
}

fn json(args: &[&str]) -> Value {
    let out = run(&[args, &["--format", "json"]].concat());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn v3(v: &Value) -> [f64; 3] {
    [0, 1, 2].map(|k| v[k].as_f64().unwrap())
}

fn near(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|k| (a[k] - b[k]).abs() <= tol)
}

#[test]
fn gjk_separated_gives_the_distance_and_the_closest_points() {
    let d = json(&["gjk-separated"]);
    assert_eq!(d["broad_phase"]["candidate_pairs"], 1);
    let p = &d["pairs"][0];
    let g = &p["gjk"];
    assert_eq!(g["result"], "separated");
    let expected = 0.5f64.sqrt() - 0.5;
    assert!(
        (g["distance"].as_f64().unwrap() - expected).abs() < 1e-12,
        "{g}"
    );
    let s = 0.5 + expected / 2f64.sqrt();
    assert!(near(v3(&g["closest"][0]), [s, s, 0.5], 1e-12), "{g}");
    assert!(near(v3(&g["closest"][1]), [0.5, 0.5, 0.5], 1e-12), "{g}");
    assert!(p["epa"].is_null());
    assert_eq!(p["contacts"].as_array().unwrap().len(), 0);
    // Every iteration has the contract's keys.
    for it in g["iterations"].as_array().unwrap() {
        for key in ["v", "direction", "support", "bound", "simplex"] {
            assert!(!it[key].is_null(), "{key}: {it}");
        }
    }
}

#[test]
fn gjk_touching_a_ball_on_a_hull_has_depth_zero_and_an_upward_normal() {
    let d = json(&["gjk-touching"]);
    let p = &d["pairs"][0];
    assert_eq!(
        (p["a"].as_str(), p["b"].as_str()),
        (Some("ball"), Some("prism"))
    );
    assert_eq!(p["gjk"]["result"], "intersecting");
    let e = &p["epa"];
    assert!(e["depth"].as_f64().unwrap().abs() < 1e-12, "{e}");
    assert!(near(v3(&e["normal"]), [0.0, 1.0, 0.0], 1e-12), "{e}");
    assert!(near(v3(&e["point"]), [0.1, 0.5, 0.05], 1e-12), "{e}");
    assert_eq!(e["feature"], "point-face");
    assert_eq!(e["source"], "margins");
}

#[test]
fn epa_edge_edge_gives_the_depth_normal_and_feature_pair() {
    let d = json(&["epa-edge-edge", "--narrow-phase", "gjk"]);
    let p = &d["pairs"][0];
    assert_eq!(p["method"], "gjk");
    let e = &p["epa"];
    assert!((e["depth"].as_f64().unwrap() - 0.05).abs() < 1e-9, "{e}");
    assert!(near(v3(&e["normal"]), [0.0, 1.0, 0.0], 1e-9), "{e}");
    assert_eq!(e["feature"], "edge-edge");
    assert!(!e["iterations"].as_array().unwrap().is_empty());
    for it in e["iterations"].as_array().unwrap() {
        for key in ["face", "distance", "support", "gap"] {
            assert!(!it[key].is_null(), "{key}: {it}");
        }
    }
}

#[test]
fn a_cylinder_on_a_box_has_its_rim_two_centimetres_into_the_top_face() {
    let d = json(&["cylinder-on-box"]);
    let p = &d["pairs"][0];
    assert_eq!(p["method"], "gjk");
    let e = &p["epa"];
    assert!((e["depth"].as_f64().unwrap() - 0.02).abs() < 1e-9, "{e}");
    assert!(near(v3(&e["normal"]), [0.0, 1.0, 0.0], 1e-9), "{e}");
    // A point of the rim in the box's face (the rim's points seen as a tiny edge).
    assert!(e["feature"].as_str().unwrap().ends_with("-face"), "{e}");
    assert!((v3(&e["point"])[1] - 0.49).abs() < 1e-9, "{e}");
}

#[test]
fn hull_stack_pairs_meet_face_to_face_and_each_rests_on_a_manifold() {
    let d = json(&["hull-stack"]);
    assert_eq!(d["broad_phase"]["bodies"], 4);
    // frustum–octagon are apart (their boxes do not meet along y).
    assert_eq!(d["broad_phase"]["pairs_ruled_out"], 1);
    let pairs = d["pairs"].as_array().unwrap();
    assert_eq!(pairs.len(), 5);
    for p in pairs {
        if p["b"] == "floor" && p["a"] != "frustum" {
            continue;
        }
        assert!(
            p["contacts"].as_array().unwrap().len() >= 4,
            "{}–{}",
            p["a"],
            p["b"]
        );
    }
    let d = json(&["hull-stack", "--pair", "hexagon,octagon"]);
    let p = &d["pairs"][0];
    assert_eq!(p["epa"]["feature"], "face-face");
}

/// The deepest contact the step generates for bodies `a`, `b` of a scene.
fn step_contact(id: &str, a: usize, b: usize, gjk: bool) -> (f64, [f64; 3]) {
    let lesson = Lesson::load(id).unwrap();
    let p = lesson.sim_params().unwrap();
    let world = lesson.world::<f64>();
    let options = Options {
        box_box: p.box_box,
        tolerance: p.contact_margin,
        narrow_phase: if gjk {
            contact_lab::physics::collide::NarrowPhase::Gjk
        } else {
            p.narrow_phase
        },
        broad_phase: p.broad_phase,
        internal_edges: p.internal_edges,
    };
    let mut out = vec![];
    ContactGenerator::new().generate_world(&world.bodies, &options, &mut out);
    let deepest = out
        .iter()
        .filter(|c| (c.body1.0, c.body2.0) == (a, b))
        .max_by(|x, y| x.contact.penetration.total_cmp(&y.contact.penetration))
        .expect("the step generates a contact for the pair");
    let n = deepest.contact.normal;
    (deepest.contact.penetration, [n.x, n.y, n.z])
}

#[test]
fn the_json_depth_and_normal_are_the_contact_the_step_generates() {
    for (id, gjk) in [
        ("epa-edge-edge", false),
        ("epa-edge-edge", true),
        ("cylinder-on-box", false),
    ] {
        let args: &[&str] = if gjk {
            &[id, "--narrow-phase", "gjk"]
        } else {
            &[id]
        };
        let d = json(args);
        let e = &d["pairs"][0]["epa"];
        let (depth, normal) = step_contact(id, 0, 1, gjk);
        // The step's deepest contact is the clipped faces' (a box's corner,
        // the cylinder rim's exact lowest point, the reference face's
        // normal): EPA's depth is within its stated tolerance of it, its
        // normal within 1e-9.
        let tolerance = e["tolerance"].as_f64().unwrap();
        assert!(
            (e["depth"].as_f64().unwrap() - depth).abs() <= tolerance.max(1e-12),
            "{id}: {e} vs {depth}"
        );
        assert!(
            near(v3(&e["normal"]), normal, 1e-9),
            "{id}: {e} vs {normal:?}"
        );
        // The contacts listed are the step's (to round-off: the command's
        // bodies come through the simulation, these from the lesson).
        let listed = d["pairs"][0]["contacts"].as_array().unwrap();
        let deepest = listed
            .iter()
            .map(|c| c["penetration"].as_f64().unwrap())
            .fold(f64::MIN, f64::max);
        assert!(
            (deepest - depth).abs() < 1e-12,
            "{id}: {deepest} vs {depth}"
        );
    }
}

#[test]
fn a_pair_asked_for_runs_even_when_the_broad_phase_rules_it_out() {
    let d = json(&["hull-stack", "--pair", "frustum,octagon"]);
    let p = &d["pairs"][0];
    assert!(
        p["ruled_out"].as_str().unwrap().contains("apart along y"),
        "{p}"
    );
    assert_eq!(p["gjk"]["result"], "separated");
    // The octagon's bottom (y = 0.8) is 0.4 above the frustum's top (y = 0.4).
    assert!((p["gjk"]["distance"].as_f64().unwrap() - 0.4).abs() < 1e-9);
}

#[test]
fn after_one_step_the_projection_has_lifted_the_cylinder_out() {
    let d = json(&["cylinder-on-box", "--step", "1"]);
    assert!((d["time"].as_f64().unwrap() - 1.0 / 60.0).abs() < 1e-12);
    let p = &d["pairs"][0];
    // Apart by under a millimetre, the contact kept within the tolerance.
    assert_eq!(p["gjk"]["result"], "separated");
    let gap = p["gjk"]["distance"].as_f64().unwrap();
    assert!(gap > 0.0 && gap < 1e-3, "{gap}");
    assert!(p["epa"].is_null());
    let contacts = p["contacts"].as_array().unwrap();
    assert!(!contacts.is_empty());
    for c in contacts {
        assert!(c["penetration"].as_f64().unwrap() <= 0.0, "{c}");
    }
}

#[test]
fn bad_arguments_exit_2_with_a_message() {
    for (args, message) in [
        (
            &["hull-stack", "--pair", "hexagon,teapot"][..],
            "no body named 'teapot'",
        ),
        (&["hull-stack", "--pair", "hexagon"][..], "two body names"),
        (&["lecture-2", "--step", "3"][..], "not a scene"),
    ] {
        let out = run(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(message), "{args:?}: {err}");
    }
}

#[test]
fn markdown_latex_and_the_figure() {
    let svg = common::scratch("detect-figure").join("pair.svg");
    let out = run(&[
        "epa-edge-edge",
        "--format",
        "latex",
        "--figure",
        svg.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    let tex = String::from_utf8(out.stdout).unwrap();
    assert!(tex.contains("\\begin{document}") && tex.contains("\\subsubsection*{EPA}"));
    let figure = std::fs::read_to_string(&svg).unwrap();
    assert!(figure.starts_with("<svg") && figure.trim_end().ends_with("</svg>"));
    // Both shapes, the Minkowski difference, the origin, the normal.
    assert!(figure.contains(">upper<") && figure.contains(">lower<"));
    assert!(figure.contains("A - B: intersecting") && figure.contains(">O<"));
    let md = String::from_utf8(run(&["epa-edge-edge", "--format", "md"]).stdout).unwrap();
    assert!(md.contains("### EPA") && md.contains("| k | closest face |"));
}

#[test]
fn tetra_on_floor_is_a_point_face_contact_one_centimetre_deep() {
    let d = json(&["tetra-on-floor"]);
    let p = &d["pairs"][0];
    assert_eq!(p["method"], "gjk");
    let e = &p["epa"];
    assert!((e["depth"].as_f64().unwrap() - 0.01).abs() < 1e-9, "{e}");
    assert!(near(v3(&e["normal"]), [0.0, 1.0, 0.0], 1e-9), "{e}");
    assert_eq!(e["feature"], "point-face");
}
