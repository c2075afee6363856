//! `solve` in text and JSON for every contact of every lesson file, held as
//! snapshots. A change here is reviewed line by line (`cargo insta review`).

use crate::common;

use contact_lab::format::Fmt;
use contact_lab::render;

#[test]
fn solve_text_and_json_of_every_lesson() {
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
            insta::assert_snapshot!("solve_text", out_text);
            insta::assert_snapshot!("solve_json", out_json);
        });
    });
}
