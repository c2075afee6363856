//! A screen's keys as one table: each row is what the help shows (the keys
//! as written, what they do) and the keys it binds to actions, so dispatch
//! and help cannot drift apart.

use ratatui::crossterm::event::KeyCode;

/// One row of a screen's key table.
#[derive(Clone, Copy)]
pub struct Binding<A: 'static> {
    /// The keys as the help writes them (`→ l / ← h`).
    pub label: &'static str,
    /// What they do.
    pub help: &'static str,
    /// Each key and its action; empty for keys read as text elsewhere
    /// (the predict mode's digits).
    pub keys: &'static [(KeyCode, A)],
}

/// The action `code` is bound to in `table`.
pub fn find<A: Copy>(table: &[Binding<A>], code: KeyCode) -> Option<A> {
    table
        .iter()
        .flat_map(|b| b.keys.iter())
        .find(|(k, _)| *k == code)
        .map(|(_, a)| *a)
}

/// The help rows of `table`: keys as written, what they do.
pub fn help<A>(table: &[Binding<A>]) -> Vec<(&'static str, &'static str)> {
    table.iter().map(|b| (b.label, b.help)).collect()
}

/// The keys every screen handles the same way, whatever its table calls
/// them: the router ([`crate::tui::router`]) acts on them once.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Global {
    NextLesson,
    PrevLesson,
    /// `/`: the lesson picker (type to filter, Tab between groups).
    PickLesson,
    /// `}` / `{`: the next / previous group's first lesson.
    NextGroup,
    PrevGroup,
    /// The view plane of the picture: xy → yz → zx.
    Plane,
    Help,
    /// Asks first when work would be lost.
    Quit,
}

/// The key rows several screens share, written once: each takes the help
/// text and the actions, in the screen's own action type.
///
/// `→ l / ← h`: forward and back.
macro_rules! forward_back {
    ($help:expr, $forward:expr, $back:expr) => {
        $crate::tui::keys::Binding {
            label: "→ l / ← h",
            help: $help,
            keys: &[
                (::ratatui::crossterm::event::KeyCode::Right, $forward),
                (::ratatui::crossterm::event::KeyCode::Char('l'), $forward),
                (::ratatui::crossterm::event::KeyCode::Left, $back),
                (::ratatui::crossterm::event::KeyCode::Char('h'), $back),
            ],
        }
    };
}

/// `Home g / End G`: the first and the last.
macro_rules! first_last {
    ($help:expr, $first:expr, $last:expr) => {
        $crate::tui::keys::Binding {
            label: "Home g / End G",
            help: $help,
            keys: &[
                (::ratatui::crossterm::event::KeyCode::Home, $first),
                (::ratatui::crossterm::event::KeyCode::Char('g'), $first),
                (::ratatui::crossterm::event::KeyCode::End, $last),
                (::ratatui::crossterm::event::KeyCode::Char('G'), $last),
            ],
        }
    };
}

/// `Tab / Shift-Tab`: the next and the previous.
macro_rules! tab_row {
    ($help:expr, $next:expr, $prev:expr) => {
        $crate::tui::keys::Binding {
            label: "Tab / Shift-Tab",
            help: $help,
            keys: &[
                (::ratatui::crossterm::event::KeyCode::Tab, $next),
                (::ratatui::crossterm::event::KeyCode::BackTab, $prev),
            ],
        }
    };
}

/// `↓ j / ↑ k`: down and up a line (or a row).
macro_rules! down_up {
    ($help:expr, $down:expr, $up:expr) => {
        $crate::tui::keys::Binding {
            label: "↓ j / ↑ k",
            help: $help,
            keys: &[
                (::ratatui::crossterm::event::KeyCode::Down, $down),
                (::ratatui::crossterm::event::KeyCode::Char('j'), $down),
                (::ratatui::crossterm::event::KeyCode::Up, $up),
                (::ratatui::crossterm::event::KeyCode::Char('k'), $up),
            ],
        }
    };
}

/// `] [ } { /`: the lessons ([`Global`]), `$global` wrapping them in the
/// screen's action type.
macro_rules! lessons_row {
    ($global:path) => {
        $crate::tui::keys::Binding {
            label: "] [ } { /",
            help: "next / previous lesson, group; / finds a lesson",
            keys: &[
                (
                    ::ratatui::crossterm::event::KeyCode::Char(']'),
                    $global($crate::tui::keys::Global::NextLesson),
                ),
                (
                    ::ratatui::crossterm::event::KeyCode::Char('['),
                    $global($crate::tui::keys::Global::PrevLesson),
                ),
                (
                    ::ratatui::crossterm::event::KeyCode::Char('}'),
                    $global($crate::tui::keys::Global::NextGroup),
                ),
                (
                    ::ratatui::crossterm::event::KeyCode::Char('{'),
                    $global($crate::tui::keys::Global::PrevGroup),
                ),
                (
                    ::ratatui::crossterm::event::KeyCode::Char('/'),
                    $global($crate::tui::keys::Global::PickLesson),
                ),
            ],
        }
    };
}

/// `v`: the view plane ([`Global::Plane`]).
macro_rules! plane_row {
    ($global:path) => {
        $crate::tui::keys::Binding {
            label: "v",
            help: "view plane of the picture: xy → yz → zx",
            keys: &[(
                ::ratatui::crossterm::event::KeyCode::Char('v'),
                $global($crate::tui::keys::Global::Plane),
            )],
        }
    };
}

/// `?`: the help ([`Global::Help`]), `$help` saying what it shows.
macro_rules! help_row {
    ($help:expr, $global:path) => {
        $crate::tui::keys::Binding {
            label: "?",
            help: $help,
            keys: &[(
                ::ratatui::crossterm::event::KeyCode::Char('?'),
                $global($crate::tui::keys::Global::Help),
            )],
        }
    };
}

pub(crate) use {down_up, first_last, forward_back, help_row, lessons_row, plane_row, tab_row};
