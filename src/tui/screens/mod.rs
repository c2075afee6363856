//! The scene screens above the contact stepper: *run* (a scene in time:
//! play, pause, step, charts, events) and *resolver* (one resolution's
//! iterations stop by stop). Enter goes down a level (frame → its resolver
//! iterations → an iteration's contact), Esc or Backspace up. Their state
//! lives here; [`nav`] updates it, [`run`] and [`resolver`] draw it. They
//! read the recorded traces ([`Player`], [`StepTrace`]): no physics here.

mod chrome;
mod edit;
mod nav;
mod picture;
mod resolver;
mod run;

use std::cell::Cell;

use ratatui::layout::Rect;

use crate::session::Player;
use crate::trace::step::StepTrace;
pub use chrome::{breadcrumb, breadcrumb_fit, render};

/// The screen on show.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Screen {
    Run,
    Resolver,
    Contact,
}

/// Playback speeds, × real time.
pub const SPEEDS: [f64; 5] = [0.25, 0.5, 1.0, 2.0, 4.0];

/// What the scene picture shows (Box2D's sample toggles).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Toggles {
    pub contacts: bool,
    pub normals: bool,
    pub sleep: bool,
    pub names: bool,
}

impl Default for Toggles {
    fn default() -> Self {
        Toggles {
            contacts: true,
            normals: true,
            sleep: true,
            names: true,
        }
    }
}

/// Which events `n` / `N` jump to.
pub const EVENT_KINDS: [&str; 6] = ["any", "bounce", "contact", "sleep", "limit", "energy"];

/// A scene's run on the run screen.
#[derive(Debug, Clone)]
pub struct RunView {
    pub player: Player,
    /// The frame on show (0: before the first step).
    pub frame: usize,
    pub playing: bool,
    /// Index into [`SPEEDS`].
    pub speed: usize,
    /// Simulated time owed to playback, in seconds (ticks add, frames take).
    pub owed: f64,
    pub toggles: Toggles,
    /// Index into [`EVENT_KINDS`].
    pub event_kind: usize,
    /// Lines the events list is scrolled up from the current event.
    pub events_scroll: usize,
}

/// One resolution on the resolver screen.
#[derive(Debug, Clone)]
pub struct ResolverView {
    pub trace: StepTrace,
    /// The stop on show (index into `trace.tables`).
    pub stop: usize,
    /// The contact selected (Tab, a click); Enter opens it.
    pub selected: usize,
    /// First table row shown.
    pub scroll: Cell<usize>,
}

/// Where the last draw put what a click can pick: the picture (and its
/// bounds in scene units), the table's rows, the events list.
#[derive(Debug, Clone, Default)]
pub struct Targets {
    pub picture: Cell<Rect>,
    /// x range, y range of the picture, in view-plane units.
    pub bounds: Cell<[f64; 4]>,
    /// Picture points that can be picked: (view-plane point, contact or body).
    pub points: std::cell::RefCell<Vec<([f64; 2], Pick)>>,
    pub table: Cell<Rect>,
    /// The contact on the table's first row.
    pub table_first: Cell<usize>,
}

/// What a click in the picture picks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pick {
    Contact(usize),
    Body(usize),
}

/// The run screen's keys (help overlay and README).
pub const RUN_KEYS: &[(&str, &str)] = &[
    ("Space", "play / pause"),
    ("→ l / ← h", "one step forward / back (pauses)"),
    ("Home g / End G", "restart at step 0 / last step computed"),
    ("+ / -", "speed ¼× … 4×"),
    ("n / N", "next / previous event (of the kind f chooses)"),
    (
        "f",
        "events to jump to: any, bounce, contact, sleep, limit, energy",
    ),
    ("Enter", "this step's resolver iterations"),
    (
        "c o s b",
        "picture: contacts, normals, sleep state, body names",
    ),
    ("v", "view plane of the picture: xy → yz → zx"),
    ("PgUp / PgDn", "scroll the events list"),
    (
        "↓ j / ↑ k",
        "scroll the events list a line (the mouse wheel too)",
    ),
    ("] / [", "next / previous lesson"),
    ("?", "this help"),
    ("q Ctrl-C", "quit"),
];

/// The resolver screen's keys (help overlay and README).
pub const RESOLVER_KEYS: &[(&str, &str)] = &[
    (
        "→ l / ← h",
        "next / previous iteration (position phase, then velocity)",
    ),
    ("Home g / End G", "first stop / last stop"),
    ("Tab / Shift-Tab", "select the next / previous contact"),
    (
        "Enter",
        "this contact's stages, bodies as this iteration finds them",
    ),
    ("Esc Backspace", "up to the run (a scene)"),
    ("v", "view plane of the picture: xy → yz → zx"),
    (
        "↓ j / ↑ k",
        "scroll the contacts table (the mouse wheel too)",
    ),
    ("] / [", "next / previous lesson"),
    ("?", "this help"),
    ("q Ctrl-C", "quit (Esc too, at the top)"),
];

/// The contact screen's keys when a level lies above it.
pub const CONTACT_UP_KEYS: &[(&str, &str)] = &[("Esc Backspace", "up to the resolver iterations")];
