//! Keys, ticks and clicks of the run and resolver screens, and the moves
//! between the three levels (run → resolver → contact and back up).

use std::cell::Cell;

use ratatui::crossterm::event::{
    KeyCode, KeyEvent, KeyModifiers, MouseButton, MouseEvent, MouseEventKind,
};

use super::{
    Key, Pick, ResolverView, RunView, Screen, Toggle, Toggles, DETECT_KEYS, EVENT_KINDS,
    RESOLVER_KEYS, RUN_KEYS, SPEEDS,
};
use crate::session::{Player, Poll};
use crate::trace::step::StepTrace;
use crate::tui::app::{App, Entry, Mode};
use crate::tui::keys;

/// At most this many steps are computed in one tick (playback falls behind
/// real time rather than freezing the app).
const STEPS_PER_TICK: usize = 64;

impl App {
    /// Opens the lesson's top screen: a scene's run; the resolver for a
    /// lesson with several contacts when `several`; else the stepper as it is.
    pub(crate) fn open_lesson_screen(&mut self, several: bool) {
        let lesson = &self.lessons[self.lesson].lesson;
        if let Some(player) = Player::new(lesson) {
            self.run = Some(Box::new(RunView {
                player,
                frame: 0,
                playing: false,
                speed: 2,
                owed: 0.0,
                toggles: Toggles::default(),
                event_kind: 0,
                events_scroll: 0,
                recording: None,
                detecting: None,
            }));
            self.screen = Screen::Run;
        } else if several && lesson.contacts.len() > 1 {
            let trace = StepTrace::of_lesson(lesson);
            self.show_resolver(trace);
        }
    }

    fn show_resolver(&mut self, trace: StepTrace) {
        let selected = trace.tables.first().and_then(|t| t.next).unwrap_or(0);
        self.resolver = Some(Box::new(ResolverView {
            trace,
            stop: 0,
            selected,
            scroll: Cell::new(0),
        }));
        self.screen = Screen::Resolver;
    }

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
            if under_way && run.player.poll() == Poll::Ready(true) && waiting && on_run {
                run.frame += 1;
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

    /// Esc or Backspace on the stepper: up a level when there is one.
    pub(crate) fn up_key(&mut self, key: KeyEvent) -> bool {
        if !matches!(key.code, KeyCode::Esc | KeyCode::Backspace) || self.resolver.is_none() {
            return false;
        }
        self.opened = None;
        self.baseline = None;
        self.screen = Screen::Resolver;
        true
    }

    /// A key on the run or resolver screen, through the screen's key table.
    pub(crate) fn screen_key(&mut self, key: KeyEvent) {
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
        match action {
            Key::Quit => self.quit = true,
            Key::Help => {
                self.help_scroll = 0;
                self.mode = Mode::Help;
            }
            Key::Plane => self.plane = self.plane.next(),
            Key::NextLesson => self.goto_lesson((self.lesson + 1) % self.lessons.len()),
            Key::PrevLesson => {
                let n = self.lessons.len();
                self.goto_lesson((self.lesson + n - 1) % n)
            }
            Key::PickLesson => self.open_picker(),
            Key::NextGroup => self.jump_group(true),
            Key::PrevGroup => self.jump_group(false),
            Key::LineDown => self.wheel(false),
            Key::LineUp => self.wheel(true),
            _ if self.screen == Screen::Run => self.run_key(action),
            _ if self.screen == Screen::Detect => self.detect_key(action),
            _ => self.resolver_key(action),
        }
    }

    fn run_key(&mut self, action: Key) {
        let Some(run) = self.run.as_deref_mut() else {
            return;
        };
        let mut said = None;
        match action {
            Key::PlayPause => {
                if !run.playing && run.frame as u64 >= run.player.steps {
                    run.frame = 0;
                }
                run.playing = !run.playing;
                run.owed = 0.0;
            }
            Key::Forward => {
                run.playing = false;
                match forward(run) {
                    Forward::Moved => {}
                    Forward::End => said = Some(end_of_run(run)),
                    Forward::Busy => said = Some(computing(run)),
                }
            }
            Key::Back => {
                run.playing = false;
                run.frame = run.frame.saturating_sub(1);
            }
            Key::First => {
                run.playing = false;
                run.frame = 0;
            }
            Key::Last => {
                run.playing = false;
                run.frame = run.player.computed() as usize;
            }
            Key::Faster => run.speed = (run.speed + 1).min(SPEEDS.len() - 1),
            Key::Slower => run.speed = run.speed.saturating_sub(1),
            Key::EventKind => run.event_kind = (run.event_kind + 1) % EVENT_KINDS.len(),
            Key::NextEvent => said = jump_event(run, true),
            Key::PrevEvent => said = jump_event(run, false),
            Key::Toggle(Toggle::Contacts) => run.toggles.contacts = !run.toggles.contacts,
            Key::Toggle(Toggle::Normals) => run.toggles.normals = !run.toggles.normals,
            Key::Toggle(Toggle::Sleep) => run.toggles.sleep = !run.toggles.sleep,
            Key::Toggle(Toggle::Names) => run.toggles.names = !run.toggles.names,
            Key::PageUp => run.events_scroll += 5,
            Key::PageDown => run.events_scroll = run.events_scroll.saturating_sub(5),
            Key::Open if run.recording.is_some() => {
                said = Some(recording(run));
            }
            Key::Open if run.player.records_later() && run.frame > 0 => {
                // A large scene: recorded on another thread (the key bar says
                // so; Esc cancels), shown by `tick` when done.
                run.playing = false;
                let at = std::time::Instant::now();
                run.recording = run.player.record_later(run.frame as u64).map(|r| (r, at));
            }
            Key::Open => {
                run.playing = false;
                let frame = run.frame as u64;
                match run.player.record(frame) {
                    Some(trace) => self.show_resolver(trace),
                    None => said = Some("step 0 is the state before the first step: nothing is resolved yet (→ takes a step)".into()),
                }
            }
            Key::Detect => {
                run.playing = false;
                return self.open_detect();
            }
            Key::Up => self.quit = true,
            _ => {}
        }
        if let Some(text) = said {
            self.say(text, false);
        }
    }

    fn resolver_key(&mut self, action: Key) {
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
            Key::Up => self.quit = true,
            _ => {}
        }
    }

    /// The stepper on the selected contact, bodies as the stop finds them.
    fn open_contact(&mut self) {
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

    /// A mouse event: a click picks a contact, a body or a table row; the
    /// wheel scrolls.
    pub fn mouse(&mut self, m: MouseEvent) {
        if self.mode != Mode::Normal || self.too_small.get() {
            return;
        }
        let up = match m.kind {
            MouseEventKind::ScrollUp => Some(true),
            MouseEventKind::ScrollDown => Some(false),
            _ => None,
        };
        if let Some(up) = up {
            return self.wheel(up);
        }
        if m.kind != MouseEventKind::Down(MouseButton::Left) {
            return;
        }
        self.status = None;
        let table = self.targets.table.get();
        if self.screen == Screen::Resolver && contains(table, m.column, m.row) {
            let first = self.targets.table_first.get();
            let Some(r) = self.resolver.as_deref_mut() else {
                return;
            };
            // One line of border and one of headings above the rows.
            if let Some(row) = (m.row as usize).checked_sub(table.y as usize + 2) {
                let k = first + row;
                if k < r.trace.world.contacts.len() {
                    r.selected = k;
                }
            }
            return;
        }
        if let Some(pick) = self.pick(m.column, m.row) {
            match pick {
                Pick::Contact(k) => {
                    if let Some(r) = self.resolver.as_deref_mut() {
                        r.selected = k;
                    }
                    self.say(
                        format!("contact {k} selected (Enter opens its stages)"),
                        false,
                    );
                }
                Pick::Body(i) => {
                    let name = self.lessons[self.lesson].lesson.bodies[i].name.clone();
                    self.say(format!("body {i}: {name}"), false);
                }
            }
        }
    }

    fn wheel(&mut self, up: bool) {
        match self.screen {
            Screen::Run => {
                if let Some(run) = self.run.as_deref_mut() {
                    run.events_scroll = if up {
                        run.events_scroll + 1
                    } else {
                        run.events_scroll.saturating_sub(1)
                    };
                }
            }
            Screen::Resolver => {
                if let Some(r) = self.resolver.as_deref() {
                    let s = r.scroll.get();
                    r.scroll.set(if up { s.saturating_sub(1) } else { s + 1 });
                }
            }
            Screen::Detect => {}
            Screen::Contact => {
                self.scroll = if up {
                    self.scroll.saturating_sub(1)
                } else {
                    (self.scroll + 1).min(self.scroll_max.get())
                }
            }
        }
    }

    /// The contact or body drawn nearest the cell clicked (within two
    /// cells); clicking again where several lie (corners seen edge-on) takes
    /// the next of them.
    fn pick(&self, col: u16, row: u16) -> Option<Pick> {
        let area = self.targets.picture.get();
        if matches!(self.screen, Screen::Contact | Screen::Detect) || !contains(area, col, row) {
            return None;
        }
        let [x0, x1, y0, y1] = self.targets.bounds.get();
        let (w, h) = (f64::from(area.width.max(2)), f64::from(area.height.max(2)));
        let cx = f64::from(col - area.x) + 0.5;
        let cy = f64::from(row - area.y) + 0.5;
        let points = self.targets.points.borrow();
        let mut near: Vec<(f64, Pick)> = points
            .iter()
            .map(|(p, pick)| {
                let px = (p[0] - x0) / (x1 - x0) * w;
                let py = (y1 - p[1]) / (y1 - y0) * h;
                ((px - cx).powi(2) + (2.0 * (py - cy)).powi(2), *pick)
            })
            .filter(|(d, _)| *d <= 4.0 * 4.0)
            .collect();
        near.sort_by(|a, b| a.0.total_cmp(&b.0));
        let best = near.first()?.0;
        // Those drawn in the same cell as the nearest.
        near.retain(|(d, _)| *d <= best + 1.0);
        let selected = self.resolver.as_ref().map(|r| Pick::Contact(r.selected));
        let at = near.iter().position(|(_, p)| Some(*p) == selected);
        Some(near[at.map_or(0, |i| (i + 1) % near.len())].1)
    }
}

fn contains(r: ratatui::layout::Rect, col: u16, row: u16) -> bool {
    col >= r.x && col < r.x + r.width && row >= r.y && row < r.y + r.height
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
