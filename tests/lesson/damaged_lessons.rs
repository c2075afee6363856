//! `parse` never panics on a damaged lesson: every prefix of each embedded
//! lesson (a truncated download, a half-saved file) and every single-byte
//! deletion. A fast, always-run relative of the fuzz target in `fuzz/`.
//!
//! Each lesson is shortened first, or the sweep would take ten times the two
//! seconds this test may use: its prose (comment lines, title, source,
//! summary, `where` and `erratum`) becomes one short string or comment; only
//! its first two `[[contact]]` and `[[printed]]` entries stay (the rest
//! repeat their form), with the `[[body]]` entries those contacts need. It
//! still sweeps about 19,000 damaged inputs in about a second.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicUsize, Ordering};

use contact_lab::error::AppError;
use contact_lab::lesson::{embedded::LESSONS, validate, Lesson};
use contact_lab::physics;

/// Entries of these kinds after the second are left out.
const AT_MOST_TWO: [&str; 2] = ["[[contact]]", "[[printed]]"];

/// The lesson with its prose shortened and its contacts and printed entries
/// after the second left out.
fn without_prose(text: &str) -> String {
    let mut out = String::from("# c\n");
    let mut seen = [0; 2];
    let mut skipping = false;
    let mut lines = text.lines();
    while let Some(line) = lines.next() {
        let key = line.split('=').next().unwrap_or("").trim();
        if let Some(kind) = AT_MOST_TWO.iter().position(|h| line.trim() == *h) {
            seen[kind] += 1;
            skipping = seen[kind] > 2;
        } else if is_header(line) && !line.starts_with("[contact.") {
            skipping = false;
        }
        if skipping || line.trim_start().starts_with('#') {
            continue;
        } else if key == "summary" {
            if line.matches("\"\"\"").count() == 1 {
                lines.by_ref().find(|l| l.contains("\"\"\""));
            }
            out.push_str("summary = \"\"\"\nS.\n\"\"\"\n");
        } else if ["title", "source", "where", "erratum"].contains(&key) {
            out.push_str(&format!("{key} = \"w\"\n"));
        } else {
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}

/// `[table]` or `[[array]]`, not a row of a matrix written over several lines.
fn is_header(line: &str) -> bool {
    let line = line.trim();
    line.starts_with('[') && line.ends_with(']') && !line.contains(',')
}

/// `without_prose`, then without the `[[body]]` entries no kept contact needs.
fn shortened(text: &str) -> String {
    let text = without_prose(text);
    let mut blocks: Vec<&str> = Vec::new();
    for (i, _) in text.match_indices("\n[") {
        let start = blocks.iter().map(|b| b.len()).sum();
        blocks.push(&text[start..=i]);
    }
    let start: usize = blocks.iter().map(|b| b.len()).sum();
    blocks.push(&text[start..]);
    for i in (0..blocks.len()).rev() {
        if blocks[i].starts_with("[[body]]") {
            let mut fewer = blocks.clone();
            fewer.remove(i);
            if validate::parse("shortened.toml", &fewer.concat()).is_ok() {
                blocks = fewer;
            }
        }
    }
    blocks.concat()
}

/// Whether contact `k` of `lesson`, or one of its bodies, differs from `original`.
fn changed(original: Option<&Lesson>, lesson: &Lesson, k: usize) -> bool {
    let Some(o) = original else { return true };
    let bodies = lesson.slots(k).into_iter().flatten();
    o.contacts.get(k) != Some(&lesson.contacts[k])
        || bodies
            .into_iter()
            .any(|i| o.bodies.get(i) != Some(&lesson.bodies[i]))
}

/// Parses `bytes`; renders the report of a lesson that is invalid, solves
/// the contacts that differ from `original`'s (the fuzz target also builds
/// and renders their traces). `Err` shows the input that panicked.
fn survives(what: &str, bytes: &[u8], original: Option<&Lesson>) -> Result<bool, String> {
    catch_unwind(AssertUnwindSafe(|| {
        match validate::parse_bytes("damaged.toml", bytes) {
            Ok(lesson) => {
                let contacts = 0..lesson.contacts.len();
                for k in contacts.filter(|&k| changed(original, &lesson, k)) {
                    physics::solve(&lesson.problem::<f64>(k));
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
    let text = shortened(text);
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
    // Two threads take the lessons from one queue.
    let next = AtomicUsize::new(0);
    let results: Vec<_> = std::thread::scope(|s| {
        let worker = || {
            let mut done = Vec::new();
            while let Some((f, text)) = LESSONS.get(next.fetch_add(1, Ordering::Relaxed)) {
                done.push(damage(f, text));
            }
            done
        };
        let threads = [s.spawn(worker), s.spawn(worker)];
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
