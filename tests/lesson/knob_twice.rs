//! A knob written twice: in two scene tables a warning (the table read
//! last wins), and twice in one table (its name and an old name) an error,
//! naming the line and column of the second.

use contact_lab::lesson::{embedded, validate, LessonError};

const SCENE: &str = r#"id = "twice"
title = "A knob twice"
source = "test"
summary = "x"

[settings]
friction_model = "millington"

[world]
friction_model = "kinetic-direction"

[step]
dt = 0.01
steps = 10

[[body]]
name = "ball"
mass = 1.0
shape = { sphere = 0.5 }
position = [0, 1, 0]
"#;

#[test]
fn a_knob_in_two_scene_tables_is_a_warning_naming_the_one_that_wins() {
    let lesson = validate::parse("twice.toml", SCENE).unwrap();
    let said: Vec<String> = lesson.warnings.iter().map(|w| w.message.clone()).collect();
    let w = lesson
        .warnings
        .iter()
        .find(|w| {
            w.message
                .contains("friction_model is set in [settings] and again in [world]")
        })
        .unwrap_or_else(|| panic!("{said:?}"));
    assert_eq!((w.line, w.column), (10, 1), "the second one");
    assert!(w.message.contains("[world] is read later"), "{}", w.message);
}

#[test]
fn a_knob_and_its_old_name_in_one_table_is_an_error() {
    let text = format!("{SCENE}\n[sleep]\nsleep = true\nenabled = false\n");
    let Err(e) = validate::parse("twice.toml", &text) else {
        panic!("loaded")
    };
    let LessonError::Invalid { diagnostics, .. } = e else {
        panic!("{e:?}")
    };
    let d = &diagnostics[0];
    assert!(
        d.message
            .contains("enabled sets the knob sleep again (`sleep` sets it above)"),
        "{}",
        d.message
    );
    assert_eq!((d.line, d.column), (24, 1), "at the second key");
}

#[test]
fn no_embedded_lesson_sets_a_knob_twice() {
    for id in embedded::ids() {
        let l = contact_lab::lesson::Lesson::load(id).unwrap();
        for w in &l.warnings {
            assert!(!w.message.contains("and again in"), "{id}: {}", w.message);
        }
    }
}
