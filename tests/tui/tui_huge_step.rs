//! The resolver screen on a huge step (issue 23): a pile of 32 coincident
//! spheres records step 1 past the row budget, and the screen says which
//! tables it elided, shows the rows the last iteration changed (or how
//! many, where they were elided), and where the picture's bodies come from.

use contact_lab::tui::screens::Screen;
use contact_lab::tui::{self, Theme};
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::Terminal;

/// A scene of `n` spheres all at the same place on a floor.
fn pile(n: usize) -> std::path::PathBuf {
    crate::common::pile::coincident("tui-huge", n)
}

#[test]
fn a_huge_steps_resolver_screen_says_what_it_elided() {
    let path = pile(32);
    let mut app = tui::open(Some(path.as_os_str()), None).expect("opens");
    app.theme = Theme { color: false };
    let mut t = Terminal::new(TestBackend::new(140, 40)).unwrap();
    let key = |app: &mut tui::App, code| app.key(KeyEvent::new(code, KeyModifiers::NONE));
    key(&mut app, KeyCode::Right);
    key(&mut app, KeyCode::Enter);
    assert_eq!(app.screen, Screen::Resolver);
    let r = app.resolver.as_ref().unwrap();
    assert!(r.trace.resolver.elision.is_some(), "a huge step");
    let screen = |app: &tui::App, t: &mut Terminal<TestBackend>| {
        t.draw(|f| f.render_widget(app, f.area())).unwrap();
        crate::common::tui::text(t.backend().buffer())
    };
    // Stop 0: the whole table.
    let s0 = screen(&app, &mut t);
    assert!(!s0.contains("Table elided"), "{s0}");
    assert!(s0.contains("32: s0 ↔ s1"), "{s0}");
    // Stop 1 follows iteration 0, whose rows are kept.
    key(&mut app, KeyCode::Right);
    let s1 = screen(&app, &mut t);
    assert!(
        s1.contains("Table elided: a huge step (528 contacts)"),
        "{s1}"
    );
    assert!(
        s1.contains("Last iteration changed 62 other contact(s):"),
        "{s1}"
    );
    // Before iteration 1 (odd: elided) the picture shows stop 0's bodies.
    assert!(
        s1.contains("The picture shows the bodies as at stop 0"),
        "{s1}"
    );
    // Stop 2 follows iteration 1, whose rows are elided.
    key(&mut app, KeyCode::Right);
    let s2 = screen(&app, &mut t);
    assert!(
        s2.contains("elided (kept at iterations 0, 2, 4, …)"),
        "{s2}"
    );
    // Before iteration 2 (even: kept) the picture is the stop's own.
    assert!(
        !s2.contains("The picture shows the bodies as at stop"),
        "{s2}"
    );
}
