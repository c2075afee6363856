//! `parse` never panics on a damaged lesson: every prefix of each embedded
//! lesson (a truncated download, a half-saved file) and every single-byte
//! deletion. A fast, always-run relative of the fuzz target in `fuzz/`.
//!
//! Each lesson is shortened first, or the sweep would take ten times the two
//! seconds this test may use: its prose (comment lines, the summary, `where`
//! and `erratum` strings) becomes one short string or comment each, and only
//! its first two `[[printed]]` entries stay (the rest repeat their form).

use std::panic::{catch_unwind, AssertUnwindSafe};

use contact_lab::error::AppError;
use contact_lab::lesson::{embedded::LESSONS, validate, Lesson};

/// The lesson with its prose shortened; still a valid lesson.
fn without_prose(text: &str) -> String {
    let mut out = String::from("# c\n");
    let mut lines = text.lines();
    let mut printed = 0;
    while let Some(line) = lines.next() {
        let key = line.split('=').next().unwrap_or("").trim();
        printed += usize::from(line.trim() == "[[printed]]");
        if line.trim_start().starts_with('#') || printed > 2 {
            continue;
        } else if key == "summary" {
            if line.matches("\"\"\"").count() == 1 {
                lines.by_ref().find(|l| l.contains("\"\"\""));
            }
            out.push_str("summary = \"\"\"\nS.\n\"\"\"\n");
        } else if key == "where" || key == "erratum" {
            out.push_str(&format!("{key} = \"w\"\n"));
        } else {
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}

/// Parses `bytes`; renders the report of a lesson that is invalid, solves
/// and renders one whose scene differs from `original`'s. `Err` shows the
/// input that panicked.
fn survives(what: &str, bytes: &[u8], original: Option<&Lesson>) -> Result<bool, String> {
    catch_unwind(AssertUnwindSafe(|| {
        match validate::parse_bytes("damaged.toml", bytes) {
            Ok(lesson) => {
                let same = original.is_some_and(|o| {
                    (&o.bodies, &o.contacts) == (&lesson.bodies, &lesson.contacts)
                });
                for k in (0..lesson.contacts.len()).filter(|_| !same) {
                    let trace = contact_lab::worked_solution(&lesson, k);
                    contact_lab::render::json::render(&trace);
                }
                true
            }
            Err(e) => {
                AppError::from(e).report(false);
                false
            }
        }
    }))
    .map_err(|_| format!("{what}:\n{}", String::from_utf8_lossy(bytes)))
}

/// Counts of (inputs, valid inputs) over every damaged version of a lesson.
fn damage(file: &str, text: &str) -> Result<(usize, usize), String> {
    let text = without_prose(text);
    assert!(
        survives(file, text.as_bytes(), None)?,
        "{file}, shortened, is valid"
    );
    let original = validate::parse(file, &text).ok();
    let bytes = text.as_bytes();
    let mut valid = 0;
    for n in 0..bytes.len() {
        let what = format!("{file} cut to {n} bytes");
        valid += usize::from(survives(&what, &bytes[..n], original.as_ref())?);
        let mut deleted = bytes.to_vec();
        deleted.remove(n);
        let what = format!("{file} without byte {n}");
        valid += usize::from(survives(&what, &deleted, original.as_ref())?);
    }
    Ok((2 * bytes.len(), valid))
}

#[test]
fn no_prefix_or_single_byte_deletion_of_a_lesson_panics() {
    let quiet = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    // Two threads, the lessons dealt alternately so each gets a big one.
    let results: Vec<_> = std::thread::scope(|s| {
        let threads: Vec<_> = (0..2)
            .map(|t| {
                s.spawn(move || {
                    let mine = LESSONS.iter().skip(t).step_by(2);
                    mine.map(|(f, text)| damage(f, text)).collect::<Vec<_>>()
                })
            })
            .collect();
        threads
            .into_iter()
            .flat_map(|t| t.join().unwrap())
            .collect()
    });
    std::panic::set_hook(quiet);
    let (mut inputs, mut valid) = (0, 0);
    for r in results {
        let (n, v) = r.unwrap_or_else(|e| panic!("panicked on {e}"));
        inputs += n;
        valid += v;
    }
    assert!(inputs > 10_000, "only {inputs} damaged inputs");
    assert!(
        valid > 100,
        "only {valid} damaged inputs are still valid lessons"
    );
}
