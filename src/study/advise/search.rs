//! The search behind `advise` (docs/study.md): a coordinate descent from
//! the reference, each pass trying every value of one dimension with the
//! others held and keeping the cheapest within the target, until a pass
//! changes nothing; then, to leave a local optimum where no one change stays
//! within the target though two together would, pair moves: every value of
//! a dimension that alone is cheaper (and failed the target) with every
//! value of another dimension; the cheapest pair within the target, if it is
//! cheaper than where the descent stopped, starts a new descent. The search
//! ends when no pair move improves (or after [`MAX_ESCAPES`] of them). The
//! descent runs from each seed the caller gives that meets the target (the
//! reference; for a per-run target also the per-step descent's choice), and
//! the pair moves from the cheapest place they stop; the caller runs it
//! again from the reference with the other solver ([`super::advise`]).
//!
//! Every configuration is measured once (a cache), and a run stops as soon
//! as its work passes the cost it would have to beat (the current
//! configuration's, or within a dimension the cheapest value already within
//! the target: values come cheap first), or, against a per-step target, at
//! the first step whose error passes it; the runs measure only what the
//! search reads ([`runner`]). The cost is deterministic work, not time, so
//! the same scene and target always give the same advice.

use super::{runner, Dimension, Eval, Per};
use crate::lesson::Lesson;
use crate::study::{grid, run, Config};

/// Most passes of one descent (each pass tries every dimension): the
/// embedded scenes at 1 cm per run end within 6 (mass-ratio-stack was still
/// improving when this was 4; tests/measure/advise_every_scene.rs).
pub const MAX_PASSES: usize = 8;

/// Costs this close (relative) are a tie, and the simpler value wins.
const COST_TIE: f64 = 1e-9;

/// Most pair moves taken (each followed by a descent).
pub const MAX_ESCAPES: usize = 4;

/// Measures configurations, each once (a run stopped at a cost cap is run
/// again only when asked with a higher cap).
pub(super) struct Evaluator<'a> {
    pub lesson: &'a Lesson,
    pub seconds: f64,
    pub reference: Vec<nalgebra::Vector3<f64>>,
    /// The reference's positions at every step.
    pub trajectory: run::Trajectory,
    /// The error measured: per run, the settled error (the largest over the
    /// run's last tenth, its end's included); per step, the largest over
    /// every step.
    pub per: Per,
    /// Each configuration's evaluation, and the cap it was stopped at.
    pub cache: Vec<(Eval, Option<f64>)>,
    /// Against a per-step target: stop a run at the first step whose error
    /// passes it (the run cannot be chosen; its cost is left unknown).
    pub stop_over: Option<f64>,
    pub steps: usize,
    pub runs: usize,
    /// Asks answered from the cache, and configurations run again (first
    /// stopped at a cap, then asked with a higher one).
    pub hits: usize,
    pub reruns: usize,
    /// Every run that went to its end, with the run's settled error (the
    /// per-run measure) whatever this evaluator measures: a
    /// search against the per-step error hands them to the one against the
    /// run's, which then need not run them again.
    pub finished: Vec<Eval>,
    /// Told of every configuration run (a long search's progress).
    pub watch: &'a dyn super::Watch,
}

impl Evaluator<'_> {
    /// `config` measured, or, when its cost passes `cap`, an evaluation of
    /// infinite cost (it cannot be chosen against a row that costs `cap`).
    pub fn eval(&mut self, config: &Config, cap: f64) -> Eval {
        if let Some((e, stopped)) = self.cache.iter().find(|(e, _)| e.config == *config) {
            if stopped.is_none_or(|c| cap <= c) {
                self.hits += 1;
                return *e;
            }
            self.reruns += 1;
        }
        let work = cap * self.seconds;
        let limit = if work.is_finite() && work < 1e18 {
            work.ceil() as usize
        } else {
            usize::MAX
        };
        let from = match self.per {
            Per::Step => 0,
            Per::Run => run::settle_from(run::steps(self.seconds, config.params.dt)),
        };
        let m = runner::run(
            self.lesson,
            config,
            self.seconds,
            limit,
            Some(runner::Against {
                reference: &self.trajectory,
                from,
                stop_over: self.stop_over,
            }),
        );
        self.runs += 1;
        self.steps += m.steps;
        self.watch.ran(self.runs, self.steps);
        // The run's settled error: the end's (against the reference's final
        // positions) or the last tenth's, the larger.
        let settled = if m.failed {
            f64::NAN
        } else {
            run::rms_distance(&m.positions, &self.reference).max(m.settle_error)
        };
        if !(m.capped || m.over) {
            self.finished.push(Eval {
                config: *config,
                cost: work_cost(m.work, m.steps, self.seconds),
                error: settled,
            });
        }
        let e = if m.capped || m.over {
            Eval {
                config: *config,
                cost: f64::INFINITY,
                error: if m.over { f64::INFINITY } else { f64::NAN },
            }
        } else {
            Eval {
                config: *config,
                cost: work_cost(m.work, m.steps, self.seconds),
                error: match self.per {
                    _ if m.failed => f64::NAN,
                    Per::Step => m.step_error,
                    Per::Run => settled,
                },
            }
        };
        self.cache.retain(|(x, _)| x.config != *config);
        self.cache.push((e, m.capped.then_some(cap)));
        e
    }
}

impl Evaluator<'_> {
    /// `config` run to its end with every step compared with the
    /// reference: its error at the end and at its worst step (m; NaN: it
    /// blew up).
    pub fn both_errors(&mut self, config: &Config) -> (f64, f64) {
        let m = runner::run(
            self.lesson,
            config,
            self.seconds,
            usize::MAX,
            Some(runner::Against {
                reference: &self.trajectory,
                from: 0,
                stop_over: None,
            }),
        );
        self.runs += 1;
        self.steps += m.steps;
        if m.failed {
            return (f64::NAN, f64::NAN);
        }
        (
            run::rms_distance(&m.positions, &self.reference),
            m.step_error,
        )
    }
}

/// Work per simulated second: (visits + ccd tests + 1) per step × steps / seconds.
pub fn cost(m: &run::Measured, seconds: f64) -> f64 {
    (m.visits_per_step + m.ccd_tests_per_step + 1.0) * m.steps as f64 / seconds
}

/// [`cost`] of a search run: its `work` (visits + ccd tests) and `steps`.
fn work_cost(work: usize, steps: usize, seconds: f64) -> f64 {
    (work + steps) as f64 / seconds
}

/// `a` cheaper than `b` beyond a tie.
pub(super) fn cheaper(a: f64, b: f64) -> bool {
    a < b * (1.0 - COST_TIE)
}

/// The best value of `dim` around `current`: the cheapest meeting `target`
/// (ties: the earlier value), with every value's evaluation.
pub(super) fn best_of(
    ev: &mut Evaluator,
    current: &Config,
    dim: &Dimension,
    target: Option<f64>,
) -> (usize, Vec<Eval>) {
    // Nothing dearer than the current configuration can be chosen, nor be
    // the cheap setting: runs stop once they pass its cost.
    // Against a target, nothing dearer than the cheapest value meeting it so
    // far either: the values come cheap first, so the cap falls early.
    let mut cap = ev.eval(current, f64::INFINITY).cost * (1.0 + 2.0 * COST_TIE);
    let evals: Vec<Eval> = dim
        .values
        .iter()
        .map(|v| {
            let mut c = *current;
            let _ = grid::set(&mut c, dim.name, v);
            let e = ev.eval(&c, cap);
            if target.is_some_and(|t| e.error <= t) {
                cap = cap.min(e.cost * (1.0 + 2.0 * COST_TIE));
            }
            e
        })
        .collect();
    let mut best: Option<usize> = None;
    for (i, e) in evals.iter().enumerate() {
        let ok = target.is_none_or(|t| e.error <= t);
        if ok && best.is_none_or(|b| cheaper(e.cost, evals[b].cost)) {
            best = Some(i);
        }
    }
    // The current value always meets the target (the descent keeps it so).
    let fallback = evals.iter().position(|e| e.config == *current).unwrap_or(0);
    (best.unwrap_or(fallback), evals)
}

/// What the search did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Searched {
    pub config: Config,
    /// Passes over all descents.
    pub passes: usize,
    /// A descent stopped at [`MAX_PASSES`] while still improving.
    pub capped: bool,
    /// Pair moves taken (each escaped a local optimum), and pair
    /// configurations tried.
    pub escapes: usize,
    pub pairs: usize,
}

/// `config` with `name` set to `value` (left as it is when the value does not apply).
fn with(config: &Config, name: &str, value: &str) -> Config {
    let mut c = *config;
    let _ = grid::set(&mut c, name, value);
    c
}

/// One coordinate descent from `start` (which meets the target): the
/// configuration it stops at, its passes, and whether it hit the cap.
pub(super) fn descend(
    ev: &mut Evaluator,
    dims: &[Dimension],
    start: Config,
    target: f64,
) -> (Config, usize, bool) {
    let mut current = start;
    let mut passes = 0;
    while passes < MAX_PASSES {
        passes += 1;
        let mut changed = false;
        for dim in dims {
            let (i, _) = best_of(ev, &current, dim, Some(target));
            let next = with(&current, dim.name, &dim.values[i]);
            if next != current {
                current = next;
                changed = true;
            }
        }
        if !changed {
            return (current, passes, false);
        }
    }
    (current, passes, true)
}

/// The cheapest pair move from `current` within `target` that is cheaper
/// than `current` (module docs), and the pair configurations tried. With
/// `free`, a move that costs the same (a tie: it changes nothing the cost
/// sees, as rollback at a tight velocity epsilon) pairs with every value of
/// another dimension too, as a cut does.
pub(super) fn pair_move(
    ev: &mut Evaluator,
    dims: &[Dimension],
    current: &Config,
    target: f64,
    free: bool,
) -> (Option<Eval>, usize) {
    let here = ev.eval(current, f64::INFINITY).cost;
    let cap = |c: f64| c * (1.0 + 2.0 * COST_TIE);
    // The single moves that cut the cost (all failed the target, or the
    // descent would have taken them).
    let mut cuts: Vec<(usize, Config)> = Vec::new();
    for (d, dim) in dims.iter().enumerate() {
        for v in &dim.values {
            let c = with(current, dim.name, v);
            let cost = ev.eval(&c, cap(here)).cost;
            if c != *current && (cheaper(cost, here) || (free && !cheaper(here, cost))) {
                cuts.push((d, c));
            }
        }
    }
    let mut best: Option<Eval> = None;
    let mut tried = 0;
    for (d, cut) in &cuts {
        for (d2, dim) in dims.iter().enumerate() {
            if d2 == *d {
                continue;
            }
            for v in &dim.values {
                let c = with(cut, dim.name, v);
                if c == *cut {
                    continue;
                }
                let bar = best.map_or(here, |b| b.cost);
                tried += 1;
                let e = ev.eval(&c, cap(bar));
                if e.error <= target && cheaper(e.cost, bar) {
                    best = Some(e);
                }
            }
        }
    }
    (best, tried)
}

/// A descent from each seed that meets the target (the first is the
/// reference), then, from the cheapest configuration they stop at (ties: the
/// earlier seed's), pair moves while one improves (module docs).
pub(super) fn search(
    ev: &mut Evaluator,
    dims: &[Dimension],
    seeds: &[Config],
    target: f64,
) -> Searched {
    let (mut passes, mut capped) = (0, false);
    let mut current: Option<Config> = None;
    for seed in seeds {
        if ev.eval(seed, f64::INFINITY).error > target {
            continue;
        }
        let (end, p, c) = descend(ev, dims, *seed, target);
        passes += p;
        capped |= c;
        let cost = ev.eval(&end, f64::INFINITY).cost;
        if current.is_none_or(|x| cheaper(cost, ev.eval(&x, f64::INFINITY).cost)) {
            current = Some(end);
        }
    }
    // No seed meets the target: pair moves from the first can still reach
    // one that does (ramp-stick at 1 cm from the lecture's order, which
    // creeps half a metre: 272 → 46); without one the search ends there.
    let mut current = current.unwrap_or(seeds[0]);
    let (mut escapes, mut pairs) = (0, 0);
    while escapes < MAX_ESCAPES {
        let (found, tried) = pair_move(ev, dims, &current, target, false);
        pairs += tried;
        let Some(e) = found else {
            break;
        };
        escapes += 1;
        let (next, p, c) = descend(ev, dims, e.config, target);
        current = next;
        passes += p;
        capped |= c;
    }
    Searched {
        config: current,
        passes,
        capped,
        escapes,
        pairs,
    }
}
