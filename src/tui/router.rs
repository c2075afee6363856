//! The router: which screen has the keys, the keys every screen shares
//! (lessons, plane, help, quit: [`Global`], handled here once), and the
//! moves between the screens of the stack.
//!
//! The screens stack as run → detection or resolver → contact: `app.run`,
//! `app.detect`, `app.resolver` hold each level's state when it is open and
//! `app.screen` names the one on top. Each screen owns its state and has
//! `key()` (its key table's actions, answering with an [`Outcome`]) and
//! `render()` ([`View`]); the contact screen's state is the app's own.

use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyEventKind, KeyModifiers};

use super::app::{App, Mode};
use super::event::{self, Action};
use super::keys::{self, Global};
use super::screens::{At, Key, Outcome, Screen, View, DETECT_KEYS, RESOLVER_KEYS, RUN_KEYS};

impl App {
    /// Handles one key press in whatever mode is active.
    pub fn key(&mut self, key: KeyEvent) {
        if key.kind != KeyEventKind::Press {
            return;
        }
        self.status = None;
        if self.too_small.get() {
            // Nothing of the app is on show: only quitting acts.
            if event::ctrl_c(key) || key.code == KeyCode::Char('q') {
                self.quit = true;
            }
            return;
        }
        match std::mem::replace(&mut self.mode, Mode::Normal) {
            Mode::Normal if self.screen != Screen::Contact => self.screen_key(key),
            Mode::Normal if self.up_key(key) => {}
            Mode::Normal if self.answer_start(key) => {}
            Mode::Normal if event::ctrl_c(key) => self.quit = true,
            Mode::Normal => match event::action(key) {
                Some(Action::Global(g)) => self.global(g),
                Some(a) => self.update(a),
                None => {}
            },
            Mode::Help => self.help_key(key),
            Mode::Glossary(at) => self.glossary_key(at, key),
            Mode::Answer { input, error } => self.answer_key(input, error, key),
            Mode::Edit(form) => self.edit_key(form, key),
            Mode::Write { input, error } => self.write_key(input, error, key),
            Mode::Pick(p) => self.picker_key(p, key),
            Mode::Quit(_) => self.quit_key(key),
            Mode::Events(at) => self.events_key(at, key),
            Mode::Confirm(path) => match key.code {
                KeyCode::Char('y') | KeyCode::Char('Y') => self.write_to(path, true),
                _ => {
                    self.say(
                        format!("not written: {} is unchanged", path.display()),
                        false,
                    );
                }
            },
        }
    }

    /// The keys every screen has, whichever screen's table bound them.
    pub(crate) fn global(&mut self, g: Global) {
        match g {
            Global::Quit => self.request_quit(),
            Global::Help => {
                self.help_scroll = 0;
                self.mode = Mode::Help;
            }
            Global::Plane => {
                self.plane = self.plane.next();
                if self.screen == Screen::Detect {
                    self.redetect();
                }
            }
            Global::NextLesson => self.goto_lesson((self.lesson + 1) % self.lessons.len()),
            Global::PrevLesson => {
                let n = self.lessons.len();
                self.goto_lesson((self.lesson + n - 1) % n)
            }
            Global::PickLesson => self.open_picker(),
            Global::NextGroup => self.jump_group(true),
            Global::PrevGroup => self.jump_group(false),
        }
    }

    /// The screen on top of the stack, unless it is the contact screen.
    pub(crate) fn top(&self) -> Option<&dyn View> {
        match self.screen {
            Screen::Run => self.run.as_deref().map(|v| v as &dyn View),
            Screen::Resolver => self.resolver.as_deref().map(|v| v as &dyn View),
            Screen::Detect => self.detect.as_deref().map(|v| v as &dyn View),
            Screen::Contact => None,
        }
    }

    /// The screen the contact screen was opened from, if any: the
    /// detection (through the step's resolution) or the resolver.
    pub(crate) fn below_contact(&self) -> Option<&dyn View> {
        match (&self.detect, &self.resolver) {
            (Some(d), Some(_)) => Some(&**d as &dyn View),
            (None, Some(r)) => Some(&**r as &dyn View),
            _ => None,
        }
    }

    /// The level names of the breadcrumb, from the run down to the screen
    /// on top (the lesson's name and the contact's are added by the caller).
    pub(crate) fn levels(&self) -> Vec<String> {
        let mut parts = vec![];
        if let Some(run) = &self.run {
            parts.push(run.crumb());
        }
        if matches!(self.screen, Screen::Detect | Screen::Contact) {
            if let Some(d) = &self.detect {
                parts.push(d.crumb(self.screen == Screen::Detect));
            }
        }
        if !matches!(self.screen, Screen::Run | Screen::Detect) {
            if let Some(r) = &self.resolver {
                parts.push(r.crumb(self.detect.is_some()));
            }
        }
        parts
    }

    /// A key on the run, resolver or detection screen, through the
    /// screen's key table.
    fn screen_key(&mut self, key: KeyEvent) {
        if key.modifiers.contains(KeyModifiers::CONTROL) {
            if key.code == KeyCode::Char('c') {
                self.quit = true;
            }
            return;
        }
        if self.screen == Screen::Run && key.code == KeyCode::Esc {
            if let Some(step) = self.cancel_recording() {
                return self.say(
                    format!("cancelled: step {step}'s resolver iterations are not recorded"),
                    false,
                );
            }
            if let Some(step) = self.cancel_detecting() {
                return self.say(format!("cancelled: step {step}'s detection"), false);
            }
        }
        let table = match self.screen {
            Screen::Run => RUN_KEYS,
            Screen::Detect => DETECT_KEYS,
            _ => RESOLVER_KEYS,
        };
        let Some(action) = keys::find(table, key.code) else {
            return;
        };
        let outcome = match action {
            Key::Global(g) => return self.global(g),
            Key::LineDown => return self.wheel(false),
            Key::LineUp => return self.wheel(true),
            _ => match self.screen {
                Screen::Run => match self.run.as_deref_mut() {
                    Some(run) => run.key(action),
                    None => return,
                },
                Screen::Detect => {
                    let (Some(run), Some(d)) = (self.run.as_deref(), self.detect.as_deref_mut())
                    else {
                        return;
                    };
                    let at = At {
                        lesson: &self.lessons[self.lesson].lesson,
                        player: &run.player,
                        step: run.frame as u64,
                        plane: self.plane,
                    };
                    d.key(action, &at)
                }
                _ => match self.resolver.as_deref_mut() {
                    Some(r) => r.key(action),
                    None => return,
                },
            },
        };
        self.follow(outcome);
    }

    /// Does what a screen's key asked of the router.
    fn follow(&mut self, outcome: Outcome) {
        match outcome {
            Outcome::Done => {}
            Outcome::Say(text) => self.say(text, false),
            Outcome::Events => self.show_events(),
            Outcome::Resolver(trace) => self.show_resolver(*trace),
            Outcome::Open(Screen::Detect) => self.open_detect(),
            Outcome::Open(Screen::Contact) if self.screen == Screen::Detect => self.open_stages(),
            Outcome::Open(Screen::Contact) => self.open_contact(),
            Outcome::Open(_) => {}
            Outcome::Up => match self.screen {
                Screen::Detect => {
                    self.detect = None;
                    self.screen = Screen::Run;
                }
                Screen::Resolver if self.run.is_some() => {
                    self.resolver = None;
                    self.screen = Screen::Run;
                }
                _ => self.request_quit(),
            },
        }
    }

    /// Esc or Backspace on the contact screen: up a level when there is one
    /// (the resolver, or the detection the contact was opened from).
    fn up_key(&mut self, key: KeyEvent) -> bool {
        if !matches!(key.code, KeyCode::Esc | KeyCode::Backspace) || self.resolver.is_none() {
            return false;
        }
        self.opened = None;
        self.baseline = None;
        if self.detect.is_some() {
            // Opened from the detection (Enter on a pair's contact): back there.
            self.resolver = None;
            self.screen = Screen::Detect;
        } else {
            self.screen = Screen::Resolver;
        }
        true
    }
}
