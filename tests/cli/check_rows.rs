//! `check` names each row as the lecture writes the quantity, with its
//! stage (`Δv (stage 3, desired Δv)`), never by the internal key
//! (`desired_delta_velocity.desired`); the JSON keeps the key and adds the
//! label.

use assert_cmd::Command;

fn check(args: &[&str]) -> String {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .arg("check")
        .args(args)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    String::from_utf8(out).unwrap()
}

#[test]
fn rows_name_the_lecture_symbol_and_the_stage() {
    let text = check(&["lecture-1"]);
    for row in [
        "✓ v_s (stage 3, desired Δv): printed -2.2173",
        "✓ Δv (stage 3, desired Δv): printed 3.9911",
        "✓ g_contact[0] (stage 4, impulse): printed 26.61",
        "✓ r₁ (stage 1, contact frame): printed (5.1084, -3.1566, 0)",
    ] {
        assert!(text.contains(row), "no row {row:?} in:\n{text}");
    }
    for key in [
        "desired_delta_velocity.",
        "unit_impulse.",
        "impulse.impulse",
        "apply_impulse.",
        "contact_frame.",
    ] {
        assert!(!text.contains(key), "internal key {key:?} in:\n{text}");
    }
}

#[test]
fn every_embedded_row_has_a_symbol_not_a_key() {
    let json: serde_json::Value = serde_json::from_str(&check(&["--format", "json"])).unwrap();
    let items = json["items"].as_array().unwrap();
    assert!(items.len() > 50, "only {} items", items.len());
    for item in items {
        let (stage, value, label) = (
            item["stage"].as_str().unwrap(),
            item["value"].as_str().unwrap(),
            item["label"].as_str().unwrap(),
        );
        assert_ne!(label, value, "{stage}.{value} has no symbol");
    }
    let desired = items
        .iter()
        .find(|i| i["lesson"] == "lecture-1" && i["value"] == "desired")
        .unwrap();
    assert_eq!(desired["stage"], "desired_delta_velocity");
    assert_eq!(desired["label"], "Δv");
}
