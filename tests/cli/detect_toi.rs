//! `detect SCENE --toi` (issue 25, docs/ccd.md): each pair's time of
//! collision over a step, test by test, in text and JSON, against the closed
//! form; and the two normals of a fast pair side by side.

use assert_cmd::Command;

fn detect(args: &[&str]) -> (Option<i32>, String, String) {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .arg("detect")
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn json(args: &[&str]) -> serde_json::Value {
    let mut all = args.to_vec();
    all.extend(["--format", "json"]);
    let (code, out, err) = detect(&all);
    assert_eq!(code, Some(0), "{err}");
    serde_json::from_str(&out).unwrap()
}

/// The bullet's speed in the first step: 100 m/s after one step of damping
/// (0.99 kept per second), and the time it takes to close its 0.48 m gap.
fn closed_form() -> f64 {
    let v = 100.0 * 0.99f64.powf(1.0 / 60.0);
    0.48 / v
}

#[test]
fn bisection_brackets_the_closed_form_and_halves_to_its_tolerance() {
    let doc = json(&["bullet-wall", "--toi", "--pair", "bullet,wall"]);
    let pair = &doc["pairs"][0];
    assert_eq!(
        (pair["a"].as_str(), pair["b"].as_str()),
        (Some("bullet"), Some("wall"))
    );
    let toi = &pair["toi"];
    assert_eq!(toi["method"], "bisection");
    assert_eq!(toi["end"], "converged");
    let t = toi["time"].as_f64().unwrap();
    let want = closed_form();
    // The last time known apart: at or before the contact, within the tolerance
    // (10⁻⁴ of the bullet's radius at 100 m/s = 10⁻⁸ s).
    assert!(t <= want && want - t < 1.1e-8, "{t} vs {want}");
    // The scan: pieces of 0.02 m of closing, the first ending inside the wall is bisected.
    let scan = toi["scan"].as_array().unwrap();
    assert!(scan.last().unwrap()["hit"].as_bool().unwrap());
    assert!(scan[..scan.len() - 1].iter().all(|p| p["hit"] == false));
    let piece = scan[0]["t1"].as_f64().unwrap() - scan[0]["t0"].as_f64().unwrap();
    // Halvings: ⌈log₂(piece / tolerance)⌉, each interval inside the last.
    let iterations = toi["iterations"].as_array().unwrap();
    let tolerance = 1e-4 * 0.01 / (100.0 * 0.99f64.powf(1.0 / 60.0));
    let expected = (piece / tolerance).log2().ceil() as usize;
    assert_eq!(iterations.len(), expected, "{piece} / {tolerance}");
    for w in iterations.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        let mid = a["trial"].as_f64().unwrap();
        let (t0, t1) = (b["t0"].as_f64().unwrap(), b["t1"].as_f64().unwrap());
        if a["hit"].as_bool().unwrap() {
            assert_eq!(t1, mid);
        } else {
            assert_eq!(t0, mid);
        }
    }
    assert_eq!(
        toi["tests"].as_u64().unwrap() as usize,
        scan.len() + iterations.len()
    );
}

#[test]
fn conservative_advancement_needs_fewer_tests_on_the_same_pair() {
    let doc = json(&["bullet-wall", "--toi", "--method", "conservative"]);
    let toi = &doc["pairs"][0]["toi"];
    assert_eq!(toi["method"], "conservative");
    let t = toi["time"].as_f64().unwrap();
    assert!((t - closed_form()).abs() < 1e-9, "{t}");
    // Straight at a face: one advance is exact, the second test confirms it.
    assert_eq!(toi["tests"], 2);
    let first = &toi["iterations"][0];
    assert!((first["distance"].as_f64().unwrap() - 0.48).abs() < 1e-12);
}

#[test]
fn the_text_shows_each_midpoint_and_the_previous_frame_normal() {
    let (code, out, err) = detect(&["bullet-wall", "--toi"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.starts_with(
            "bullet-wall: step 1 (t = 0 s to 0.0166667 s), time of collision by bisection"
        ),
        "{out}"
    );
    assert!(out.contains("bullet ↔ wall"), "{out}");
    assert!(
        out.contains("midpoint 0.00486111 intersects → keep [0.0047619, 0.00486111]"),
        "{out}"
    );
    assert!(
        out.contains("time of collision: t = 0.0048008 s into the step (converged, 40 tests)"),
        "{out}"
    );
    assert!(
        out.contains("normal at the step's end (EPA): none: apart at the step's end"),
        "{out}"
    );
    assert!(
        out.contains("normal one frame earlier (closest points at the step's start): (-1, 0, 0)"),
        "{out}"
    );
}

#[test]
fn a_fast_thin_box_at_an_edge_has_two_different_normals() {
    let doc = json(&["spinning-edge", "--toi", "--step", "1"]);
    let normals = &doc["pairs"][0]["normals"];
    let epa: Vec<f64> = serde_json::from_value(normals["epa_at_end"]["normal"].clone()).unwrap();
    let before: Vec<f64> = serde_json::from_value(normals["previous_frame"].clone()).unwrap();
    assert!((epa[0] - 1.0).abs() < 1e-9, "{epa:?}");
    assert!((before[1] - 1.0).abs() < 1e-9, "{before:?}");
}

#[test]
fn a_pair_that_is_not_in_the_scene_is_a_usage_error() {
    let (code, _, err) = detect(&["bullet-wall", "--toi", "--pair", "bullet,floor"]);
    assert_eq!(code, Some(2));
    assert!(
        err.contains("no body named \"floor\" (its bodies: bullet, wall)"),
        "{err}"
    );
    let (code, _, err) = detect(&["lecture-2", "--toi"]);
    assert_eq!(code, Some(2));
    assert!(err.contains("lecture-2 is not a scene"), "{err}");
}

/// `ball-floor-fast` at step 3 (no damping; gravity added at each step's
/// start): the ball's lowest point's height at the step's start, and its
/// speed over the step.
fn floor_closed_form() -> (f64, f64) {
    let (g, dt) = (9.81, 1.0 / 60.0);
    let v = |k: f64| 100.0 + k * g * dt;
    let lowest = 4.5 - (v(1.0) + v(2.0)) * dt - 0.5;
    (lowest, v(3.0))
}

#[test]
fn a_ball_onto_a_half_space_floor_meets_it_at_gap_over_speed_with_either_search() {
    let (gap, speed) = floor_closed_form();
    let want = gap / speed;
    for (method, tests) in [("bisection", None), ("conservative", Some(2))] {
        let doc = json(&[
            "ball-floor-fast",
            "--toi",
            "--step",
            "3",
            "--method",
            method,
        ]);
        let pairs = doc["pairs"].as_array().unwrap();
        assert_eq!(pairs.len(), 1, "{method}: {doc}");
        let pair = &pairs[0];
        assert_eq!(
            (pair["a"].as_str(), pair["b"].as_str()),
            (Some("ball"), Some("floor"))
        );
        let toi = &pair["toi"];
        assert_eq!(toi["method"], method);
        assert_eq!(toi["end"], "converged", "{method}: {toi}");
        let t = toi["time"].as_f64().unwrap();
        // The last time known apart, within the tolerance: 10⁻⁴ of the
        // radius (5·10⁻⁵ m) at 100 m/s is 5·10⁻⁷ s.
        assert!(
            t <= want + 1e-12 && want - t < 5.1e-7,
            "{method}: {t} vs {want}"
        );
        if let Some(n) = tests {
            // Straight at a plane: one advance is exact, the second test confirms it.
            assert_eq!(toi["tests"], n, "{method}: {toi}");
        }
        // The ball ends the step inside the floor: the normal at the end is the plane's.
        let end = &pair["normals"]["epa_at_end"];
        assert_eq!(end["normal"], serde_json::json!([0.0, 1.0, 0.0]), "{end}");
    }
}

#[test]
fn the_toi_figure_draws_the_pair_at_the_start_and_at_the_time_found() {
    for (scene, step) in [("ball-floor-fast", "3"), ("bullet-wall", "1")] {
        let path = crate::common::scratch(&format!("toi-figure-{scene}")).join("F.svg");
        let (code, _, err) = detect(&[
            scene,
            "--toi",
            "--step",
            step,
            "--figure",
            path.to_str().unwrap(),
        ]);
        assert_eq!(code, Some(0), "{err}");
        let svg = std::fs::read_to_string(&path).expect("the figure is written");
        assert!(svg.starts_with("<svg"), "{svg}");
        assert!(svg.contains("time of collision (bisection)"), "{svg}");
        assert!(
            svg.contains("the box each body sweeps over the next step"),
            "{svg}"
        );
        // Each body drawn twice: at t = 0 and at the time found.
        let names = svg.matches("text-anchor=\"middle\"").count();
        let planes = usize::from(scene == "ball-floor-fast");
        assert_eq!(names + 2 * planes, 4, "{svg}");
    }
}

#[test]
fn method_without_toi_is_a_usage_error() {
    let (code, _, err) = detect(&["bullet-wall", "--method", "conservative"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("--toi"), "{err}");
}

/// Two spheres 1 cm inside each other, moving apart: apart again by the
/// step's end, so a scan that looks only at piece ends would see nothing.
#[test]
fn two_spheres_overlapping_at_the_steps_start_report_at_start() {
    let path = crate::common::scratch("toi-overlap").join("toi-overlap.toml");
    std::fs::write(
        &path,
        r#"id = "toi-overlap"
title = "Two spheres overlapping at the start"
[world]
gravity = [0, 0, 0]
[step]
dt = 0.016666666666666666
steps = 2
[sleep]
enabled = false
[[body]]
name = "a"
mass = 1.0
shape = { sphere = 0.5 }
position = [-0.495, 0, 0]
velocity = [-1, 0, 0]
[[body]]
name = "b"
mass = 1.0
shape = { sphere = 0.5 }
position = [0.495, 0, 0]
velocity = [1, 0, 0]
"#,
    )
    .unwrap();
    for method in ["bisection", "conservative"] {
        let doc = json(&[path.to_str().unwrap(), "--toi", "--method", method]);
        let toi = &doc["pairs"][0]["toi"];
        assert_eq!(toi["end"], "at_start", "{method}: {toi}");
        assert_eq!(toi["time"], 0.0, "{method}: {toi}");
    }
}

/// The text prints every test the outcome counts: the scan's pieces, then
/// the trials (the TUI's `t` steps through the same list).
#[test]
fn the_text_prints_as_many_tests_as_the_outcome_counts() {
    for method in ["bisection", "conservative"] {
        let (code, out, err) = detect(&["bullet-wall", "--toi", "--method", method]);
        assert_eq!(code, Some(0), "{err}");
        let lines: Vec<&str> = out.lines().collect();
        let pieces = lines
            .iter()
            .filter(|l| l.starts_with("  scan piece "))
            .count();
        let trials = lines
            .iter()
            .filter(|l| l.starts_with("  [t₀, t₁] = ") || l.starts_with("  t = "))
            .count();
        let outcome = lines
            .iter()
            .find(|l| l.starts_with("  time of collision: "))
            .unwrap();
        let n = pieces + trials;
        assert!(
            outcome.ends_with(&format!(", {n} tests)")),
            "{method}: {n} lines, {outcome}"
        );
        assert_eq!(pieces > 0, method == "bisection", "{out}");
    }
    let (_, out, _) = detect(&["bullet-wall", "--toi", "--method", "conservative"]);
    assert!(
        out.contains("time of collision by conservative advancement"),
        "{out}"
    );
}

/// A half-space pair's normals come from the plane, not from EPA or closest
/// points (issue 40): the text says what computed each; a pair of two
/// convex shapes still names EPA.
#[test]
fn the_text_says_what_gave_each_normal() {
    let (code, out, err) = detect(&["ball-floor-fast", "--toi", "--step", "3"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(!out.contains("EPA"), "{out}");
    assert!(!out.contains("closest points"), "{out}");
    assert!(
        out.contains(
            "normal at the step's end (the half-space's normal, the depth in closed form): (0, 1, 0)"
        ),
        "{out}"
    );
    let (code, out, err) = detect(&["bullet-wall", "--toi", "--pair", "bullet,wall"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("normal at the step's end (EPA): "), "{out}");
    assert!(
        out.contains("normal one frame earlier (closest points at the step's start): "),
        "{out}"
    );
}
