//! `simulate --ccd` (issue 25, docs/ccd.md): the collision continuous
//! detection finds inside a step is a `toi` event in the text and the JSON,
//! and the tunnelled event is gone.

use std::process::Command;

fn simulate(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args(["simulate", "bullet-wall", "--steps", "5"])
        .args(args)
        .output()
        .expect("contact-lab runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn simulate_with_ccd_lists_a_toi_event_in_json_and_no_tunnelled_one() {
    for method in ["bisection", "conservative"] {
        let doc: serde_json::Value =
            serde_json::from_str(&simulate(&["--ccd", method, "--format", "json"])).unwrap();
        let events = doc["events"].as_array().expect("events");
        let kinds: Vec<&str> = events.iter().map(|e| e["kind"].as_str().unwrap()).collect();
        assert_eq!(kinds, vec!["toi"], "{method}: {events:?}");
        assert_eq!(events[0]["step"], 1);
        let text = events[0]["text"].as_str().unwrap();
        assert!(text.contains(&format!("({method},")), "{text}");
        assert!(text.contains("bullet ↔ wall met at t = 0.0048 s"), "{text}");
        assert!(text.contains("separating at 50 m/s"), "{text}");
    }
}

#[test]
fn simulate_with_ccd_prints_the_toi_event_in_its_text() {
    // Unfolded (`--width 0`): the event on one line.
    let text = simulate(&["--ccd", "conservative", "--width", "0"]);
    assert!(
        text.contains(
            "time of collision (conservative, 2 tests): bullet ↔ wall met at t = 0.0048 s"
        ),
        "{text}"
    );
    assert!(!text.contains("tunnelled"), "{text}");
    let without = simulate(&["--ccd", "none"]);
    assert!(without.contains("tunnelled: bullet ↔ wall"), "{without}");
}
