//! The cheapest model that meets a target (`contact-lab advise`): the
//! study's dimensions (the budget, the float type, and every knob of the
//! table offered to the study) searched from the scene's reference (error 0,
//! the dearest configuration) by coordinate descent with pair moves to leave
//! local optima ([`search`]), from the reference at each time step (a pair
//! move with free moves, then descents: the time-step starts), and again
//! from the reference with the other solver, the cheapest end kept. The
//! per-run target bounds the settled error (`Per::Run`).
//!
//! Cost: (contact visits + continuous detection's tests + 1) per step ×
//! steps per simulated second — the resolver's visits of both phases, the
//! time-of-collision searches' GJK calls, plus one for the step's own work
//! (integration, detection), per simulated second so that time steps of
//! different lengths compare.

mod runner;
mod search;
mod snippet;
mod starts;

use super::{grid, run, Config};
use crate::knobs::{Kind, Needs, DT};
use crate::lesson::knob_value;
use crate::lesson::Lesson;

pub use search::{cost, MAX_ESCAPES, MAX_PASSES};
pub use snippet::{settings_snippet, snippet};

/// One dimension searched: a name (the study's) and its values as text,
/// cheap or simple first (ties in cost go to the earlier value).
#[derive(Debug, Clone, PartialEq)]
pub struct Dimension {
    pub name: &'static str,
    pub values: Vec<String>,
}

/// A dimension left out of the search, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct Held {
    pub name: &'static str,
    pub why: String,
}

/// What the error target bounds (`advise --per`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Per {
    /// The run's settled error: the largest, over the run's last tenth of
    /// steps (its end included), of the RMS distance to the reference at
    /// the same time: the outcome, not a moment the run passes through.
    Run,
    /// Every step's: the largest, over the run's steps, of the RMS distance
    /// to the reference at the same time (interpolated between its steps).
    Step,
}

impl Per {
    pub fn name(self) -> &'static str {
        match self {
            Per::Run => "run",
            Per::Step => "step",
        }
    }

    /// The error measured, in words.
    pub fn describe(self) -> &'static str {
        match self {
            Per::Run => "the run's settled error: the largest, over the run's last tenth of steps (its end included), of the RMS distance to the reference at the same time",
            Per::Step => "the per-step error: the largest, over the steps, of the RMS distance to the reference at the same time",
        }
    }
}

/// A configuration measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Eval {
    pub config: Config,
    /// Work per simulated second (see the module's head).
    pub cost: f64,
    /// The error against the reference, m (NaN: blew up): [`Per`] says which.
    pub error: f64,
}

/// A knob the choice keeps above its cheap setting, and the error without it.
#[derive(Debug, Clone, PartialEq)]
pub struct Needed {
    pub knob: &'static str,
    pub value: String,
    pub cheap: String,
    pub error_without: f64,
}

/// The advice.
#[derive(Debug, Clone, PartialEq)]
pub struct Advice {
    pub scene: String,
    pub title: String,
    pub seconds: f64,
    pub target: f64,
    /// What the target bounds.
    pub per: Per,
    pub reference: String,
    pub reference_cost: f64,
    pub choice: Eval,
    /// The choice's error at the run's end (RMS distance of the final
    /// positions to the reference's, m) and at its worst step (the largest
    /// over every step, m): both measures whatever `per` bounds.
    pub end_error: f64,
    pub worst_step_error: f64,
    /// The chosen value of every searched dimension, in search order.
    pub values: Vec<(&'static str, String)>,
    pub needed: Vec<Needed>,
    pub not_needed: Vec<&'static str>,
    pub held: Vec<Held>,
    /// The search's own cost: configurations run, steps simulated, passes
    /// of the descents, pair moves taken and pair configurations tried,
    /// and its wall time (s).
    pub runs: usize,
    pub steps: usize,
    pub passes: usize,
    pub escapes: usize,
    pub pairs: usize,
    pub wall_seconds: f64,
    /// Asks the cache answered, and configurations run a second time (first
    /// stopped at a lower cap): of `runs`, `reruns` were repeats.
    pub hits: usize,
    pub reruns: usize,
    /// A descent stopped at [`MAX_PASSES`] while still improving.
    pub capped: bool,
    /// What the reference run exercised (the evidence).
    pub exercised: super::exercised::Exercised,
    /// The scene's own spelling of each knob it sets (`Lesson::spellings`):
    /// the snippet writes the same key, so that merged by its rule (a key
    /// the scene already sets is replaced) it replaces it.
    pub spellings: Vec<(crate::knobs::Table, &'static str, String)>,
    /// The scene's own configuration, and why its run (the scene as
    /// written) or the reference's blew up, if it did: the advice then
    /// does not model the scene as written, and says so first.
    pub default: Config,
    pub default_failure: Option<String>,
    pub reference_failure: Option<String>,
}

/// How far past the target a per-run choice's worst step must be for the
/// advice to say that the run strays on the way (`Advice::strays`).
pub const STRAYS_FAR: f64 = 10.0;

impl Advice {
    /// Per run: the choice's worst step over [`STRAYS_FAR`] × the target
    /// (its settled error meeting it): how many times the target it is.
    /// The outcome is right; the way there is not (sphere-row-20 at 1 cm:
    /// 18 cm off in the first steps, 7 mm at the end).
    pub fn strays(&self) -> Option<f64> {
        let times = self.worst_step_error / self.target;
        (self.per == Per::Run && self.choice.error <= self.target && times > STRAYS_FAR)
            .then_some(times)
    }
}

/// The dimensions searched for a scene, and those held at the scene's value.
/// The order is the descent's: the time step and the budget first (they
/// cut most), then the table's knobs in table order, the float type last.
pub fn dimensions(
    default: &Config,
    reference: &Config,
    features: grid::Features,
) -> (Vec<Dimension>, Vec<Held>) {
    let mut dims = Vec::new();
    let mut held = Vec::new();
    let mut knobs: Vec<_> = super::study_knobs().collect();
    // The time step first: it divides every other cost.
    knobs.sort_by_key(|k| **k != DT);
    let mut budget_pushed = false;
    for k in knobs {
        if *k != DT && !budget_pushed {
            dims.push(Dimension {
                name: "budget",
                values: ["1", "2", "4", "8", "16", "converged"]
                    .map(String::from)
                    .to_vec(),
            });
            budget_pushed = true;
        }
        // Penetration only picks the study's rows: the search tries
        // rollback everywhere (mass-ratio-stack's cheapest model uses it).
        let wanted = k.needs == Needs::Penetration || features.meet(k.needs);
        if !wanted {
            held.push(Held {
                name: k.name,
                why: match k.needs {
                    Needs::Friction => "the scene has no friction".into(),
                    _ => "the scene has fewer than two boxes".into(),
                },
            });
            continue;
        }
        let default_value = knob_value::text(default.get(k));
        let reference_value = knob_value::text(reference.get(k));
        let mut values: Vec<String> = match k.kind {
            // The table's default (the lecture's) first: the simpler model.
            Kind::Choice { choices, .. } => std::iter::once(k.default.to_string())
                .chain(choices.iter().map(|c| c.name.to_string()))
                .collect(),
            Kind::Flag => vec![k.default.to_string(), (k.default != "true").to_string()],
            _ if !k.grid.is_empty() => k
                .grid
                .iter()
                .map(|v| v.to_string())
                .chain([default_value.clone(), reference_value])
                .collect(),
            _ => {
                held.push(Held {
                    name: k.name,
                    why: format!("no values to try (the table gives it no grid): kept at the scene's {default_value}"),
                });
                continue;
            }
        };
        let mut seen: Vec<Config> = Vec::new();
        values.retain(|v| {
            // The solvers searched are the two the study measures
            // ([`super::SEARCHED_SOLVERS`]).
            if *k == crate::knobs::SOLVER && !super::SEARCHED_SOLVERS.contains(&v.as_str()) {
                return false;
            }
            let mut c = *reference;
            let ok = grid::set(&mut c, k.name, v).is_ok() && !seen.contains(&c);
            seen.push(c);
            ok
        });
        if values.len() < 2 {
            continue;
        }
        dims.push(Dimension {
            name: k.name,
            values,
        });
    }
    dims.push(Dimension {
        name: "precision",
        values: vec!["f32".into(), "f64".into()],
    });
    (dims, held)
}

/// The value of dimension `name` in `c`, as text.
pub fn value_of(c: &Config, name: &str) -> String {
    c.knobs()
        .into_iter()
        .find(|(n, _)| *n == name)
        .map_or_else(String::new, |(_, v)| match name {
            "budget" => v.trim_end_matches('×').to_string(),
            "dt" => grid::dt_label(c.params.dt),
            _ => v,
        })
}

/// How long `advise` runs a scene and which solver its reference uses: the
/// study's default scenes' (`grid::SCENES`); any other scene its own length,
/// at most 2 s, against sequential impulses. None: not a scene.
pub fn run_of(lesson: &Lesson) -> Option<(f64, crate::physics::Solver)> {
    let scene = lesson.simulation.as_ref()?;
    Some(
        match grid::SCENES.iter().find(|(id, _, _)| *id == lesson.id) {
            Some(&(_, seconds, solver)) => (seconds, solver),
            None => (
                (scene.steps as f64 * scene.dt).min(2.0),
                crate::physics::Solver::SequentialImpulse,
            ),
        },
    )
}

/// What a search tells as it goes, for a progress display (nothing here
/// prints): how many stages it will take, each stage as it begins, and
/// each configuration run (runs and steps so far).
pub trait Watch {
    fn plan(&self, _stages: usize) {}
    fn stage(&self, _what: &str) {}
    fn ran(&self, _runs: usize, _steps: usize) {}
}

/// Nobody watching.
impl Watch for () {}

/// Searches `lesson` for the cheapest configuration whose error against
/// the reference stays at or below `target` (m), the error measured `per`
/// run or per step.
pub fn advise(
    lesson: &Lesson,
    seconds: f64,
    reference_solver: crate::physics::Solver,
    target: f64,
    per: Per,
) -> Option<Advice> {
    advise_watched(lesson, seconds, reference_solver, target, per, &())
}

/// [`advise`], telling `watch` how the search goes.
pub fn advise_watched(
    lesson: &Lesson,
    seconds: f64,
    reference_solver: crate::physics::Solver,
    target: f64,
    per: Per,
    watch: &dyn Watch,
) -> Option<Advice> {
    let started = std::time::Instant::now();
    let default = grid::default_config(lesson)?;
    let reference_config = grid::reference(&default, reference_solver);
    let features = grid::features(lesson);
    let (dims, held) = dimensions(&default, &reference_config, features);
    // The stages: the reference and the scene's own run, the per-step seed
    // (per run), the first search, one per time step, the other solver,
    // what each knob buys.
    let time_steps = dims
        .iter()
        .find(|d| d.name == DT.name)
        .map_or(0, |d| d.values.len());
    watch.plan(4 + usize::from(per == Per::Run) + time_steps);
    watch.stage("the reference and the scene's own run");
    let (reference_run, exercised) = super::exercised::measure(lesson, &reference_config, seconds);
    // The scene as written: a run that blows up is said up front.
    let default_failure = run::measure(lesson, &default, seconds).failure;
    // The reference run again, its positions kept at every step (both
    // measures compare steps with it: per run the last tenth, per step all).
    let trajectory = run::trajectory(lesson, &reference_config, seconds);
    let mut ev = search::Evaluator {
        lesson,
        seconds,
        reference: reference_run.positions.clone(),
        trajectory: trajectory.clone(),
        per,
        cache: Vec::new(),
        stop_over: None,
        steps: reference_run.steps * 2,
        runs: 2,
        hits: 0,
        reruns: 0,
        finished: Vec::new(),
        watch,
    };
    let reference_eval = Eval {
        config: reference_config,
        cost: cost(&reference_run, seconds),
        error: 0.0,
    };
    ev.cache.push((reference_eval, None));
    // The seeds: the reference and, for a per-run target, where the descent
    // against the per-step error stops. It meets the run's target too (the
    // run's error is its last step's) and lies where a descent from the
    // reference, one knob at a time, cannot go: on mass-ratio-stack at 1 cm
    // it changes the time step, rollback, the epsilon and sleep together.
    let mut seeds = vec![reference_config];
    if per == Per::Run {
        let mut by_step = search::Evaluator {
            lesson,
            seconds,
            reference: reference_run.positions.clone(),
            trajectory: trajectory.clone(),
            per: Per::Step,
            cache: vec![(reference_eval, None)],
            stop_over: Some(target),
            steps: 0,
            runs: 0,
            hits: 0,
            reruns: 0,
            finished: Vec::new(),
            watch,
        };
        watch.stage("the descent against the per-step error");
        let (seed, _, _) = search::descend(&mut by_step, &dims, reference_config, target);
        ev.runs += by_step.runs;
        ev.steps += by_step.steps;
        ev.hits += by_step.hits;
        ev.reruns += by_step.reruns;
        // The runs it finished, measured against the run's error as well.
        for e in by_step.finished {
            if !ev.cache.iter().any(|(x, _)| x.config == e.config) {
                ev.cache.push((e, None));
            }
        }
        seeds.push(seed);
    }
    watch.stage("the descent from the reference");
    let mut searched = search::search(&mut ev, &dims, &seeds, target);
    starts::from_each_time_step(&mut ev, &dims, &reference_config, &mut searched, target);
    watch.stage("the other solver");
    starts::with_the_other_solver(&mut ev, &dims, &reference_config, &mut searched, target);
    watch.stage("what each knob buys");
    let current = searched.config;
    let choice = ev.eval(&current, f64::INFINITY);
    // The choice once more, every step compared: its end and worst step.
    let (end_error, worst_step_error) = ev.both_errors(&current);
    // What each dimension buys: its cheap setting (the cheapest value, ties
    // to the earlier) with everything else as chosen.
    let mut needed = Vec::new();
    let mut not_needed = Vec::new();
    let mut values = Vec::new();
    for dim in &dims {
        let here = value_of(&current, dim.name);
        let (cheap, evals) = search::best_of(&mut ev, &current, dim, None);
        let chosen = evals.iter().position(|e| e.config == current);
        values.push((dim.name, here.clone()));
        if chosen == Some(cheap) {
            not_needed.push(dim.name);
        } else {
            needed.push(Needed {
                knob: dim.name,
                value: here,
                cheap: dim.values[cheap].clone(),
                error_without: evals[cheap].error,
            });
        }
    }
    Some(Advice {
        scene: lesson.id.clone(),
        title: lesson.title.clone(),
        seconds,
        target,
        per,
        reference: grid::describe_reference(&reference_config),
        reference_cost: reference_eval.cost,
        choice,
        end_error,
        worst_step_error,
        values,
        needed,
        not_needed,
        held,
        runs: ev.runs,
        steps: ev.steps,
        passes: searched.passes,
        escapes: searched.escapes,
        pairs: searched.pairs,
        wall_seconds: started.elapsed().as_secs_f64(),
        hits: ev.hits,
        reruns: ev.reruns,
        capped: searched.capped,
        exercised,
        spellings: lesson.spellings.clone(),
        default,
        default_failure,
        reference_failure: reference_run.failure.clone(),
    })
}
