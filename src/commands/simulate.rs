//! `contact-lab simulate`: advance a scene in time and show the run as a
//! table with events, as JSON, or as a film strip with charts.

use std::io::Write;

use super::warn_knobs;
use super::{blew_up, figure::plane, io, progress, warn};
use crate::cli::{RunFormat, SimulateArgs};
use crate::error::AppError;
use crate::format::exact;
use crate::format::Fmt;
use crate::knobs::{Value, ANGULAR_DAMPING, LINEAR_DAMPING, MAX_STEPS, STEPS};
use crate::lesson::{knob_value, Lesson, Overrides};
use crate::physics::step::Simulation;
use crate::render::run;
use crate::render::run_stream::{RunWriter, Streamed};
use crate::trace::run::{Frame, RunTrace};

pub fn simulate(
    args: &SimulateArgs,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<(), AppError> {
    // `-o FILE`: the output written whole, atomically, even where the run
    // stops (the page writes its own).
    match &args.output {
        Some(path) if args.format != RunFormat::Html => {
            let mut buffer = Vec::new();
            let result = run(args, &mut buffer, err);
            super::write_atomic(path, &buffer)?;
            result
        }
        _ => run(args, out, err),
    }
}

fn run(args: &SimulateArgs, out: &mut dyn Write, err: &mut dyn Write) -> Result<(), AppError> {
    let overrides = overrides(args)?;
    let lesson = super::load(&args.lesson, &overrides, None)?;
    warn(&lesson, err);
    let (mut sim, steps) = simulation(&lesson, args, &overrides)?;
    warn_knobs(&sim.params.resolver, err);
    for l in sim.lowered_tolerances() {
        let _ = writeln!(err, "warning: {}", crate::trace::run::lowered_text(&l));
    }
    if let Some(split) = sim.split() {
        let _ = writeln!(err, "warning: {}", crate::trace::run::split_text(&split));
    }
    for text in substepped_warnings(sim.params.resolver.solver) {
        let _ = writeln!(err, "warning: {text}");
    }
    for b in sim.below_rounding() {
        let name = lesson
            .bodies
            .get(b.body)
            .map_or("a body", |x| x.name.as_str());
        let text = crate::trace::run::below_rounding_text(name, &b);
        let _ = writeln!(err, "warning: {text}");
    }
    let html = args.format == RunFormat::Html;
    if let Some(n) = args.trace_step.filter(|_| !html) {
        return trace_step(&lesson, args, sim, steps, n, out);
    }
    let movable = sim.world.bodies.iter().filter(|b| b.movable).count().max(1) as u64;
    if !args.force && steps.saturating_mul(movable) > progress::SIMULATE_WORK_CAP {
        return Err(progress::beyond_cap(
            format!("{steps} steps of {movable} movable bodies"),
            "100 million steps × bodies",
        ));
    }
    if html {
        return super::simulate_html::page(&lesson, args, sim, steps, out, err);
    }
    let mut bar = progress::bar(
        steps,
        "steps",
        &format!(
            "{}: {steps} steps of {} s ({} s of scene time), {movable} movable bodies",
            lesson.id,
            exact(sim.params.dt),
            exact(steps as f64 * sim.params.dt)
        ),
    );
    let names = lesson.bodies.iter().map(|b| b.name.clone()).collect();
    let mut trace = RunTrace::new(&lesson.id, &lesson.title, names, &sim);
    let kind = match args.format {
        RunFormat::Svg => return film(&lesson, args, sim, steps, trace, out),
        RunFormat::Text if args.table => Streamed::Text(Fmt::new(args.digits as usize)),
        RunFormat::Text => Streamed::Summary(Fmt::new(args.digits as usize), Box::default()),
        RunFormat::Json => Streamed::Json,
        RunFormat::Html => unreachable!("the page is written above"),
    };
    // The summary folds in every step (its extremes are the run's, not a
    // sample's); `--every` thins the table and the JSON.
    let every = match kind {
        Streamed::Summary(..) => 1,
        _ => args.every,
    };
    // Written as computed: memory stays flat in the number of steps.
    let width = match args.format {
        RunFormat::Text => super::text_width(args.fold.width),
        _ => 0,
    };
    let folded = crate::render::wrap::WrapWriter::new(out, width);
    let buffered = std::io::BufWriter::with_capacity(1 << 16, folded);
    let mut w = RunWriter::begin(buffered, kind, &trace).map_err(io)?;
    w.frame(&mut trace, &RunTrace::initial(&sim)).map_err(io)?;
    let interrupted = progress::interrupted_mid_step();
    for n in 1..=steps {
        if interrupted.load(std::sync::atomic::Ordering::SeqCst) {
            // The output written so far stays one document, ending here.
            let e = interruption(&lesson, n - 1, steps);
            trace.stopped = Some(e.to_string());
            w.end(&trace).map_err(io)?;
            return Err(e);
        }
        let advanced = sim.advance();
        if interrupted.load(std::sync::atomic::Ordering::SeqCst) {
            // Ctrl-C during the step may have cut its resolution short: the
            // step is not written, the output ends at the one before.
            let e = interruption(&lesson, n - 1, steps);
            trace.stopped = Some(e.to_string());
            w.end(&trace).map_err(io)?;
            return Err(e);
        }
        match advanced {
            Ok(mut report) => {
                if n == steps {
                    // A burial still going has only its start event so far.
                    report.events.extend(sim.burials_going());
                }
                trace.add_events(&report);
                if n % every == 0 || n == steps {
                    w.frame(&mut trace, &RunTrace::frame(&sim, &report))
                        .map_err(io)?;
                }
                bar.at(n);
            }
            Err(blow_up) => {
                // The output written so far stays one document, ending
                // where the run stopped.
                let names = crate::trace::resolver::Names::of_lesson(&lesson);
                trace.stopped = Some(crate::session::blew_up(&names, &blow_up));
                w.end(&trace).map_err(io)?;
                return Err(blew_up(&lesson, &blow_up));
            }
        }
    }
    w.end(&trace).map_err(io)?;
    Ok(())
}

/// The SVG film strip: the frames it draws are kept whole, the others only
/// for the charts (their numbers, not their bodies).
fn film(
    lesson: &Lesson,
    args: &SimulateArgs,
    mut sim: Simulation<f64>,
    steps: u64,
    mut trace: RunTrace,
    out: &mut dyn Write,
) -> Result<(), AppError> {
    let every = args.every.max(1);
    let total = 1 + steps / every + u64::from(!steps.is_multiple_of(every));
    let picks = run::film_picks(total as usize);
    // Also whole: the first frame after each of the first few events the
    // strip marks (tunnelled, toi), which it swaps in.
    let mut marked = 0;
    let keep = |trace: &mut RunTrace, mut f: Frame, event: bool| {
        if picks.binary_search(&trace.frames.len()).is_err() && !event {
            f.bodies = Vec::new();
            f.contact_points = Vec::new();
        }
        trace.frames.push(f);
    };
    keep(&mut trace, RunTrace::initial(&sim), false);
    let mut failure = None;
    let mut pending = false;
    let interrupted = progress::interrupted_mid_step();
    for n in 1..=steps {
        if interrupted.load(std::sync::atomic::Ordering::SeqCst) {
            // The film strip up to the stop is still drawn.
            let e = interruption(lesson, n - 1, steps);
            trace.stopped = Some(e.to_string());
            failure = Some(e);
            break;
        }
        let advanced = sim.advance();
        if interrupted.load(std::sync::atomic::Ordering::SeqCst) {
            // A step Ctrl-C may have cut short is not drawn.
            let e = interruption(lesson, n - 1, steps);
            trace.stopped = Some(e.to_string());
            failure = Some(e);
            break;
        }
        match advanced {
            Ok(mut report) => {
                if n == steps {
                    report.events.extend(sim.burials_going());
                }
                let before = trace.events.len();
                trace.add_events(&report);
                if marked < run::MAX_MARKED && trace.events[before..].iter().any(run::marked) {
                    marked += 1;
                    pending = true;
                }
                if n % every == 0 || n == steps {
                    keep(&mut trace, RunTrace::frame(&sim, &report), pending);
                    pending = false;
                }
            }
            Err(blow_up) => {
                // The film strip up to the stop is still drawn.
                let e = blew_up(lesson, &blow_up);
                trace.stopped = Some(e.to_string());
                failure = Some(e);
                break;
            }
        }
    }
    out.write_all(run::svg(&trace, plane(args.plane)).as_bytes())
        .map_err(io)?;
    failure.map_or(Ok(()), Err)
}

/// A run stopped by Ctrl-C after `done` of its `steps` steps.
fn interruption(lesson: &Lesson, done: u64, steps: u64) -> AppError {
    AppError::Runtime(format!(
        "{}: interrupted (Ctrl-C) after step {done} of {steps}; the output ends there",
        lesson.id
    ))
}

/// `--trace-step N`: the run up to step N - 1 unrecorded, then step N's
/// resolution recorded and printed as `resolve` prints a lesson's.
fn trace_step(
    lesson: &Lesson,
    args: &SimulateArgs,
    mut sim: Simulation<f64>,
    steps: u64,
    n: u64,
    out: &mut dyn Write,
) -> Result<(), AppError> {
    if n > steps {
        return Err(AppError::Usage(format!(
            "--trace-step {n}: the run has {steps} step(s), numbered from 1"
        )));
    }
    for _ in 1..n {
        sim.advance().map_err(|e| blew_up(lesson, &e))?;
    }
    if sim.params.resolver.solver == crate::physics::Solver::SoftStep {
        return super::soft_trace::print(lesson, args, sim, n, out);
    }
    let names = crate::trace::resolver::Names::of_lesson(lesson);
    let described =
        crate::trace::step::describe_next(&mut sim, &names).map_err(|e| blew_up(lesson, &e))?;
    let fmt = Fmt::new(args.digits as usize);
    let text = match args.format {
        RunFormat::Text => {
            let head = format!(
                "Step {n} (t = {} s): the resolution of its {} contact(s).\n\n",
                fmt.num(sim.time),
                described.contacts
            );
            let body = crate::render::resolve::text::render(&described.resolver, &fmt);
            let previous = crate::render::previous_frame::text(&described.previous, &fmt);
            crate::render::wrap::wrap(
                &(head + &body + &previous),
                super::text_width(args.fold.width),
            )
        }
        RunFormat::Json => {
            // Written as it is built: a huge step's log is never held whole.
            let previous = crate::render::previous_frame::json(&described.previous);
            return crate::render::resolve::json::write(
                &described.resolver,
                &crate::render::resolve::Seconds::default(),
                true,
                &[("previous_frame_normals", previous)],
                out,
            )
            .map_err(io);
        }
        RunFormat::Svg => {
            return Err(AppError::Usage(
                "--trace-step prints text or json, not svg".into(),
            ))
        }
        RunFormat::Html => unreachable!("the page records the step itself"),
    };
    out.write_all(text.as_bytes()).map_err(io)
}

/// The knobs the command line sets: one flag per knob, and `--damping`,
/// which sets both dampings, each checked by its rule.
fn overrides(args: &SimulateArgs) -> Result<Overrides, AppError> {
    let mut overrides = super::overrides(&args.knobs)?;
    if let Some(d) = args.damping {
        for knob in [&LINEAR_DAMPING, &ANGULAR_DAMPING] {
            knob_value::check(knob, Value::Number(d))
                .map_err(|e| AppError::Usage(format!("--damping: {e}")))?;
            overrides.set(knob, Value::Number(d));
        }
    }
    Ok(overrides)
}

/// The simulation a lesson (loaded with the command line's `overrides`)
/// describes, and how many steps to run.
fn simulation(
    lesson: &Lesson,
    args: &SimulateArgs,
    overrides: &Overrides,
) -> Result<(Simulation<f64>, u64), AppError> {
    if lesson.simulation.is_none() {
        return Err(AppError::Usage(format!(
            "{} is not a scene: it has no [world], [step] or [sleep] table, so nothing says how to step it (its contacts are solved by `solve` and `resolve`)",
            lesson.id
        )));
    }
    let usage = |what: &str| Err(AppError::Usage(what.to_string()));
    let scene = lesson.simulation.clone().unwrap_or_default();
    let p = lesson.sim_params().unwrap_or_default();
    let steps_given = overrides.0.iter().any(|(k, _)| **k == STEPS);
    let steps = match args.seconds {
        Some(t) if !steps_given => {
            if !(t.is_finite() && t >= 0.0) {
                return usage(&format!(
                    "--seconds must be a finite time ≥ 0, got {}",
                    exact(t)
                ));
            }
            let n = (t / p.dt).round();
            if n > MAX_STEPS as f64 {
                return usage(&format!(
                    "--seconds {} at dt = {} is over the limit of {MAX_STEPS} steps",
                    exact(t),
                    exact(p.dt)
                ));
            }
            n as u64
        }
        _ => scene.steps,
    };
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Ok((Simulation::new(world, p, scene.materials.clone()), steps))
}

/// What a substepped solver does not do that the lecture's step does, said
/// before its run (never silent): the soft step and XPBD move their bodies
/// in their own substeps, past continuous detection, the tunnelling audit
/// and the energy audits; and XPBD's figures that miss their closed forms.
pub fn substepped_warnings(solver: crate::physics::Solver) -> Vec<String> {
    use crate::knobs::Choice;
    use crate::physics::Solver;
    let name = solver.name();
    let mut out = Vec::new();
    if matches!(solver, Solver::SoftStep | Solver::Xpbd) {
        out.push(format!(
            "--solver {name} moves the bodies in its own substeps: continuous detection (--ccd), the tunnelling audit and the energy audits do not run, so a body faster than its own size in a substep can pass through another with no event, and an energy rise has no event"
        ));
    }
    if solver == Solver::Xpbd {
        out.push(
            "--solver xpbd is under test: a 1 m box resting on a floor turns and creeps about 13 mm in 5 s, and a sliding box decelerates at 0.87 μ_d g where the closed form is μ_d g (study --verdicts shows where it fails)".to_string(),
        );
    }
    out
}
