//! The run screen's events list shows the tunnelling auditor's `tunnelled`
//! event, and with continuous detection on the `toi` event instead
//! (issue 25, item 6).

use crate::common;
use crate::common::tui::{draw, key, term, text};

use contact_lab::lesson::embedded;
use contact_lab::tui::{self, App};
use ratatui::crossterm::event::KeyCode;

/// The run screen of `lesson` after its first step, as text.
fn after_first_step(lesson: &std::path::Path) -> (App, String) {
    let mut a = tui::open(Some(lesson.as_os_str()), None).expect("opens");
    key(&mut a, KeyCode::Right);
    let mut t = term(200, 40);
    draw(&mut t, &a);
    let shown = text(t.backend().buffer());
    (a, shown)
}

#[test]
fn the_events_list_shows_tunnelled_without_ccd_and_toi_with_it() {
    let dir = common::scratch("ccd-events");
    let source = embedded::find("bullet-wall").unwrap();
    let without = dir.join("bullet.toml");
    std::fs::write(&without, source).unwrap();
    let with = dir.join("bullet-ccd.toml");
    std::fs::write(
        &with,
        source.replace("steps = 30", "steps = 30\nccd = \"conservative\""),
    )
    .unwrap();
    let (a, shown) = after_first_step(&without);
    let kinds = event_kinds(&a);
    assert_eq!(kinds, vec!["tunnelled"]);
    assert!(
        shown.contains("tunnelled: bullet ↔ wall met at t = 0.0048 s"),
        "{shown}"
    );
    let (a, shown) = after_first_step(&with);
    let kinds = event_kinds(&a);
    assert_eq!(kinds, vec!["toi"]);
    assert!(
        shown.contains("time of collision (conservative, 2 tests): bullet ↔ wall"),
        "{shown}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn f_chooses_tunnelled_events_and_n_jumps_to_one() {
    let dir = common::scratch("ccd-events-jump");
    let path = dir.join("bullet.toml");
    std::fs::write(&path, embedded::find("bullet-wall").unwrap()).unwrap();
    let mut a = tui::open(Some(path.as_os_str()), None).expect("opens");
    let kinds = contact_lab::tui::screens::EVENT_KINDS;
    let at = kinds
        .iter()
        .position(|k| *k == "tunnelled")
        .expect("a kind f offers");
    for _ in 0..at {
        key(&mut a, KeyCode::Char('f'));
    }
    key(&mut a, KeyCode::Char('n'));
    let run = a.run.as_ref().unwrap();
    let event = run
        .player
        .run
        .events
        .iter()
        .find(|e| e.kind == "tunnelled")
        .unwrap();
    assert_eq!(
        run.frame as u64, event.step,
        "n jumps to the tunnelled event"
    );
}

/// The kinds of the run's events so far.
fn event_kinds(a: &App) -> Vec<&'static str> {
    let run = a.run.as_ref().unwrap();
    run.player.run.events.iter().map(|e| e.kind).collect()
}

/// `n` past the last event of any kind says so in plain words: "no event
/// after step 1", not "no any event" (the filter's name is not a word of
/// the sentence).
#[test]
fn n_past_the_last_event_says_no_event() {
    let dir = common::scratch("ccd-events-none");
    let path = dir.join("bullet.toml");
    std::fs::write(&path, embedded::find("bullet-wall").unwrap()).unwrap();
    let mut a = tui::open(Some(path.as_os_str()), None).expect("opens");
    key(&mut a, KeyCode::Char('n'));
    assert_eq!(
        a.run.as_ref().unwrap().frame,
        1,
        "n jumps to step 1's event"
    );
    key(&mut a, KeyCode::Char('n'));
    let said = a.status.as_ref().map(|s| s.text.clone());
    assert_eq!(said.as_deref(), Some("no event after step 1"));
    let _ = std::fs::remove_dir_all(&dir);
}
