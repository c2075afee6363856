//! `detect` as text and JSON for one box–box pair (EPA, edge–edge) and one
//! sphere–hull pair (GJK on the cores, touching), held as snapshots.

use crate::common;

use assert_cmd::Command;

fn detect(args: &[&str]) -> String {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .arg("detect")
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

/// Every number to 9 significant digits, below 1e-12 as 0: the snapshot
/// holds the geometry, not the last bits of round-off.
fn rounded(json: &str) -> String {
    fn round(v: &mut serde_json::Value) {
        match v {
            serde_json::Value::Number(n) if n.is_f64() => {
                let x = n.as_f64().unwrap();
                let r: f64 = format!("{x:.8e}").parse().unwrap();
                *v = serde_json::json!(if r.abs() < 1e-12 { 0.0 } else { r });
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
fn detect_text_and_json_of_a_box_pair_and_a_sphere_on_a_hull() {
    common::snapshot_settings().bind(|| {
        for id in ["epa-edge-edge", "gjk-touching"] {
            insta::assert_snapshot!(format!("detect_text@{id}"), detect(&[id, "--digits", "5"]));
            insta::assert_snapshot!(
                format!("detect_json@{id}"),
                rounded(&detect(&[id, "--format", "json"]))
            );
        }
    });
}
