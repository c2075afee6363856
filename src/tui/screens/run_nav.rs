//! Keys and playback of the run screen: play, step, jump to events, and a
//! large scene's step computed (or its resolution recorded) on another
//! thread.

use super::{Key, Outcome, RunView, Screen, Toggle, Toggles, EVENT_KINDS, SPEEDS};
use crate::session::Poll;
use crate::tui::app::{App, Mode, Status};

/// At most this many steps are computed in one tick (playback falls behind
/// real time rather than freezing the app).
const STEPS_PER_TICK: usize = 64;

impl App {
    /// Whether the run is playing, or a step is being computed on another
    /// thread (the terminal loop then ticks).
    pub fn playing(&self) -> bool {
        self.run.as_ref().is_some_and(|r| {
            (self.screen == Screen::Run && r.playing)
                || r.player.computing().is_some()
                || r.recording.is_some()
                || r.detecting.is_some()
        })
    }

    /// Playback: `seconds` of real time passed. A large scene's step being
    /// computed on another thread is collected here when it is done.
    pub fn tick(&mut self, seconds: f64) {
        if !self.playing() {
            return;
        }
        self.collect_recording();
        self.collect_detection();
        let on_run = self.screen == Screen::Run;
        let Some(run) = self.run.as_deref_mut() else {
            return;
        };
        if !(on_run && run.playing) {
            // A step asked for with → (or left over from playback): shown
            // when it is done, if the frame before it is still on show.
            // Only a step under way is collected: polling otherwise starts
            // the next one (ticks also come while a recording or a
            // detection is under way, and must not step the run).
            let waiting = run.frame as u64 == run.player.computed();
            let under_way = run.player.computing().is_some();
            let finished = under_way && run.player.poll() == Poll::Ready(true);
            if finished && waiting && on_run {
                run.frame += 1;
            }
            // The key bar's "computing step N" is stale once the step is in.
            let stale = |s: &Status| s.text.starts_with("computing step");
            if finished && self.status.as_ref().is_some_and(stale) {
                self.status = None;
            }
            return;
        }
        let dt = run.player.run.dt;
        run.owed += seconds * SPEEDS[run.speed];
        let mut steps = 0;
        while run.owed >= dt && steps < STEPS_PER_TICK {
            run.owed -= dt;
            steps += 1;
            match forward(run) {
                Forward::Moved => {}
                Forward::End => {
                    run.playing = false;
                    run.owed = 0.0;
                    break;
                }
                Forward::Busy => {
                    // Playback waits for the step; time owed meanwhile is dropped.
                    run.owed = 0.0;
                    break;
                }
            }
        }
        if steps == STEPS_PER_TICK {
            run.owed = 0.0;
        }
    }

    /// A step's resolution recorded on another thread (Enter on a large
    /// scene): shown when it is done, if the run screen is still on show.
    fn collect_recording(&mut self) {
        let Some(run) = self.run.as_deref_mut() else {
            return;
        };
        let Some(done) = run.recording.as_ref().and_then(|(r, _)| r.poll()) else {
            return;
        };
        let step = run.recording.take().map_or(0, |(r, _)| r.step);
        match done {
            Some(trace) if self.screen == Screen::Run && self.mode == Mode::Normal => {
                self.show_resolver(trace)
            }
            Some(_) => {}
            None => self.say(
                format!("step {step}'s resolution could not be recorded: the run blew up"),
                true,
            ),
        }
    }

    /// Cancels a recording under way (its thread stops at the next step).
    pub(crate) fn cancel_recording(&mut self) -> Option<u64> {
        let (r, _) = self.run.as_deref_mut()?.recording.take()?;
        r.cancel();
        Some(r.step)
    }
}

impl RunView {
    /// The run at step 0, paused, at 1× speed.
    pub(crate) fn new(player: crate::session::Player) -> Self {
        RunView {
            player,
            frame: 0,
            playing: false,
            speed: 2,
            owed: 0.0,
            toggles: Toggles::default(),
            event_kind: 0,
            events_scroll: 0,
            events_shown: std::cell::Cell::new((0, 0)),
            events_max: std::cell::Cell::new(0),
            recording: None,
            detecting: None,
        }
    }

    /// A key of the run's table (the router has taken the shared ones).
    pub(crate) fn key(&mut self, action: Key) -> Outcome {
        let run = self;
        let said = match action {
            Key::PlayPause => {
                if !run.playing && run.frame as u64 >= run.player.steps {
                    run.frame = 0;
                }
                run.playing = !run.playing;
                run.owed = 0.0;
                None
            }
            Key::Forward => {
                run.playing = false;
                match forward(run) {
                    Forward::Moved => None,
                    Forward::End => Some(end_of_run(run)),
                    Forward::Busy => Some(computing(run)),
                }
            }
            Key::Back => {
                run.playing = false;
                run.frame = run.frame.saturating_sub(1);
                None
            }
            Key::First => {
                run.playing = false;
                run.frame = 0;
                None
            }
            Key::Last => {
                run.playing = false;
                run.frame = run.player.computed() as usize;
                None
            }
            Key::Faster => {
                run.speed = (run.speed + 1).min(SPEEDS.len() - 1);
                None
            }
            Key::Slower => {
                run.speed = run.speed.saturating_sub(1);
                None
            }
            Key::EventKind => {
                run.event_kind = (run.event_kind + 1) % EVENT_KINDS.len();
                None
            }
            Key::NextEvent => jump_event(run, true),
            Key::PrevEvent => jump_event(run, false),
            Key::Toggle(t) => {
                let on = match t {
                    Toggle::Contacts => &mut run.toggles.contacts,
                    Toggle::Normals => &mut run.toggles.normals,
                    Toggle::Sleep => &mut run.toggles.sleep,
                    Toggle::Names => &mut run.toggles.names,
                    Toggle::Bounds => &mut run.toggles.bounds,
                };
                *on = !*on;
                None
            }
            Key::Events => return Outcome::Events,
            Key::PageUp => {
                run.events_scroll += 5;
                None
            }
            Key::PageDown => {
                run.events_scroll = run.events_scroll.saturating_sub(5);
                None
            }
            Key::Open if run.recording.is_some() => Some(recording(run)),
            Key::Open if run.player.records_later() && run.frame > 0 => {
                // A large scene: recorded on another thread (the key bar says
                // so; Esc cancels), shown by `tick` when done.
                run.playing = false;
                let at = std::time::Instant::now();
                run.recording = run.player.record_later(run.frame as u64).map(|r| (r, at));
                None
            }
            Key::Open => {
                run.playing = false;
                let frame = run.frame as u64;
                match run.player.record(frame) {
                    Some(trace) => return Outcome::Resolver(Box::new(trace)),
                    None => Some("step 0 is the state before the first step: nothing is resolved yet (→ takes a step)".into()),
                }
            }
            Key::Detect => {
                run.playing = false;
                return Outcome::Open(Screen::Detect);
            }
            Key::Up => return Outcome::Up,
            _ => None,
        };
        said.map_or(Outcome::Done, Outcome::Say)
    }

    /// The run's level in the breadcrumb: the frame on show.
    pub(crate) fn crumb(&self) -> String {
        let frame = &self.player.run.frames[self.frame];
        format!("t = {:.3} s, step {}", frame.time, frame.step)
    }

    /// What the key bar says while work runs on another thread (a step's
    /// resolution recorded, its detection computed).
    pub(crate) fn busy(&self) -> Option<String> {
        if self.recording.is_some() {
            Some(recording(self))
        } else if self.detecting.is_some() {
            Some(super::detect_nav::detecting(self))
        } else {
            None
        }
    }
}

/// What one frame forward did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Forward {
    Moved,
    /// The run's end (or where it stopped).
    End,
    /// A large scene's next step is being computed on another thread.
    Busy,
}

/// One frame forward, computing it when needed (a large scene's step on
/// another thread: `Busy` until it is done).
fn forward(run: &mut RunView) -> Forward {
    if (run.frame as u64) < run.player.computed() {
        run.frame += 1;
        return Forward::Moved;
    }
    match run.player.poll() {
        Poll::Ready(true) => {
            run.frame += 1;
            Forward::Moved
        }
        Poll::Ready(false) => Forward::End,
        Poll::Busy => Forward::Busy,
    }
}

fn computing(run: &RunView) -> String {
    format!(
        "computing step {} (a large scene: the keys still answer; q quits)",
        run.player.computing().unwrap_or(0)
    )
}

/// What the key bar says while a step's resolution is recorded.
pub(crate) fn recording(run: &RunView) -> String {
    let Some((r, since)) = &run.recording else {
        return String::new();
    };
    let spin = ["⠋", "⠙", "⠹", "⠸", "⠼", "⠴", "⠦", "⠧", "⠇", "⠏"];
    let elapsed = since.elapsed();
    format!(
        "{} working: recording step {}'s resolver iterations ({:.0} s; a large scene) · Esc cancels · q quits",
        spin[(elapsed.as_millis() / 100) as usize % spin.len()],
        r.step,
        elapsed.as_secs_f64().floor()
    )
}

fn end_of_run(run: &RunView) -> String {
    match &run.player.run.stopped {
        Some(why) => format!("the run stopped: {why}"),
        None => format!(
            "the scene's last step ({}): Home restarts",
            run.player.steps
        ),
    }
}

/// Moves to the next (or previous) event of the chosen kind, computing steps
/// until one comes; says so when there is none.
fn jump_event(run: &mut RunView, next: bool) -> Option<String> {
    run.playing = false;
    let kind = EVENT_KINDS[run.event_kind];
    let step = run.frame as u64;
    let fits = |k: &str| kind == "any" || kind == k;
    if next {
        loop {
            let hit = run
                .player
                .run
                .events
                .iter()
                .find(|e| e.step > step && fits(e.kind))
                .map(|e| e.step);
            if let Some(s) = hit {
                run.frame = s as usize;
                return None;
            }
            match run.player.poll() {
                Poll::Ready(true) => {}
                Poll::Ready(false) => return Some(format!("no {kind} event after step {step}")),
                Poll::Busy => return Some(computing(run)),
            }
        }
    }
    match run
        .player
        .run
        .events
        .iter()
        .rev()
        .find(|e| e.step < step && fits(e.kind))
    {
        Some(e) => {
            run.frame = e.step as usize;
            None
        }
        None => Some(format!("no {kind} event before step {step}")),
    }
}
