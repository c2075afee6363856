//! The scene screens above the contact stepper: *run* (a scene in time:
//! play, pause, step, charts, events) and *resolver* (one resolution's
//! iterations stop by stop). Enter goes down a level (frame → its resolver
//! iterations → an iteration's contact), Esc or Backspace up. Their state
//! lives here or in the screen's own file ([`detect_nav`]); each has a
//! `key()` ([`run_nav`], [`resolver_nav`], [`detect_nav`]) and a [`View`]
//! (its body drawn by [`run`], [`resolver`], [`detect`]); the router in
//! [`crate::tui::router`] hands keys to the one on top. They read the
//! recorded traces ([`Player`], [`StepTrace`]): no physics here.

mod chrome;
mod detect;
mod detect_minkowski;
mod detect_nav;
mod detect_toi;
mod edit;
mod events;
mod nav;
mod picture;
mod resolver;
mod resolver_lcp;
mod resolver_nav;
pub mod resolver_substeps;
mod run;
mod run_nav;

use std::cell::Cell;

use ratatui::buffer::Buffer;
use ratatui::layout::Rect;

use crate::session::{Player, Recording};
use crate::trace::step::StepTrace;
pub use chrome::{breadcrumb, breadcrumb_fit, render};
pub(crate) use detect_nav::At;
pub use detect_nav::{DetectView, Shown, DETECT_KEYS};

/// What a screen's key asks of the router ([`crate::tui::router`]).
#[derive(Debug)]
pub(crate) enum Outcome {
    /// Done inside the screen.
    Done,
    /// A line in the key bar.
    Say(String),
    /// The screen named, one level down (the router builds it).
    Open(Screen),
    /// The resolver on this resolution (Enter on the run).
    Resolver(Box<StepTrace>),
    /// The events on show, each in full (`i` on the run).
    Events,
    /// Esc: up a level (quits at the top).
    Up,
}

/// A screen above the contact stepper, as the chrome draws it: its body,
/// its key table (dispatch and help), its help notes and its key bar.
pub(crate) trait View {
    /// The key table: what each key does and what the help says.
    fn keys(&self) -> &'static [Binding<Key>];
    /// The help overlay's title and the notes under the keys.
    fn help(&self) -> (&'static str, &'static [&'static str]);
    /// The key bar's short list (help and quit last: they always show).
    fn bar(&self) -> &'static [(&'static str, &'static str)];
    /// The body, between the header and the key bar.
    fn render(&self, app: &crate::tui::app::App, area: Rect, buf: &mut Buffer);
    /// The first line of the contact screen's help, when opened from here.
    fn up_note(&self) -> &'static str {
        ""
    }
}

/// The screen on show.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Screen {
    Run,
    Resolver,
    Contact,
    /// A step's detection: pairs, GJK and EPA iterations, time of collision.
    Detect,
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
    /// Movement bounds over the step (recorded with continuous detection on).
    pub bounds: bool,
}

impl Default for Toggles {
    fn default() -> Self {
        Toggles {
            contacts: true,
            normals: true,
            sleep: true,
            names: true,
            bounds: true,
        }
    }
}

/// Which events `n` / `N` jump to.
pub const EVENT_KINDS: [&str; 9] = [
    "any",
    "bounce",
    "contact",
    "sleep",
    "limit",
    "energy",
    "overlap",
    "tunnelled",
    "toi",
];

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
    /// The events the list showed when last drawn (`i` shows them whole).
    pub events_shown: Cell<(usize, usize)>,
    /// How far `i`'s pop-up can scroll, as last drawn.
    pub events_max: Cell<u16>,
    /// Enter on a large scene: the step's resolution being recorded on
    /// another thread, and since when (the key bar shows it; Esc cancels).
    pub recording: Option<(Recording, std::time::Instant)>,
    /// `d` on a large scene: the step's detection being computed on another
    /// thread, and since when (the key bar shows it; Esc cancels).
    pub detecting: Option<(crate::session::Detecting, std::time::Instant)>,
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
    /// Under `solver = "lcp"`, at the velocity phase's first stop: A and b
    /// (0) or pivot j - 1 (j) on show instead of the table.
    pub pivot: Option<usize>,
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

/// What a key does on the run or the resolver screen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Key {
    PlayPause,
    /// → on the run: a step forward; on the resolver: the next stop.
    Forward,
    Back,
    First,
    Last,
    Faster,
    Slower,
    NextEvent,
    PrevEvent,
    EventKind,
    /// Enter: down a level (the step's resolver, the contact's stages).
    Open,
    Toggle(Toggle),
    PageUp,
    PageDown,
    NextContact,
    PrevContact,
    /// Esc / Backspace: up a level (quits at the top).
    Up,
    LineDown,
    LineUp,
    /// `d` on the run: the step's detection.
    Detect,
    /// `t` on the detection: the pair's time of collision.
    Toi,
    /// `m` with the time of collision: bisection ↔ conservative advancement.
    ToiMethod,
    NextPair,
    PrevPair,
    /// `x` on the detection: the shapes and A - B, the shapes, A - B.
    Picture,
    /// `i` on the run: the events on show, each in full.
    Events,
    /// A key every screen has (lessons, plane, help, quit): the router's.
    Global(Global),
}

/// What the run screen's picture shows or hides.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Toggle {
    Contacts,
    Normals,
    Sleep,
    Names,
    Bounds,
}

use crate::tui::keys::{
    down_up, first_last, forward_back, help_row, lessons_row, plane_row, tab_row, Binding, Global,
};
use ratatui::crossterm::event::KeyCode as C;

/// The quit row: `q` (and Esc where Esc is not up a level).
macro_rules! quit_row {
    ($help:expr, $keys:expr) => {
        Binding {
            label: "q Ctrl-C",
            help: $help,
            keys: $keys,
        }
    };
}
pub(crate) use quit_row;

/// The run screen's keys: what the help shows and what each key does.
pub const RUN_KEYS: &[Binding<Key>] = &[
    Binding {
        label: "Space",
        help: "play / pause",
        keys: &[(C::Char(' '), Key::PlayPause)],
    },
    forward_back!("one step forward / back (pauses)", Key::Forward, Key::Back),
    first_last!(
        "restart at step 0 / last step computed",
        Key::First,
        Key::Last
    ),
    Binding {
        label: "+ / -",
        help: "speed ¼× … 4×",
        keys: &[
            (C::Char('+'), Key::Faster),
            (C::Char('='), Key::Faster),
            (C::Char('-'), Key::Slower),
        ],
    },
    Binding {
        label: "n / N",
        help: "next / previous event (of the kind f chooses)",
        keys: &[
            (C::Char('n'), Key::NextEvent),
            (C::Char('N'), Key::PrevEvent),
        ],
    },
    Binding {
        label: "f",
        help:
            "events to jump to: any, bounce, contact, sleep, limit, energy, overlap, tunnelled, toi",
        keys: &[(C::Char('f'), Key::EventKind)],
    },
    Binding {
        label: "Enter",
        help: "this step's resolver iterations",
        keys: &[(C::Enter, Key::Open)],
    },
    Binding {
        label: "d",
        help: "this step's detection: pairs, GJK and EPA iterations, time of collision",
        keys: &[(C::Char('d'), Key::Detect)],
    },
    Binding {
        label: "c o s b m",
        help: "picture: contacts, normals, sleep state, body names, movement bounds (with ccd on)",
        keys: &[
            (C::Char('c'), Key::Toggle(Toggle::Contacts)),
            (C::Char('o'), Key::Toggle(Toggle::Normals)),
            (C::Char('s'), Key::Toggle(Toggle::Sleep)),
            (C::Char('b'), Key::Toggle(Toggle::Names)),
            (C::Char('m'), Key::Toggle(Toggle::Bounds)),
        ],
    },
    plane_row!(Key::Global),
    Binding {
        label: "PgUp / PgDn",
        help: "scroll the events list",
        keys: &[(C::PageUp, Key::PageUp), (C::PageDown, Key::PageDown)],
    },
    Binding {
        label: "i",
        help: "the events the list shows, each in full (a list cuts them at its edge)",
        keys: &[(C::Char('i'), Key::Events)],
    },
    down_up!(
        "scroll the events list a line (the mouse wheel too)",
        Key::LineDown,
        Key::LineUp
    ),
    lessons_row!(Key::Global),
    help_row!("this help", Key::Global),
    quit_row!(
        "quit",
        &[
            (C::Char('q'), Key::Global(Global::Quit)),
            (C::Esc, Key::Global(Global::Quit)),
        ]
    ),
];

/// The resolver screen's keys: what the help shows and what each key does.
pub const RESOLVER_KEYS: &[Binding<Key>] = &[
    forward_back!(
        "next / previous iteration (position phase, then velocity; lcp: A and b, each pivot, after)",
        Key::Forward,
        Key::Back
    ),
    first_last!("first stop / last stop", Key::First, Key::Last),
    tab_row!(
        "select the next / previous contact",
        Key::NextContact,
        Key::PrevContact
    ),
    Binding {
        label: "Enter",
        help: "this contact's stages, bodies as this iteration finds them",
        keys: &[(C::Enter, Key::Open)],
    },
    Binding {
        label: "Esc Backspace",
        help: "up to the run (a scene)",
        keys: &[(C::Esc, Key::Up), (C::Backspace, Key::Up)],
    },
    plane_row!(Key::Global),
    down_up!(
        "scroll the contacts table (the mouse wheel too)",
        Key::LineDown,
        Key::LineUp
    ),
    lessons_row!(Key::Global),
    help_row!("this help", Key::Global),
    quit_row!(
        "quit (Esc too, at the top)",
        &[(C::Char('q'), Key::Global(Global::Quit))]
    ),
];

/// The contact screen's keys when a level lies above it.
pub const CONTACT_UP_KEYS: &[(&str, &str)] = &[("Esc Backspace", "up to the resolver iterations")];
