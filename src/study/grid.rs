//! Which configurations a study runs: the default scenes and their run
//! lengths, each scene's default configuration (its lesson's settings), the
//! reference, and the grid — one knob at a time around the default, plus the
//! iteration budget for each solver — or the knobs a user asks for
//! (`--grid KNOB=V1,V2`).

use super::{Budget, Config, Precision};
use crate::lesson::Lesson;
use crate::physics::params::BoxBoxMode;
use crate::physics::{FrictionModel, ProjectionMethod, RestitutionFrom, Solver};

/// The default scenes, how long each runs (s), and which solver the
/// reference uses (the lecture's order for the cradle, whose real answer is
/// a sequence of collisions; sequential impulses elsewhere).
pub const SCENES: [(&str, f64, Solver); 8] = [
    ("sphere-row-20", 0.5, Solver::SequentialImpulse),
    ("resting-box", 2.0, Solver::SequentialImpulse),
    ("stack-5", 2.0, Solver::SequentialImpulse),
    ("mass-ratio-stack", 2.0, Solver::SequentialImpulse),
    ("ramp-stick", 2.0, Solver::SequentialImpulse),
    ("ball-drop", 2.0, Solver::SequentialImpulse),
    ("cradle-over-time", 1.0, Solver::DeepestFirst),
    ("overlap-recovery", 1.0, Solver::SequentialImpulse),
];

/// The reference's time step and epsilon.
pub const REFERENCE_DT: f64 = 1.0 / 480.0;
pub const REFERENCE_EPSILON: f64 = 1e-4;

/// The knobs `--grid` accepts.
pub const KNOBS: [&str; 13] = [
    "solver",
    "warm_start",
    "budget",
    "epsilon",
    "precision",
    "friction_model",
    "projection",
    "relaxation",
    "velocity_limit",
    "restitution_from",
    "box_box",
    "sleep",
    "dt",
];

/// `1/60` for a time step that is one over a whole number, else the number.
pub fn dt_label(dt: f64) -> String {
    let n = (1.0 / dt).round();
    if n >= 1.0 && (1.0 / n - dt).abs() <= 1e-12 * dt {
        format!("1/{n}")
    } else {
        crate::format::exact(dt)
    }
}

/// The scene's own configuration: its lesson's settings, the lecture's
/// solver and budget (8 visits per contact), f64.
pub fn default_config(lesson: &Lesson) -> Option<Config> {
    let p = lesson.sim_params()?;
    Some(Config {
        solver: p.resolver.solver,
        warm_start: p.resolver.warm_start,
        budget: Budget::PerContact(8),
        epsilon: p.resolver.position_epsilon,
        precision: Precision::F64,
        friction_model: p.friction_model,
        projection: p.contact.projection,
        relaxation: p.contact.relaxation,
        velocity_limit: p.contact.velocity_limit,
        restitution_from: p.resolver.restitution_from,
        box_box: p.box_box,
        sleep: p.sleep.enabled,
        dt: p.dt,
    })
}

/// The most accurate configuration: `solver` (warm-started if sequential),
/// converged, epsilon 1e-4, f64, dt = 1/480 s, no sleep.
pub fn reference(default: &Config, solver: Solver) -> Config {
    Config {
        solver,
        warm_start: solver == Solver::SequentialImpulse,
        budget: Budget::Converged,
        epsilon: REFERENCE_EPSILON,
        precision: Precision::F64,
        sleep: false,
        dt: REFERENCE_DT,
        ..*default
    }
}

/// The reference in words.
pub fn describe_reference(c: &Config) -> String {
    format!(
        "{}, {} visits per contact (to convergence), epsilon {}, f64, dt = {} s, no sleep, the scene's other settings",
        match c.solver {
            Solver::DeepestFirst => "the lecture's deepest-first order",
            Solver::SequentialImpulse => "sequential impulses, warm-started",
        },
        super::CONVERGED,
        crate::format::exact(c.epsilon),
        dt_label(c.dt)
    )
}

/// Sets `knob` to the text `value` in `config`; an error names what is accepted.
pub fn set(config: &mut Config, knob: &str, value: &str) -> Result<(), String> {
    let bad = |accepted: &str| Err(format!("{knob}={value}: expected {accepted}"));
    let number = |v: &str| -> Option<f64> {
        let x = match v.split_once('/') {
            Some((a, b)) => a.trim().parse::<f64>().ok()? / b.trim().parse::<f64>().ok()?,
            None => v.trim().parse().ok()?,
        };
        x.is_finite().then_some(x)
    };
    let on = |v: &str| match v {
        "on" | "true" | "yes" => Some(true),
        "off" | "false" | "no" => Some(false),
        _ => None,
    };
    match knob {
        "solver" => match value {
            "sequential_impulse+warm" => {
                config.solver = Solver::SequentialImpulse;
                config.warm_start = true;
            }
            _ => match Solver::from_name(value) {
                Some(s) => config.solver = s,
                None => return bad("deepest_first, sequential_impulse or sequential_impulse+warm"),
            },
        },
        "warm_start" => match on(value) {
            Some(b) => config.warm_start = b,
            None => return bad("on or off"),
        },
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
        "epsilon" => match number(value) {
            Some(x) if x >= 0.0 => config.epsilon = x,
            _ => return bad("a number ≥ 0"),
        },
        "precision" => match value {
            "f32" => config.precision = Precision::F32,
            "f64" => config.precision = Precision::F64,
            _ => return bad("f32 or f64"),
        },
        "friction_model" => match FrictionModel::from_name(value) {
            Some(m) => config.friction_model = m,
            None => return bad("millington, kinetic-direction or velocity-scaling"),
        },
        "projection" => match ProjectionMethod::from_name(value) {
            Some(m) => config.projection = m,
            None => return bad("linear or nonlinear"),
        },
        "relaxation" => match number(value) {
            Some(x) if x > 0.0 && x <= 1.0 => config.relaxation = x,
            _ => return bad("a number in (0, 1]"),
        },
        "velocity_limit" => match number(value) {
            Some(x) if x >= 0.0 => config.velocity_limit = x,
            _ => return bad("a speed ≥ 0"),
        },
        "restitution_from" => match RestitutionFrom::from_name(value) {
            Some(m) => config.restitution_from = m,
            None => return bad("current or initial"),
        },
        "box_box" => match BoxBoxMode::from_name(value) {
            Some(m) => config.box_box = m,
            None => return bad("single or manifold"),
        },
        "sleep" => match on(value) {
            Some(b) => config.sleep = b,
            None => return bad("on or off"),
        },
        "dt" => match number(value) {
            Some(x) if (1e-5..=0.1).contains(&x) => config.dt = x,
            _ => return bad("a time step from 1e-5 to 0.1 s, e.g. 1/120"),
        },
        _ => {
            return Err(format!(
                "unknown knob '{knob}': the knobs are {}",
                KNOBS.join(", ")
            ))
        }
    }
    Ok(())
}

/// A `--grid KNOB=V1,V2` argument, checked against a default configuration.
pub fn parse_grid(arg: &str) -> Result<(String, Vec<String>), String> {
    let (knob, values) = arg.split_once('=').ok_or_else(|| {
        format!(
            "--grid {arg}: expected KNOB=V1,V2,… (knobs: {})",
            KNOBS.join(", ")
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
        solver: Solver::DeepestFirst,
        warm_start: false,
        budget: Budget::PerContact(8),
        epsilon: 0.01,
        precision: Precision::F64,
        friction_model: FrictionModel::Millington,
        projection: ProjectionMethod::Nonlinear,
        relaxation: 1.0,
        velocity_limit: 0.25,
        restitution_from: RestitutionFrom::Current,
        box_box: BoxBoxMode::Manifold,
        sleep: true,
        dt: 1.0 / 60.0,
    }
}

/// What the scene has that some knobs act on.
#[derive(Debug, Clone, Copy)]
pub struct Features {
    pub friction: bool,
    pub box_pairs: bool,
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
    let solvers: &[(Solver, bool)] = if quick {
        &[
            (Solver::DeepestFirst, false),
            (Solver::SequentialImpulse, false),
        ]
    } else {
        &[
            (Solver::DeepestFirst, false),
            (Solver::SequentialImpulse, false),
            (Solver::SequentialImpulse, true),
        ]
    };
    for &(solver, warm_start) in solvers {
        for &budget in budgets {
            let c = Config {
                solver,
                warm_start,
                budget,
                ..*default
            };
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
    one("epsilon", &["0.1", "0.001"], &mut out);
    one("precision", &["f32"], &mut out);
    if features.friction {
        one(
            "friction_model",
            &["millington", "kinetic-direction", "velocity-scaling"],
            &mut out,
        );
    }
    one("projection", &["linear", "nonlinear"], &mut out);
    one("relaxation", &["0.5"], &mut out);
    one("velocity_limit", &["0", "0.25", "1"], &mut out);
    one("restitution_from", &["current", "initial"], &mut out);
    if features.box_pairs {
        one("box_box", &["single", "manifold"], &mut out);
    }
    one("sleep", &["on", "off"], &mut out);
    one("dt", &["1/30", "1/60", "1/120", "1/240", "1/480"], &mut out);
    out
}
