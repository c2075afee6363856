//! Movement bounds in `detect`'s figure (issue 25, item 2): with continuous
//! detection on, each moving body's swept AABB (dashed) and swept sphere
//! (dotted) over the next step, under the shapes; nothing with it off.

use crate::common;

use assert_cmd::Command;

/// The figure of bullet–wall at step 0 with `extra` arguments.
fn figure(name: &str, extra: &[&str]) -> String {
    let dir = common::scratch(name);
    let svg = dir.join("pair.svg");
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args(["detect", "bullet-wall", "--pair", "bullet,wall", "--figure"])
        .arg(&svg)
        .args(extra)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    text
}

/// The numbers of the first `<rect … stroke-dasharray>` (the swept AABB).
fn dashed_rect(svg: &str) -> [f64; 4] {
    let line = svg
        .lines()
        .find(|l| l.contains("<rect") && l.contains("stroke-dasharray"))
        .expect("a dashed rectangle");
    let num = |key: &str| -> f64 {
        let at = line.find(&format!(" {key}=\"")).unwrap() + key.len() + 3;
        line[at..].split('"').next().unwrap().parse().unwrap()
    };
    [num("x"), num("y"), num("width"), num("height")]
}

#[test]
fn with_ccd_the_figure_draws_the_bullets_movement_bounds_and_without_it_none() {
    let with = figure("bounds-with-ccd", &["--ccd", "bisection"]);
    common::snapshot_settings().bind(|| {
        insta::assert_snapshot!("detect_figure_bullet_wall_ccd", with);
    });
    assert!(with.contains("the box each body sweeps over the next step (ccd)"));
    // The bullet's swept AABB runs from x = −0.51 to −0.49 + v Δt, v the
    // velocity the step integrates (100 m/s damped by 0.99^Δt): 1.6864 m,
    // against the wall's 2 m height (the figure's span, 0.85 × 480 px):
    // 344 px, within the one-decimal rounding.
    let [_, _, width, height] = dashed_rect(&with);
    let px_per_m = 0.85 * 480.0 / 2.0;
    let dt = 1.0 / 60.0;
    let reach = 0.02 + 100.0 * 0.99f64.powf(dt) * dt;
    assert!((width - reach * px_per_m).abs() < 0.1, "{width}");
    assert!((height - 0.02 * px_per_m).abs() < 0.2, "{height}");
    let without = figure("bounds-without-ccd", &[]);
    assert!(!without.contains("stroke-dasharray"), "{without}");
    assert!(!without.contains("sweeps over the next step"));
}
