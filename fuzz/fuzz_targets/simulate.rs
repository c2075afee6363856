//! `simulate` on generated scenes: shaped bodies under gravity with world,
//! step and sleep settings, run for up to 120 steps, text and JSON.
#![no_main]

use arbitrary::Unstructured;
use contact_lab_fuzz::{check, run, scratch, simulate_scene};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok(scene) = simulate_scene(&mut u) else { return };
    let path = scratch(&scene);
    let path = path.to_str().expect("temp path is UTF-8");
    let (code, text) = run(&["simulate", path, "--every", "10"]);
    check(code, &text, &scene);
    let (json_code, json) = run(&["simulate", path, "--every", "10", "--format", "json"]);
    assert_eq!(code, json_code, "text and JSON disagree on:\n{scene}");
    check(json_code, &json, &scene);
});
