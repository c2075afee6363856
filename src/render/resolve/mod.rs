//! `resolve`'s output: a scene's contacts resolved together, as text,
//! Markdown and the JSON of docs/resolve.md, all read from a
//! [`ResolverTrace`](crate::trace::resolver::ResolverTrace).

pub mod json;
pub mod lcp;
pub mod markdown;
pub mod text;

use crate::format::Fmt;
use crate::physics::resolver::Phase;
use crate::physics::{RestitutionFrom, Solver};
use crate::trace::resolver::{ContactRow, Iteration, PhaseTrace, ResolverTrace};

/// Wall-clock seconds of each part of a resolve (the fastest of `--repeat` runs).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Seconds {
    pub prepare: f64,
    pub position: f64,
    pub velocity: f64,
}

/// One line saying how the scene was resolved.
pub fn how(trace: &ResolverTrace) -> String {
    let restitution = match trace.restitution_from {
        RestitutionFrom::Current => {
            "restitution from each contact's velocity when it is taken (the reference engine's way)"
        }
        RestitutionFrom::Initial => {
            "restitution from each contact's velocity before the velocity phase (Box2D's way)"
        }
    };
    if trace.position.solver == Solver::Lcp {
        return format!(
            "{} contacts resolved together: positions by the lecture's projection (the deepest first), velocities simultaneously by one linear complementarity problem (Lemke's method); {restitution}.",
            trace.before.len()
        );
    }
    if trace.position.solver == Solver::SequentialImpulse {
        return format!(
            "{} contacts resolved together by sequential impulses (every contact in turn, sweep after sweep, accumulated and clamped impulses); restitution from each contact's velocity before the velocity phase.",
            trace.before.len()
        );
    }
    format!(
        "{} contacts resolved together by the {} resolver; {restitution}.",
        trace.before.len(),
        trace.implementation.name()
    )
}

/// What a huge step's recording left out, when it did (one paragraph).
pub fn elision_note(trace: &ResolverTrace) -> Option<String> {
    let e = trace.elision?;
    Some(format!(
        "Elided: a huge step. Every iteration is listed with the contact it takes and its moves or impulse, \
         but the other contacts it changed are listed at iterations 0, {}, {}, … of each phase only (the rest say how many), \
         to keep the recording within {} rows; the full contact tables are the ones before and after.",
        e.every,
        2 * e.every,
        e.budget
    ))
}

/// The phase's heading: what it takes first, its epsilon and limit.
pub fn phase_heading(p: &PhaseTrace, fmt: &Fmt) -> String {
    if p.solver == Solver::SequentialImpulse {
        let (name, eps, what) = match p.phase {
            Phase::Position => ("Position", "position_epsilon", "moves"),
            Phase::Velocity => ("Velocity", "velocity_epsilon", "impulses"),
        };
        return format!(
            "{name} phase: every contact in file order, sweep after sweep ({what} accumulated, until a sweep changes nothing by more than {eps} {}), at most {} contact visits",
            fmt.num(p.epsilon),
            p.iteration_limit
        );
    }
    if p.solver == Solver::Lcp && p.phase == Phase::Velocity {
        return "Velocity phase: every contact at once, one simultaneous solve (each contact's impulse applied is one line)".to_string();
    }
    match p.phase {
        Phase::Position => format!(
            "Position phase: the deepest penetration above position_epsilon {} first, at most {} iterations",
            fmt.num(p.epsilon),
            p.iteration_limit
        ),
        Phase::Velocity => format!(
            "Velocity phase: the largest desired Δv above velocity_epsilon {} first, at most {} iterations",
            fmt.num(p.epsilon),
            p.iteration_limit
        ),
    }
}

/// The phase's summary notes: iterations used, what is left, the limit, worse contacts.
pub fn phase_notes(p: &PhaseTrace, fmt: &Fmt) -> Vec<String> {
    let what = match p.phase {
        Phase::Position => "deepest penetration",
        Phase::Velocity => "largest desired Δv",
    };
    if p.contacts == 0 {
        return vec!["No contacts: nothing to resolve.".into()];
    }
    let mut out = vec![format!(
        "{} iteration(s) of {}; {what} before {}, left {} at contact {}.",
        p.iterations_used,
        p.iteration_limit,
        fmt.num(p.max_before),
        fmt.num(p.max_after),
        p.max_after_contact
    )];
    if p.iteration_limit == 0 {
        out.push(format!(
            "The {} iteration limit is 0: nothing was resolved.",
            p.phase.name()
        ));
    } else if p.iterations_used == 0 {
        out.push(format!(
            "Nothing above epsilon {}: nothing to resolve.",
            fmt.num(p.epsilon)
        ));
    }
    if p.limit_reached {
        out.push(format!(
            "{} iteration limit {} reached: {what} left {} at contact {}.",
            p.phase.name(),
            p.iteration_limit,
            fmt.num(p.max_after),
            p.max_after_contact
        ));
    }
    if p.worsening_iterations > 0 {
        out.push(format!(
            "{} of {} iteration(s) made another contact worse (marked “worse”): {}.",
            p.worsening_iterations,
            p.iterations_used,
            match p.phase {
                Phase::Position => "moving a body out of one contact pushed it deeper into another",
                Phase::Velocity => "an impulse at one contact made another close faster",
            }
        ));
    }
    out
}

/// A contacts table's numbers (penetration, v_s, desired Δv) as text, each
/// column one quantity: a value that is round-off against its column's
/// largest prints as 0.
pub fn row_numbers(rows: &[ContactRow], fmt: &Fmt) -> Vec<[String; 3]> {
    let scale = |f: fn(&ContactRow) -> f64| {
        crate::format::scale_of(rows.iter().map(f).collect::<Vec<_>>().iter())
    };
    let s = [
        scale(|r| r.penetration),
        scale(|r| r.separating),
        scale(|r| r.desired),
    ];
    rows.iter()
        .map(|r| {
            [
                fmt.num_at(r.penetration, s[0]),
                fmt.num_at(r.separating, s[1]),
                fmt.num_at(r.desired, s[2]),
            ]
        })
        .collect()
}

/// `2: 0.03 → 0.041 (worse)`, the others an iteration changed; for an
/// iteration whose rows a huge step's recording elided, how many it changed.
pub fn updates(it: &Iteration, fmt: &Fmt) -> String {
    if it.elided {
        if it.changed == 0 {
            return String::new();
        }
        return format!(
            "changed {} other contact(s), {} for the worse (rows elided)",
            it.changed, it.worse
        );
    }
    it.updated
        .iter()
        .map(|u| {
            format!(
                "{}: {}{}",
                u.contact,
                fmt.change(u.from, u.to),
                if u.worse() { " (worse)" } else { "" }
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The moves (position) or the impulse (velocity) of an iteration.
pub fn action(it: &Iteration, fmt: &Fmt) -> String {
    let v = |x: &[f64; 3]| format!("({})", fmt.list(x));
    if let Some(g) = &it.impulse_contact {
        let regime = it
            .regime
            .map(|r| format!(", {r} friction"))
            .unwrap_or_default();
        return format!("g = {} in contact space{regime}", v(g));
    }
    it.moves
        .iter()
        .map(|m| {
            let turn = if m.angular == [0.0; 3] {
                String::new()
            } else {
                format!(
                    ", Δθ {}{}",
                    v(&m.angular),
                    if m.limited { " (limited)" } else { "" }
                )
            };
            format!("{} Δp {}{turn}", m.body, v(&m.linear))
        })
        .collect::<Vec<_>>()
        .join("; ")
}
