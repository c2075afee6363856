//! `simulate` says when a pair tunnelled (issue 25, docs/simulate.md): the JSON's
//! events have `kind: "tunnelled"` naming both bodies, once for a bullet
//! that crosses a thin wall inside one step.

use std::process::Command;

use crate::common;

const BULLET: &str = r#"
id = "bullet"
title = "A bullet at a thin wall"
source = "issue 25"
summary = "The bullet moves farther in a step than the wall is thick."

[world]
gravity = [0, 0, 0]

[step]
dt = 0.016666666666666666
steps = 20

[[body]]
name = "bullet"
mass = 0.01
shape = { sphere = 0.01 }
position = [-0.5, 0, 0]
velocity = [100, 0, 0]

[[body]]
name = "wall"
mass = inf
shape = { box = [0.02, 2, 2] }
position = [0, 0, 0]
"#;

#[test]
fn simulate_json_lists_one_tunnelled_event_naming_both_bodies() {
    let dir = common::scratch("tunnelled");
    let file = dir.join("bullet.toml");
    std::fs::write(&file, BULLET).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args(["simulate", file.to_str().unwrap(), "--format", "json"])
        .output()
        .expect("contact-lab runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let events = doc["events"].as_array().expect("events");
    let tunnelled: Vec<_> = events.iter().filter(|e| e["kind"] == "tunnelled").collect();
    assert_eq!(tunnelled.len(), 1, "{events:?}");
    assert_eq!(tunnelled[0]["step"], 1);
    let text = tunnelled[0]["text"].as_str().unwrap();
    assert!(text.contains("bullet ↔ wall"), "{text}");
    assert!(text.contains("t = 0.0048 s"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}
