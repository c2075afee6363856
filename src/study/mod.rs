//! Speed against accuracy, measured: each scene run under a grid of
//! configurations, each configuration's cost and its error against the most
//! accurate configuration of the same scene (the reference). [`grid`] says
//! which configurations, [`run`] runs and measures one, [`pareto`] marks the
//! front and says what the trade is. Renderers show the [`Study`].

pub mod advise;
pub mod broad;
pub mod exercised;
pub mod grid;
pub mod pareto;
pub mod run;
pub mod sweep;
pub mod verdicts;

use crate::knobs::{Knob, Offered, Value, KNOBS};
use crate::physics::{Settings, SimParams, Solver};

/// Visits per contact that stand for "to convergence": the phases stop at
/// their epsilons long before (a limit that binds is counted per row).
pub const CONVERGED: usize = 1000;

/// The iteration budget of each phase, in contact visits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Budget {
    PerContact(usize),
    /// [`CONVERGED`] visits per contact.
    Converged,
}

impl Budget {
    pub fn per_contact(self) -> usize {
        match self {
            Budget::PerContact(n) => n,
            Budget::Converged => CONVERGED,
        }
    }

    pub fn label(self) -> String {
        match self {
            Budget::PerContact(n) => format!("{n}×"),
            Budget::Converged => "converged".into(),
        }
    }
}

/// The float type the physics runs in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Precision {
    F32,
    F64,
}

impl Precision {
    pub fn name(self) -> &'static str {
        match self {
            Precision::F32 => "f32",
            Precision::F64 => "f64",
        }
    }
}

/// One configuration: the run's knobs (the scene's, with the study's
/// choices over them), the iteration budget and the float type.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Config {
    pub params: SimParams<f64>,
    pub budget: Budget,
    pub precision: Precision,
}

impl Config {
    /// The solver with its warm start, as one label.
    pub fn solver_label(&self) -> &'static str {
        match (self.params.resolver.solver, self.params.resolver.warm_start) {
            (Solver::DeepestFirst, _) => "deepest-first",
            (Solver::SequentialImpulse, false) => "sequential-impulse",
            (Solver::SequentialImpulse, true) => "sequential-impulse+warm",
            (Solver::SoftStep, _) => "soft-step",
            (Solver::Xpbd, _) => "xpbd",
            (Solver::Lcp, _) => "lcp",
        }
    }

    pub fn solver(&self) -> Solver {
        self.params.resolver.solver
    }

    /// The value of `knob` here.
    pub fn get(&self, knob: &Knob) -> Value {
        (knob.get)(&Settings::of_run(&self.params))
    }

    /// Sets `knob` to `value`.
    pub fn set(&mut self, knob: &Knob, value: Value) {
        let mut all = Settings::of_run(&self.params);
        (knob.set)(&mut all, value);
        let resolver = self.params.resolver;
        self.params = all.sim_params();
        // The budget decides the limits: no explicit count.
        self.params.resolver.position_iterations = resolver.position_iterations;
        self.params.resolver.velocity_iterations = resolver.velocity_iterations;
    }

    /// Every knob's value as (name, text), in a fixed order: the budget, the
    /// float type, then the knob table's study knobs.
    pub fn knobs(&self) -> Vec<(&'static str, String)> {
        let mut out = vec![
            ("budget", self.budget.label()),
            ("precision", self.precision.name().into()),
        ];
        out.extend(study_knobs().map(|k| (k.name, crate::lesson::knob_value::text(self.get(k)))));
        out
    }
}

/// The knobs the study turns (and `--grid` takes), from the knob table.
pub fn study_knobs() -> impl Iterator<Item = &'static Knob> {
    KNOBS.iter().filter(|k| k.study == Offered::Yes)
}

/// What one configuration did.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The knob this row turns away from the default ("default", "budget", …).
    pub knob: String,
    /// The value that knob has here, as shown.
    pub value: String,
    pub config: Config,
    /// µs per step: median, min and max over the timed runs (None: --no-timing).
    pub microseconds: Option<[f64; 3]>,
    /// µs per simulated second: the same timings × steps per second.
    pub microseconds_per_second: Option<[f64; 3]>,
    /// Contact visits (both phases) per step, mean over the run.
    pub visits_per_step: f64,
    /// Continuous detection's time-of-collision tests (GJK calls) per step,
    /// mean over the run (0 with `ccd = "none"`).
    pub ccd_tests_per_step: f64,
    /// Steps in which a phase stopped at its limit with work left.
    pub limit_steps: usize,
    pub steps: usize,
    /// Work per simulated second, advise's cost ([`advise::cost`]):
    /// (contact visits + continuous detection's tests + 1) per step ×
    /// steps per simulated second. The front is drawn against it.
    pub work_per_second: f64,
    pub max_penetration: f64,
    pub max_closing_velocity: f64,
    pub energy_gain: f64,
    pub drift: f64,
    /// Tunnelled events over the run (missed collisions).
    pub missed_collisions: usize,
    pub error_vs_reference: f64,
    /// On the Pareto front of ([`Row::cost`], error) among this scene's rows.
    pub pareto: bool,
    /// Why the run stopped early (the scene blew up); its numbers are NaN.
    pub failure: Option<String>,
}

impl Row {
    /// Deterministic work per step: contact visits plus continuous
    /// detection's tests, one GJK call counted as one visit.
    pub fn work(&self) -> f64 {
        self.visits_per_step + self.ccd_tests_per_step
    }

    /// The cost the front is computed on and the chart plots: the work
    /// per simulated second (deterministic; a smaller time step pays for
    /// its extra steps).
    pub fn cost(&self) -> f64 {
        self.work_per_second
    }
}

/// One scene's study.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneStudy {
    pub scene: String,
    pub title: String,
    pub seconds: f64,
    /// The reference configuration, described.
    pub reference: String,
    pub reference_config: Config,
    pub rows: Vec<Row>,
    /// One sentence: what the trade is in this scene.
    pub verdict: String,
    /// For a quick study: how many rows of the full grid it did not run.
    pub partial: Option<usize>,
}

/// The whole study.
#[derive(Debug, Clone, PartialEq)]
pub struct Study {
    pub scenes: Vec<SceneStudy>,
    pub timed: bool,
    /// Timed runs per configuration.
    pub repeats: usize,
}

/// The solvers `advise` searches: the lecture's order and sequential
/// impulses. The soft step, XPBD and the simultaneous (lcp) solve are left
/// out: XPBD is under test (it blows up on some embedded scenes), the lcp
/// solve is an impact solver, and the soft step's advice has not yet been
/// held by the measure layer's every-scene check (`study --verdicts`
/// measures all three beside the two).
pub const SEARCHED_SOLVERS: &[&str] = &["deepest-first", "sequential-impulse"];
