//! The cheapest model that meets a target (`contact-lab advise`): a
//! coordinate descent over the study's dimensions (the budget, the float
//! type, and every knob of the table offered to the study), starting from
//! the scene's reference (error 0, the dearest configuration), each pass
//! trying every value of one dimension with the others held and keeping the
//! cheapest whose error stays at or below the target, until a pass changes
//! nothing. Every configuration is measured once (a cache): the cost is
//! deterministic work, not time, so the same scene and target always give
//! the same advice.
//!
//! Cost: (contact visits + 1) per step × steps per simulated second — the
//! resolver's visits of both phases plus one for the step's own work
//! (integration, detection), per simulated second so that time steps of
//! different lengths compare.

use super::{grid, run, Config};
use crate::lesson::knob_value;
use crate::lesson::Lesson;
use crate::physics::knobs::{Kind, Needs, Table};

/// Most passes of the descent (each pass tries every dimension): the
/// embedded scenes at 1 cm per run end within 6 (mass-ratio-stack was still
/// improving when this was 4; tests/measure/advise_every_scene.rs).
pub const MAX_PASSES: usize = 8;

/// Costs this close (relative) are a tie, and the simpler value wins.
const COST_TIE: f64 = 1e-9;

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
    /// The run's error: RMS distance of the final positions to the reference's.
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
            Per::Run => "the run's error: RMS over the movable bodies of the distance between final positions",
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
    /// The chosen value of every searched dimension, in search order.
    pub values: Vec<(&'static str, String)>,
    pub needed: Vec<Needed>,
    pub not_needed: Vec<&'static str>,
    pub held: Vec<Held>,
    /// The search's own cost: configurations run, steps simulated, passes.
    pub runs: usize,
    pub steps: usize,
    pub passes: usize,
    /// What the reference run exercised (the evidence).
    pub exercised: super::exercised::Exercised,
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
    knobs.sort_by_key(|k| k.name != "dt");
    let mut budget_pushed = false;
    for k in knobs {
        if k.name != "dt" && !budget_pushed {
            dims.push(Dimension {
                name: "budget",
                values: ["1", "2", "4", "8", "16", "converged"]
                    .map(String::from)
                    .to_vec(),
            });
            budget_pushed = true;
        }
        let wanted = match k.needs {
            Needs::Always => true,
            Needs::Friction => features.friction,
            Needs::BoxPairs => features.box_pairs,
        };
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
                .chain(choices.iter().map(|(c, _)| c.to_string()))
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

/// Measures configurations, each once (a run stopped at a cost cap is run
/// again only when asked with a higher cap).
struct Evaluator<'a> {
    lesson: &'a Lesson,
    seconds: f64,
    reference: Vec<nalgebra::Vector3<f64>>,
    /// The reference's positions at every step, for [`Per::Step`].
    trajectory: Option<run::Trajectory>,
    /// Each configuration's evaluation, and the cap it was stopped at.
    cache: Vec<(Eval, Option<f64>)>,
    steps: usize,
    runs: usize,
}

impl Evaluator<'_> {
    /// `config` measured, or, when its cost passes `cap`, an evaluation of
    /// infinite cost (it cannot be chosen against a row that costs `cap`).
    fn eval(&mut self, config: &Config, cap: f64) -> Eval {
        if let Some((e, stopped)) = self.cache.iter().find(|(e, _)| e.config == *config) {
            if stopped.is_none_or(|c| cap <= c) {
                return *e;
            }
        }
        let work = cap * self.seconds;
        let limit = if work.is_finite() && work < 1e18 {
            work.ceil() as usize
        } else {
            usize::MAX
        };
        let m = run::measure_against(
            self.lesson,
            config,
            self.seconds,
            limit,
            self.trajectory.as_ref(),
        );
        self.runs += 1;
        self.steps += m.steps;
        let e = if m.capped {
            Eval {
                config: *config,
                cost: f64::INFINITY,
                error: f64::NAN,
            }
        } else {
            Eval {
                config: *config,
                cost: cost(&m, self.seconds),
                error: if m.failure.is_some() {
                    f64::NAN
                } else if self.trajectory.is_some() {
                    m.step_error
                } else {
                    run::rms_distance(&m.positions, &self.reference)
                },
            }
        };
        self.cache.retain(|(x, _)| x.config != *config);
        self.cache.push((e, m.capped.then_some(cap)));
        e
    }
}

/// Work per simulated second: (visits + ccd tests + 1) per step × steps / seconds.
pub fn cost(m: &run::Measured, seconds: f64) -> f64 {
    (m.visits_per_step + m.ccd_tests_per_step + 1.0) * m.steps as f64 / seconds
}

/// `a` cheaper than `b` beyond a tie.
fn cheaper(a: f64, b: f64) -> bool {
    a < b * (1.0 - COST_TIE)
}

/// The best value of `dim` around `current`: the cheapest meeting `target`
/// (ties: the earlier value), with every value's evaluation.
fn best_of(
    ev: &mut Evaluator,
    current: &Config,
    dim: &Dimension,
    target: Option<f64>,
) -> (usize, Vec<Eval>) {
    // Nothing dearer than the current configuration can be chosen, nor be
    // the cheap setting: runs stop once they pass its cost.
    let cap = ev.eval(current, f64::INFINITY).cost * (1.0 + 2.0 * COST_TIE);
    let evals: Vec<Eval> = dim
        .values
        .iter()
        .map(|v| {
            let mut c = *current;
            let _ = grid::set(&mut c, dim.name, v);
            ev.eval(&c, cap)
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
    let default = grid::default_config(lesson)?;
    let reference_config = grid::reference(&default, reference_solver);
    let features = grid::features(lesson);
    let (dims, held) = dimensions(&default, &reference_config, features);
    let (reference_run, exercised) = super::exercised::measure(lesson, &reference_config, seconds);
    // Per step: the reference run again, its positions kept at every step.
    let trajectory =
        (per == Per::Step).then(|| run::trajectory(lesson, &reference_config, seconds));
    let mut ev = Evaluator {
        lesson,
        seconds,
        reference: reference_run.positions.clone(),
        trajectory,
        cache: Vec::new(),
        steps: reference_run.steps * if per == Per::Step { 2 } else { 1 },
        runs: if per == Per::Step { 2 } else { 1 },
    };
    let reference_eval = Eval {
        config: reference_config,
        cost: cost(&reference_run, seconds),
        error: 0.0,
    };
    ev.cache.push((reference_eval, None));
    let mut current = reference_config;
    let mut passes = 0;
    while passes < MAX_PASSES {
        passes += 1;
        let mut changed = false;
        for dim in &dims {
            let (i, _) = best_of(&mut ev, &current, dim, Some(target));
            let mut next = current;
            let _ = grid::set(&mut next, dim.name, &dim.values[i]);
            if next != current {
                current = next;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    let choice = ev.eval(&current, f64::INFINITY);
    // What each dimension buys: its cheap setting (the cheapest value, ties
    // to the earlier) with everything else as chosen.
    let mut needed = Vec::new();
    let mut not_needed = Vec::new();
    let mut values = Vec::new();
    for dim in &dims {
        let here = value_of(&current, dim.name);
        let (cheap, evals) = best_of(&mut ev, &current, dim, None);
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
        values,
        needed,
        not_needed,
        held,
        runs: ev.runs,
        steps: ev.steps,
        passes,
        exercised,
    })
}

/// The tables a scene's knobs are read from, in the order the lesson reads
/// them (lesson/validate/simulation.rs): a knob set in a later table
/// overrides one set in an earlier (`friction_model` in `[world]` over
/// `[settings]`).
const SCENE_TABLES: [Table; 4] = [Table::Settings, Table::World, Table::Step, Table::Sleep];

/// The choice as lesson tables, ready to paste: each searched knob in its
/// table (`visits_per_contact` for the budget; a knob with several homes
/// in the one the scene reads last), the float type as a
/// comment (a lesson runs in f64; the study and advise can run f32).
pub fn settings_snippet(a: &Advice) -> String {
    let mut tables: Vec<(Table, Vec<String>)> = Vec::new();
    let mut push = |t: Table, line: String| match tables.iter_mut().find(|(x, _)| *x == t) {
        Some((_, lines)) => lines.push(line),
        None => tables.push((t, vec![line])),
    };
    let c = &a.choice.config;
    push(
        Table::Settings,
        format!("visits_per_contact = {}", c.budget.per_contact()),
    );
    for (name, _) in &a.values {
        let Some(k) = crate::physics::knobs::find(name) else {
            continue;
        };
        // The table the scene reads last among the knob's homes, so that
        // the snippet overrides the scene wherever the scene spells it.
        let Some(table) = SCENE_TABLES
            .into_iter()
            .rev()
            .find(|t| k.tables.contains(t))
            .or(k.tables.first().copied())
        else {
            continue;
        };
        let v = c.get(k);
        let toml = match v {
            crate::physics::knobs::Value::Choice(s) => format!("\"{s}\""),
            _ => knob_value::text(v),
        };
        push(table, format!("{} = {toml}", k.name));
    }
    let mut out = String::new();
    for (t, lines) in &tables {
        out.push_str(t.name());
        out.push('\n');
        for l in lines {
            out.push_str(l);
            out.push('\n');
        }
        out.push('\n');
    }
    out.push_str(&format!(
        "# precision: {} (the float type: a lesson runs in f64; study --grid precision={0} runs this one)\n",
        c.precision.name()
    ));
    out
}
