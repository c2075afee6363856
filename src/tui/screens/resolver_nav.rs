//! Keys of the resolver screen: step through one resolution's iterations,
//! select a contact, and go down to its stages (Esc comes back up).

use std::cell::Cell;

use ratatui::crossterm::event::{KeyCode, KeyEvent};

use super::{Key, ResolverView, Screen};
use crate::trace::step::StepTrace;
use crate::tui::app::{App, Entry};

impl App {
    pub(super) fn show_resolver(&mut self, trace: StepTrace) {
        let selected = trace.tables.first().and_then(|t| t.next).unwrap_or(0);
        self.resolver = Some(Box::new(ResolverView {
            trace,
            stop: 0,
            selected,
            scroll: Cell::new(0),
        }));
        self.screen = Screen::Resolver;
    }

    /// Esc or Backspace on the stepper: up a level when there is one (the
    /// resolver, or the detection the contact was opened from).
    pub(crate) fn up_key(&mut self, key: KeyEvent) -> bool {
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

    pub(super) fn resolver_key(&mut self, action: Key) {
        let Some(r) = self.resolver.as_deref_mut() else {
            return;
        };
        let last = r.trace.tables.len().saturating_sub(1);
        let contacts = r.trace.world.contacts.len();
        let stop = match action {
            Key::Forward => Some((r.stop + 1).min(last)),
            Key::Back => Some(r.stop.saturating_sub(1)),
            Key::First => Some(0),
            Key::Last => Some(last),
            _ => None,
        };
        if let Some(s) = stop {
            r.stop = s;
            if let Some(k) = r.trace.tables[s].next {
                r.selected = k;
            }
            return;
        }
        match action {
            Key::NextContact if contacts > 0 => r.selected = (r.selected + 1) % contacts,
            Key::PrevContact if contacts > 0 => r.selected = (r.selected + contacts - 1) % contacts,
            Key::Open if contacts == 0 => self.say("this step has no contacts".into(), false),
            Key::Open => self.open_contact(),
            Key::Up if self.run.is_some() => {
                self.resolver = None;
                self.screen = Screen::Run;
            }
            Key::Up => self.request_quit(),
            _ => {}
        }
    }

    /// The stepper on the selected contact, bodies as the stop finds them.
    pub(super) fn open_contact(&mut self) {
        let Some(r) = self.resolver.as_deref() else {
            return;
        };
        let lesson = r.trace.lesson_at(&self.lessons[self.lesson].lesson, r.stop);
        let k = r.selected.min(lesson.contacts.len().saturating_sub(1));
        self.opened = Some(Entry {
            pristine: lesson.clone(),
            lesson,
            edits: vec![],
        });
        self.contact = k;
        self.page = 0;
        self.scroll = 0;
        self.baseline = None;
        self.recompute();
        self.screen = Screen::Contact;
    }
}
