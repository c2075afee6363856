//! `--format html` of `simulate`, `study` and `detect --toi` as a user runs
//! them (docs/html.md): `-o FILE` writes the page, stdout stays empty; a
//! `--trace-step` past the run is a usage error; `-o` also takes the other
//! formats of `simulate`.

use crate::common::{self, cli::run};

#[test]
fn simulate_writes_the_player_with_the_traced_step() {
    let dir = common::scratch("html-simulate");
    let file = dir.join("stack.html");
    let r = run(&[
        "simulate",
        "stack-5",
        "--steps",
        "40",
        "--every",
        "4",
        "--trace-step",
        "9",
        "--format",
        "html",
        "-o",
        file.to_str().unwrap(),
    ]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert!(r.stdout.is_empty(), "{}", r.stdout);
    let page = std::fs::read_to_string(&file).unwrap();
    assert!(page.starts_with("<!DOCTYPE html>"));
    assert!(page.contains("<code>--every 4</code>"));
    assert!(
        page.contains("holds 12 frames"),
        "0, 4, …, 40 and the traced 9"
    );
    assert!(page.contains("Step 9's resolution"));
}

#[test]
fn a_trace_step_past_the_run_is_a_usage_error() {
    let r = run(&[
        "simulate",
        "stack-5",
        "--steps",
        "10",
        "--trace-step",
        "11",
        "--format",
        "html",
    ]);
    assert_eq!(r.code, Some(2), "{}", r.stderr);
    assert!(r.stderr.contains("--trace-step 11"), "{}", r.stderr);
    assert!(r.stdout.is_empty());
}

#[test]
fn simulate_o_writes_the_other_formats_too() {
    let dir = common::scratch("html-simulate-json");
    let file = dir.join("run.json");
    let r = run(&[
        "simulate",
        "ball-drop",
        "--steps",
        "5",
        "--format",
        "json",
        "-o",
        file.to_str().unwrap(),
    ]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert!(r.stdout.is_empty());
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
    assert_eq!(doc["steps"].as_array().unwrap().len(), 6);
}

#[test]
fn detect_toi_writes_its_page() {
    let r = run(&["detect", "bullet-wall", "--toi", "--format", "html"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert!(r.stdout.contains("class=\"timeline\""));
    assert!(r.stdout.contains("bullet ↔ wall: result"));
    let r = run(&["detect", "bullet-wall", "--toi", "--format", "md"]);
    assert_eq!(r.code, Some(2), "Markdown stays refused: {}", r.stderr);
}

#[test]
fn study_writes_its_page() {
    let dir = common::scratch("html-study");
    let file = dir.join("study.html");
    let r = run(&[
        "study",
        "ball-drop",
        "--quick",
        "--no-timing",
        "--seconds",
        "0.25",
        "--format",
        "html",
        "-o",
        file.to_str().unwrap(),
    ]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let page = std::fs::read_to_string(&file).unwrap();
    assert!(page.contains("<table class=\"sortable\">"));
    assert!(page.contains("<g class=\"tip\"><title>"));
}
