//! Keys of the detection screen: open it on the run's step (the trace
//! `session` builds, as `contact-lab detect --step N` prints it), select a
//! pair, step through its iterations or its time-of-collision trials, show
//! the shapes and A - B, and go down to a contact's stages (Enter).

use ratatui::crossterm::event::KeyCode as C;

use super::{Key, Screen, PLANE};
use crate::physics::detect::ToiMethod;
use crate::render::detect::steps::stops;
use crate::session::PairToiRun;
use crate::trace::detect::{DetectTrace, PairTrace};
use crate::tui::app::App;
use crate::tui::keys::Binding;

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
    Binding {
        label: "↓ j / ↑ k",
        help: "select the next / previous pair (kept, then ruled out)",
        keys: &[
            (C::Down, Key::NextPair),
            (C::Char('j'), Key::NextPair),
            (C::Up, Key::PrevPair),
            (C::Char('k'), Key::PrevPair),
        ],
    },
    Binding {
        label: "→ l / ← h",
        help: "next / previous iteration: GJK's, EPA's, the result (t: trial)",
        keys: &[
            (C::Right, Key::Forward),
            (C::Char('l'), Key::Forward),
            (C::Left, Key::Back),
            (C::Char('h'), Key::Back),
        ],
    },
    Binding {
        label: "Home g / End G",
        help: "first iteration / the result (with t: first / last trial)",
        keys: &[
            (C::Home, Key::First),
            (C::Char('g'), Key::First),
            (C::End, Key::Last),
            (C::Char('G'), Key::Last),
        ],
    },
    Binding {
        label: "x",
        help: "picture: the shapes and A - B beside them → the shapes → A - B",
        keys: &[(C::Char('x'), Key::Picture)],
    },
    Binding {
        label: "Tab / Shift-Tab",
        help: "select the next / previous contact the pair gives the resolver",
        keys: &[(C::Tab, Key::NextContact), (C::BackTab, Key::PrevContact)],
    },
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
    PLANE,
    Binding {
        label: "Esc Backspace",
        help: "back to the run at the same step",
        keys: &[(C::Esc, Key::Up), (C::Backspace, Key::Up)],
    },
    Binding {
        label: "?",
        help: "this help",
        keys: &[(C::Char('?'), Key::Help)],
    },
    Binding {
        label: "q Ctrl-C",
        help: "quit",
        keys: &[(C::Char('q'), Key::Quit)],
    },
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
    pub(crate) fn show_detect(&mut self, trace: crate::trace::detect::DetectTrace) {
        if trace.pairs.is_empty() {
            self.say(
                "no pair reaches the narrow phase at this step: the list says why each is ruled out (t: a pair's time of collision)".into(),
                false,
            );
        }
        let scene = scene_method(&self.lessons[self.lesson].lesson);
        self.detect = Some(Box::new(DetectView {
            trace,
            pair: 0,
            stop: 0,
            toi: None,
            method: scene.unwrap_or(ToiMethod::Bisection),
            scene_method: scene,
            forced: None,
            shown: Shown::Both,
            contact: 0,
        }));
        self.screen = Screen::Detect;
        self.force_selected();
    }

    pub(super) fn detect_key(&mut self, action: Key) {
        let Some(d) = self.detect.as_deref_mut() else {
            return;
        };
        let pairs = d.trace.pairs.len() + d.trace.dropped.len();
        // The last stop is the result, after the iterations.
        let last = match (&d.toi, d.narrow()) {
            (Some((t, _)), _) => t.trace.pairs.first().map_or(0, |p| p.record.tests().len()),
            (None, Some(p)) => stops(p).len(),
            (None, None) => 0,
        };
        let at = match &mut d.toi {
            Some((_, trial)) => trial,
            None => &mut d.stop,
        };
        match action {
            Key::Forward => *at = (*at + 1).min(last),
            Key::Back => *at = at.saturating_sub(1),
            Key::First => *at = 0,
            Key::Last => *at = last,
            Key::NextPair | Key::PrevPair if pairs > 1 => {
                d.pair = if action == Key::NextPair {
                    (d.pair + 1) % pairs
                } else {
                    (d.pair + pairs - 1) % pairs
                };
                d.stop = 0;
                d.toi = None;
                d.forced = None;
                d.contact = 0;
                self.force_selected();
            }
            Key::NextContact | Key::PrevContact => {
                let n = d.trace.pairs.get(d.pair).map_or(0, |p| p.contacts.len());
                if n > 0 {
                    d.contact = if action == Key::NextContact {
                        (d.contact + 1) % n
                    } else {
                        (d.contact + n - 1) % n
                    };
                    if d.toi.is_none() {
                        d.stop = last;
                    }
                }
                let text = match n {
                    0 => "the pair gives the resolver no contact at this step".to_string(),
                    n => format!("contact {} of {n} (Enter opens its stages)", d.contact + 1),
                };
                self.say(text, false);
            }
            Key::Picture => {
                d.shown = match d.shown {
                    Shown::Both => Shown::Shapes,
                    Shown::Shapes => Shown::Difference,
                    Shown::Difference => Shown::Both,
                };
            }
            Key::Open => self.open_stages(),
            Key::NextPair | Key::PrevPair => {
                self.say(format!("{pairs} pair(s) at this step"), false);
            }
            Key::Toi if d.toi.is_some() => d.toi = None,
            Key::Toi => self.open_toi(),
            Key::ToiMethod => {
                d.method = match d.method {
                    ToiMethod::Bisection => ToiMethod::Conservative,
                    ToiMethod::Conservative => ToiMethod::Bisection,
                };
                let method = d.method;
                if d.toi.is_some() {
                    self.open_toi();
                } else {
                    self.say(
                        format!("time of collision by {} (t shows it)", method_name(method)),
                        false,
                    );
                }
            }
            Key::Up if d.toi.is_some() => d.toi = None,
            Key::Up => {
                self.detect = None;
                self.screen = Screen::Run;
            }
            _ => {}
        }
    }

    /// `v` on the detection: the step's detection again in the new view
    /// plane (A - B's outline is traced in it), the pair and stop kept.
    pub(super) fn redetect(&mut self) {
        let (Some(run), Some(d)) = (self.run.as_deref(), self.detect.as_deref()) else {
            return;
        };
        let lesson = &self.lessons[self.lesson].lesson;
        let Some(trace) = run
            .player
            .detect(lesson, run.frame as u64, self.plane, None)
        else {
            return;
        };
        let forced = d.forced.is_some();
        if let Some(d) = self.detect.as_deref_mut() {
            d.trace = trace;
        }
        if forced {
            self.force_selected();
        }
    }

    /// A ruled-out pair selected: its narrow phase run anyway.
    fn force_selected(&mut self) {
        let (Some(run), Some(d)) = (self.run.as_deref(), self.detect.as_deref()) else {
            return;
        };
        let Some((a, b, false)) = d.selected() else {
            return;
        };
        let lesson = &self.lessons[self.lesson].lesson;
        let index = |name: &str| lesson.bodies.iter().position(|x| x.name == name);
        let (Some(i), Some(j)) = (index(a), index(b)) else {
            return;
        };
        let step = run.frame as u64;
        let forced = run
            .player
            .detect(lesson, step, self.plane, Some((i, j)))
            .and_then(|t| t.pairs.into_iter().next());
        if let Some(d) = self.detect.as_deref_mut() {
            d.forced = forced;
        }
    }

    /// `t`: the selected pair's time of collision over the next step.
    fn open_toi(&mut self) {
        let (Some(run), Some(d)) = (self.run.as_deref(), self.detect.as_deref()) else {
            return;
        };
        let Some((a, b, _)) = d.selected() else {
            return self.say("this step has no pair of bodies".into(), false);
        };
        let lesson = &self.lessons[self.lesson].lesson;
        let index = |name: &str| lesson.bodies.iter().position(|x| x.name == name);
        let (Some(i), Some(j)) = (index(a), index(b)) else {
            return;
        };
        let step = run.frame as u64;
        match run.player.toi(lesson, step, d.method, (i, j)) {
            Some(t) => {
                if let Some(d) = self.detect.as_deref_mut() {
                    d.toi = Some((t, 0));
                }
            }
            None => self.say(
                format!(
                    "{a} – {b} has no time of collision: both bodies need a convex shape (a half-space has none)"
                ),
                false,
            ),
        }
    }
}

/// The search the scene's continuous detection runs, if any: the
/// time-of-collision view starts with it (bisection when none).
fn scene_method(lesson: &crate::lesson::Lesson) -> Option<ToiMethod> {
    lesson.sim_params().and_then(|p| p.ccd.method())
}

/// The search's name in words.
pub(super) fn method_name(m: ToiMethod) -> &'static str {
    crate::trace::toi::method_words(m)
}
