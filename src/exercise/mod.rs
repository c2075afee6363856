//! Exercise generator: scenes drawn from a seed, each written as a lesson
//! file, read back through the lesson validator, solved, and kept only when
//! it practises what its kind says (a sticking contact really sticks, …)
//! and every check of the solution passes.

pub mod answer;
pub mod asked;
pub mod grade;
pub mod rng;
pub mod setup;
pub mod sheet;

use crate::lesson::{validate, Lesson};
use crate::physics::stages::FrictionRegime;
use crate::physics::{solve, Solution};
use crate::trace::Trace;
use rng::SplitMix64;
use setup::Setup;

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
    pub solution: Solution<f64>,
    pub trace: Trace,
}

/// Draws this many scenes at most before giving up on one exercise.
const ATTEMPTS: usize = 2000;

/// Whether a solved scene is a good exercise of `kind`: read from the
/// solution's typed records.
pub fn fits(kind: Kind, lesson: &Lesson, s: &Solution<f64>) -> bool {
    let checks_pass = s.checks.all_passed();
    // Inertia tensors that print exactly in four decimals, as the lecture's do.
    let exact = |x: f64| ((x * 1e4).round() - x * 1e4).abs() < 1e-6;
    let round_tensors = lesson
        .bodies
        .iter()
        .filter_map(|b| b.inertia)
        .all(|m| m.iter().all(|x| exact(*x)));
    let clean = lesson.warnings.is_empty() && checks_pass && round_tensors;
    let well_conditioned = s.condition_number().is_none_or(|k| k < 1e4);
    // A clear margin either side of the Coulomb limit, so rounding cannot flip the regime.
    let ratio = match &s.friction {
        Some(f) if f.limit > 0.0 => f.planar / f.limit,
        _ => f64::NAN,
    };
    let regime = s.regime();
    let impulse = s.closing() && s.desired.desired > 0.5;
    clean
        && well_conditioned
        && match kind {
            Kind::Frictionless => impulse && s.friction.is_none(),
            Kind::StaticFriction => {
                impulse && regime == Some(FrictionRegime::Static) && ratio < 0.9
            }
            Kind::DynamicFriction => {
                impulse && regime == Some(FrictionRegime::Dynamic) && ratio > 1.1
            }
            Kind::Penetration => s.projection.is_some(),
        }
}

/// Whether the solved contact `t` describes is a good exercise of `kind`
/// (solves that contact of `lesson` again and asks [`fits`]).
pub fn suits(kind: Kind, lesson: &Lesson, t: &Trace) -> bool {
    fits(kind, lesson, &solve(&lesson.problem::<f64>(t.contact)))
}

fn draw(rng: &mut SplitMix64, kind: Kind) -> Setup {
    let family = match kind {
        Kind::Penetration => rng.pick(&[0, 2]),
        Kind::Frictionless => rng.pick(&[0, 1, 2]),
        Kind::StaticFriction | Kind::DynamicFriction => rng.pick(&[0, 1]),
    };
    match family {
        0 => setup::cube_on_floor(rng, kind),
        1 => setup::two_spheres(rng, kind),
        _ => setup::cube_on_sphere(rng, kind),
    }
}

/// Exercise `number` of the sheet for `seed`, of the given kind.
fn exercise(seed: u64, number: usize, sub_seed: u64, kind: Kind) -> Result<Exercise, String> {
    let mut rng = SplitMix64::new(sub_seed);
    let id = format!("exercise-{seed}-{number}");
    for _ in 0..ATTEMPTS {
        let setup = draw(&mut rng, kind);
        let title = format!("Exercise {number}: {}", setup.title);
        let source = format!(
            "contact-lab exercise --seed {seed}, exercise {number} ({})",
            kind.name()
        );
        let summary = format!(
            "A generated {} exercise; numbers are given to at most four decimals.",
            kind.name()
        );
        let toml = setup.toml(&id, &title, &source, &summary);
        let lesson = validate::parse(&format!("{id}.toml"), &toml)
            .map_err(|e| format!("a generated lesson does not validate: {e}\n{toml}"))?;
        let solution = solve(&lesson.problem::<f64>(0));
        if fits(kind, &lesson, &solution) {
            let trace = crate::trace::build(&lesson, 0, &solution);
            return Ok(Exercise {
                number,
                kind,
                toml,
                lesson,
                solution,
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
