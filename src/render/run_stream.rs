//! A run written as it is computed (`simulate`): the text table and the JSON
//! document frame by frame, so that memory stays flat in the number of
//! steps. The bytes are those of [`super::run::text`] and of
//! [`super::run::json`] printed pretty (one document, the same keys in the
//! same order); only the events, which the JSON lists after the steps, are
//! kept until the end.

use std::io::{self, Write};

use serde_json::Value as J;

use super::run::{event_line, frame_json, frame_row, text_header};
use super::run_summary::Summary;
use crate::format::Fmt;
use crate::trace::run::{Frame, RunTrace};

/// How the run is written.
#[derive(Debug, Clone)]
pub enum Streamed {
    /// The full table (`--table`).
    Text(Fmt),
    Json,
    /// The summary (`simulate`'s default text): nothing is written until
    /// the end; the frames are folded in as they come.
    Summary(Fmt, Box<Summary>),
}

/// Writes a run to `out` as its frames come.
pub struct RunWriter<W: Write> {
    out: W,
    kind: Streamed,
    /// Events already written (text: written events are dropped from the run).
    frames: usize,
}

impl<W: Write> RunWriter<W> {
    /// Starts the output: the text header, or the JSON up to `"steps": [`.
    pub fn begin(out: W, kind: Streamed, run: &RunTrace) -> io::Result<Self> {
        let mut w = RunWriter {
            out,
            kind,
            frames: 0,
        };
        match &w.kind {
            Streamed::Text(fmt) => w.out.write_all(text_header(run, fmt).as_bytes())?,
            Streamed::Summary(..) => {}
            Streamed::Json => write!(
                w.out,
                "{{\n  \"lesson\": {},\n  \"dt\": {},\n  \"steps\": [",
                J::String(run.lesson.clone()),
                json_number(run.dt)
            )?,
        }
        Ok(w)
    }

    /// Writes frame `f`; in text, the events up to it first (and drops
    /// them from `run`: nothing else needs them).
    pub fn frame(&mut self, run: &mut RunTrace, f: &Frame) -> io::Result<()> {
        match &mut self.kind {
            Streamed::Summary(_, summary) => summary.add(f),
            Streamed::Text(fmt) => {
                let upto = run.events.partition_point(|e| e.step <= f.step);
                for e in run.events.drain(..upto) {
                    self.out.write_all(event_line(&e, fmt).as_bytes())?;
                }
                self.out.write_all(frame_row(f, fmt).as_bytes())?;
            }
            Streamed::Json => {
                let text = pretty(&frame_json(run, f))?;
                self.out
                    .write_all(if self.frames == 0 { b"\n" } else { b",\n" })?;
                self.out.write_all(indent(&text, "    ", true).as_bytes())?;
            }
        }
        self.frames += 1;
        Ok(())
    }

    /// Ends the output: the events left and why the run stopped.
    pub fn end(mut self, run: &RunTrace) -> io::Result<W> {
        match &self.kind {
            Streamed::Summary(fmt, summary) => {
                self.out
                    .write_all(summary.text(run, &run.events, fmt).as_bytes())?;
            }
            Streamed::Text(fmt) => {
                for e in &run.events {
                    self.out.write_all(event_line(e, fmt).as_bytes())?;
                }
                if let Some(why) = &run.stopped {
                    writeln!(self.out, "\nstopped: {why}")?;
                }
            }
            Streamed::Json => {
                if self.frames == 0 {
                    self.out.write_all(b"],\n")?;
                } else {
                    self.out.write_all(b"\n  ],\n")?;
                }
                let events = pretty(&super::run::events_json(run))?;
                write!(self.out, "  \"events\": {}", indent(&events, "  ", false))?;
                if let Some(why) = &run.stopped {
                    write!(self.out, ",\n  \"stopped\": {}", J::String(why.clone()))?;
                }
                self.out.write_all(b"\n}\n")?;
            }
        }
        self.out.flush()?;
        Ok(self.out)
    }
}

/// A number as serde_json writes it (`null` when not finite).
fn json_number(x: f64) -> J {
    serde_json::json!(x)
}

fn pretty(v: &J) -> io::Result<String> {
    serde_json::to_string_pretty(v).map_err(io::Error::other)
}

/// Every line of `text` after the first (and the first when `first`)
/// prefixed by `pad`: a value printed pretty on its own, placed deeper.
fn indent(text: &str, pad: &str, first: bool) -> String {
    let mut out = String::with_capacity(text.len() + 64);
    for (i, line) in text.split('\n').enumerate() {
        if i > 0 {
            out.push('\n');
        }
        if i > 0 || first {
            out.push_str(pad);
        }
        out.push_str(line);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lesson::Lesson;
    use crate::session::Player;

    /// A scene's run of `steps` steps, as the TUI's player keeps it.
    fn run_of(id: &str, steps: u64) -> RunTrace {
        let mut p = Player::new(&Lesson::load(id).unwrap()).unwrap();
        p.reach(steps);
        p.run
    }

    fn streamed(run: &RunTrace, kind: Streamed) -> String {
        let mut copy = run.clone();
        let frames = std::mem::take(&mut copy.frames);
        let mut w = RunWriter::begin(Vec::new(), kind, &copy).unwrap();
        for f in &frames {
            w.frame(&mut copy, f).unwrap();
        }
        String::from_utf8(w.end(&copy).unwrap()).unwrap()
    }

    #[test]
    fn streamed_text_and_json_are_the_whole_runs_bytes() {
        for (id, steps) in [("ball-drop", 400), ("stack-5", 60), ("sleep-modes", 90)] {
            let mut run = run_of(id, steps);
            for stopped in [None, Some("the scene blew up: \"here\"".to_string())] {
                run.stopped = stopped;
                for events in [true, false] {
                    if !events {
                        run.events.clear();
                    }
                    let fmt = Fmt::new(4);
                    assert_eq!(
                        streamed(&run, Streamed::Text(fmt)),
                        super::super::run::text(&run, &fmt),
                        "{id} text"
                    );
                    let whole = serde_json::to_string_pretty(&super::super::run::json(&run))
                        .unwrap()
                        + "\n";
                    let json = streamed(&run, Streamed::Json);
                    assert_eq!(json, whole, "{id} json");
                    let _: J = serde_json::from_str(&json).expect("one valid document");
                }
            }
        }
    }

    #[test]
    fn a_run_without_frames_is_still_one_document() {
        let mut run = run_of("ball-drop", 3);
        run.frames.clear();
        let json = streamed(&run, Streamed::Json);
        let whole = serde_json::to_string_pretty(&super::super::run::json(&run)).unwrap() + "\n";
        assert_eq!(json, whole);
    }
}
