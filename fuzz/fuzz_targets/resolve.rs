//! `resolve` on generated scenes: bodies and hand-placed contacts, every
//! output format, both implementations (which must print the same).
#![no_main]

use arbitrary::Unstructured;
use contact_lab_fuzz::{check, resolve_scene, run, scratch};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok(scene) = resolve_scene(&mut u) else { return };
    let path = scratch(&scene);
    let path = path.to_str().expect("temp path is UTF-8");
    let (code, text) = run(&["resolve", path]);
    check(code, &text, &scene);
    let (json_code, json) = run(&["resolve", path, "--format", "json"]);
    assert_eq!(code, json_code, "text and JSON disagree on:\n{scene}");
    check(json_code, &json, &scene);
    let (scan_code, scan) = run(&["resolve", path, "--format", "json", "--implementation", "scan"]);
    assert_eq!(code, scan_code);
    if code == 0 {
        // Everything but the measured seconds must be the same.
        let untimed = |s: &str| {
            let mut v: serde_json::Value = serde_json::from_str(s).expect("resolve prints JSON");
            v.as_object_mut().map(|o| o.remove("seconds"));
            v
        };
        assert_eq!(untimed(&json), untimed(&scan), "scan and indexed resolvers differ on:\n{scene}");
    }
});
