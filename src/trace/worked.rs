//! The worked solution of one lesson contact: the names the lesson gives,
//! the stages described by [`super::contact`], the state after, the verdicts
//! and the scene picture, in one [`Trace`].

use super::contact::{self, AsWritten, ContactNames, SolvedContact};
use super::scene::scene;
use super::Trace;
use crate::lesson::Lesson;
use crate::physics::solve::Solution;
use crate::physics::Problem;

impl ContactNames {
    /// The names lesson contact `k` shows: its bodies, its label, and the
    /// normal and shape tensors as the file wrote them.
    pub fn of_lesson(lesson: &Lesson, k: usize) -> ContactNames {
        let slots = lesson.slots(k);
        let def = |i: usize| slots[i].map(|b| &lesson.bodies[b]);
        ContactNames {
            bodies: [0, 1].map(|i| def(i).map(|b| b.name.clone())),
            label: lesson.contact_label(k),
            written: AsWritten {
                normal_length: lesson.contacts[k].normal_length,
                shape_inertia: [0, 1].map(|i| def(i).and_then(|b| b.shape_inertia)),
            },
            previous_normal: lesson.contacts[k].previous_normal.map(Into::into),
        }
    }
}

/// Builds the trace of contact `k` of `lesson`, solved as `solution`.
pub fn build(lesson: &Lesson, k: usize, solution: &Solution<f64>) -> Trace {
    build_of(lesson, k, &lesson.problem::<f64>(k), solution)
}

/// [`build`] with contact `k`'s problem already at hand (the one `solution`
/// solved), so it is not taken from the lesson twice.
pub fn build_of(
    lesson: &Lesson,
    k: usize,
    problem: &Problem<f64>,
    solution: &Solution<f64>,
) -> Trace {
    let names = ContactNames::of_lesson(lesson, k);
    let solved = SolvedContact::new(problem, solution, &names);
    Trace {
        lesson: lesson.id.clone(),
        title: lesson.title.clone(),
        source: lesson.source.clone(),
        summary: lesson.summary.clone(),
        contact: k,
        contact_label: names.label.clone(),
        bodies: names.slot_names(),
        stages: contact::build(problem, solution, &names),
        after: contact::after(problem, solution, &names),
        verdicts: contact::verdicts(&solved),
        warnings: lesson.warnings.iter().map(|w| w.to_string()).collect(),
        scene: scene(lesson, k, problem, solution),
        impact: contact::impact_curves(solution),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lesson_contact_names_its_slots_label_and_written_facts() {
        let lesson = Lesson::load("lecture-2").unwrap();
        let names = ContactNames::of_lesson(&lesson, 0);
        assert_eq!(names.bodies, [Some("cube".into()), Some("floor".into())]);
        assert_eq!(names.label, lesson.contact_label(0));
        assert_eq!(names.slot_names(), lesson.contact_body_names(0));
        assert_eq!(names.written.normal_length, 1.0);
        assert!(
            names.written.shape_inertia[0].is_some(),
            "the cube has a shape"
        );
        assert_eq!(
            names.written.shape_inertia[0],
            lesson.bodies[0].shape_inertia
        );
        // The floor is immovable: no shape tensor, whatever its shape.
        assert_eq!(names.written.shape_inertia[1], None);
    }

    #[test]
    fn the_trace_is_the_contact_builders_plus_the_lesson() {
        let lesson = Lesson::load("friction-cube").unwrap();
        let problem = lesson.problem::<f64>(1);
        let solution = crate::physics::solve(&problem);
        let t = build(&lesson, 1, &solution);
        let names = ContactNames::of_lesson(&lesson, 1);
        assert_eq!(t.stages, contact::build(&problem, &solution, &names));
        assert_eq!(t.contact_label, names.label);
        assert_eq!(t.after.len(), 1);
        assert_eq!(t.verdicts.len(), solution.checks.items.len());
    }
}
