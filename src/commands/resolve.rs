//! `contact-lab resolve`: every contact of a lesson resolved together
//! (docs/resolve.md), as text, Markdown or JSON; `--show` hands one iteration's
//! contact to the single-contact worked solution.

use std::io::Write;
use std::time::Instant;

use super::{io, load, warn};
use crate::cli::{ImplementationArg, ResolveArgs, ResolveFormat};
use crate::error::AppError;
use crate::format::Fmt;
use crate::knobs::Choice;
use crate::physics::resolver::{Implementation, Resolver, Silent};
use crate::physics::{ResolverParams, World};
use crate::render::resolve::{self, Seconds};

pub(crate) fn implementation(args: &ResolveArgs) -> Implementation {
    match args.implementation {
        ImplementationArg::Scan => Implementation::Scan,
        ImplementationArg::Indexed => Implementation::Indexed,
    }
}

/// The phases of the fastest of `repeat` silent runs (prepare, position, velocity).
fn time(
    world: &World<f64>,
    params: &ResolverParams,
    implementation: Implementation,
    repeat: u32,
) -> Seconds {
    let mut best: Option<Seconds> = None;
    let mut r: Option<Resolver<f64>> = None;
    for _ in 0..repeat {
        let t0 = Instant::now();
        // The first run allocates the resolver's storage; the others reuse it.
        let r = match &mut r {
            Some(r) => {
                r.prepare_again(world, params);
                r
            }
            None => r.insert(Resolver::prepare(world, params)),
        };
        let t1 = Instant::now();
        r.position_phase(implementation, &mut Silent);
        let t2 = Instant::now();
        r.velocity_phase(implementation, &mut Silent);
        let t3 = Instant::now();
        let run = Seconds {
            prepare: (t1 - t0).as_secs_f64(),
            position: (t2 - t1).as_secs_f64(),
            velocity: (t3 - t2).as_secs_f64(),
        };
        let total = |s: &Seconds| s.prepare + s.position + s.velocity;
        if best.as_ref().is_none_or(|b| total(&run) < total(b)) {
            best = Some(run);
        }
    }
    best.unwrap_or_default()
}

/// A note when the indexed phases' neighbour table would outgrow its budget
/// and they find the neighbours through the body → contacts adjacency
/// instead (the same results).
fn table_note(
    lesson: &crate::lesson::Lesson,
    params: &ResolverParams,
    implementation: Implementation,
    err: &mut dyn Write,
) {
    if implementation != Implementation::Indexed {
        return;
    }
    let r = Resolver::prepare(&lesson.world::<f64>(), params);
    if r.table_over_budget() {
        let _ = writeln!(
            err,
            "note: {}: the neighbour table of these contacts would hold {} entries (one body's contacts, squared), over its budget of {}: the indexed phases find each contact's neighbours through its bodies' contact lists instead (the same contacts in the same order, the same results)",
            lesson.id,
            r.table_entries(),
            r.table_budget
        );
    }
}

pub fn resolve(
    args: &ResolveArgs,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> Result<(), AppError> {
    // Ctrl-C exits 130 at once (nothing is written before the end); a
    // large lesson's loading says that it works, on a terminal after half
    // a second.
    super::progress::exit_on_interrupt();
    let loading = super::progress::later(format!("{}: loading", args.lesson.to_string_lossy()), "");
    let lesson = load(&args.lesson, &super::overrides(&args.knobs)?, None)?;
    drop(loading);
    warn(&lesson, err);
    if lesson.contacts.is_empty() {
        // Only a scene may write no contact: its contacts come from its shapes.
        return Err(AppError::Usage(format!(
            "{} is a scene and writes no [[contact]]: its contacts are generated from the shapes at every step. \
             Resolve one step's contacts with `contact-lab simulate {} --trace-step N`",
            lesson.id, args.lesson.to_string_lossy()
        )));
    }
    let params = lesson.resolver;
    if let Some(why) = time_stepper(params.solver) {
        // A substepped solver moves its bodies between substeps, so a set
        // of contacts at one instant has no answer of its own.
        return Err(AppError::Usage(format!(
            "{}: resolve takes the contacts at one instant; {why} and has no single-instant answer. \
             Step a scene with `contact-lab simulate SCENE --solver {} --trace-step N`",
            lesson.id,
            params.solver.name()
        )));
    }
    super::warn_knobs(&params, err);
    let implementation = implementation(args);
    let n = lesson.contacts.len();
    // A large resolve says that it works (on a terminal), until it prints.
    let spinner = (n >= super::progress::RESOLVE_SPINNER_FROM).then(|| {
        super::progress::spinner(format!(
            "{}: resolving {n} contacts (checked first, then up to {} position and {} velocity iterations{})",
            lesson.id,
            params.position_limit(n),
            params.velocity_limit(n),
            if args.repeat > 1 { format!(", {} timed runs", args.repeat) } else { String::new() }
        ))
    });
    table_note(&lesson, &params, implementation, err);
    crate::lesson::overflow::check_resolve(&lesson, &params, implementation)
        .map_err(|e| AppError::Runtime(format!("{}: {e}", lesson.id)))?;
    let fmt = Fmt::new(args.digits as usize);
    if let Some(pair) = args.compare {
        let text = super::resolve_compare::render(
            &lesson,
            &params,
            implementation,
            pair,
            args.format,
            &fmt,
        )?;
        drop(spinner);
        return match &args.output {
            Some(path) => super::write_atomic(path, text.as_bytes()),
            None => out.write_all(text.as_bytes()).map_err(io),
        };
    }
    if let Some(show) = args.show {
        return super::show::show(
            &lesson,
            &params,
            implementation,
            show,
            args.format,
            &fmt,
            out,
        );
    }
    let text = match args.format {
        ResolveFormat::Json => {
            let seconds = time(&lesson.world(), &params, implementation, args.repeat);
            let trace =
                crate::trace::resolver::describe(&lesson, &params, implementation, args.log);
            resolve::json::render(&trace, &seconds, args.log)
        }
        ResolveFormat::Text => {
            let trace = crate::trace::resolver::describe(&lesson, &params, implementation, true);
            crate::render::wrap::wrap(
                &resolve::text::render(&trace, &fmt),
                super::text_width(args.fold.width),
            )
        }
        ResolveFormat::Md => {
            let trace = crate::trace::resolver::describe(&lesson, &params, implementation, true);
            resolve::markdown::render(&trace, &fmt)
        }
        ResolveFormat::Html => {
            let trace = crate::trace::resolver::describe(&lesson, &params, implementation, true);
            let worked = worked(&lesson, &params, implementation, &trace, &fmt);
            crate::render::html::resolve::document(&trace, &worked, &fmt)
        }
    };
    // The spinner's line cleared before the output.
    drop(spinner);
    match &args.output {
        Some(path) => super::write_atomic(path, text.as_bytes()),
        None => out.write_all(text.as_bytes()).map_err(io),
    }
}

/// Iterations whose worked stages a web page carries, per phase: enough for
/// a lesson, and a page that stays small for a large scene.
pub const WORKED_PER_PHASE: usize = 24;

/// The worked solution of each of the first [`WORKED_PER_PHASE`] iterations'
/// contacts, per phase (as `--show` makes it).
fn worked(
    lesson: &crate::lesson::Lesson,
    params: &ResolverParams,
    implementation: Implementation,
    trace: &crate::trace::resolver::ResolverTrace,
    fmt: &Fmt,
) -> crate::render::html::resolve::Worked {
    let phase = |p: &crate::trace::resolver::PhaseTrace, velocity: bool| {
        p.log
            .iter()
            .enumerate()
            .map(|(n, it)| {
                (n < WORKED_PER_PHASE)
                    .then(|| {
                        let show = crate::cli::Show {
                            velocity,
                            iteration: it.iteration,
                        };
                        super::show::at_iteration(lesson, params, implementation, show, fmt)
                            .ok()
                            .map(|(t, _)| t)
                    })
                    .flatten()
            })
            .collect()
    };
    [phase(&trace.position, false), phase(&trace.velocity, true)]
}

/// Why `solver` has no single-instant answer (`None`: it has one).
fn time_stepper(solver: crate::physics::Solver) -> Option<&'static str> {
    match solver {
        crate::physics::Solver::SoftStep => Some(
            "the soft step integrates velocities and positions over a time step's substeps",
        ),
        crate::physics::Solver::Xpbd => Some(
            "XPBD is a time stepper (its contacts are positions moved over substeps of a step, its velocities come from those moves)",
        ),
        _ => None,
    }
}
