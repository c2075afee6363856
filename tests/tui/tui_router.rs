//! The router (issue 41): the keys every screen has — help, the view
//! plane, the lessons, quit — act the same on the run, the detection, the
//! resolver and the contact screen, whichever screen's table binds them.

use crate::common::tui::{app, key};

use contact_lab::tui::app::Mode;
use contact_lab::tui::screens::Screen;
use contact_lab::tui::App;
use ratatui::crossterm::event::KeyCode;

/// The app on each screen, with the screen's name.
fn on_each_screen() -> Vec<(Screen, App)> {
    let run = app("gjk-separated", false);
    let mut detect = app("gjk-separated", false);
    key(&mut detect, KeyCode::Char('d'));
    let mut resolver = app("stack-5", false);
    key(&mut resolver, KeyCode::Right);
    key(&mut resolver, KeyCode::Enter);
    let contact = app("lecture-2", false);
    let all = vec![
        (Screen::Run, run),
        (Screen::Detect, detect),
        (Screen::Resolver, resolver),
        (Screen::Contact, contact),
    ];
    for (screen, a) in &all {
        assert_eq!(a.screen, *screen, "the app is not on the {screen:?} screen");
    }
    all
}

#[test]
fn question_mark_opens_the_help_on_every_screen() {
    for (screen, mut a) in on_each_screen() {
        key(&mut a, KeyCode::Char('?'));
        assert_eq!(a.mode, Mode::Help, "{screen:?}");
        assert_eq!(a.screen, screen, "the help opens over the screen");
    }
}

#[test]
fn v_turns_the_view_plane_on_every_screen() {
    for (screen, mut a) in on_each_screen() {
        let before = a.plane;
        key(&mut a, KeyCode::Char('v'));
        assert_eq!(a.plane, before.next(), "{screen:?}");
        assert_eq!(a.screen, screen, "v keeps the screen");
    }
}

#[test]
fn q_quits_at_once_on_every_screen_when_nothing_would_be_lost() {
    for (screen, mut a) in on_each_screen() {
        key(&mut a, KeyCode::Char('q'));
        assert!(a.quit, "{screen:?}: {:?}", a.mode);
    }
}

#[test]
fn right_bracket_opens_the_next_lesson_except_on_the_detection() {
    // The detection's ] does nothing: its table does not bind the lessons.
    for (screen, mut a) in on_each_screen() {
        let lesson = a.lesson;
        key(&mut a, KeyCode::Char(']'));
        let moved = a.lesson != lesson;
        assert_eq!(moved, screen != Screen::Detect, "{screen:?}");
    }
}
