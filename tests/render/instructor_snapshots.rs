//! Markdown, LaTeX and SVG of the lecture lessons, and the lecture check, held
//! as snapshots. A change here is reviewed line by line (`cargo insta review`).

use crate::common;

use assert_cmd::Command;
use contact_lab::format::Fmt;
use contact_lab::render::{self, svg::Plane};

#[test]
fn markdown_latex_and_svg_of_the_lecture_lessons() {
    common::snapshot_settings().bind(|| {
        insta::glob!("../../lessons", "lecture-*.toml", |path| {
            let lesson = common::lesson_file(path);
            let traces: Vec<_> = (0..lesson.contacts.len())
                .map(|k| contact_lab::worked_solution(&lesson, k))
                .collect();
            let fmt = Fmt::default();
            insta::assert_snapshot!(
                "solve_md",
                render::contact::markdown::document(&traces, &fmt, &[])
            );
            insta::assert_snapshot!(
                "solve_latex",
                render::contact::latex::document(&traces, &fmt, false)
            );
            let svg: Vec<String> = traces
                .iter()
                .map(|t| render::svg::render(t, Plane::Xy))
                .collect();
            insta::assert_snapshot!("figure_svg", svg.join("\n"));
        });
    });
}

/// The instructor's errata sheet: every printed lecture number, its computed
/// value, and the errata with their recomputed values.
#[test]
fn check_of_the_lecture_lessons_lists_the_errata() {
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .args(["check", "lecture-1", "lecture-2", "lecture-3"])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    common::snapshot_settings().bind(|| insta::assert_snapshot!("check_lectures", text));
    let json = Command::cargo_bin("contact-lab")
        .unwrap()
        .args([
            "check",
            "lecture-1",
            "lecture-2",
            "lecture-3",
            "--format",
            "json",
        ])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let json: serde_json::Value = serde_json::from_slice(&json).unwrap();
    common::snapshot_settings().bind(|| insta::assert_json_snapshot!("check_lectures_json", json));
}
