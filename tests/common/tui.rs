//! TUI test helpers (gitui style): an app on a lesson, a `TestBackend`
//! terminal, scripted keys, the edit form, and the screen read back as text.

use contact_lab::tui::app::Mode;
use contact_lab::tui::{self, App, Theme};
use ratatui::backend::TestBackend;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::Terminal;

/// The app opened on `lesson`, with or without colours.
pub fn app(lesson: &str, color: bool) -> App {
    let (lessons, at) = tui::lessons(Some(lesson)).expect("lesson loads");
    App::new(lessons, at, 0, Theme { color })
}

/// A `w × h` test terminal.
pub fn term(w: u16, h: u16) -> Terminal<TestBackend> {
    Terminal::new(TestBackend::new(w, h)).unwrap()
}

/// Draws `app` on the whole terminal.
pub fn draw(t: &mut Terminal<TestBackend>, app: &App) {
    t.draw(|f| f.render_widget(app, f.area())).unwrap();
}

/// One key press without modifiers.
pub fn key(app: &mut App, code: KeyCode) {
    app.key(KeyEvent::new(code, KeyModifiers::NONE));
}

/// The same key pressed `n` times.
pub fn keys(app: &mut App, code: KeyCode, n: usize) {
    for _ in 0..n {
        key(app, code);
    }
}

/// Ctrl + `c`.
pub fn ctrl(app: &mut App, c: char) {
    app.key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::CONTROL));
}

/// Types `text` one character key at a time.
pub fn type_text(app: &mut App, text: &str) {
    for c in text.chars() {
        key(app, KeyCode::Char(c));
    }
}

/// Opens the edit form on the field labelled `label`, clears it, types
/// `value` and sets it (Enter); the form stays open.
pub fn edit(app: &mut App, label: &str, value: &str) {
    key(app, KeyCode::Char('e'));
    let Mode::Edit(form) = &app.mode else {
        panic!("e opens the form")
    };
    let at = form
        .fields
        .iter()
        .position(|f| f.label == label)
        .unwrap_or_else(|| panic!("no field {label}"));
    keys(app, KeyCode::Down, at);
    key(app, KeyCode::Enter);
    ctrl(app, 'u');
    type_text(app, value);
    key(app, KeyCode::Enter);
}

/// The terminal held as the snapshot `name` in snapshots/.
pub fn snapshot(name: &str, t: &Terminal<TestBackend>) {
    super::snapshot_settings().bind(|| insta::assert_snapshot!(name, t.backend()));
}

/// Row `y` of the buffer as text.
pub fn row(buf: &Buffer, y: u16) -> String {
    (0..buf.area.width).map(|x| buf[(x, y)].symbol()).collect()
}

/// The whole buffer as text, a line per row.
pub fn text(buf: &Buffer) -> String {
    (0..buf.area.height)
        .map(|y| row(buf, y))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Position of the first cell where `text` starts (counted in cells: a
/// cell may hold a letter with its combining accent, e.g. d̂).
pub fn find(buf: &Buffer, text: &str) -> (u16, u16) {
    for y in 0..buf.area.height {
        let r = row(buf, y);
        if let Some(byte) = r.find(text) {
            let mut len = 0;
            let x = (0..buf.area.width)
                .take_while(|&x| {
                    len += buf[(x, y)].symbol().len();
                    len <= byte
                })
                .count() as u16;
            return (x, y);
        }
    }
    panic!("'{text}' is not on the screen:\n{}", self::text(buf));
}

/// The screen of `app` drawn at `w × h`, row by row.
pub fn screen(app: &App, w: u16, h: u16) -> Vec<String> {
    let mut t = term(w, h);
    draw(&mut t, app);
    let buf = t.backend().buffer();
    (0..h).map(|y| row(buf, y)).collect()
}

/// The first row that contains `text`.
pub fn row_of(rows: &[String], text: &str) -> Option<usize> {
    rows.iter().position(|r| r.contains(text))
}
