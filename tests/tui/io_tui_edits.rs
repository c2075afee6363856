//! Random key and edit sequences driven into the app on a `TestBackend`
//! (issue 23): whatever the keys, the app never panics, and the frame on
//! show always exists (a run shortened by an edit that blew it up keeps the
//! frames before it and says why it stopped).

use contact_lab::tui::screens::Screen;
use contact_lab::tui::{self, App, Theme};
use proptest::prelude::*;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::Terminal;

fn open(lesson: &str) -> App {
    let mut a = tui::open(Some(lesson), None).expect("opens");
    a.theme = Theme { color: false };
    a
}

fn key(app: &mut App, code: KeyCode) {
    app.key(KeyEvent::new(code, KeyModifiers::NONE));
}

fn keys(app: &mut App, code: KeyCode, n: usize) {
    for _ in 0..n {
        key(app, code);
    }
}

fn draw(t: &mut Terminal<TestBackend>, app: &App) -> String {
    t.draw(|f| f.render_widget(app, f.area())).unwrap();
    let buf = t.backend().buffer();
    (0..buf.area.height)
        .map(|y| {
            (0..buf.area.width)
                .map(|x| buf[(x, y)].symbol())
                .collect::<String>()
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Opens the edit form on `label`, sets `value`, closes the form.
fn edit(app: &mut App, label: &str, value: &str) {
    key(app, KeyCode::Char('e'));
    let contact_lab::tui::app::Mode::Edit(form) = &app.mode else {
        panic!("e opens the form")
    };
    let at = form
        .fields
        .iter()
        .position(|f| f.label == label)
        .unwrap_or_else(|| panic!("no field {label}"));
    keys(app, KeyCode::Down, at);
    key(app, KeyCode::Enter);
    app.key(KeyEvent::new(KeyCode::Char('u'), KeyModifiers::CONTROL));
    for c in value.chars() {
        key(app, KeyCode::Char(c));
    }
    key(app, KeyCode::Enter);
    if matches!(app.mode, contact_lab::tui::app::Mode::Edit(_)) {
        key(app, KeyCode::Esc);
    }
}

/// The sequence: stack-5, → 40 times, Enter, End, Enter, `e`,
/// box1's velocity set to 1e6, 0, 0. The run blows up at the step edited:
/// it panicked drawing frame 40 of 40.
#[test]
fn an_edit_that_blows_the_run_up_at_its_step_keeps_the_frames_before() {
    let mut a = open("stack-5");
    keys(&mut a, KeyCode::Right, 40);
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::End);
    key(&mut a, KeyCode::Enter);
    edit(&mut a, "box1: velocity", "1e6, 0, 0");
    let mut t = Terminal::new(TestBackend::new(100, 30)).unwrap();
    let shown = draw(&mut t, &a);
    let run = a.run.as_ref().expect("a run");
    assert!(
        run.frame < run.player.run.frames.len(),
        "the frame on show exists"
    );
    assert_eq!(
        run.player.computed(),
        39,
        "frames up to the step before kept"
    );
    assert_eq!(a.screen, Screen::Run, "back on the run, where it stopped");
    assert!(!a.quit);
    let stopped = run
        .player
        .run
        .stopped
        .clone()
        .expect("the run says it stopped");
    assert!(stopped.contains("blew up"), "{stopped}");
    assert!(shown.contains("blew up"), "the screen says why:\n{shown}");
    // Every key still answers without a panic.
    for code in [
        KeyCode::Right,
        KeyCode::Enter,
        KeyCode::End,
        KeyCode::Esc,
        KeyCode::Left,
    ] {
        key(&mut a, code);
        draw(&mut t, &a);
    }
}

/// One thing a user does.
#[derive(Debug, Clone)]
enum Act {
    Key(KeyCode),
    /// Right this many times (a run played forward).
    Forward(usize),
    /// `e`, the form's field `field` (modulo their number) set to `value`.
    Edit(usize, &'static str),
    /// Playback time passing, in seconds.
    Tick(f64),
    Resize(u16, u16),
}

const VALUES: [&str; 10] = [
    "1e6, 0, 0",
    "0, 3, 0",
    "0, -50, 0",
    "0.5",
    "0",
    "1e9",
    "1e-9",
    "-1",
    "2",
    "nonsense",
];

fn act() -> impl Strategy<Value = Act> {
    let codes = prop::sample::select(vec![
        KeyCode::Right,
        KeyCode::Left,
        KeyCode::Enter,
        KeyCode::End,
        KeyCode::Home,
        KeyCode::Esc,
        KeyCode::Backspace,
        KeyCode::Tab,
        KeyCode::BackTab,
        KeyCode::Char(' '),
        KeyCode::Char('n'),
        KeyCode::Char('N'),
        KeyCode::Char('l'),
        KeyCode::Char('h'),
        KeyCode::Char('G'),
        KeyCode::Char('g'),
        KeyCode::Char('>'),
        KeyCode::Char('<'),
        KeyCode::Up,
        KeyCode::Down,
        KeyCode::PageDown,
        KeyCode::PageUp,
        KeyCode::Char('?'),
        KeyCode::Char('v'),
        KeyCode::Char('z'),
        KeyCode::Char('t'),
    ]);
    prop_oneof![
        6 => codes.prop_map(Act::Key),
        2 => (1usize..60).prop_map(Act::Forward),
        3 => (0usize..40, prop::sample::select(VALUES.to_vec())).prop_map(|(f, v)| Act::Edit(f, v)),
        1 => (0.0f64..2.0).prop_map(Act::Tick),
        1 => (1u16..140, 1u16..50).prop_map(|(w, h)| Act::Resize(w, h)),
    ]
}

/// Goes down to the stepper (Enter on the run, on the resolver) and sets
/// field `field` of the form `e` opens (when it opens) to `value`.
fn edit_nth(app: &mut App, field: usize, value: &str) {
    for _ in 0..2 {
        if app.screen != Screen::Contact && app.mode == contact_lab::tui::app::Mode::Normal {
            key(app, KeyCode::Enter);
        }
    }
    key(app, KeyCode::Char('e'));
    let contact_lab::tui::app::Mode::Edit(form) = &app.mode else {
        return;
    };
    let n = form.fields.len();
    if n == 0 {
        return;
    }
    keys(app, KeyCode::Down, field % n);
    key(app, KeyCode::Enter);
    app.key(KeyEvent::new(KeyCode::Char('u'), KeyModifiers::CONTROL));
    for c in value.chars() {
        key(app, KeyCode::Char(c));
    }
    key(app, KeyCode::Enter);
    if matches!(app.mode, contact_lab::tui::app::Mode::Edit(_)) {
        key(app, KeyCode::Esc);
    }
}

fn play(lesson: &str, acts: &[Act]) {
    let mut a = open(lesson);
    let mut t = Terminal::new(TestBackend::new(100, 30)).unwrap();
    for act in acts {
        match act {
            Act::Key(code) => key(&mut a, *code),
            Act::Forward(n) => keys(&mut a, KeyCode::Right, *n),
            Act::Edit(f, v) => edit_nth(&mut a, *f, v),
            Act::Tick(s) => a.tick(*s),
            Act::Resize(w, h) => t = Terminal::new(TestBackend::new(*w, *h)).unwrap(),
        }
        if a.quit {
            // The real loop ends here; start again as a user would.
            a = open(lesson);
        }
        draw(&mut t, &a);
        if let Some(run) = &a.run {
            assert!(run.frame < run.player.run.frames.len(), "{act:?}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    #[test]
    fn random_keys_and_edits_never_panic_on_stack_5(acts in prop::collection::vec(act(), 1..40)) {
        play("stack-5", &acts);
    }

    #[test]
    fn random_keys_and_edits_never_panic_on_sleep_modes(acts in prop::collection::vec(act(), 1..40)) {
        play("sleep-modes", &acts);
    }

    #[test]
    fn random_keys_and_edits_never_panic_on_cradle_over_time(acts in prop::collection::vec(act(), 1..40)) {
        play("cradle-over-time", &acts);
    }
}
