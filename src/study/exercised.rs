//! What a run actually exercised — the evidence behind the advice: sliding
//! or only sticking contacts, rotation, resting contacts, fast bodies
//! against thin ones, mass ratios across a contact — read from the
//! reference run after every step, and the model each calls for.

use nalgebra::Vector3;

use super::{run, Config};
use crate::lesson::Lesson;
use crate::physics::step::Simulation;
use crate::physics::Shape;

/// Tangential speed (m/s) above which a contact with friction slides.
pub const SLIP: f64 = 1e-3;
/// Normal speed (m/s) below which a touching contact rests.
pub const REST: f64 = 0.05;
/// Angular speed (rad/s) that counts as rotation.
pub const SPIN: f64 = 0.1;
/// A body moving more than this share of the thinnest other body in one
/// step of the scene's own dt can pass through it.
pub const FAST: f64 = 0.5;
/// A mass ratio across one contact above this strains an iterative solver.
pub const HEAVY: f64 = 10.0;

/// Counts over the run (contact-steps: one contact in one step).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Exercised {
    pub contact_steps: usize,
    pub friction_contact_steps: usize,
    pub sliding: usize,
    pub sticking: usize,
    pub resting: usize,
    pub max_angular_speed: f64,
    /// Largest |v|·dt (the scene's dt) over the thinnest other body.
    pub fast_ratio: f64,
    /// Largest ratio of the masses of two movable bodies in one contact.
    pub mass_ratio: f64,
}

/// The thinnest extent of a shape (m); a half-space has none.
pub fn thinnest(shape: &Option<Shape>) -> f64 {
    match shape {
        Some(Shape::Sphere { radius } | Shape::HollowSphere { radius }) => 2.0 * radius,
        Some(Shape::Box { sides }) => sides.iter().copied().fold(f64::INFINITY, f64::min),
        Some(Shape::Cylinder { radius, height }) => (2.0 * radius).min(*height),
        _ => f64::INFINITY,
    }
}

fn watch(x: &mut Exercised, sim: &Simulation<f64>, scene_dt: f64) {
    let bodies = &sim.world.bodies;
    for k in &sim.world.contacts {
        x.contact_steps += 1;
        let v = |id: Option<crate::physics::BodyId>| {
            id.map_or(Vector3::zeros(), |id| {
                let b = &sim.world.body(id).state;
                b.point_velocity(&(k.input.point - b.position))
            })
        };
        let rel = v(Some(k.body1)) - v(k.body2);
        let n = k.input.normal;
        let vn = rel.dot(&n);
        let vt = (rel - n * vn).norm();
        if vn.abs() < REST {
            x.resting += 1;
        }
        if k.input.has_friction() {
            x.friction_contact_steps += 1;
            if vt > SLIP {
                x.sliding += 1;
            } else {
                x.sticking += 1;
            }
        }
        if let Some(b2) = k.body2 {
            let (a, b) = (sim.world.body(k.body1), sim.world.body(b2));
            if a.movable && b.movable {
                let (m1, m2) = (a.state.mass, b.state.mass);
                x.mass_ratio = x.mass_ratio.max(m1.max(m2) / m1.min(m2));
            }
        }
    }
    for (i, b) in bodies.iter().enumerate().filter(|(_, b)| b.movable) {
        x.max_angular_speed = x.max_angular_speed.max(b.state.angular_velocity.norm());
        let step = b.state.velocity.norm() * scene_dt;
        for (j, o) in bodies.iter().enumerate() {
            if i != j {
                x.fast_ratio = x.fast_ratio.max(step / thinnest(&o.shape));
            }
        }
    }
}

/// Runs `config` (the reference) and reads what it exercised; `scene_dt`
/// is the scene's own time step (fast bodies are fast at that step).
pub fn measure(lesson: &Lesson, config: &Config, seconds: f64) -> (run::Measured, Exercised) {
    let scene_dt = lesson
        .simulation
        .as_ref()
        .map_or(config.params.dt, |s| s.dt);
    let mut x = Exercised {
        mass_ratio: 1.0,
        ..Default::default()
    };
    let m = run::measure_watched(lesson, config, seconds, &mut |sim| {
        watch(&mut x, sim, scene_dt)
    });
    (m, x)
}

/// One feature: what the run showed, and the model it calls for.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    pub feature: &'static str,
    pub present: bool,
    pub evidence: String,
    pub calls_for: &'static str,
}

/// The features in words (the same list for every scene, present or not).
pub fn findings(x: &Exercised) -> Vec<Finding> {
    let share = |n: usize, of: usize| {
        if of == 0 {
            "none".to_string()
        } else {
            format!("{n} of {of} contact-steps")
        }
    };
    let fmt = crate::format::Fmt::new(2);
    vec![
        Finding {
            feature: "sliding contacts",
            present: x.sliding > 0,
            evidence: format!(
                "slipping faster than {SLIP} m/s: {}; sticking: {}",
                share(x.sliding, x.friction_contact_steps),
                share(x.sticking, x.friction_contact_steps)
            ),
            calls_for: if x.friction_contact_steps == 0 {
                "no friction model: the scene has no friction"
            } else if x.sliding > 0 {
                "a friction model that slides the way the lectures teach (the friction model matters)"
            } else {
                "static friction only: every friction model sticks alike"
            },
        },
        Finding {
            feature: "rotation",
            present: x.max_angular_speed > SPIN,
            evidence: format!("fastest spin {} rad/s", fmt.num(x.max_angular_speed)),
            calls_for: if x.max_angular_speed > SPIN {
                "the nonlinear projection (angular moves) and orientation updates"
            } else {
                "no rotation: a linear projection moves the same"
            },
        },
        Finding {
            feature: "resting contacts",
            present: x.resting > 0,
            evidence: format!(
                "closing or separating slower than {REST} m/s: {}",
                share(x.resting, x.contact_steps)
            ),
            calls_for: if x.resting > 0 {
                "contacts that persist: sequential impulses with warm start, acceleration compensation, sleep"
            } else {
                "only impacts: one-shot impulses in the lecture's order"
            },
        },
        Finding {
            feature: "fast bodies against thin ones",
            present: x.fast_ratio > FAST,
            evidence: format!(
                "largest step of a body over the thinnest other body, at the scene's dt: {}",
                fmt.num(x.fast_ratio)
            ),
            calls_for: if x.fast_ratio > FAST {
                "a smaller time step or continuous detection (time of impact)"
            } else {
                "discrete detection at the scene's step"
            },
        },
        Finding {
            feature: "mass ratios",
            present: x.mass_ratio > HEAVY,
            evidence: format!(
                "largest mass ratio across a contact of two movable bodies: {}",
                fmt.num(x.mass_ratio)
            ),
            calls_for: if x.mass_ratio > HEAVY {
                "more iterations (a converged budget) or warm start: the heavy body is held up slowly"
            } else {
                "no mass ratio that strains the iterations"
            },
        },
        Finding {
            feature: "slip reversing within an impact",
            present: false,
            evidence: "not measured in a run: the exact impact integration runs per contact (solve --exact)".into(),
            calls_for: "exact impact integration where a contact's slip reverses (see solve --exact)",
        },
    ]
}
