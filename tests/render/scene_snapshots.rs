//! `simulate` of every scene as rounded JSON (every second; every value,
//! `common::json`), and of the ball drop (the closed-form bounce) also as
//! the full table a reader sees (`--table`: a row every half second, the
//! events between), held as snapshots.

use crate::common;

use assert_cmd::Command;

fn simulate(path: &std::path::Path, args: &[&str]) -> String {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .arg("simulate")
        .arg(path)
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn simulate_json_of_every_scene_and_text_of_the_ball_drop() {
    common::snapshot_settings().bind(|| {
        insta::glob!("../../lessons/scenes", "*.toml", |path| {
            let lesson = common::lesson_file(path);
            let scene = lesson.simulation.as_ref().unwrap();
            let half_second = ((0.5 / scene.dt).round() as u64).max(1).to_string();
            let second = ((1.0 / scene.dt).round() as u64).max(1).to_string();
            if path.file_stem().is_some_and(|s| s == "ball-drop") {
                insta::assert_snapshot!(
                    "simulate_text",
                    simulate(path, &["--table", "--every", &half_second, "--digits", "5"])
                );
            }
            insta::assert_snapshot!(
                "simulate_json",
                common::json::rounded(
                    &simulate(path, &["--every", &second, "--format", "json"]),
                    // Below 1e-9 a value is round-off left by the resolver.
                    Some(1e-9)
                )
            );
        });
    });
}
