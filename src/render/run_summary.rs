//! `simulate`'s default text: a run in a screenful. Energy at the start and
//! the end (and its extremes), the deepest penetration, the iterations the
//! resolver used, the events, and every movable body's final state. The
//! frames are folded in as they come, so memory stays flat in the number of
//! steps; `--table` prints the full per-step table instead
//! ([`super::run::text`]).

use std::fmt::Write;

use crate::format::Fmt;
use crate::trace::run::{EventLine, Frame, RunTrace};

/// A value and the frame (step, time) where it was seen.
#[derive(Debug, Clone, Copy, PartialEq)]
struct At {
    value: f64,
    step: u64,
    time: f64,
}

/// The run's numbers, folded frame by frame.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Summary {
    first: Option<Frame>,
    last: Option<Frame>,
    frames: u64,
    lowest: Option<At>,
    highest: Option<At>,
    deepest: Option<At>,
    most_position: usize,
    most_velocity: usize,
    most_contacts: usize,
}

fn energy(f: &Frame) -> f64 {
    f.kinetic_energy + f.potential_energy
}

impl Summary {
    /// Folds in one recorded frame.
    pub fn add(&mut self, f: &Frame) {
        let at = |value| At {
            value,
            step: f.step,
            time: f.time,
        };
        let e = energy(f);
        if self.lowest.is_none_or(|l| e < l.value) {
            self.lowest = Some(at(e));
        }
        if self.highest.is_none_or(|h| e > h.value) {
            self.highest = Some(at(e));
        }
        if self.deepest.is_none_or(|d| f.max_penetration > d.value) {
            self.deepest = Some(at(f.max_penetration));
        }
        self.most_position = self.most_position.max(f.position_iterations);
        self.most_velocity = self.most_velocity.max(f.velocity_iterations);
        self.most_contacts = self.most_contacts.max(f.contacts);
        if self.first.is_none() {
            self.first = Some(f.clone());
        }
        self.last = Some(f.clone());
        self.frames += 1;
    }

    /// The summary as text, with `run`'s events (all of them, in order).
    pub fn text(&self, run: &RunTrace, events: &[EventLine], fmt: &Fmt) -> String {
        let mut out = String::new();
        let _ = writeln!(out, "{} — {}", run.lesson, run.title);
        let (Some(first), Some(last)) = (&self.first, &self.last) else {
            let _ = writeln!(out, "no step recorded");
            return out;
        };
        let movable = run.movable.iter().filter(|m| **m).count();
        let _ = writeln!(
            out,
            "{} steps of dt = {} s ({} s), {} bodies ({movable} movable)\n",
            last.step,
            fmt.num(run.dt),
            fmt.num(last.time),
            run.names.len()
        );
        let (e0, e1) = (energy(first), energy(last));
        let change = e1 - e0;
        let percent = if e0 != 0.0 {
            format!(" ({} %)", Fmt::new(3).num(100.0 * change / e0.abs()))
        } else {
            String::new()
        };
        let _ = writeln!(
            out,
            "energy (J)           {} at t = {} s → {} at t = {} s: change {}{percent}",
            fmt.num(e0),
            fmt.num(first.time),
            fmt.num(e1),
            fmt.num(last.time),
            fmt.num(change)
        );
        if let (Some(lo), Some(hi)) = (self.lowest, self.highest) {
            let _ = writeln!(
                out,
                "                     lowest {} at t = {} s, highest {} at t = {} s",
                fmt.num(lo.value),
                fmt.num(lo.time),
                fmt.num(hi.value),
                fmt.num(hi.time)
            );
        }
        match self.deepest {
            Some(d) if d.value > 0.0 => {
                let _ = writeln!(
                    out,
                    "deepest penetration  {} m at t = {} s (step {})",
                    fmt.num(d.value),
                    fmt.num(d.time),
                    d.step
                );
            }
            _ => {
                let _ = writeln!(out, "deepest penetration  none");
            }
        }
        let _ = writeln!(
            out,
            "resolver             at most {} contact(s), {} position and {} velocity iterations in a step",
            self.most_contacts, self.most_position, self.most_velocity
        );
        let _ = writeln!(
            out,
            "awake at the end     {} of {movable} movable bodies",
            last.awake
        );
        events_text(&mut out, events, fmt);
        let _ = writeln!(out, "\nfinal state (t = {} s):", fmt.num(last.time));
        for (i, b) in last.bodies.iter().enumerate() {
            if !run.movable.get(i).copied().unwrap_or(false) {
                continue;
            }
            let _ = writeln!(
                out,
                "   {}: position ({}) m, orientation [{}], velocity ({}) m/s, angular velocity ({}) rad/s, {}",
                run.names.get(i).map_or("?", String::as_str),
                fmt.list(&b.position),
                fmt.list(&b.orientation),
                fmt.list(&b.velocity),
                fmt.list(&b.angular_velocity),
                if b.awake { "awake" } else { "asleep" }
            );
        }
        if let Some(why) = &run.stopped {
            let _ = writeln!(out, "\nstopped: {why}");
        }
        let _ = writeln!(
            out,
            "\nEvery step as a table: --table (one row in every K steps: --every K)."
        );
        out
    }
}

/// How many events are listed before the list is cut (the first ones and
/// the last ones are kept).
const EVENTS_SHOWN: usize = 24;

/// The events: a count by kind, then the events themselves (the first and
/// the last ones when there are many).
fn events_text(out: &mut String, events: &[EventLine], fmt: &Fmt) {
    let mut kinds: Vec<(&str, usize)> = Vec::new();
    for e in events {
        match kinds.iter_mut().find(|(k, _)| *k == e.kind) {
            Some((_, n)) => *n += 1,
            None => kinds.push((e.kind, 1)),
        }
    }
    let by_kind = kinds
        .iter()
        .map(|(k, n)| format!("{n} {}", k.replace('_', " ")))
        .collect::<Vec<_>>()
        .join(", ");
    let _ = writeln!(
        out,
        "\nevents: {}{}",
        events.len(),
        if events.is_empty() {
            String::new()
        } else {
            format!(" ({by_kind})")
        }
    );
    let line = |out: &mut String, e: &EventLine| {
        let _ = writeln!(
            out,
            "   · t = {} s (step {}): {}",
            fmt.num(e.time),
            e.step,
            e.text
        );
    };
    if events.len() <= EVENTS_SHOWN {
        events.iter().for_each(|e| line(out, e));
        return;
    }
    let (head, tail) = (EVENTS_SHOWN * 2 / 3, EVENTS_SHOWN / 3);
    events[..head].iter().for_each(|e| line(out, e));
    let _ = writeln!(
        out,
        "   … {} more (--table shows every event in place)",
        events.len() - head - tail
    );
    events[events.len() - tail..]
        .iter()
        .for_each(|e| line(out, e));
}
