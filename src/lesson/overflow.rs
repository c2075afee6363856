//! The last guard of "a validated lesson never produces a non-finite
//! number": the ranges of `lesson::ranges` bound every input, but a stage
//! may multiply six of them (the kinetic-direction model's μ j t turned by
//! I⁻¹ about an arm r, with j from m and a speed ω r), which f64 cannot
//! hold. So each contact is solved once when the lesson is read (a few
//! microseconds) and refused, naming the contact and the value, if any
//! number of its solution is not finite or beyond ±[`LIMIT`] (which leaves
//! the renderers room to turn radians into degrees and to take norms).

use super::Lesson;
use crate::physics::FrictionModel;

/// The largest magnitude a stage's result may have.
pub const LIMIT: f64 = 1e300;

/// The first result of contact `k` that is not finite or beyond ±[`LIMIT`]:
/// the field that holds it, and the number. `None` when all are fine.
///
/// The solution is walked through its `Debug` text, which names every field
/// and prints every number, so no record can be forgotten as the stages
/// change. `angular_limit: inf` is the setting "no limit", not an overflow.
pub fn first_overflow(lesson: &Lesson, k: usize) -> Option<(String, f64)> {
    first_overflow_of(&lesson.problem::<f64>(k))
}

fn first_overflow_of(problem: &crate::physics::Problem<f64>) -> Option<(String, f64)> {
    let solution = crate::physics::solve(problem);
    let text = format!("{solution:?}");
    let mut field = String::new();
    let mut token = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        // Named values, `("energy_before", 1.5)`: the name is the field.
        if c == '"' {
            field = chars.by_ref().take_while(|c| *c != '"').collect();
            token.clear();
            continue;
        }
        if c.is_alphanumeric() || matches!(c, '_' | '.' | '-' | '+') {
            token.push(c);
            continue;
        }
        if c == ':' && chars.peek() == Some(&' ') {
            field = std::mem::take(&mut token);
            continue;
        }
        if let Ok(x) = token.parse::<f64>() {
            let setting = field == "angular_limit" && x == f64::INFINITY;
            if !setting && (x.is_nan() || x.abs() > LIMIT) {
                return Some((field, x));
            }
        }
        token.clear();
    }
    None
}

/// The refusal for contact `k`, or `Ok` when its solution is finite under
/// its own friction model and under the others (which `--friction-model`,
/// `--compare-friction` and the TUI can choose).
pub fn check(lesson: &Lesson, k: usize) -> Result<(), String> {
    let own = lesson.contacts[k].friction_model;
    let models = std::iter::once(own).chain(FrictionModel::ALL.into_iter().filter(|m| *m != own));
    for model in models {
        let mut problem = lesson.problem::<f64>(k);
        problem.contact.friction_model = model;
        if let Some((field, x)) = first_overflow_of(&problem) {
            let under = if model == own {
                String::new()
            } else {
                format!(" under the {} friction model", model.name())
            };
            return Err(format!(
                "contact {k}: its numbers overflow a 64-bit float{under}: `{field}` reaches {} (every input is in range, but the stages multiply them beyond ±1e300); bring the masses, inertia, lengths, speeds and friction closer to 1",
                crate::format::exact(x)
            ));
        }
    }
    Ok(())
}

/// [`check`] for every contact of the lesson.
pub fn check_all(lesson: &Lesson) -> Result<(), String> {
    (0..lesson.contacts.len()).try_for_each(|k| check(lesson, k))
}
