//! The lesson list's group jump and type-to-filter (issue 28, item 5):
//! `/` opens the picker, letters filter, Tab jumps to the next group
//! (lessons, robustness, scenes), Enter opens; `{` `}` jump between groups;
//! the help lists the keys; and the run picture keeps the floor in view.

use crate::common::tui::{app, draw, key, keys, term, text, type_text};
use contact_lab::tui::app::Mode;
use contact_lab::tui::event::KEYS;
use contact_lab::tui::keys;
use contact_lab::tui::picker::PICKER_KEYS;
use contact_lab::tui::screens::{Screen, RESOLVER_KEYS, RUN_KEYS};
use ratatui::crossterm::event::KeyCode;

fn picked(a: &contact_lab::tui::App) -> String {
    let Mode::Pick(p) = &a.mode else {
        panic!("the picker is open")
    };
    a.lessons[p.at].lesson.id.clone()
}

#[test]
fn slash_then_letters_then_enter_opens_a_scene_in_a_few_presses() {
    let mut a = app("lecture-2", false);
    key(&mut a, KeyCode::Char('/'));
    type_text(&mut a, "stack-5");
    assert_eq!(picked(&a), "stack-5");
    let mut t = term(80, 24);
    draw(&mut t, &a);
    let screen = text(t.backend().buffer());
    assert!(screen.contains("/ stack-5"), "{screen}");
    assert!(screen.contains("Scenes (in time)"), "{screen}");
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.mode, Mode::Normal);
    assert_eq!(a.lessons[a.lesson].lesson.id, "stack-5");
    assert_eq!(a.screen, Screen::Run);
}

#[test]
fn tab_in_the_picker_jumps_from_group_to_group() {
    let mut a = app("lecture-2", false);
    let group = |a: &contact_lab::tui::App, id: &str| {
        let l = a.lessons.iter().find(|e| e.lesson.id == id).unwrap();
        contact_lab::tui::group(&l.lesson)
    };
    key(&mut a, KeyCode::Char('/'));
    key(&mut a, KeyCode::Tab);
    let first = picked(&a);
    assert_eq!(group(&a, &first), "Robustness (extreme-*)", "{first}");
    key(&mut a, KeyCode::Tab);
    let second = picked(&a);
    assert_eq!(group(&a, &second), "Scenes (in time)", "{second}");
    key(&mut a, KeyCode::Tab);
    assert_eq!(group(&a, &picked(&a)), "Lessons");
    key(&mut a, KeyCode::BackTab);
    assert_eq!(picked(&a), second);
    // A filter nothing matches: Enter keeps the picker open, Esc closes it.
    type_text(&mut a, "zzzz-no-such");
    key(&mut a, KeyCode::Enter);
    assert!(matches!(a.mode, Mode::Pick(_)));
    key(&mut a, KeyCode::Esc);
    assert_eq!(a.mode, Mode::Normal);
    assert_eq!(a.lessons[a.lesson].lesson.id, "lecture-2");
}

#[test]
fn braces_jump_to_the_next_group_on_every_screen() {
    let mut a = app("lecture-2", false);
    key(&mut a, KeyCode::Char('}'));
    let here = &a.lessons[a.lesson].lesson;
    assert_eq!(contact_lab::tui::group(here), "Robustness (extreme-*)");
    key(&mut a, KeyCode::Char('}'));
    assert_eq!(
        contact_lab::tui::group(&a.lessons[a.lesson].lesson),
        "Scenes (in time)"
    );
    assert_eq!(a.screen, Screen::Run);
    // On the run screen too, and back round to the lessons.
    key(&mut a, KeyCode::Char('}'));
    assert_eq!(
        contact_lab::tui::group(&a.lessons[a.lesson].lesson),
        "Lessons"
    );
    key(&mut a, KeyCode::Char('{'));
    assert_eq!(
        contact_lab::tui::group(&a.lessons[a.lesson].lesson),
        "Scenes (in time)"
    );
}

#[test]
fn the_help_of_every_screen_lists_the_picker_keys() {
    for (screen, help) in [
        ("contact", keys::help(KEYS)),
        ("run", keys::help(RUN_KEYS)),
        ("resolver", keys::help(RESOLVER_KEYS)),
    ] {
        assert!(
            help.iter()
                .any(|(l, h)| *l == "] [ } { /" && h.contains("/ finds a lesson")),
            "{screen}: the picker's keys missing"
        );
    }
    let picker = keys::help(PICKER_KEYS);
    assert!(picker
        .iter()
        .any(|(l, h)| *l == "Tab / Shift-Tab" && h.contains("group")));
}

/// Issue 28 item 5: ball-drop at step 0 shows its floor (the ball is 1 m
/// above it: the picture takes the floor's nearest point into view).
#[test]
fn ball_drop_at_step_0_shows_the_floor() {
    let a = app("ball-drop", false);
    assert_eq!(a.run.as_ref().unwrap().frame, 0);
    let mut t = term(100, 30);
    draw(&mut t, &a);
    let screen = text(t.backend().buffer());
    // The floor's line and hatching: a long run of braille in one row of the picture.
    let floor_row = screen
        .lines()
        .filter(|l| l.chars().filter(|c| *c == '⠤').count() > 30)
        .count();
    assert!(floor_row >= 1, "{screen}");
}

/// Issue 28 item 5: on the resolver screen of stack-5 (contacts numbered at
/// the boxes' corners, beside the boxes' names) no label is drawn over
/// another: every body name is whole ("box" and its number), at both sizes.
#[test]
fn resolver_labels_do_not_overlap() {
    for (w, h) in [(100, 30), (80, 24)] {
        let mut a = app("stack-5", false);
        keys(&mut a, KeyCode::Right, 90);
        key(&mut a, KeyCode::Enter);
        assert_eq!(a.screen, Screen::Resolver);
        let mut t = term(w, h);
        draw(&mut t, &a);
        let screen = text(t.backend().buffer());
        // The picture is the left half; the table's rows name boxes too.
        for line in screen.lines() {
            let picture: String = line.chars().take(usize::from(w) / 2).collect();
            for (i, _) in picture.match_indices('b') {
                // "box4" cut by a contact number reads "b14" or "bo12".
                let rest: Vec<char> = picture[i..].chars().collect();
                let digit = |k: usize| rest.get(k).is_some_and(|c| c.is_ascii_digit());
                assert!(
                    !(digit(1) || (rest.get(1) == Some(&'o') && digit(2))),
                    "{w}×{h}: a name cut by another label: {line}"
                );
            }
        }
    }
}
