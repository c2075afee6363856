//! Terminal events, and the keys of the main screen as [`Action`]s.
//! (The edit form and the write prompt read keys themselves: they take text.)

use super::keys::{
    down_up, first_last, help_row, lessons_row, plane_row, tab_row, Binding, Global,
};
use ratatui::crossterm::event::{
    self, Event as CtEvent, KeyCode, KeyEvent, KeyEventKind, KeyModifiers, MouseEvent,
    MouseEventKind,
};

use Action::*;

/// What the main screen does with a key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Action {
    NextStage,
    PrevStage,
    /// Space / Enter: in predict mode reveal the next hidden result, else the next stage.
    Advance,
    FirstStage,
    LastStage,
    NextContact,
    PrevContact,
    ScrollDown,
    ScrollUp,
    LineDown,
    LineUp,
    Edit,
    Reset,
    Predict,
    Zoom,
    Symbols,
    Write,
    /// A key every screen has (lessons, plane, help, quit): the router's.
    Global(Global),
}

/// The contact screen's keys: what the help shows and what each key does.
pub const KEYS: &[Binding<Action>] = &[
    Binding {
        label: "→ l",
        help: "next stage",
        keys: &[(KeyCode::Right, NextStage), (KeyCode::Char('l'), NextStage)],
    },
    Binding {
        label: "← h",
        help: "previous stage",
        keys: &[(KeyCode::Left, PrevStage), (KeyCode::Char('h'), PrevStage)],
    },
    Binding {
        label: "Space Enter",
        help: "next stage; in predict mode first reveal the next result",
        keys: &[(KeyCode::Char(' '), Advance), (KeyCode::Enter, Advance)],
    },
    first_last!("first / last stage", FirstStage, LastStage),
    tab_row!("next / previous contact", NextContact, PrevContact),
    lessons_row!(Action::Global),
    down_up!(
        "scroll the stage panel a line (the mouse wheel too)",
        LineDown,
        LineUp
    ),
    Binding {
        label: "PgDn / PgUp",
        help: "scroll the stage panel a page",
        keys: &[(KeyCode::PageDown, ScrollDown), (KeyCode::PageUp, ScrollUp)],
    },
    Binding {
        label: "e",
        help: "edit restitution, friction, masses, velocities, … of this contact",
        keys: &[(KeyCode::Char('e'), Edit)],
    },
    Binding {
        label: "r",
        help: "reset this lesson to its file's values",
        keys: &[(KeyCode::Char('r'), Reset)],
    },
    Binding {
        label: "p",
        help: "predict mode: hide each result until Space reveals it",
        keys: &[(KeyCode::Char('p'), Predict)],
    },
    plane_row!(Action::Global),
    Binding {
        label: "z",
        help: "picture full size / beside the stages",
        keys: &[(KeyCode::Char('z'), Zoom)],
    },
    Binding {
        label: "s",
        help: "list the symbols of the stage's formulas, with meaning and unit",
        keys: &[(KeyCode::Char('s'), Symbols)],
    },
    Binding {
        label: "0-9 - . ( [",
        help: "predict mode: type your answer to the hidden result (number or vector); Enter grades it",
        keys: &[],
    },
    Binding {
        label: "w",
        help: "write this worked solution to a Markdown file",
        keys: &[(KeyCode::Char('w'), Write)],
    },
    help_row!(
        "this help; ? again: the glossary of every symbol",
        Action::Global
    ),
    Binding {
        label: "q Esc Ctrl-C",
        help: "quit (q and Esc ask first when edits or a predict score would be lost)",
        keys: &[
            (KeyCode::Char('q'), Action::Global(Global::Quit)),
            (KeyCode::Esc, Action::Global(Global::Quit)),
        ],
    },
];

/// The main screen's meaning of a key press, if any (from [`KEYS`]).
pub fn action(key: KeyEvent) -> Option<Action> {
    if key.kind != KeyEventKind::Press {
        return None;
    }
    if key.modifiers.contains(KeyModifiers::CONTROL) {
        return matches!(key.code, KeyCode::Char('c')).then_some(Action::Global(Global::Quit));
    }
    super::keys::find(KEYS, key.code)
}

/// Ctrl-C: quits at once, whatever would be lost.
pub fn ctrl_c(key: KeyEvent) -> bool {
    key.code == KeyCode::Char('c') && key.modifiers.contains(KeyModifiers::CONTROL)
}

/// A terminal event the app cares about.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Event {
    Key(KeyEvent),
    Mouse(MouseEvent),
    /// Playback's clock: this many seconds passed since the last tick.
    Tick(f64),
    /// The terminal changed size: draw again.
    Resize,
}

/// Waits for the next key press, mouse event or resize (other events are
/// skipped), or with `tick` until that much time has passed (a
/// [`Event::Tick`]); `None` as soon as `stop` is set (a signal asked the app
/// to end), checked every 100 ms while nothing comes.
pub fn next(
    stop: &std::sync::atomic::AtomicUsize,
    tick: Option<std::time::Duration>,
) -> std::io::Result<Option<Event>> {
    let start = std::time::Instant::now();
    loop {
        if stop.load(std::sync::atomic::Ordering::Relaxed) != 0 {
            return Ok(None);
        }
        let wait = match tick {
            Some(t) => {
                let gone = start.elapsed();
                if gone >= t {
                    return Ok(Some(Event::Tick(gone.as_secs_f64())));
                }
                (t - gone).min(std::time::Duration::from_millis(100))
            }
            None => std::time::Duration::from_millis(100),
        };
        if !event::poll(wait)? {
            continue;
        }
        match event::read()? {
            CtEvent::Key(k) if k.kind == KeyEventKind::Press => return Ok(Some(Event::Key(k))),
            CtEvent::Mouse(m) if m.kind != MouseEventKind::Moved => {
                return Ok(Some(Event::Mouse(m)))
            }
            CtEvent::Resize(..) => return Ok(Some(Event::Resize)),
            _ => {}
        }
    }
}
