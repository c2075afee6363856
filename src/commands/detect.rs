//! `contact-lab detect`: how a scene's contacts are found (docs/detect.md).

use std::io::Write;

use super::{io, load, overrides, warn, write_atomic};
use crate::cli::{DetectArgs, DetectPhaseArg, Format};
use crate::error::AppError;
use crate::format::Fmt;
use crate::lesson::Lesson;
use crate::physics::step::{SimParams, Simulation};
use crate::render::detect as show;
use crate::trace::detect::PairTrace;

pub fn detect(args: &DetectArgs, out: &mut dyn Write, err: &mut dyn Write) -> Result<(), AppError> {
    // A huge scene (a hull of 100,000 points, a pile of 1,000 spheres)
    // says that it works, on a terminal after half a second; Ctrl-C exits
    // 130 at once (nothing is written before the end).
    super::progress::exit_on_interrupt();
    let mut working = super::progress::later(
        format!("{}: loading", args.lesson.to_string_lossy()),
        "pairs",
    );
    let lesson = load(&args.lesson, &overrides(&args.knobs)?, None)?;
    warn(&lesson, err);
    if args.toi {
        drop(working);
        return super::detect_toi::detect_toi(args, &lesson, out);
    }
    let names: Vec<String> = lesson.bodies.iter().map(|b| b.name.clone()).collect();
    let only = args.pair.as_deref().map(|p| pair(p, &names)).transpose()?;
    if args.step > 0 {
        working
            .bar
            .set_message(format!("{}: stepping to step {}", lesson.id, args.step));
    }
    let sim = advanced(&lesson, args.step)?;
    let plane = super::figure::plane(args.plane);
    working.bar.set_message(format!(
        "{}: detecting step {}'s contacts",
        lesson.id, args.step
    ));
    let trace = crate::session::detect_trace_watched(
        &sim,
        &lesson,
        args.step,
        plane,
        only,
        &mut |done, total| {
            working.of(done, total);
            true
        },
    )
    .ok_or_else(|| AppError::Runtime("detect: stopped".into()))?;
    drop(working);
    if let Some(path) = &args.figure {
        let first = trace.pairs.first().ok_or_else(|| {
            AppError::Usage("--figure: no pair reaches the narrow phase, so there is nothing to draw (name one with --pair A,B)".into())
        })?;
        let shown = shown(args, first)?;
        let svg = show::svg_at(&trace, 0, shown)
            .ok_or_else(|| AppError::Runtime("--figure: nothing to draw".into()))?;
        write_atomic(path, svg.as_bytes())?;
    }
    let f = Fmt::new(args.digits as usize);
    let text = match args.format {
        Format::Text => {
            let width = super::text_width(args.fold.width);
            crate::render::wrap::wrap(&show::text(&trace, &f, width), width)
        }
        Format::Md => show::markdown(&trace, &f),
        Format::Latex => show::latex(&trace, &f),
        Format::Json => show::json(&trace),
        Format::Html => crate::render::html::detect::document(&trace, &f),
    };
    match &args.output {
        Some(path) => write_atomic(path, text.as_bytes()),
        None => out.write_all(text.as_bytes()).map_err(io),
    }
}

/// The stop (an index into [`show::steps::stops`]: GJK's iterations, then
/// EPA's; `usize::MAX`: the result) `--iteration K` / `--phase` ask the
/// figure to draw, checked against the pair's GJK or EPA iteration count
/// (exit 2 outside).
fn shown(args: &DetectArgs, p: &PairTrace) -> Result<usize, AppError> {
    let phase = match (args.phase, args.iteration) {
        (None, None) => return Ok(usize::MAX),
        (Some(phase), _) => phase,
        (None, Some(_)) => DetectPhaseArg::Gjk,
    };
    let (name, count) = match phase {
        DetectPhaseArg::Gjk => ("GJK", p.gjk.as_ref().map_or(0, |g| g.iterations.len())),
        DetectPhaseArg::Epa => ("EPA", p.epa.as_ref().map_or(0, |e| e.iterations.len())),
    };
    let pair = format!("{} – {}", p.a, p.b);
    if count == 0 {
        return Err(AppError::Usage(format!(
            "--phase {}: pair {pair} has no {name} iterations (method {}{})",
            name.to_lowercase(),
            p.method,
            match &p.gjk {
                Some(g) => format!(", GJK: {}", g.result),
                None => String::new(),
            }
        )));
    }
    let k = match args.iteration {
        None => count,
        Some(k) if (1..=count as u64).contains(&k) => k as usize,
        Some(k) => {
            return Err(AppError::Usage(format!(
                "--iteration {k}: pair {pair} has {count} {name} iteration(s), 1 to {count}"
            )))
        }
    };
    let gjk = p.gjk.as_ref().map_or(0, |g| g.iterations.len());
    Ok(match phase {
        DetectPhaseArg::Gjk => k - 1,
        DetectPhaseArg::Epa => gjk + k - 1,
    })
}

/// `A,B` as two body indices.
fn pair(text: &str, names: &[String]) -> Result<(usize, usize), AppError> {
    let find = |n: &str| {
        names.iter().position(|m| m == n.trim()).ok_or_else(|| {
            AppError::Usage(format!(
                "--pair: no body named '{}'; the bodies are {}",
                n.trim(),
                names.join(", ")
            ))
        })
    };
    match text.split_once(',') {
        Some((a, b)) if a.trim() != b.trim() => Ok((find(a)?, find(b)?)),
        Some(_) => Err(AppError::Usage("--pair names two different bodies".into())),
        None => Err(AppError::Usage(format!(
            "--pair takes two body names, A,B; got '{text}'"
        ))),
    }
}

/// The lesson's bodies after `steps` steps of its scene (a lesson without
/// [world], [step] or [sleep] has only its loaded poses: step 0).
fn advanced(lesson: &Lesson, steps: u64) -> Result<Simulation<f64>, AppError> {
    let params = match lesson.sim_params() {
        Some(p) => p,
        None if steps == 0 => SimParams::default(),
        None => {
            return Err(AppError::Usage(format!(
            "{} is not a scene (no [world], [step] or [sleep]): only --step 0, its loaded poses",
            lesson.id
        )))
        }
    };
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson
        .simulation
        .as_ref()
        .map(|s| s.materials.clone())
        .unwrap_or_else(|| vec![Default::default(); world.bodies.len()]);
    let mut sim = Simulation::new(world, params, materials);
    for k in 0..steps {
        sim.advance().map_err(|e| {
            AppError::Runtime(format!(
                "{}: step {} blew up: {}",
                lesson.id,
                k + 1,
                crate::trace::blow_up::plain(&e)
            ))
        })?;
    }
    Ok(sim)
}
