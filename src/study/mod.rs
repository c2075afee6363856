//! Speed against accuracy, measured: each scene run under a grid of
//! configurations, each configuration's cost and its error against the most
//! accurate configuration of the same scene (the reference). [`grid`] says
//! which configurations, [`run`] runs and measures one, [`pareto`] marks the
//! front and says what the trade is. Renderers show the [`Study`].

pub mod grid;
pub mod pareto;
pub mod run;
pub mod sweep;

use crate::physics::params::BoxBoxMode;
use crate::physics::{FrictionModel, ProjectionMethod, RestitutionFrom, Solver};

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

/// One configuration: every knob the study turns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Config {
    pub solver: Solver,
    pub warm_start: bool,
    pub budget: Budget,
    /// Position and velocity epsilon (one knob).
    pub epsilon: f64,
    pub precision: Precision,
    pub friction_model: FrictionModel,
    pub projection: ProjectionMethod,
    pub relaxation: f64,
    pub velocity_limit: f64,
    pub restitution_from: RestitutionFrom,
    pub box_box: BoxBoxMode,
    pub sleep: bool,
    pub dt: f64,
}

impl Config {
    /// The solver with its warm start, as one label.
    pub fn solver_label(&self) -> &'static str {
        match (self.solver, self.warm_start) {
            (Solver::DeepestFirst, _) => "deepest_first",
            (Solver::SequentialImpulse, false) => "sequential_impulse",
            (Solver::SequentialImpulse, true) => "sequential_impulse+warm",
        }
    }

    /// Every knob's value as (name, text), in a fixed order.
    pub fn knobs(&self) -> Vec<(&'static str, String)> {
        vec![
            ("solver", self.solver.name().to_string()),
            ("warm_start", self.warm_start.to_string()),
            ("budget", self.budget.label()),
            ("epsilon", crate::format::exact(self.epsilon)),
            ("precision", self.precision.name().into()),
            ("friction_model", self.friction_model.name().into()),
            ("projection", self.projection.name().into()),
            ("relaxation", crate::format::exact(self.relaxation)),
            ("velocity_limit", crate::format::exact(self.velocity_limit)),
            ("restitution_from", self.restitution_from.name().into()),
            ("box_box", self.box_box.name().into()),
            ("sleep", if self.sleep { "on" } else { "off" }.into()),
            ("dt", grid::dt_label(self.dt)),
        ]
    }
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
    /// Contact visits (both phases) per step, mean over the run.
    pub visits_per_step: f64,
    /// Steps in which a phase stopped at its limit with work left.
    pub limit_steps: usize,
    pub steps: usize,
    pub max_penetration: f64,
    pub max_closing_velocity: f64,
    pub energy_gain: f64,
    pub drift: f64,
    pub error_vs_reference: f64,
    /// On the Pareto front of (cost, error) among this scene's rows.
    pub pareto: bool,
    /// Why the run stopped early (the scene blew up); its numbers are NaN.
    pub failure: Option<String>,
}

impl Row {
    /// The cost the front is drawn against: µs per step when timed, else visits per step.
    pub fn cost(&self) -> f64 {
        self.microseconds.map_or(self.visits_per_step, |m| m[0])
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
}

/// The whole study.
#[derive(Debug, Clone, PartialEq)]
pub struct Study {
    pub scenes: Vec<SceneStudy>,
    pub timed: bool,
    /// Timed runs per configuration.
    pub repeats: usize,
}
