//! `simulate SCENE --format html`: the run recorded for the player
//! (docs/html.md): one frame in every `--every` steps with its bodies, the
//! last step, and the step `--trace-step K` names with its resolution
//! recorded; the summary folded over every step.

use std::io::Write;

use super::{io, progress};
use crate::cli::SimulateArgs;
use crate::error::AppError;
use crate::format::Fmt;
use crate::lesson::Lesson;
use crate::physics::step::Simulation;
use crate::render::html::player::{self, Player};
use crate::render::run_summary::Summary;
use crate::trace::resolver::ResolverTrace;
use crate::trace::run::RunTrace;
use crate::trace::Plane;

/// A page over this many bytes says so, and how to thin it.
pub const LARGE_PAGE: usize = 3_000_000;

/// The run as the page holds it: its frames (one in `every` steps, the
/// last, the traced one), the summary's text over every step, the traced
/// step's resolution, and why it stopped early (if it did).
pub struct Recorded {
    pub run: RunTrace,
    pub summary: String,
    pub traced: Option<(u64, ResolverTrace)>,
    pub failure: Option<AppError>,
}

/// Runs `sim` for `steps` steps and records them for the player; `tick`
/// hears each step done.
pub fn record(
    lesson: &Lesson,
    mut sim: Simulation<f64>,
    (steps, every): (u64, u64),
    trace_step: Option<u64>,
    fmt: &Fmt,
    tick: &mut dyn FnMut(u64),
) -> Recorded {
    let every = every.max(1);
    let names = lesson.bodies.iter().map(|b| b.name.clone()).collect();
    let mut run = RunTrace::new(&lesson.id, &lesson.title, names, &sim);
    let mut summary = Summary::default();
    let first = RunTrace::initial(&sim);
    summary.add(&first);
    run.frames.push(first);
    let labels = crate::trace::resolver::Names::of_lesson(lesson);
    let mut traced = None;
    let mut failure = None;
    let interrupted = progress::interrupted();
    for n in 1..=steps {
        if interrupted.load(std::sync::atomic::Ordering::SeqCst) {
            let e = AppError::Runtime(format!(
                "{}: interrupted (Ctrl-C) after step {} of {steps}; the page ends there",
                lesson.id,
                n - 1
            ));
            run.stopped = Some(e.to_string());
            failure = Some(e);
            break;
        }
        let report = if trace_step == Some(n) {
            crate::trace::step::describe_next(&mut sim, &labels).map(|d| {
                traced = Some((n, d.resolver));
                d.report
            })
        } else {
            sim.advance()
        };
        match report {
            Ok(report) => {
                run.add_events(&report);
                let frame = RunTrace::frame(&sim, &report);
                summary.add(&frame);
                if n % every == 0 || n == steps || trace_step == Some(n) {
                    run.frames.push(frame);
                }
                tick(n);
            }
            Err(blow_up) => {
                let text = crate::session::blew_up(&labels, &blow_up);
                run.stopped = Some(text.clone());
                failure = Some(AppError::Runtime(format!(
                    "{}: {text}; try a smaller --dt or more iterations",
                    lesson.id
                )));
                break;
            }
        }
    }
    let events = run.events.clone();
    let summary = summary.text(&run, &events, fmt);
    Recorded {
        run,
        summary,
        traced,
        failure,
    }
}

/// The page of `rec`.
pub fn render(rec: &Recorded, (steps, every): (u64, u64), plane: Plane, fmt: &Fmt) -> String {
    player::document(
        &Player {
            run: &rec.run,
            every: every.max(1),
            steps,
            summary: rec.summary.clone(),
            traced: rec.traced.as_ref().map(|(k, t)| (*k, t)),
            plane,
        },
        fmt,
    )
}

/// The page of an embedded scene run for `steps` steps (its own number
/// when `None`), seen along z: what `simulate SCENE --format html` writes.
pub fn scene_page(
    lesson: &Lesson,
    steps: Option<u64>,
    every: u64,
    trace_step: Option<u64>,
) -> Option<String> {
    let scene = lesson.simulation.clone()?;
    let params = lesson.sim_params()?;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let sim = Simulation::new(world, params, scene.materials.clone());
    let steps = steps.unwrap_or(scene.steps);
    let fmt = Fmt::new(6);
    let rec = record(lesson, sim, (steps, every), trace_step, &fmt, &mut |_| {});
    Some(render(&rec, (steps, every), Plane::Xy, &fmt))
}

pub fn page(
    lesson: &Lesson,
    args: &SimulateArgs,
    sim: Simulation<f64>,
    steps: u64,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<(), AppError> {
    if let Some(k) = args.trace_step.filter(|k| *k > steps) {
        return Err(AppError::Usage(format!(
            "--trace-step {k}: the run has {steps} step(s), numbered from 1"
        )));
    }
    let mut bar = progress::bar(
        steps,
        "steps",
        &format!("{}: {steps} steps for the player", lesson.id),
    );
    let fmt = Fmt::new(args.digits as usize);
    let rec = record(
        lesson,
        sim,
        (steps, args.every),
        args.trace_step,
        &fmt,
        &mut |n| bar.at(n),
    );
    drop(bar);
    let html = render(
        &rec,
        (steps, args.every),
        super::figure::plane(args.plane),
        &fmt,
    );
    if html.len() > LARGE_PAGE {
        let _ = writeln!(
            err,
            "warning: the page is {:.1} MB ({} frames); --every N keeps one frame in N for a smaller page",
            html.len() as f64 / 1e6,
            rec.run.frames.len()
        );
    }
    match &args.output {
        Some(path) => super::write_atomic(path, html.as_bytes())?,
        None => out.write_all(html.as_bytes()).map_err(io)?,
    }
    rec.failure.map_or(Ok(()), Err)
}
