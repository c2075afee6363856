//! The load-time overflow guard reads a solution's typed fields
//! (`physics::contact::numbers`): every stage's numbers by field name, down
//! to the impact integration's samples and the checks' measurements.

use contact_lab::lesson::Lesson;
use contact_lab::physics::contact::numbers::Numbers;

fn visited(s: &impl Numbers) -> Vec<(String, f64)> {
    let mut out = Vec::new();
    s.numbers("solution", &mut |f, x| out.push((f.to_string(), x)));
    out
}

#[test]
fn every_stage_is_visited_by_field_name() {
    let lesson = Lesson::load("lecture-2").unwrap();
    let solution = contact_lab::physics::solve(&lesson.problem::<f64>(0));
    let all = visited(&solution);
    let field = |name: &str| -> Vec<f64> {
        all.iter()
            .filter(|(f, _)| f == name)
            .map(|(_, x)| *x)
            .collect()
    };
    assert_eq!(field("desired"), vec![solution.desired.desired]);
    let g = solution.impulse.as_ref().unwrap().impulse_world;
    assert_eq!(field("impulse_world")[..3], [g.x, g.y, g.z]);
    assert_eq!(field("contact_to_world").len(), 9);
    assert_eq!(
        field("energy_after").len(),
        1,
        "the energy check's measurement"
    );
}

#[test]
fn the_impact_integration_is_visited_to_its_samples() {
    let lesson = Lesson::load("rod-reverses").unwrap();
    let mut solution = contact_lab::physics::solve(&lesson.problem::<f64>(0));
    let exact = solution.exact.as_mut().unwrap().as_mut().unwrap();
    let last = exact.outcome.samples.len() - 1;
    assert!(last > 0);
    exact.outcome.samples[last].work_normal = f64::NAN;
    let nan: Vec<_> = visited(&solution)
        .into_iter()
        .filter(|(_, x)| x.is_nan())
        .collect();
    assert_eq!(nan.len(), 1);
    assert_eq!(nan[0].0, "work_normal");
}

#[test]
fn a_no_limit_setting_is_not_an_overflow() {
    // excessive-rotation's contact 1 sets `angular_limit = inf`: its
    // projection's `angular_limit` is inf, a setting. Every embedded
    // lesson passes the guard.
    let lesson = Lesson::load("excessive-rotation").unwrap();
    let solution = contact_lab::physics::solve(&lesson.problem::<f64>(1));
    assert!(visited(&solution)
        .iter()
        .any(|(f, x)| f == "angular_limit" && *x == f64::INFINITY));
    for lesson in crate::common::all_lessons() {
        for k in 0..lesson.contacts.len() {
            assert_eq!(
                contact_lab::lesson::overflow::first_overflow(&lesson, k),
                None,
                "{} contact {k}",
                lesson.id
            );
        }
    }
}
