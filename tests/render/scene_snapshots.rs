//! `simulate --table` of every scene as text (a row every half second, the events
//! between) and as JSON (every second), held as snapshots.

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

/// The JSON with every number to 9 significant digits: the snapshot holds
/// the physics, not the last bits of round-off (the output keeps full f64).
fn rounded(json: &str) -> String {
    fn round(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Number(n) if n.is_f64() => {
                let x = n.as_f64().unwrap();
                // Below 1e-9 a value is round-off left by the resolver.
                let r: f64 = format!("{x:.8e}").parse().unwrap();
                *v = serde_json::json!(if r.abs() < 1e-9 { 0.0 } else { r });
            }
            serde_json::Value::Array(a) => a.iter_mut().for_each(round),
            serde_json::Value::Object(o) => o.values_mut().for_each(round),
            _ => {}
        }
    }
    let mut v: serde_json::Value = serde_json::from_str(json).unwrap();
    round(&mut v);
    serde_json::to_string_pretty(&v).unwrap()
}

#[test]
fn simulate_text_and_json_of_every_scene() {
    common::snapshot_settings().bind(|| {
        insta::glob!("../../lessons/scenes", "*.toml", |path| {
            let lesson = common::lesson_file(path);
            let scene = lesson.simulation.as_ref().unwrap();
            let half_second = ((0.5 / scene.dt).round() as u64).max(1).to_string();
            let second = ((1.0 / scene.dt).round() as u64).max(1).to_string();
            insta::assert_snapshot!(
                "simulate_text",
                simulate(path, &["--table", "--every", &half_second, "--digits", "5"])
            );
            insta::assert_snapshot!(
                "simulate_json",
                rounded(&simulate(path, &["--every", &second, "--format", "json"]))
            );
        });
    });
}
