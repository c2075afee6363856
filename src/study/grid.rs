//! Which configurations a study runs: the default scenes and their run
//! lengths, each scene's default configuration (its lesson's settings), the
//! reference, and the grid — one knob at a time around the default, plus the
//! iteration budget for each solver — or the knobs a user asks for
//! (`--grid KNOB=V1,V2`).

use super::{Budget, Config, Precision};
use crate::knobs::Needs;
use crate::lesson::Lesson;
use crate::physics::{SimParams, Solver};

/// The default scenes, how long each runs (s), and which solver the
/// reference uses (the lecture's order for the cradle, whose real answer is
/// a sequence of collisions; sequential impulses elsewhere).
pub const SCENES: [(&str, f64, Solver); 9] = [
    ("sphere-row-20", 0.5, Solver::SequentialImpulse),
    ("resting-box", 2.0, Solver::SequentialImpulse),
    ("stack-5", 2.0, Solver::SequentialImpulse),
    ("mass-ratio-stack", 2.0, Solver::SequentialImpulse),
    ("ramp-stick", 2.0, Solver::SequentialImpulse),
    ("ball-drop", 2.0, Solver::SequentialImpulse),
    ("cradle-over-time", 1.0, Solver::DeepestFirst),
    ("overlap-recovery", 1.0, Solver::SequentialImpulse),
    ("bullet-wall", 0.5, Solver::SequentialImpulse),
];

/// The reference's time step and epsilon.
pub const REFERENCE_DT: f64 = 1.0 / 480.0;
pub const REFERENCE_EPSILON: f64 = 1e-4;

/// The study's own dimensions besides the knob table's: the iteration
/// budget (visits per contact, or converged) and the float type.
pub const DIMENSIONS: [&str; 2] = ["budget", "precision"];

/// The names `--grid` accepts.
pub fn knob_names() -> Vec<&'static str> {
    DIMENSIONS
        .into_iter()
        .chain(super::study_knobs().map(|k| k.name))
        .collect()
}

/// `1/60` for a time step that is one over a whole number, else the number.
pub fn dt_label(dt: f64) -> String {
    let n = (1.0 / dt).round();
    if n >= 1.0 && (1.0 / n - dt).abs() <= 1e-12 * dt {
        format!("1/{n}")
    } else {
        crate::format::exact(dt)
    }
}

/// The scene's own configuration: its lesson's settings, its budget
/// (`visits_per_contact`, the lecture's 8 unless the lesson says; 1000 is
/// converged), f64.
pub fn default_config(lesson: &Lesson) -> Option<Config> {
    let mut params = lesson.sim_params()?;
    params.resolver.position_iterations = None;
    params.resolver.velocity_iterations = None;
    let budget = match params.resolver.visits_per_contact {
        super::CONVERGED => Budget::Converged,
        n => Budget::PerContact(n),
    };
    Some(Config {
        params,
        budget,
        precision: Precision::F64,
    })
}

/// The most accurate configuration: `solver` (warm-started if sequential),
/// converged, epsilons 1e-4, f64, dt = 1/480 s, no sleep, continuous
/// detection by conservative advancement (no collision missed).
pub fn reference(default: &Config, solver: Solver) -> Config {
    let mut c = *default;
    c.params.resolver.solver = solver;
    c.params.resolver.warm_start = solver == Solver::SequentialImpulse;
    c.params.resolver.position_epsilon = REFERENCE_EPSILON;
    c.params.resolver.velocity_epsilon = REFERENCE_EPSILON;
    c.params.sleep.enabled = false;
    c.params.dt = REFERENCE_DT;
    c.params.ccd = crate::physics::step::ccd_mode::Ccd::Conservative;
    c.budget = Budget::Converged;
    c.precision = Precision::F64;
    c
}

/// The reference in words.
pub fn describe_reference(c: &Config) -> String {
    format!(
        "{}, {} visits per contact (to convergence), epsilon {}, f64, dt = {} s, no sleep, continuous detection (conservative advancement), the scene's other settings",
        match c.solver() {
            Solver::DeepestFirst => "the lecture's deepest-first order",
            Solver::SequentialImpulse => "sequential impulses, warm-started",
            Solver::SoftStep => "the soft step (Box2D v3's)",
            Solver::Xpbd => "XPBD",
            Solver::Lcp => "the simultaneous (lcp) solve",
        },
        super::CONVERGED,
        crate::format::exact(c.params.resolver.position_epsilon),
        dt_label(c.params.dt)
    )
}

/// Sets `knob` to the text `value` in `config`; an error names what is accepted.
pub fn set(config: &mut Config, knob: &str, value: &str) -> Result<(), String> {
    let bad = |accepted: &str| Err(format!("{knob}={value}: expected {accepted}"));
    match knob {
        "budget" => match value {
            "converged" => config.budget = Budget::Converged,
            _ => match value
                .trim_end_matches('×')
                .trim_end_matches('x')
                .parse::<usize>()
            {
                Ok(n) if (1..=100_000).contains(&n) => config.budget = Budget::PerContact(n),
                _ => return bad("visits per contact, 1 to 100000, or converged"),
            },
        },
        "precision" => match value {
            "f32" => config.precision = Precision::F32,
            "f64" => config.precision = Precision::F64,
            _ => return bad("f32 or f64"),
        },
        // The label the study gives a warm-started solver (`sequential-impulse+warm`).
        _ if value.ends_with("+warm") => {
            set(config, knob, value.trim_end_matches("+warm"))?;
            config.params.resolver.warm_start = true;
        }
        _ => {
            let Some(k) = super::study_knobs().find(|k| k.name == knob.replace('-', "_")) else {
                return Err(format!(
                    "unknown knob '{knob}': the knobs are {}",
                    knob_names().join(", ")
                ));
            };
            let v = crate::lesson::knob_value::from_text(k, value)
                .map_err(|e| format!("{knob}={value}: {e}"))?;
            config.set(k, v);
        }
    }
    Ok(())
}

/// A `--grid KNOB=V1,V2` argument, checked against a default configuration.
pub fn parse_grid(arg: &str) -> Result<(String, Vec<String>), String> {
    let (knob, values) = arg.split_once('=').ok_or_else(|| {
        format!(
            "--grid {arg}: expected KNOB=V1,V2,… (knobs: {})",
            knob_names().join(", ")
        )
    })?;
    let knob = knob.trim().replace('-', "_");
    let values: Vec<String> = values.split(',').map(|v| v.trim().to_string()).collect();
    let mut probe = probe_config();
    for v in &values {
        set(&mut probe, &knob, v)?;
    }
    Ok((knob, values))
}

fn probe_config() -> Config {
    Config {
        params: SimParams::default(),
        budget: Budget::PerContact(8),
        precision: Precision::F64,
    }
}

/// What the scene has that some knobs act on.
#[derive(Debug, Clone, Copy)]
pub struct Features {
    pub friction: bool,
    pub box_pairs: bool,
    /// Bodies that can end deep in one another ([`Needs::Penetration`]).
    pub penetration: bool,
}

impl Features {
    /// True when the scene has what `needs` asks for.
    pub fn meet(&self, needs: Needs) -> bool {
        match needs {
            Needs::Always => true,
            Needs::Friction => self.friction,
            Needs::BoxPairs => self.box_pairs,
            Needs::Penetration => self.penetration,
        }
    }
}

/// [`Needs::Penetration`] from the lesson's bodies at the start: two movable
/// bodies whose masses differ more than [`super::exercised::HEAVY`] times,
/// or a movable body whose speed — its own, plus what it gains falling to
/// the lowest other body, √(v² + 2 g h) — crosses more than
/// [`super::exercised::FAST`] of the thinnest other body in one step of the
/// scene's dt.
fn penetration(lesson: &Lesson) -> bool {
    let Some(scene) = lesson.simulation.as_ref() else {
        return false;
    };
    let g = scene.world.gravity.norm();
    let up = if g > 0.0 {
        -scene.world.gravity / g
    } else {
        nalgebra::Vector3::zeros()
    };
    let movable: Vec<_> = lesson.bodies.iter().filter(|b| b.movable()).collect();
    let heavy = movable.iter().any(|a| {
        movable
            .iter()
            .any(|b| a.mass > super::exercised::HEAVY * b.mass)
    });
    let fast = movable.iter().any(|a| {
        lesson.bodies.iter().any(|o| {
            if std::ptr::eq(*a, o) {
                return false;
            }
            let h = (a.position - o.position).dot(&up).max(0.0);
            let speed = (a.velocity.norm_squared() + 2.0 * g * h).sqrt();
            speed * scene.dt > super::exercised::FAST * super::exercised::thinnest(&o.shape)
        })
    });
    heavy || fast
}

pub fn features(lesson: &Lesson) -> Features {
    let friction = lesson.simulation.as_ref().is_some_and(|s| {
        s.materials
            .iter()
            .any(|m| m.static_friction > 0.0 || m.dynamic_friction > 0.0)
    });
    let boxes = lesson
        .bodies
        .iter()
        .filter(|b| matches!(b.shape, Some(crate::physics::Shape::Box { .. })))
        .count();
    Features {
        friction,
        box_pairs: boxes >= 2,
        penetration: penetration(lesson),
    }
}

/// The rows to run: (knob, value label, configuration). `user` holds the
/// `--grid` knobs: then their cross product around the default is the grid.
pub fn rows(
    default: &Config,
    features: Features,
    quick: bool,
    user: &[(String, Vec<String>)],
) -> Vec<(String, String, Config)> {
    let mut out = vec![(
        "default".to_string(),
        default.solver_label().to_string(),
        *default,
    )];
    let push = |knob: &str, value: &str, c: Config, out: &mut Vec<(String, String, Config)>| {
        if !out.iter().any(|(_, _, x)| *x == c) {
            out.push((knob.to_string(), value.to_string(), c));
        }
    };
    if !user.is_empty() {
        let mut configs = vec![(String::new(), *default)];
        for (knob, values) in user {
            let mut next = Vec::new();
            for (label, c) in &configs {
                for v in values {
                    let mut c = *c;
                    let _ = set(&mut c, knob, v);
                    let sep = if label.is_empty() { "" } else { ", " };
                    next.push((format!("{label}{sep}{knob}={v}"), c));
                }
            }
            configs = next;
        }
        let knob = user
            .iter()
            .map(|(k, _)| k.as_str())
            .collect::<Vec<_>>()
            .join("+");
        for (label, c) in configs {
            push(&knob, &label, c, &mut out);
        }
        return out;
    }
    let budgets: &[Budget] = if quick {
        &[
            Budget::PerContact(1),
            Budget::PerContact(8),
            Budget::Converged,
        ]
    } else {
        &[
            Budget::PerContact(1),
            Budget::PerContact(2),
            Budget::PerContact(4),
            Budget::PerContact(8),
            Budget::PerContact(16),
            Budget::Converged,
        ]
    };
    // Quick keeps the rows the verdict compares (warm start at 8×): its
    // short answer must not reverse the full one.
    let solvers: &[(Solver, bool)] = &[
        (Solver::DeepestFirst, false),
        (Solver::SequentialImpulse, false),
        (Solver::SequentialImpulse, true),
    ];
    for &(solver, warm_start) in solvers {
        for &budget in budgets {
            let mut c = Config { budget, ..*default };
            c.params.resolver.solver = solver;
            c.params.resolver.warm_start = warm_start;
            push(
                "budget",
                &format!("{} {}", c.solver_label(), budget.label()),
                c,
                &mut out,
            );
        }
    }
    let one = |knob: &str, values: &[&str], out: &mut Vec<(String, String, Config)>| {
        for v in values {
            let mut c = *default;
            if set(&mut c, knob, v).is_ok() && c != *default {
                push(knob, v, c, out);
            }
        }
    };
    if quick {
        one("precision", &["f32"], &mut out);
        one("dt", &["1/30"], &mut out);
        return out;
    }
    one("precision", &["f32"], &mut out);
    for knob in super::study_knobs().filter(|k| !k.grid.is_empty()) {
        if features.meet(knob.needs) {
            one(knob.name, knob.grid, &mut out);
        }
    }
    out
}
