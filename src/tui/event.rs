//! Terminal events, and the keys of the main screen as [`Action`]s.
//! (The edit form and the write prompt read keys themselves: they take text.)

use ratatui::crossterm::event::{
    self, Event as CtEvent, KeyCode, KeyEvent, KeyEventKind, KeyModifiers, MouseEvent,
    MouseEventKind,
};

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
    NextLesson,
    PrevLesson,
    ScrollDown,
    ScrollUp,
    LineDown,
    LineUp,
    Edit,
    Reset,
    Predict,
    Plane,
    Zoom,
    Symbols,
    Write,
    Help,
    Quit,
}

/// Every key of the main screen: keys, action, what it does (help overlay and README).
pub const KEYS: &[(&str, &str)] = &[
    ("→ l", "next stage"),
    ("← h", "previous stage"),
    (
        "Space Enter",
        "next stage; in predict mode first reveal the next result",
    ),
    ("Home g / End G", "first / last stage"),
    ("Tab / Shift-Tab", "next / previous contact"),
    ("] / [", "next / previous lesson"),
    (
        "↓ j / ↑ k",
        "scroll the stage panel a line (the mouse wheel too)",
    ),
    ("PgDn / PgUp", "scroll the stage panel a page"),
    (
        "e",
        "edit restitution, friction, masses, velocities, … of this contact",
    ),
    ("r", "reset this lesson to its file's values"),
    ("p", "predict mode: hide each result until Space reveals it"),
    ("v", "view plane of the picture: xy → yz → zx"),
    ("z", "picture full size / beside the stages"),
    (
        "s",
        "list the symbols of the stage's formulas, with meaning and unit",
    ),
    (
        "0-9 - . ( [",
        "predict mode: type your answer to the hidden result (number or vector); Enter grades it",
    ),
    ("w", "write this worked solution to a Markdown file"),
    ("?", "this help; ? again: the glossary of every symbol"),
    ("q Esc Ctrl-C", "quit"),
];

/// The main screen's meaning of a key press, if any.
pub fn action(key: KeyEvent) -> Option<Action> {
    use Action::*;
    if key.kind != KeyEventKind::Press {
        return None;
    }
    if key.modifiers.contains(KeyModifiers::CONTROL) {
        return matches!(key.code, KeyCode::Char('c')).then_some(Quit);
    }
    Some(match key.code {
        KeyCode::Right | KeyCode::Char('l') => NextStage,
        KeyCode::Left | KeyCode::Char('h') => PrevStage,
        KeyCode::Char(' ') | KeyCode::Enter => Advance,
        KeyCode::Home | KeyCode::Char('g') => FirstStage,
        KeyCode::End | KeyCode::Char('G') => LastStage,
        KeyCode::Tab => NextContact,
        KeyCode::BackTab => PrevContact,
        KeyCode::Char(']') => NextLesson,
        KeyCode::Char('[') => PrevLesson,
        KeyCode::Down | KeyCode::Char('j') => LineDown,
        KeyCode::Up | KeyCode::Char('k') => LineUp,
        KeyCode::PageDown => ScrollDown,
        KeyCode::PageUp => ScrollUp,
        KeyCode::Char('e') => Edit,
        KeyCode::Char('r') => Reset,
        KeyCode::Char('p') => Predict,
        KeyCode::Char('v') => Plane,
        KeyCode::Char('z') => Zoom,
        KeyCode::Char('s') => Symbols,
        KeyCode::Char('w') => Write,
        KeyCode::Char('?') => Help,
        KeyCode::Char('q') | KeyCode::Esc => Quit,
        _ => return None,
    })
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
