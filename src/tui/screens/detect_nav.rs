//! The detection screen's state and keys: open it on the run's step (the
//! trace `session` builds, as `contact-lab detect --step N` prints it; on a
//! large scene computed on another thread), select a pair, step through its
//! iterations or its time-of-collision trials, show the shapes and A - B,
//! and go down to a contact's stages (Enter). [`super::detect`] draws it.

use ratatui::crossterm::event::KeyCode as C;

use std::cell::Cell;

use super::{quit_row, Key, Outcome, ResolverView, RunView, Screen};
use crate::lesson::Lesson;
use crate::physics::detect::ToiMethod;
use crate::render::detect::steps::stops;
use crate::session::{PairToiRun, Player};
use crate::trace::detect::{DetectTrace, PairTrace};
use crate::trace::Plane;
use crate::tui::app::{App, Mode};
use crate::tui::keys::{
    down_up, first_last, forward_back, help_row, plane_row, tab_row, Binding, Global,
};

/// A step's detection on the detection screen (`d` on the run).
#[derive(Debug, Clone)]
pub struct DetectView {
    pub trace: DetectTrace,
    /// The pair selected: `trace.pairs` (the narrow phase's), then
    /// `trace.dropped` (ruled out) counted on from them.
    pub pair: usize,
    /// The iteration on show (GJK's, then EPA's); one past them: the result.
    pub stop: usize,
    /// `t`: the selected pair's time of collision, and the trial on show
    /// (one past the trials: the result).
    pub toi: Option<(PairToiRun, usize)>,
    /// The search `t` runs (`m` switches): at first the scene's.
    pub method: ToiMethod,
    /// The search the scene's continuous detection runs (`None`: none).
    pub scene_method: Option<ToiMethod>,
    /// A ruled-out pair selected: its narrow phase run anyway, as
    /// `detect --pair A,B` runs it.
    pub forced: Option<PairTrace>,
    /// What the picture area shows (`x`).
    pub shown: Shown,
    /// The selected pair's contact Enter opens (Tab at the result).
    pub contact: usize,
}

/// What the detection screen's picture area shows (`x` cycles; where the
/// area is too small for two, `Both` shows the shapes).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shown {
    /// The two shapes and, beside them, A - B.
    Both,
    Shapes,
    /// A - B alone.
    Difference,
}

/// The detection screen's keys: what the help shows and what each key does.
pub const DETECT_KEYS: &[Binding<Key>] = &[
    down_up!(
        "select the next / previous pair (kept, then ruled out)",
        Key::NextPair,
        Key::PrevPair
    ),
    forward_back!(
        "next / previous: mesh nodes, triangles, GJK's, EPA's, result (t: trial)",
        Key::Forward,
        Key::Back
    ),
    first_last!(
        "first iteration / the result (with t: first / last trial)",
        Key::First,
        Key::Last
    ),
    Binding {
        label: "x",
        help: "picture: the shapes and A - B beside them → the shapes → A - B",
        keys: &[(C::Char('x'), Key::Picture)],
    },
    tab_row!(
        "select the next / previous contact the pair gives the resolver",
        Key::NextContact,
        Key::PrevContact
    ),
    Binding {
        label: "Enter",
        help: "the selected contact's stages, as the resolver gets it (Esc: back here)",
        keys: &[(C::Enter, Key::Open)],
    },
    Binding {
        label: "t",
        help: "the pair's time of collision over the next step (t, Esc: back)",
        keys: &[(C::Char('t'), Key::Toi)],
    },
    Binding {
        label: "m",
        help: "time of collision by bisection / by conservative advancement",
        keys: &[(C::Char('m'), Key::ToiMethod)],
    },
    plane_row!(Key::Global),
    Binding {
        label: "Esc Backspace",
        help: "back to the run at the same step",
        keys: &[(C::Esc, Key::Up), (C::Backspace, Key::Up)],
    },
    help_row!("this help", Key::Global),
    quit_row!("quit", &[(C::Char('q'), Key::Global(Global::Quit))]),
];

impl DetectView {
    /// The selected pair's narrow phase: as the step runs it, or run
    /// anyway for a pair the broad phase rules out.
    pub fn narrow(&self) -> Option<&PairTrace> {
        self.trace.pairs.get(self.pair).or(self.forced.as_ref())
    }

    /// The selected pair's two body names, and whether the broad phase kept it.
    pub fn selected(&self) -> Option<(&str, &str, bool)> {
        let kept = self.trace.pairs.len();
        match self.trace.pairs.get(self.pair) {
            Some(p) => Some((&p.a, &p.b, true)),
            None => {
                let d = self.trace.dropped.get(self.pair - kept)?;
                Some((&d.a, &d.b, false))
            }
        }
    }

    fn new(trace: DetectTrace, lesson: &Lesson) -> Self {
        let scene = scene_method(lesson);
        DetectView {
            trace,
            pair: 0,
            stop: 0,
            toi: None,
            method: scene.unwrap_or(ToiMethod::Bisection),
            scene_method: scene,
            forced: None,
            shown: Shown::Both,
            contact: 0,
        }
    }

    /// A key of the detection's table (the router has taken the shared ones).
    pub(crate) fn key(&mut self, action: Key, at: &At) -> Outcome {
        let pairs = self.trace.pairs.len() + self.trace.dropped.len();
        // The last stop is the result, after the iterations.
        let last = match (&self.toi, self.narrow()) {
            (Some((t, _)), _) => t.trace.pairs.first().map_or(0, |p| p.record.tests().len()),
            (None, Some(p)) => stops(p).len(),
            (None, None) => 0,
        };
        let stop = match &mut self.toi {
            Some((_, trial)) => trial,
            None => &mut self.stop,
        };
        match action {
            Key::Forward => *stop = (*stop + 1).min(last),
            Key::Back => *stop = stop.saturating_sub(1),
            Key::First => *stop = 0,
            Key::Last => *stop = last,
            Key::NextPair | Key::PrevPair if pairs > 1 => {
                self.pair = if action == Key::NextPair {
                    (self.pair + 1) % pairs
                } else {
                    (self.pair + pairs - 1) % pairs
                };
                self.stop = 0;
                self.toi = None;
                self.forced = None;
                self.contact = 0;
                self.force_selected(at);
            }
            Key::NextContact | Key::PrevContact => {
                let n = self
                    .trace
                    .pairs
                    .get(self.pair)
                    .map_or(0, |p| p.contacts.len());
                if n > 0 {
                    self.contact = if action == Key::NextContact {
                        (self.contact + 1) % n
                    } else {
                        (self.contact + n - 1) % n
                    };
                    if self.toi.is_none() {
                        self.stop = last;
                    }
                }
                return Outcome::Say(match n {
                    0 => "the pair gives the resolver no contact at this step".to_string(),
                    n => format!(
                        "contact {} of {n} (Enter opens its stages)",
                        self.contact + 1
                    ),
                });
            }
            Key::Picture => {
                self.shown = match self.shown {
                    Shown::Both => Shown::Shapes,
                    Shown::Shapes => Shown::Difference,
                    Shown::Difference => Shown::Both,
                };
            }
            Key::Open => return Outcome::Open(Screen::Contact),
            Key::NextPair | Key::PrevPair => {
                return Outcome::Say(format!("{pairs} pair(s) at this step"));
            }
            Key::Toi if self.toi.is_some() => self.toi = None,
            Key::Toi => return self.open_toi(at),
            Key::ToiMethod => {
                self.method = match self.method {
                    ToiMethod::Bisection => ToiMethod::Conservative,
                    ToiMethod::Conservative => ToiMethod::Bisection,
                };
                if self.toi.is_some() {
                    return self.open_toi(at);
                }
                return Outcome::Say(format!(
                    "time of collision by {} (t shows it)",
                    method_name(self.method)
                ));
            }
            Key::Up if self.toi.is_some() => self.toi = None,
            Key::Up => return Outcome::Up,
            _ => {}
        }
        Outcome::Done
    }

    /// `v` on the detection: the step's detection again in the new view
    /// plane (A - B's outline is traced in it), the pair and stop kept.
    fn redetect(&mut self, at: &At) {
        let Some(trace) = at.player.detect(at.lesson, at.step, at.plane, None) else {
            return;
        };
        self.trace = trace;
        if self.forced.is_some() {
            self.force_selected(at);
        }
    }

    /// A ruled-out pair selected: its narrow phase run anyway.
    fn force_selected(&mut self, at: &At) {
        let Some((i, j, false)) = self.bodies(at.lesson) else {
            return;
        };
        self.forced = at
            .player
            .detect(at.lesson, at.step, at.plane, Some((i, j)))
            .and_then(|t| t.pairs.into_iter().next());
    }

    /// The selected pair's two bodies, as indices into the lesson.
    fn bodies(&self, lesson: &Lesson) -> Option<(usize, usize, bool)> {
        let (a, b, kept) = self.selected()?;
        let index = |name: &str| lesson.bodies.iter().position(|x| x.name == name);
        Some((index(a)?, index(b)?, kept))
    }

    /// `t`: the selected pair's time of collision over the next step.
    fn open_toi(&mut self, at: &At) -> Outcome {
        let Some((a, b, _)) = self.selected() else {
            return Outcome::Say("this step has no pair of bodies".into());
        };
        let words = format!(
            "{a} – {b} has no time of collision: both bodies need a convex shape (a half-space has none)"
        );
        let Some((i, j, _)) = self.bodies(at.lesson) else {
            return Outcome::Done;
        };
        match at.player.toi(at.lesson, at.step, self.method, (i, j)) {
            Some(t) => {
                self.toi = Some((t, 0));
                Outcome::Done
            }
            None => Outcome::Say(words),
        }
    }

    /// The detection's level in the breadcrumb (`on_top`: no screen above it).
    pub(crate) fn crumb(&self, on_top: bool) -> String {
        match &self.toi {
            Some(_) if on_top => "detection › time of collision".into(),
            _ => "detection".into(),
        }
    }
}

/// What the detection's keys read of the run: the lesson, the run's
/// player and the step on show, and the view plane.
pub(crate) struct At<'a> {
    pub lesson: &'a Lesson,
    pub player: &'a Player,
    pub step: u64,
    pub plane: Plane,
}

impl App {
    /// `d` on the run: the detection of the bodies at the frame on show.
    pub(crate) fn open_detect(&mut self) {
        let Some(run) = self.run.as_deref() else {
            return;
        };
        if run.player.detects_later() {
            // A large scene: computed on another thread, shown by `tick`.
            return self.detect_later();
        }
        let lesson = &self.lessons[self.lesson].lesson;
        let step = run.frame as u64;
        let Some(trace) = run.player.detect(lesson, step, self.plane, None) else {
            return self.say(
                format!("step {step}'s bodies could not be found again: the run blew up"),
                true,
            );
        };
        self.show_detect(trace);
    }

    /// The detection screen on `trace`.
    fn show_detect(&mut self, trace: DetectTrace) {
        if trace.pairs.is_empty() {
            self.say(
                "no pair reaches the narrow phase at this step: the list says why each is ruled out (t: a pair's time of collision)".into(),
                false,
            );
        }
        let lesson = &self.lessons[self.lesson].lesson;
        let mut d = DetectView::new(trace, lesson);
        if let Some(run) = self.run.as_deref() {
            d.force_selected(&At {
                lesson,
                player: &run.player,
                step: run.frame as u64,
                plane: self.plane,
            });
        }
        self.detect = Some(Box::new(d));
        self.screen = Screen::Detect;
    }

    /// `v` on the detection: the step's detection again in the new plane.
    pub(crate) fn redetect(&mut self) {
        let (Some(run), Some(d)) = (self.run.as_deref(), self.detect.as_deref_mut()) else {
            return;
        };
        d.redetect(&At {
            lesson: &self.lessons[self.lesson].lesson,
            player: &run.player,
            step: run.frame as u64,
            plane: self.plane,
        });
    }

    /// Starts the detection of the frame on show on another thread (or
    /// says that one is under way).
    fn detect_later(&mut self) {
        let lesson = &self.lessons[self.lesson].lesson;
        let plane = self.plane;
        let Some(run) = self.run.as_deref_mut() else {
            return;
        };
        if run.detecting.is_some() {
            let text = detecting(run);
            return self.say(text, false);
        }
        let at = std::time::Instant::now();
        run.detecting = run
            .player
            .detect_later(lesson, run.frame as u64, plane)
            .map(|d| (d, at));
    }

    /// A detection computed on another thread, shown when it is done, if
    /// the run is still on show.
    pub(crate) fn collect_detection(&mut self) {
        let Some(run) = self.run.as_deref_mut() else {
            return;
        };
        let Some(done) = run.detecting.as_ref().and_then(|(d, _)| d.poll()) else {
            return;
        };
        let step = run.detecting.take().map_or(0, |(d, _)| d.step);
        match done {
            Some(trace) if self.screen == Screen::Run && self.mode == Mode::Normal => {
                self.show_detect(trace)
            }
            Some(_) => {}
            None => self.say(
                format!("step {step}'s bodies could not be found again: the run blew up"),
                true,
            ),
        }
    }

    /// Cancels a detection under way.
    pub(crate) fn cancel_detecting(&mut self) -> Option<u64> {
        let (d, _) = self.run.as_deref_mut()?.detecting.take()?;
        d.cancel();
        Some(d.step)
    }

    /// Enter: the selected pair's contact as the resolver gets it, on its
    /// stages (Esc comes back here). The bodies after step N are what step
    /// N + 1 detects and resolves, so the contact is looked up in step
    /// N + 1's resolution (the one the run opens with Enter at step N + 1),
    /// at its first stop, with the bodies as the resolver is handed them.
    pub(crate) fn open_stages(&mut self) {
        let Some(d) = self.detect.as_deref() else {
            return;
        };
        let Some(p) = d.trace.pairs.get(d.pair) else {
            return self.say(
                "a pair the broad phase rules out gives the resolver no contact".into(),
                false,
            );
        };
        let Some(c) = p.contacts.get(d.contact) else {
            return self.say(
                format!(
                    "{} – {} gives the resolver no contact at this step",
                    p.a, p.b
                ),
                false,
            );
        };
        let (a, b, point) = (p.a.clone(), p.b.clone(), c.point);
        let Some(run) = self.run.as_deref_mut() else {
            return;
        };
        let step = run.frame as u64 + 1;
        run.playing = false;
        if !run.player.reach(step) {
            let end = run.player.computed();
            return self.say(
                format!("no step {step} resolves this contact: the run ends at step {end}"),
                false,
            );
        }
        let Some(trace) = run.player.record(step) else {
            return self.say(
                format!("step {step}'s resolution could not be recorded: the run blew up"),
                true,
            );
        };
        let Some(k) = trace.contact_near(&a, &b, point) else {
            return self.say(
                format!("step {step}'s resolver has no contact of {a} – {b}"),
                false,
            );
        };
        self.resolver = Some(Box::new(ResolverView {
            trace,
            stop: 0,
            selected: k,
            scroll: Cell::new(0),
            pivot: None,
        }));
        self.open_contact();
    }
}

/// What the key bar says while a step's detection is computed.
pub(crate) fn detecting(run: &RunView) -> String {
    let Some((d, since)) = &run.detecting else {
        return String::new();
    };
    let spin = ["⠋", "⠙", "⠹", "⠸", "⠼", "⠴", "⠦", "⠧", "⠇", "⠏"];
    let elapsed = since.elapsed();
    // The narrow phase's pairs done, once the worker has counted them.
    let counted = match d.progress() {
        Some((done, 1)) => format!(", {done} of 1 pair"),
        Some((done, total)) => format!(", {done} of {total} pairs"),
        None => String::new(),
    };
    format!(
        "{} working: detecting step {}'s contacts{counted} ({:.0} s; a large scene) · Esc cancels · q quits",
        spin[(elapsed.as_millis() / 100) as usize % spin.len()],
        d.step,
        elapsed.as_secs_f64().floor()
    )
}

/// The search the scene's continuous detection runs, if any: the
/// time-of-collision view starts with it (bisection when none).
fn scene_method(lesson: &Lesson) -> Option<ToiMethod> {
    lesson.sim_params().and_then(|p| p.ccd.method())
}

/// The search's name in words.
pub(super) fn method_name(m: ToiMethod) -> &'static str {
    crate::trace::toi::method_words(m)
}
