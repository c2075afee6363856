//! The TUI's state and its update (TEA): keys become actions, actions change
//! the state. Nothing here draws, and nothing computes physics: every number
//! comes from [`crate::worked_solution`], called again after each edit.

use std::cell::Cell;
use std::path::PathBuf;

use super::event::Action;
use super::form::Form;
use super::screens::{DetectView, ResolverView, RunView, Screen, Targets};
use super::theme::Theme;
use super::write;
use crate::exercise::answer::Score;
use crate::format::Fmt;
use crate::lesson::{edit, Lesson};
use crate::trace::Trace;

/// A lesson as loaded, and as edited in this session.
#[derive(Debug, Clone)]
pub struct Entry {
    pub pristine: Lesson,
    pub lesson: Lesson,
    /// What was changed, in order (`restitution 0.8 → 0.5`).
    pub edits: Vec<String>,
}

pub use crate::trace::Plane;

/// What has the keyboard.
#[derive(Debug, Clone, PartialEq)]
pub enum Mode {
    Normal,
    Help,
    /// Help's second page, the glossary, scrolled this many lines.
    Glossary(u16),
    /// Predict mode: the student's answer to the hidden result, being typed.
    Answer {
        input: String,
        error: Option<String>,
    },
    Edit(Form),
    /// Asking for the Markdown file name.
    Write {
        input: String,
        error: Option<String>,
    },
    /// The file exists: overwrite it?
    Confirm(PathBuf),
    /// The lesson picker (`/`): a filter and the lesson under the cursor.
    Pick(super::picker::Picker),
    /// Quit? The work it would lose, in words.
    Quit(String),
    /// The run's events on show, each in full, scrolled this many lines.
    Events(u16),
}

/// A one-line message in the key bar until the next key.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Status {
    pub text: String,
    pub error: bool,
}

#[derive(Debug, Clone)]
pub struct App {
    pub lessons: Vec<Entry>,
    pub lesson: usize,
    pub contact: usize,
    /// 0 is the lesson overview; `i ≥ 1` is `trace.stages[i - 1]`.
    pub page: usize,
    pub trace: Trace,
    /// The trace before the last edit: values that differ are marked.
    pub baseline: Option<Trace>,
    pub plane: Plane,
    pub predict: bool,
    /// Predict mode: results shown so far, per stage.
    pub revealed: Vec<usize>,
    /// Predict mode: answers graded in this lesson (reset with the lesson).
    pub score: Score,
    /// The stage panel lists the symbols of the formulas on show (`s`).
    pub symbols: bool,
    /// The last frame said "terminal too small": keys other than quit do nothing.
    pub too_small: Cell<bool>,
    /// How far the glossary page can scroll, as last drawn.
    pub glossary_max: Cell<u16>,
    /// Lines the help page is scrolled down, and how far it can, as drawn.
    pub help_scroll: u16,
    pub help_max: Cell<u16>,
    /// Lines the stage panel is scrolled down.
    pub scroll: u16,
    /// How far the stage panel can scroll, as last drawn.
    pub scroll_max: Cell<u16>,
    /// Rows of text the stage panel shows, as last drawn (a page).
    pub page_rows: Cell<u16>,
    /// Cells of text in a line of the stage panel, as last drawn.
    pub panel_width: Cell<u16>,
    /// The picture fills the right-hand side.
    pub zoom: bool,
    pub mode: Mode,
    pub status: Option<Status>,
    pub theme: Theme,
    pub fmt: Fmt,
    /// Where `w` writes.
    pub write_dir: PathBuf,
    pub quit: bool,
    /// The screen on show: run, resolver or this contact stepper.
    pub screen: Screen,
    /// A scene's run (time), when the lesson has time settings.
    pub run: Option<Box<RunView>>,
    /// One resolution's iterations, when opened.
    pub resolver: Option<Box<ResolverView>>,
    /// A step's detection, when opened (`d` on the run).
    pub detect: Option<Box<DetectView>>,
    /// The lesson the stepper shows when opened from a resolver iteration:
    /// the bodies as that iteration finds them (the lesson list keeps its own).
    pub opened: Option<Entry>,
    /// Where things were drawn, for the mouse.
    pub targets: Targets,
    /// Edits carried into the scene's run (lost when the lesson changes).
    pub run_edits: usize,
}

impl App {
    /// Opens on `lessons[lesson]`, contact `contact` (both must exist); a
    /// scene (a lesson with time settings) opens on its run instead.
    pub fn new(lessons: Vec<Lesson>, lesson: usize, contact: usize, theme: Theme) -> Self {
        let scene = lessons.get(lesson).is_some_and(|l| l.simulation.is_some());
        assert!(
            lesson < lessons.len() && (scene || contact < lessons[lesson].contacts.len()),
            "App::new: lesson {lesson} contact {contact} out of range"
        );
        let lessons: Vec<Entry> = lessons
            .into_iter()
            .map(|l| Entry {
                pristine: l.clone(),
                lesson: l,
                edits: vec![],
            })
            .collect();
        // A scene has no contact of its own until one is opened: the stepper
        // holds the first lesson with contacts meanwhile (never on show).
        let shown = if scene {
            lessons
                .iter()
                .position(|e| !e.lesson.contacts.is_empty())
                .expect("an embedded lesson has contacts")
        } else {
            lesson
        };
        let contact = if scene { 0 } else { contact };
        let trace = crate::worked_solution(&lessons[shown].lesson, contact);
        let mut app = App {
            lessons,
            lesson,
            contact,
            page: 0,
            revealed: vec![0; trace.stages.len()],
            trace,
            baseline: None,
            plane: Plane::Xy,
            predict: false,
            score: Score::default(),
            symbols: false,
            glossary_max: Cell::new(0),
            too_small: Cell::new(false),
            help_scroll: 0,
            help_max: Cell::new(0),
            scroll: 0,
            scroll_max: Cell::new(0),
            page_rows: Cell::new(0),
            panel_width: Cell::new(40),
            zoom: false,
            mode: Mode::Normal,
            status: None,
            theme,
            fmt: Fmt::new(6),
            write_dir: PathBuf::from("."),
            quit: false,
            screen: Screen::Contact,
            run: None,
            resolver: None,
            detect: None,
            opened: None,
            targets: Targets::default(),
            run_edits: 0,
        };
        app.plane = app.natural_plane();
        if scene {
            app.open_lesson_screen(false);
        }
        app
    }

    /// The lesson the stepper works on.
    pub fn entry(&self) -> &Entry {
        self.opened.as_ref().unwrap_or(&self.lessons[self.lesson])
    }

    pub(super) fn entry_mut(&mut self) -> &mut Entry {
        match &mut self.opened {
            Some(e) => e,
            None => &mut self.lessons[self.lesson],
        }
    }

    pub fn pages(&self) -> usize {
        self.trace.stages.len() + 1
    }

    /// The stage on screen, `None` on the overview.
    pub fn stage(&self) -> Option<usize> {
        self.page.checked_sub(1)
    }

    /// Solves the current contact again and keeps the place.
    pub(super) fn recompute(&mut self) {
        self.trace = crate::worked_solution(&self.entry().lesson, self.contact);
        self.page = self.page.min(self.pages() - 1);
        self.revealed = vec![0; self.trace.stages.len()];
    }

    /// The plane in which the scene moves: the one the velocities, normal and
    /// arms lie in, xy when they all do.
    pub(super) fn natural_plane(&self) -> Plane {
        let s = &self.trace.scene;
        let mut weight = [0.0f64; 3];
        let mut add = |v: [f64; 3]| {
            for (w, x) in weight.iter_mut().zip(v) {
                *w += x.abs();
            }
        };
        add(s.normal);
        for b in s.bodies.iter().filter(|b| b.slot > 0) {
            add(b.velocity);
            add(b.velocity_after);
            add([0, 1, 2].map(|i| b.position[i] - s.point[i]));
        }
        let total: f64 = weight.iter().sum();
        let flat = |axis: usize| weight[axis] <= 1e-9 * total;
        if flat(2) || !(flat(0) || flat(1)) {
            Plane::Xy
        } else if flat(0) {
            Plane::Yz
        } else {
            Plane::Zx
        }
    }

    pub(super) fn goto_lesson(&mut self, i: usize) {
        self.cancel_recording();
        self.cancel_detecting();
        self.lesson = i;
        self.score = Score::default();
        self.contact = 0;
        self.page = 0;
        self.baseline = None;
        self.scroll = 0;
        self.opened = None;
        self.run = None;
        self.resolver = None;
        self.detect = None;
        self.run_edits = 0;
        self.screen = Screen::Contact;
        if self.lessons[i].lesson.simulation.is_some() {
            self.open_lesson_screen(false);
            return;
        }
        self.recompute();
        self.plane = self.natural_plane();
        self.open_lesson_screen(true);
    }

    pub(super) fn goto_contact(&mut self, k: usize) {
        self.contact = k;
        self.baseline = None;
        self.scroll = 0;
        self.recompute();
    }

    fn goto_page(&mut self, page: usize) {
        let page = page.min(self.pages() - 1);
        if page != self.page {
            self.scroll = 0;
        }
        self.page = page;
    }

    /// Predict mode: are some of the current stage's results still hidden?
    pub fn hidden_here(&self) -> bool {
        self.stage().is_some_and(|s| !self.revealed_all(s))
    }

    /// Whether stage `s` shows all its results (always, outside predict mode).
    pub fn revealed_all(&self, s: usize) -> bool {
        !self.predict
            || self.trace.stages[s].skipped.is_some()
            || self.revealed[s] >= self.trace.stages[s].formulas.len()
    }

    /// Whether the results of the stage `id` may be shown (in the picture
    /// and the checks panel too).
    pub fn shown(&self, id: &str) -> bool {
        match self
            .trace
            .stages
            .iter()
            .position(|s| s.id.json_name() == id)
        {
            Some(s) => self.revealed_all(s),
            None => true,
        }
    }

    /// The contact screen's actions (the keys every screen has go to
    /// [`App::global`]).
    pub fn update(&mut self, action: Action) {
        use Action::*;
        match action {
            NextStage => self.goto_page(self.page + 1),
            PrevStage => self.goto_page(self.page.saturating_sub(1)),
            Advance => {
                if self.hidden_here() {
                    let s = self.page - 1;
                    self.revealed[s] += 1;
                } else if self.page + 1 < self.pages() {
                    self.goto_page(self.page + 1);
                }
            }
            FirstStage => self.goto_page(0),
            LastStage => self.goto_page(self.pages() - 1),
            NextContact | PrevContact => {
                let n = self.entry().lesson.contacts.len();
                let k = if action == NextContact {
                    (self.contact + 1) % n
                } else {
                    (self.contact + n - 1) % n
                };
                if n == 1 {
                    self.say("this lesson has one contact".into(), false);
                } else {
                    self.goto_contact(k);
                }
            }
            // A page keeps one line of the last in view.
            ScrollDown => self.scroll_by(i32::from(self.page_rows.get().max(2)) - 1),
            ScrollUp => self.scroll_by(1 - i32::from(self.page_rows.get().max(2))),
            LineDown => self.scroll_by(1),
            LineUp => self.scroll_by(-1),
            Edit => {
                let fields = edit::fields(&self.entry().lesson, self.contact);
                self.mode = Mode::Edit(Form::new(fields));
            }
            Reset => {
                let e = self.entry_mut();
                if e.edits.is_empty() {
                    self.say(
                        "nothing to reset: the lesson has its file's values".into(),
                        false,
                    );
                } else {
                    e.lesson = e.pristine.clone();
                    e.edits.clear();
                    self.baseline = Some(self.trace.clone());
                    self.recompute();
                    self.say("reset to the lesson's values".into(), false);
                }
            }
            Predict => {
                self.predict = !self.predict;
                self.score = Score::default();
                self.revealed = vec![0; self.trace.stages.len()];
                self.say(
                    if self.predict {
                        "predict mode: work out each result, type it and Enter to grade (or Space reveals)"
                    } else {
                        "predict mode off: every result shown"
                    }
                    .into(),
                    false,
                );
            }
            Zoom => self.zoom = !self.zoom,
            Symbols => self.toggle_symbols(),
            Write => {
                self.mode = Mode::Write {
                    input: write::Context::of(self).file_name(),
                    error: None,
                }
            }
            Global(g) => self.global(g),
        }
    }

    /// `s`: lists the symbols (scrolled into view when below the fold) or hides them.
    fn toggle_symbols(&mut self) {
        self.symbols = !self.symbols;
        if !self.symbols {
            return;
        }
        let Some(at) = super::stage::symbols_line(self) else {
            return self.say(
                "the symbols are listed on a stage's page (→ goes to the first)".into(),
                false,
            );
        };
        // The heading and a line of the list in view, else the list at the top.
        let rows = self.page_rows.get();
        if at + 2 > self.scroll + rows || at < self.scroll {
            self.scroll = at;
        }
    }

    /// Scrolls the stage panel by `lines` (down when positive), within its text.
    fn scroll_by(&mut self, lines: i32) {
        let max = i32::from(self.scroll_max.get());
        let at = i32::from(self.scroll.min(self.scroll_max.get()));
        self.scroll = (at + lines).clamp(0, max) as u16;
    }

    pub(super) fn say(&mut self, text: String, error: bool) {
        self.status = Some(Status { text, error });
    }
}
