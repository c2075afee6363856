//! The TUI's contact stages show the normal from the previous frame beside
//! the contact's own (issue 25, item 5): the spinning blade's step 2,
//! resolver, Enter on contact 0, → to stage 1.

use crate::common::tui::{draw, key, term, text};

use contact_lab::tui;
use ratatui::crossterm::event::KeyCode;

#[test]
fn the_contact_frame_stage_of_a_scene_step_shows_both_normals_and_the_angle() {
    let lesson = std::ffi::OsString::from("spinning-edge");
    let mut a = tui::open(Some(lesson.as_os_str()), None).expect("opens");
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Enter);
    // From the overview to stage 1, the contact frame.
    key(&mut a, KeyCode::Right);
    let mut t = term(120, 50);
    draw(&mut t, &a);
    let shown = text(t.backend().buffer());
    assert!(shown.contains("θ = acos(d̂ · d̂₋)"), "{shown}");
    assert!(shown.contains("= 90"), "{shown}");
}
