//! The Pareto front of a scene's rows (no other row is both cheaper and more
//! accurate) and the one sentence that says what the trade is.

use super::{Budget, Row, SceneStudy};
use crate::format::Fmt;
use crate::physics::Solver;

/// Marks the rows on the front of (cost, error): a row is on it when no
/// other row has cost ≤ and error ≤ with one of them strictly less. Rows
/// that failed or have no finite numbers take no part.
pub fn mark(rows: &mut [Row]) {
    let point = |r: &Row| {
        let (c, e) = (r.cost(), r.error_vs_reference);
        (r.failure.is_none() && c.is_finite() && e.is_finite()).then_some((c, e))
    };
    let points: Vec<Option<(f64, f64)>> = rows.iter().map(point).collect();
    for (i, row) in rows.iter_mut().enumerate() {
        row.pareto = match points[i] {
            None => false,
            Some((c, e)) => !points.iter().enumerate().any(|(j, q)| {
                j != i && q.is_some_and(|(c2, e2)| c2 <= c && e2 <= e && (c2 < c || e2 < e))
            }),
        };
    }
}

/// The rows of the front, cheapest first.
pub fn front(rows: &[Row]) -> Vec<&Row> {
    let mut f: Vec<&Row> = rows.iter().filter(|r| r.pareto).collect();
    f.sort_by(|a, b| a.cost().total_cmp(&b.cost()));
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

/// One sentence: the cheapest and the most accurate configuration of the
/// front, and the two solvers at equal work (8 visits per contact).
pub fn verdict(study: &SceneStudy, cost_unit: &str) -> String {
    let fmt = Fmt::new(2);
    let f = front(&study.rows);
    let (Some(cheap), Some(best)) = (f.first(), f.last()) else {
        return "No configuration finished: nothing to compare.".into();
    };
    let name = |r: &Row| format!("{} = {}", r.knob, r.value);
    let mut s = if f.len() == 1 {
        format!(
            "One configuration is both the cheapest and the most accurate: {} ({} {cost_unit}, error {} m)",
            name(cheap),
            fmt.num(cheap.cost()),
            fmt.num(cheap.error_vs_reference),
        )
    } else {
        format!(
            "The front runs from {} ({} {cost_unit}, error {} m) to {} ({} {cost_unit}, error {} m)",
            name(cheap),
            fmt.num(cheap.cost()),
            fmt.num(cheap.error_vs_reference),
            name(best),
            fmt.num(best.cost()),
            fmt.num(best.error_vs_reference),
        )
    };
    let df = at_budget(&study.rows, Solver::DeepestFirst.name(), 8);
    let si = at_budget(&study.rows, "sequential_impulse+warm", 8)
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
            si.config.solver_label().replace('-', " "),
            fmt.num(b),
        ));
    }
    s.push('.');
    s
}
