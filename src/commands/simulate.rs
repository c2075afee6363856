//! `contact-lab simulate`: advance a scene in time and show the run as a
//! table with events, as JSON, or as a film strip with charts.

use std::io::Write;

use super::{figure::plane, io, warn};
use crate::cli::{BoxBoxArg, RunFormat, SimulateArgs, SleepModeArg};
use crate::error::AppError;
use crate::format::exact;
use crate::format::Fmt;
use crate::lesson::validate::{damping_rule, rules};
use crate::lesson::Lesson;
use crate::physics::params::BoxBoxMode;
use crate::physics::step::{Simulation, SleepMode};
use crate::render::run;
use crate::trace::run::RunTrace;

/// The most steps one command runs.
const MAX_STEPS: u64 = 10_000_000;

pub fn simulate(
    args: &SimulateArgs,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<(), AppError> {
    let lesson = Lesson::load(&args.lesson)?;
    warn(&lesson, err);
    let (mut sim, steps) = simulation(&lesson, args)?;
    for l in sim.lowered_tolerances() {
        let _ = writeln!(err, "warning: {}", crate::trace::run::lowered_text(&l));
    }
    if let Some(n) = args.trace_step {
        return trace_step(&lesson, args, sim, steps, n, out);
    }
    let names = lesson.bodies.iter().map(|b| b.name.clone()).collect();
    let mut trace = RunTrace::new(&lesson.id, &lesson.title, names, &sim);
    trace.frames.push(RunTrace::initial(&sim));
    // A blow-up stops the run: what was computed up to it is still written
    // (its last line says where and why it stopped), then the command fails.
    let mut failure = None;
    for n in 1..=steps {
        match sim.advance() {
            Ok(report) => {
                trace.add_events(&report);
                if n % args.every == 0 || n == steps {
                    trace.frames.push(RunTrace::frame(&sim, &report));
                }
            }
            Err(blow_up) => {
                let e = blew_up(&lesson, &blow_up);
                trace.stopped = Some(e.to_string());
                failure = Some(e);
                break;
            }
        }
    }
    let text = match args.format {
        RunFormat::Text => run::text(&trace, &Fmt::new(args.digits as usize)),
        RunFormat::Json => {
            let mut s = serde_json::to_string_pretty(&run::json(&trace))
                .map_err(|e| AppError::Runtime(e.to_string()))?;
            s.push('\n');
            s
        }
        RunFormat::Svg => run::svg(&trace, plane(args.plane)),
    };
    out.write_all(text.as_bytes()).map_err(io)?;
    failure.map_or(Ok(()), Err)
}

fn blew_up(lesson: &Lesson, e: &crate::physics::step::BlowUp) -> AppError {
    let names = crate::trace::resolver::Names::of_lesson(lesson);
    AppError::Runtime(format!(
        "{}: {}; try a smaller --dt or more iterations",
        lesson.id,
        crate::trace::player::blew_up(&names, e)
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
    let names = crate::trace::resolver::Names::of_lesson(lesson);
    let step =
        crate::trace::step::record_next(&mut sim, &names).map_err(|e| blew_up(lesson, &e))?;
    let fmt = Fmt::new(args.digits as usize);
    let text = match args.format {
        RunFormat::Text => {
            let head = format!(
                "Step {n} (t = {} s): the resolution of its {} contact(s).\n\n",
                fmt.num(step.time),
                step.world.contacts.len()
            );
            head + &crate::render::resolve::text::render(&step.resolver, &fmt)
        }
        RunFormat::Json => crate::render::resolve::json::render(
            &step.resolver,
            &crate::render::resolve::Seconds::default(),
            true,
        ),
        RunFormat::Svg => {
            return Err(AppError::Usage(
                "--trace-step prints text or json, not svg".into(),
            ))
        }
    };
    out.write_all(text.as_bytes()).map_err(io)
}

/// The simulation a lesson and the command line describe, and how many steps to run.
pub fn simulation(
    lesson: &Lesson,
    args: &SimulateArgs,
) -> Result<(Simulation<f64>, u64), AppError> {
    let Some(scene) = &lesson.simulation else {
        return Err(AppError::Usage(format!(
            "{} is not a scene: it has no [world], [step] or [sleep] table, so nothing says how to step it (its contacts are solved by `solve` and `resolve`)",
            lesson.id
        )));
    };
    let usage = |what: &str| Err(AppError::Usage(what.to_string()));
    let mut p = lesson.sim_params().unwrap_or_default();
    if let Some(dt) = args.dt {
        if !(dt.is_finite() && dt > 0.0 && dt <= 1e6) {
            return usage(&format!(
                "--dt must be a finite number of seconds > 0, got {}",
                exact(dt)
            ));
        }
        rules::duration(dt).map_err(|e| AppError::Usage(format!("--dt: {e}")))?;
        p.dt = dt;
    }
    if let Some(g) = &args.gravity {
        if g.len() != 3 || g.iter().any(|x| rules::finite(*x).is_err()) {
            return usage(
                "--gravity takes three finite numbers x,y,z, each 0 or of magnitude 1e-60 to 1e60",
            );
        }
        p.world.gravity = nalgebra::Vector3::new(g[0], g[1], g[2]);
    }
    if let Some(d) = args.damping {
        damping_rule(d).map_err(|e| AppError::Usage(format!("--damping: {e}")))?;
        p.world.linear_damping = d;
        p.world.angular_damping = d;
    }
    if args.no_sleep {
        p.sleep.enabled = false;
    }
    if let Some(m) = args.sleep_mode {
        p.sleep.mode = match m {
            SleepModeArg::Body => SleepMode::Body,
            SleepModeArg::Island => SleepMode::Island,
        };
    }
    if let Some(m) = args.box_box {
        p.box_box = match m {
            BoxBoxArg::Single => BoxBoxMode::Single,
            BoxBoxArg::Manifold => BoxBoxMode::Manifold,
        };
    }
    if args.no_compensation {
        p.acceleration_compensation = false;
    }
    if let Some(v) = args.velocity_limit {
        rules::velocity_limit(v).map_err(|e| AppError::Usage(format!("--velocity-limit: {e}")))?;
        p.contact.velocity_limit = v;
    }
    p.resolver = super::resolve::params(&p.resolver, &args.resolver)?;
    let steps = match (args.steps, args.seconds) {
        (Some(n), _) => n,
        (None, Some(t)) => {
            if !(t.is_finite() && t >= 0.0) {
                return usage(&format!(
                    "--seconds must be a finite time ≥ 0, got {}",
                    exact(t)
                ));
            }
            let n = (t / p.dt).round();
            if n > MAX_STEPS as f64 {
                return usage(&format!(
                    "--seconds {t} at dt = {} is over {MAX_STEPS} steps",
                    p.dt
                ));
            }
            n as u64
        }
        (None, None) => scene.steps,
    };
    if steps > MAX_STEPS {
        return usage(&format!("at most {MAX_STEPS} steps, got {steps}"));
    }
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Ok((Simulation::new(world, p, scene.materials.clone()), steps))
}
