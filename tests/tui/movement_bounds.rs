//! The run screen draws each moving body's movement bounds over the step
//! (swept AABB and swept sphere) when continuous detection is on, with a
//! legend in the picture's title; `m` hides and shows them (issue 25,
//! item 2).

use crate::common;
use crate::common::tui::{draw, key, snapshot, term, text};

use contact_lab::lesson::embedded;
use contact_lab::tui;
use ratatui::crossterm::event::KeyCode;

#[test]
fn the_run_picture_shows_the_bullets_movement_bounds_and_m_hides_them() {
    let dir = common::scratch("movement-bounds-tui");
    let source = embedded::find("bullet-wall").unwrap();
    let with = dir.join("bullet-ccd.toml");
    std::fs::write(
        &with,
        source.replace("steps = 30", "steps = 30\nccd = \"bisection\""),
    )
    .unwrap();
    let mut a = tui::open(Some(with.as_os_str()), None).expect("opens");
    key(&mut a, KeyCode::Right);
    let frame = &a.run.as_ref().unwrap().player.run.frames[1];
    let bullet = frame.movement[0].expect("the bullet moves");
    assert!(frame.movement[1].is_none(), "the wall does not move");
    // Its swept AABB over step 1: from −0.51 to −0.49 + v Δt along x, v the
    // velocity the step integrates (100 m/s damped by 0.99^Δt); its swept
    // sphere about the middle of the path, radius 0.01 + v Δt / 2.
    let dt = 1.0 / 60.0;
    let reach = 100.0 * 0.99f64.powf(dt) * dt;
    assert!((bullet.aabb[0][0] + 0.51).abs() < 1e-9, "{bullet:?}");
    assert!(
        (bullet.aabb[1][0] - (-0.49 + reach)).abs() < 1e-9,
        "{bullet:?}"
    );
    assert!((bullet.centre[0] - (-0.5 + reach / 2.0)).abs() < 1e-9);
    assert!((bullet.radius - (0.01 + reach / 2.0)).abs() < 1e-9);
    let mut t = term(100, 30);
    draw(&mut t, &a);
    snapshot("tui_run_movement_bounds_100x30", &t);
    let shown = text(t.backend().buffer());
    assert!(shown.contains("movement bounds (m)"), "{shown}");
    key(&mut a, KeyCode::Char('m'));
    draw(&mut t, &a);
    let hidden = text(t.backend().buffer());
    assert!(!hidden.contains("movement bounds"), "{hidden}");
    assert_ne!(shown, hidden);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn without_ccd_no_bounds_are_recorded() {
    let dir = common::scratch("movement-bounds-tui-off");
    let lesson = dir.join("bullet.toml");
    std::fs::write(&lesson, embedded::find("bullet-wall").unwrap()).unwrap();
    let mut a = tui::open(Some(lesson.as_os_str()), None).expect("opens");
    key(&mut a, KeyCode::Right);
    assert!(a.run.as_ref().unwrap().player.run.frames[1]
        .movement
        .is_empty());
    let _ = std::fs::remove_dir_all(&dir);
}
