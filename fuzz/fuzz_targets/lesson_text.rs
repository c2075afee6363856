//! Raw bytes as a lesson file: the validator must refuse (65) or accept
//! without panicking, and an accepted lesson must resolve and, when it is a
//! scene, simulate with finite output.
#![no_main]

use contact_lab_fuzz::{check, run, scratch};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else { return };
    let path = scratch(text);
    let path = path.to_str().expect("temp path is UTF-8");
    let (code, out) = run(&["resolve", path]);
    check(code, &out, text);
    if text.contains("[step]") {
        let (code, out) = run(&["simulate", path, "--steps", "30"]);
        check(code, &out, text);
    }
});
