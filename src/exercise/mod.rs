//! Exercise generator: scenes drawn from a seed, each written as a lesson
//! file, read back through the lesson validator, solved, and kept only when
//! it practises what its kind says (a sticking contact really sticks, …)
//! and every check of the solution passes.

pub mod rng;
pub mod scene;
pub mod sheet;

use crate::lesson::{validate, Lesson};
use crate::trace::{Trace, Value};
use rng::SplitMix64;
use scene::Scene;

/// What an exercise practises.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Frictionless,
    StaticFriction,
    DynamicFriction,
    Penetration,
}

impl Kind {
    pub const ALL: [Kind; 4] = [
        Kind::Frictionless,
        Kind::StaticFriction,
        Kind::DynamicFriction,
        Kind::Penetration,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Kind::Frictionless => "frictionless",
            Kind::StaticFriction => "static friction",
            Kind::DynamicFriction => "dynamic friction",
            Kind::Penetration => "penetration",
        }
    }
}

/// One generated exercise.
#[derive(Debug, Clone)]
pub struct Exercise {
    /// 1-based.
    pub number: usize,
    pub kind: Kind,
    /// The lesson file, as written.
    pub toml: String,
    pub lesson: Lesson,
    pub trace: Trace,
}

/// Draws this many scenes at most before giving up on one exercise.
const ATTEMPTS: usize = 2000;

fn text(t: &Trace, stage: &str, name: &str) -> Option<String> {
    match t.value(stage, name) {
        Some(Value::Text(s)) => Some(s.clone()),
        _ => None,
    }
}

fn scalar(t: &Trace, stage: &str, name: &str) -> Option<f64> {
    match t.value(stage, name) {
        Some(Value::Scalar(x)) => Some(*x),
        _ => None,
    }
}

fn ran(t: &Trace, stage: &str) -> bool {
    t.stage(stage).is_some_and(|s| s.skipped.is_none())
}

/// Whether a solved scene is a good exercise of `kind`.
pub fn suits(kind: Kind, lesson: &Lesson, t: &Trace) -> bool {
    let checks_pass = t.verdicts.iter().all(|v| v.passed != Some(false));
    // Inertia tensors that print exactly in four decimals, as the lecture's do.
    let exact = |x: f64| ((x * 1e4).round() - x * 1e4).abs() < 1e-6;
    let round_tensors = lesson
        .bodies
        .iter()
        .filter_map(|b| b.inertia)
        .all(|m| m.iter().all(|x| exact(*x)));
    let clean = lesson.warnings.is_empty() && checks_pass && round_tensors;
    let well_conditioned = scalar(t, "impulse", "condition_number").is_none_or(|k| k < 1e4);
    // A clear margin either side of the Coulomb limit, so rounding cannot flip the regime.
    let ratio = match (
        scalar(t, "friction_clamp", "planar"),
        scalar(t, "friction_clamp", "limit"),
    ) {
        (Some(p), Some(l)) if l > 0.0 => p / l,
        _ => f64::NAN,
    };
    let regime = text(t, "friction_clamp", "regime");
    let impulse = ran(t, "impulse")
        && scalar(t, "desired_delta_velocity", "desired").is_some_and(|d| d > 0.5);
    clean
        && well_conditioned
        && match kind {
            Kind::Frictionless => impulse && !ran(t, "friction_clamp"),
            Kind::StaticFriction => impulse && regime.as_deref() == Some("static") && ratio < 0.9,
            Kind::DynamicFriction => impulse && regime.as_deref() == Some("dynamic") && ratio > 1.1,
            Kind::Penetration => ran(t, "nonlinear_projection"),
        }
}

fn draw(rng: &mut SplitMix64, kind: Kind) -> Scene {
    let family = match kind {
        Kind::Penetration => rng.pick(&[0, 2]),
        Kind::Frictionless => rng.pick(&[0, 1, 2]),
        Kind::StaticFriction | Kind::DynamicFriction => rng.pick(&[0, 1]),
    };
    match family {
        0 => scene::cube_on_floor(rng, kind),
        1 => scene::two_spheres(rng, kind),
        _ => scene::cube_on_sphere(rng, kind),
    }
}

/// Exercise `number` of the sheet for `seed`, of the given kind.
fn exercise(seed: u64, number: usize, sub_seed: u64, kind: Kind) -> Result<Exercise, String> {
    let mut rng = SplitMix64::new(sub_seed);
    let id = format!("exercise-{seed}-{number}");
    for _ in 0..ATTEMPTS {
        let scene = draw(&mut rng, kind);
        let title = format!("Exercise {number}: {}", scene.title);
        let source = format!(
            "contact-lab exercise --seed {seed}, exercise {number} ({})",
            kind.name()
        );
        let summary = format!(
            "A generated {} exercise; numbers are given to at most four decimals.",
            kind.name()
        );
        let toml = scene.toml(&id, &title, &source, &summary);
        let lesson = validate::parse(&format!("{id}.toml"), &toml)
            .map_err(|e| format!("a generated lesson does not validate: {e}\n{toml}"))?;
        let trace = crate::worked_solution(&lesson, 0);
        if suits(kind, &lesson, &trace) {
            return Ok(Exercise {
                number,
                kind,
                toml,
                lesson,
                trace,
            });
        }
    }
    Err(format!(
        "no suitable {} scene in {ATTEMPTS} draws (seed {seed}, exercise {number})",
        kind.name()
    ))
}

/// `count` exercises for `seed`; `kind: None` mixes the four kinds. Each
/// exercise has its own stream of numbers, so the first exercises of a
/// longer sheet are those of a shorter one.
pub fn generate(seed: u64, kind: Option<Kind>, count: usize) -> Result<Vec<Exercise>, String> {
    let mut master = SplitMix64::new(seed);
    let mut order = Kind::ALL;
    master.shuffle(&mut order);
    (1..=count)
        .map(|n| {
            let sub_seed = master.next_u64();
            let k = kind.unwrap_or(order[(n - 1) % order.len()]);
            exercise(seed, n, sub_seed, k)
        })
        .collect()
}
