//! Load warnings where a lesson is probably wrong (issue 28, item 6): a
//! contact point deeper inside a body than the stated penetration, a normal
//! that points from body 1 toward body 2, a printed zero compared with a
//! computed value that is not zero. Each names file, line and column on
//! stderr; `deliberate = [...]` silences the one a lesson means; no
//! embedded lesson warns unless it is marked.

use crate::common;

use assert_cmd::Command;
use contact_lab::lesson::{embedded, Lesson};

const BALL: &str = r#"id = "ball"
title = "A ball on the floor"

[[body]]
name = "ball"
mass = 2.0
shape = { sphere = 1.0 }
position = [0.0, 1.0, 0.0]
velocity = [0.0, -2.0, 0.0]

[[contact]]
bodies = ["ball"]
point = POINT
normal = NORMAL
restitution = 0.5
MARK
[[printed]]
stage = "desired_delta_velocity"
value = "desired"
printed = PRINTED
where = "a slide"
PRINTED_MARK
"#;

fn lesson(point: &str, normal: &str, mark: &str, printed: &str, printed_mark: &str) -> String {
    BALL.replace("POINT", point)
        .replace("NORMAL", normal)
        .replace("PRINTED_MARK", printed_mark)
        .replace("MARK", mark)
        .replace("PRINTED", printed)
}

/// `solve FILE`'s exit code and stderr.
fn solve(name: &str, text: &str) -> (Option<i32>, String, String) {
    let dir = common::scratch(&format!("load-warnings-{}", name.trim_end_matches(".toml")));
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    let out = Command::cargo_bin("contact-lab")
        .unwrap()
        .arg("solve")
        .arg(&path)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8(out.stderr).unwrap(),
        path.display().to_string(),
    )
}

#[test]
fn a_plausible_lesson_loads_without_a_warning() {
    let (code, err, _) = solve(
        "fine.toml",
        &lesson("[0.0, 0.0, 0.0]", "[0.0, 1.0, 0.0]", "", "3.0", ""),
    );
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(err, "");
}

#[test]
fn a_point_inside_the_body_warns_with_file_line_and_column() {
    let text = lesson("[0.0, 0.5, 0.0]", "[0.0, 1.0, 0.0]", "", "3.0", "");
    let (code, err, path) = solve("inside.toml", &text);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        err.contains(&format!("warning: {path}:13:9: the contact point lies 0.5 inside 'ball', deeper than the stated penetration 0")),
        "{err}"
    );
    let marked = lesson(
        "[0.0, 0.5, 0.0]",
        "[0.0, 1.0, 0.0]",
        "deliberate = [\"point-inside-body\"]",
        "3.0",
        "",
    );
    assert_eq!(solve("inside-marked.toml", &marked).1, "");
}

#[test]
fn a_normal_toward_body_2_warns() {
    let text = lesson("[0.0, 0.0, 0.0]", "[0.0, -1.0, 0.0]", "", "3.0", "");
    let (_, err, path) = solve("normal.toml", &text);
    assert!(
        err.contains(&format!(
            "warning: {path}:14:10: the contact normal points from body 1 'ball' toward body 2"
        )),
        "{err}"
    );
    let marked = lesson(
        "[0.0, 0.0, 0.0]",
        "[0.0, -1.0, 0.0]",
        "deliberate = [\"normal-into-body\"]",
        "3.0",
        "",
    );
    assert_eq!(solve("normal-marked.toml", &marked).1, "");
}

#[test]
fn a_printed_zero_against_a_computed_value_warns() {
    let text = lesson("[0.0, 0.0, 0.0]", "[0.0, 1.0, 0.0]", "", "0", "");
    let (_, err, path) = solve("zero.toml", &text);
    assert!(
        err.contains(&format!("warning: {path}:20:11: printed 0 for desired_delta_velocity.desired (a slide) is compared with the computed 3, which is not zero")),
        "{err}"
    );
    let marked = lesson(
        "[0.0, 0.0, 0.0]",
        "[0.0, 1.0, 0.0]",
        "",
        "0",
        "deliberate = [\"printed-zero\"]",
    );
    assert_eq!(solve("zero-marked.toml", &marked).1, "");
}

#[test]
fn an_unknown_mark_is_invalid_lesson_data() {
    let text = lesson(
        "[0.0, 0.0, 0.0]",
        "[0.0, 1.0, 0.0]",
        "deliberate = [\"typo\"]",
        "3.0",
        "",
    );
    let (code, err, path) = solve("typo.toml", &text);
    assert_eq!(code, Some(65), "{err}");
    assert!(
        err.contains(&path) && err.contains("deliberate: unknown warning \"typo\""),
        "{err}"
    );
}

#[test]
fn no_embedded_lesson_warns_unless_marked() {
    for id in embedded::ids() {
        let l = Lesson::load(id).unwrap();
        for w in &l.warnings {
            let w = w.to_string();
            assert!(
                !w.contains("the contact point lies")
                    && !w.contains("the contact normal points from body 1"),
                "{id}: {w}"
            );
        }
        let zeros = contact_lab::errata::zero_warnings(&l, |k| contact_lab::worked_solution(&l, k));
        assert!(zeros.is_empty(), "{id}: {zeros:?}");
    }
}
