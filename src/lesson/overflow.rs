//! The last guard of "a validated lesson never produces a non-finite
//! number": the ranges of `lesson::ranges` bound every input, but a stage
//! may multiply six of them (the kinetic-direction model's μ j t turned by
//! I⁻¹ about an arm r, with j from m and a speed ω r), which f64 cannot
//! hold. So each contact is solved once when the lesson is read (a few
//! microseconds) and refused, naming the contact and the value, if any
//! number of its solution is not finite or beyond ±[`LIMIT`] (which leaves
//! the renderers room to turn radians into degrees and to take norms).
//! `resolve` applies the stages repeatedly: [`check_resolve`] guards it.

use super::Lesson;
use crate::knobs::Choice;
use crate::knobs::{self, Range};
use crate::physics::contact::numbers::Numbers;
use crate::physics::FrictionModel;

/// The largest magnitude a stage's result may have.
pub const LIMIT: f64 = 1e300;

/// The first result of contact `k` that is not finite or beyond ±[`LIMIT`]:
/// the field that holds it, and the number. `None` when all are fine.
///
/// Every number of every stage record is visited through its typed fields
/// (`physics::contact::numbers`: a field added to a stage and forgotten
/// there does not compile); the checks' measurements by the names the
/// checks give them (`energy_after`), then their causes. A knob set to
/// `inf` for "no limit" (the angular limit) is a setting, not an overflow.
pub fn first_overflow(lesson: &Lesson, k: usize) -> Option<(String, f64)> {
    first_overflow_of(&lesson.problem::<f64>(k))
}

fn first_overflow_of(problem: &crate::physics::Problem<f64>) -> Option<(String, f64)> {
    let solution = crate::physics::solve(problem);
    let mut found = None;
    solution.numbers("solution", &mut |field, x| {
        if found.is_none() && too_large(&x) && !no_limit(field, x) {
            found = Some((field.to_string(), x));
        }
    });
    found
}

fn too_large(x: &f64) -> bool {
    x.is_nan() || x.abs() > LIMIT
}

/// A knob whose `inf` means "no limit" (the angular limit) is a setting.
fn no_limit(field: &str, x: f64) -> bool {
    x == f64::INFINITY
        && knobs::find(field).is_some_and(|k| k.kind.range() == Some(Range::NonNegativeOrInf))
}

/// The refusal for contact `k`, or `Ok` when its solution is finite under
/// its own friction model and under the others (which `--friction-model`,
/// `--compare-friction` and the TUI can choose).
pub fn check(lesson: &Lesson, k: usize) -> Result<(), String> {
    let own = lesson.contacts[k].settings.friction_model;
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

/// `resolve`'s guard: the lesson's contacts resolved together under
/// `params`. The phases apply each contact's stages again and again, so a
/// model that gains energy (kinetic-direction, Kane's effect) compounds it
/// past what one solve reaches. The refusal names the body or contact and
/// the value; `Ok` when every body state, every contact's bookkeeping and
/// the kinetic energy stay finite and within ±[`LIMIT`].
pub fn check_resolve(
    lesson: &Lesson,
    params: &crate::physics::ResolverParams,
    implementation: crate::physics::resolver::Implementation,
) -> Result<(), String> {
    use crate::physics::resolver::{checks::scene_checks, Resolver, Silent};
    let world = lesson.world::<f64>();
    let mut resolver = Resolver::prepare(&world, params);
    resolver.position_phase(implementation, &mut Silent);
    resolver.velocity_phase(implementation, &mut Silent);
    let checks = scene_checks(&world, &resolver);
    let mut values: Vec<(String, f64)> = vec![
        ("the kinetic energy after".into(), checks.energy_after),
        ("the kinetic energy before".into(), checks.energy_before),
    ];
    for b in &resolver.bodies {
        let name = &lesson.bodies[b.id.0].name;
        let parts = [
            ("position", b.position),
            ("velocity", b.velocity),
            ("angular velocity", b.angular_velocity),
        ];
        for (what, v) in parts {
            values.extend(v.iter().map(|x| (format!("body '{name}' {what}"), *x)));
        }
        let q = b.orientation.coords;
        values.extend(q.iter().map(|x| (format!("body '{name}' orientation"), *x)));
    }
    for (k, c) in resolver.contacts.iter().enumerate() {
        values.push((format!("contact {k}'s penetration"), c.penetration));
        values.push((format!("contact {k}'s desired Δv"), c.desired));
        let v = c
            .velocity
            .iter()
            .map(|x| (format!("contact {k}'s velocity"), *x));
        values.extend(v);
    }
    match values.into_iter().find(|(_, x)| too_large(x)) {
        None => Ok(()),
        Some((what, x)) => Err(format!(
            "resolving the contacts together overflows a 64-bit float: {what} reaches {} (each contact alone stays in range, but the phases apply the stages again and again, and a friction model that gains energy compounds it); use fewer iterations, another friction model, or numbers closer to 1",
            crate::format::exact(x)
        )),
    }
}
