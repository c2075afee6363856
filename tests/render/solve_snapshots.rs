//! `solve` for every contact of every lesson file, held as snapshots: the
//! text a reader sees for the lectures' worked examples (the lessons with
//! the lecture's printed numbers), and rounded JSON (every value, 9
//! significant digits, `common::json`) for the rest. A change here is
//! reviewed line by line (`cargo insta review`).

use crate::common;

use contact_lab::format::Fmt;
use contact_lab::render;

#[test]
fn solve_text_of_the_lectures_and_json_of_every_other_lesson() {
    let mut lectures = 0;
    common::snapshot_settings().bind(|| {
        insta::glob!("../../lessons", "{*.toml,extremes/*.toml}", |path| {
            let lesson = common::lesson_file(path);
            let mut out_text = String::new();
            let mut out_json = String::new();
            for k in 0..lesson.contacts.len() {
                let trace = contact_lab::worked_solution(&lesson, k);
                out_text.push_str(&render::contact::text::render(&trace, &Fmt::default()));
                out_json.push_str(&render::contact::json::render(&trace));
            }
            // The lecture's worked examples print one contact's numbers; a
            // lesson whose printed numbers are all of its contacts resolved
            // together (the simultaneous-impact lessons) is not one.
            if lesson.printed.iter().all(|p| p.resolved()) {
                insta::assert_snapshot!(
                    "solve_json",
                    common::json::rounded_stream(&out_json, None)
                );
            } else {
                lectures += 1;
                insta::assert_snapshot!("solve_text", out_text);
            }
        });
    });
    assert_eq!(lectures, 3, "the lecture's three worked examples");
}
