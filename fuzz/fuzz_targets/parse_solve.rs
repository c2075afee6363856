//! Arbitrary bytes as a lesson file: parse and validate; report the errors
//! of an invalid lesson as the CLI would; solve every contact of a valid one
//! and render it as text and JSON. Any panic is a finding.

#![no_main]

use contact_lab::error::AppError;
use contact_lab::format::Fmt;
use contact_lab::lesson::validate;
use contact_lab::render;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    match validate::parse_bytes("fuzz.toml", data) {
        Ok(lesson) => {
            for k in 0..lesson.contacts.len() {
                let trace = contact_lab::worked_solution(&lesson, k);
                render::contact::text::render(&trace, &Fmt::default());
                render::contact::json::render(&trace);
            }
        }
        Err(e) => {
            let report = AppError::from(e).report(false);
            assert!(report.starts_with("error: fuzz.toml:"), "{report}");
        }
    }
});
