//! Keys of the resolver screen: step through one resolution's iterations,
//! select a contact, and go down to its stages (Esc comes back up).

use std::cell::Cell;

use super::{Key, Outcome, ResolverView, Screen};
use crate::physics::resolver::Phase;
use crate::trace::step::StepTrace;
use crate::tui::app::{App, Entry};

impl App {
    pub(crate) fn show_resolver(&mut self, trace: StepTrace) {
        let selected = trace.tables.first().and_then(|t| t.next).unwrap_or(0);
        self.resolver = Some(Box::new(ResolverView {
            trace,
            stop: 0,
            selected,
            scroll: Cell::new(0),
            pivot: None,
        }));
        self.screen = Screen::Resolver;
    }

    /// The stepper on the selected contact, bodies as the stop finds them.
    pub(crate) fn open_contact(&mut self) {
        let Some(r) = self.resolver.as_deref() else {
            return;
        };
        // The soft step and XPBD have no lecture stages: their own record.
        if r.trace.substeps.is_some() {
            self.screen = Screen::Resolver;
            return;
        }
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

impl ResolverView {
    /// A key of the resolver's table (the router has taken the shared ones).
    pub(crate) fn key(&mut self, action: Key) -> Outcome {
        if self.trace.substeps.is_some() {
            return super::resolver_substeps::key(self, action);
        }
        let r = self;
        if r.lcp_key(action) {
            return Outcome::Done;
        }
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
            return Outcome::Done;
        }
        match action {
            Key::NextContact if contacts > 0 => r.selected = (r.selected + 1) % contacts,
            Key::PrevContact if contacts > 0 => r.selected = (r.selected + contacts - 1) % contacts,
            Key::Open if contacts == 0 => return Outcome::Say("this step has no contacts".into()),
            Key::Open => return Outcome::Open(Screen::Contact),
            Key::Up => return Outcome::Up,
            _ => {}
        }
        Outcome::Done
    }

    /// The resolver's level in the breadcrumb: the iteration on show, or,
    /// under a contact opened from the detection, the step it resolves.
    pub(crate) fn crumb(&self, from_detection: bool) -> String {
        if from_detection {
            return format!("step {}'s resolver", self.trace.step);
        }
        if let Some(rec) = &self.trace.substeps {
            return super::resolver_substeps::crumb(self, rec);
        }
        if let Some(lcp) = self.lcp_crumb() {
            return lcp;
        }
        let table = &self.trace.tables[self.stop];
        let (phase, used) = match table.stop.phase {
            Phase::Position => ("position", self.trace.resolver.position.iterations_used),
            Phase::Velocity => ("velocity", self.trace.resolver.velocity.iterations_used),
        };
        if table.stop.iteration < used {
            format!("{phase} iteration {}", table.stop.iteration)
        } else {
            format!("{phase} phase done ({used} iterations)")
        }
    }
}
