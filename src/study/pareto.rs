//! The Pareto front of a scene's rows (no other row is both cheaper and more
//! accurate, beyond the spread of the timed runs) and the one sentence that
//! says what the trade is.

use super::{Budget, Row, SceneStudy};
use crate::format::Fmt;
use crate::knobs::Choice;
use crate::physics::Solver;

/// Errors this close (relative, or absolute in metres) are a tie: the runs
/// are deterministic, so only round-off parts them.
const ERROR_TIE_RELATIVE: f64 = 1e-6;
const ERROR_TIE_ABSOLUTE: f64 = 1e-12;

/// A row's cost for the front: its work per simulated second
/// ([`Row::cost`], deterministic: advise's cost), the axis the chart plots.
fn cost_of(r: &Row) -> f64 {
    r.cost()
}

/// Work per simulated second, a count: whole from 10 up (`1262`, not
/// `1.26e3`), the formatter's below ("—" when not a number).
pub fn work_text(fmt: &Fmt, x: f64) -> String {
    if !x.is_finite() {
        "—".into()
    } else if x >= 10.0 {
        format!("{x:.0}")
    } else {
        fmt.num(x)
    }
}

/// `a` below `b` beyond round-off.
fn less_error(a: f64, b: f64) -> bool {
    a < b - (ERROR_TIE_RELATIVE * b.abs()).max(ERROR_TIE_ABSOLUTE)
}

/// True when `j` dominates `i`: `j` does no more work per simulated second
/// and is either cheaper in work and no less accurate, or more accurate
/// beyond round-off. Timing does not decide: a rule on the timed min–max
/// ranges (a row dominated only when slower beyond both ranges) still moved
/// the marks between two runs wherever two ranges nearly touched, so the
/// marks follow the work, and the table shows each row's timed range
/// beside it.
fn dominates(j: (f64, f64), i: (f64, f64)) -> bool {
    let ((jv, ej), (iv, ei)) = (j, i);
    if jv > iv {
        return false;
    }
    (jv < iv && !less_error(ei, ej)) || less_error(ej, ei)
}

/// Marks the rows on the front of (cost, error): a row leaves it only when
/// another row dominates it ([`dominates`]); rows of equal work and tied
/// errors both stay (a tie is shown as a tie). Rows that failed or have no
/// finite numbers take no part.
pub fn mark(rows: &mut [Row]) {
    let point = |r: &Row| {
        let (v, e) = (cost_of(r), r.error_vs_reference);
        (r.failure.is_none() && v.is_finite() && e.is_finite()).then_some((v, e))
    };
    let points: Vec<_> = rows.iter().map(point).collect();
    for (i, row) in rows.iter_mut().enumerate() {
        row.pareto = match points[i] {
            None => false,
            Some(p) => !points
                .iter()
                .enumerate()
                .any(|(j, q)| j != i && q.is_some_and(|q| dominates(q, p))),
        };
    }
}

/// The rows of the front, cheapest first: by work per simulated second
/// (deterministic), then by error, so that the order does not follow
/// timing noise.
pub fn front(rows: &[Row]) -> Vec<&Row> {
    let mut f: Vec<&Row> = rows.iter().filter(|r| r.pareto).collect();
    f.sort_by(|a, b| {
        a.cost()
            .total_cmp(&b.cost())
            .then(b.error_vs_reference.total_cmp(&a.error_vs_reference))
    });
    f
}

/// The budget row of `solver` (warm or not) at `per_contact` visits.
fn at_budget<'a>(rows: &'a [Row], label: &str, per_contact: usize) -> Option<&'a Row> {
    rows.iter().find(|r| {
        (r.knob == "budget" || r.knob == "default")
            && r.config.solver_label() == label
            && r.config.budget == Budget::PerContact(per_contact)
            && r.failure.is_none()
    })
}

/// `a` against `b` in a word: less, more, or the same (within round-off).
fn compared(a: f64, b: f64) -> &'static str {
    if less_error(a, b) {
        "less"
    } else if less_error(b, a) {
        "more"
    } else {
        "the same"
    }
}

/// Where the grid turns `rollback` (scenes that can end deep in one
/// another): that row against the default's, on what rolling back trades —
/// penetration left, energy gained (a body rolled back against gravity
/// gains potential energy), work and error; all deterministic, so the same
/// study says the same sentence.
fn rollback_sentence(study: &SceneStudy, fmt: &Fmt) -> Option<String> {
    let default = study.rows.iter().find(|r| r.knob == "default")?;
    let other = study.rows.iter().find(|r| r.knob == "rollback")?;
    let (to, from) = (
        other.config.params.rollback.name(),
        default.config.params.rollback.name(),
    );
    if other.failure.is_some() || default.failure.is_some() {
        return Some(format!(
            "Rollback: with rollback = {to} instead of {from} (the default) a run blew up, so the two do not compare."
        ));
    }
    let pairs = [
        (other.max_penetration, default.max_penetration),
        (other.energy_gain, default.energy_gain),
        (other.cost(), default.cost()),
        (other.error_vs_reference, default.error_vs_reference),
    ];
    if pairs.iter().all(|&(a, b)| compared(a, b) == "the same") {
        return Some(format!(
            "Rollback: rollback = {to} changes nothing against {from} here: no pair was found deeper than position_epsilon while closing, so none had a time of collision to go back to."
        ));
    }
    Some(format!(
        "Rollback: with rollback = {to} instead of {from} (the default) the run leaves {} penetration ({} m against {} m), gains {} energy ({} J against {} J), does {} work ({} against {} per simulated second) and ends {} the reference ({} m against {} m).",
        compared(pairs[0].0, pairs[0].1),
        fmt.num(pairs[0].0),
        fmt.num(pairs[0].1),
        compared(pairs[1].0, pairs[1].1),
        fmt.num(pairs[1].0),
        fmt.num(pairs[1].1),
        compared(pairs[2].0, pairs[2].1),
        work_text(fmt, pairs[2].0),
        work_text(fmt, pairs[2].1),
        match compared(pairs[3].0, pairs[3].1) {
            "less" => "nearer to",
            "more" => "further from",
            _ => "as far from",
        },
        fmt.num(pairs[3].0),
        fmt.num(pairs[3].1),
    ))
}

/// One sentence: the cheapest and the most accurate configuration of the
/// front, and the two solvers at equal work (8 visits per contact). Costs
/// are quoted as work per simulated second (deterministic) whether or not
/// timing is on, so the same study gives the same sentence.
pub fn verdict(study: &SceneStudy) -> String {
    let fmt = Fmt::new(2);
    let work = |r: &Row| format!("work {}/s", work_text(&fmt, r.cost()));
    let f = front(&study.rows);
    let (Some(cheap), Some(best)) = (f.first(), f.last()) else {
        return "No configuration finished: nothing to compare.".into();
    };
    let name = |r: &Row| format!("{} = {}", r.knob, r.value);
    let mut s = if f.len() == 1 {
        format!(
            "One configuration is both the cheapest and the most accurate: {} ({}, error {} m)",
            name(cheap),
            work(cheap),
            fmt.num(cheap.error_vs_reference),
        )
    } else {
        format!(
            "The front runs from {} ({}, error {} m) to {} ({}, error {} m)",
            name(cheap),
            work(cheap),
            fmt.num(cheap.error_vs_reference),
            name(best),
            work(best),
            fmt.num(best.error_vs_reference),
        )
    };
    // The labels are the study's (`Config::solver_label`): warm-started
    // sequential impulses where the grid has them (quick and full both do).
    let df = at_budget(&study.rows, Solver::DeepestFirst.name(), 8);
    let si = at_budget(&study.rows, "sequential-impulse+warm", 8)
        .or_else(|| at_budget(&study.rows, Solver::SequentialImpulse.name(), 8));
    if let (Some(df), Some(si)) = (df, si) {
        let (a, b) = (df.error_vs_reference, si.error_vs_reference);
        let winner = if a < 0.5 * b {
            "the lecture's order wins"
        } else if b < 0.5 * a {
            "sequential impulses win"
        } else {
            "neither wins by a factor of two"
        };
        s.push_str(&format!(
            "; at equal work (8 visits per contact) the lecture's order leaves error {} m and {} {} m: {winner}",
            fmt.num(a),
            if si.config.solver_label().ends_with("+warm") {
                "warm-started sequential impulses leave"
            } else {
                "sequential impulses leave"
            },
            fmt.num(b),
        ));
    }
    s.push('.');
    if let Some(r) = rollback_sentence(study, &fmt) {
        s.push(' ');
        s.push_str(&r);
    }
    if let Some(missing) = study.partial {
        s.push_str(&format!(
            " The grid is partial (quick): {missing} rows of the full grid were not run, and they could move the front; the solvers are compared on the same rows as the full grid's."
        ));
    }
    s
}
