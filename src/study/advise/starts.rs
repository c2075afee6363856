//! advise's later searches (docs/study.md, "The time-step starts"): from
//! the reference at each time step, and from the reference with each
//! other solver. Each replaces the first search's choice only when cheaper,
//! so no scene does worse than from the first seeds alone.

use super::search::{self, Evaluator, Searched};
use super::Dimension;
use crate::study::grid;
use crate::study::Config;

/// From each time step: the reference at that step, its cheapest pair move
/// (free moves included), a descent with the time step held, and a
/// descent over every dimension.
pub(super) fn from_each_time_step(
    ev: &mut Evaluator<'_>,
    dims: &[Dimension],
    reference_config: &Config,
    searched: &mut Searched,
    target: f64,
) {
    // Why: the descent from the reference takes the time step first and cannot
    // come back: mass-ratio-stack's cheapest settled model is at dt = 1/60
    // s with a loose velocity epsilon and rollback, two changes of which
    // neither alone helps (the epsilon alone costs more and misses,
    // rollback alone changes nothing the cost sees).
    let (time_step, other_dims): (Vec<Dimension>, Vec<Dimension>) = dims
        .iter()
        .cloned()
        .partition(|d| d.name == crate::knobs::DT.name);
    for v in time_step.iter().flat_map(|d| &d.values) {
        ev.watch.stage(&format!("from dt = {v} s"));
        let mut c = *reference_config;
        if grid::set(&mut c, "dt", v).is_err()
            || c == *reference_config
            || ev.eval(&c, f64::INFINITY).error > target
        {
            continue;
        }
        let (pair, tried) = search::pair_move(ev, &other_dims, &c, target, true);
        let (held, p, _) = search::descend(ev, &other_dims, pair.map_or(c, |e| e.config), target);
        let (end, q, capped) = search::descend(ev, dims, held, target);
        searched.pairs += tried;
        searched.passes += p + q;
        searched.capped |= capped;
        let (here, there) = (
            ev.eval(&searched.config, f64::INFINITY).cost,
            ev.eval(&end, f64::INFINITY).cost,
        );
        if search::cheaper(there, here) {
            searched.config = end;
        }
    }
}

/// A second search from the reference with each other solver.
pub(super) fn with_the_other_solver(
    ev: &mut Evaluator<'_>,
    dims: &[Dimension],
    reference_config: &Config,
    searched: &mut Searched,
    target: f64,
) {
    // The solver decides which other settings work (stack-5's cheapest at 1 cm
    // is the lecture's order sleeping by island, far from any descent from
    // sequential impulses). The cheaper of the two ends wins (a tie: the
    // first's), so no scene does worse than from the first seeds alone.
    // (The other solver: every value of a dimension that changes it.)
    let others: Vec<Config> = dims
        .iter()
        .flat_map(|d| d.values.iter().map(move |v| (d.name, v)))
        .filter_map(|(name, v)| {
            let mut c = *reference_config;
            (grid::set(&mut c, name, v).is_ok() && c.solver() != reference_config.solver())
                .then_some(c)
        })
        .collect();
    if !others.is_empty() {
        let other = search::search(ev, dims, &others, target);
        let (there, here) = (
            ev.eval(&other.config, f64::INFINITY),
            ev.eval(&searched.config, f64::INFINITY),
        );
        // (From a seed that misses the target, only a pair move can reach one that meets it.)
        let better = there.error <= target && search::cheaper(there.cost, here.cost);
        *searched = search::Searched {
            config: if better {
                other.config
            } else {
                searched.config
            },
            passes: searched.passes + other.passes,
            capped: searched.capped || other.capped,
            escapes: searched.escapes + other.escapes,
            pairs: searched.pairs + other.pairs,
        };
    }
}
