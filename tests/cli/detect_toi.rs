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
