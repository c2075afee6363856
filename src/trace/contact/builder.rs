//! What every stage builder shares: the solved contact it reads
//! ([`SolvedContact`]), the collector of one [`Step`], skip reasons and the
//! geometric tests behind the notes.

use nalgebra::Vector3;

use super::ContactNames;
use crate::physics::scale::stable_norm;
use crate::physics::solve::{Skip, Solution};
use crate::physics::{Problem, RigidBody, StageId};
use crate::trace::{Formula, Step, Text, Value};

/// Subscripts of body 1 and body 2.
pub(super) const SUB: [&str; 2] = ["₁", "₂"];

/// One solved contact and the names to show it with: what each stage
/// builder reads. Cheap to copy (three references).
#[derive(Debug, Clone, Copy)]
pub struct SolvedContact<'a> {
    pub problem: &'a Problem<f64>,
    pub solution: &'a Solution<f64>,
    pub names: &'a ContactNames,
}

impl<'a> SolvedContact<'a> {
    pub fn new(
        problem: &'a Problem<f64>,
        solution: &'a Solution<f64>,
        names: &'a ContactNames,
    ) -> Self {
        SolvedContact {
            problem,
            solution,
            names,
        }
    }

    /// The name of the body in slot `i`; "the world" for an empty slot.
    pub(super) fn name(&self, i: usize) -> &'a str {
        self.names.bodies[i].as_deref().unwrap_or("the world")
    }

    /// Slots holding a movable body.
    pub(super) fn movable(&self) -> impl Iterator<Item = usize> + 'a {
        let bodies = &self.problem.bodies;
        (0..2).filter(move |&i| bodies[i].is_some())
    }

    pub(super) fn body(&self, i: usize) -> &'a RigidBody<f64> {
        self.problem.bodies[i].as_ref().expect("movable slot")
    }

    /// Slots that name a body which is immovable (an empty slot names none).
    pub(super) fn immovable_named(&self) -> impl Iterator<Item = usize> + 'a {
        let (names, bodies) = (&self.names.bodies, &self.problem.bodies);
        (0..2).filter(move |&i| names[i].is_some() && bodies[i].is_none())
    }

    /// Body slot `i`'s arm r = q - p (zero for an empty slot).
    pub(super) fn r(&self, i: usize) -> Vector3<f64> {
        self.solution.frame.r[i].unwrap_or_default()
    }
}

/// Collects one stage.
pub(super) struct B {
    step: Step,
}

impl B {
    pub(super) fn new(id: StageId) -> Self {
        B {
            step: Step {
                id,
                title: id.title(),
                skipped: None,
                // Nothing allocated until something is pushed (a skipped
                // stage allocates nothing); see `push`.
                formulas: vec![],
                inputs: vec![],
                values: vec![],
                notes: vec![],
            },
        }
    }
    pub(super) fn input(&mut self, name: impl Into<Text>, v: impl Into<Value>) {
        push(&mut self.step.inputs, (name.into(), v.into()));
    }
    pub(super) fn value(&mut self, name: impl Into<Text>, v: impl Into<Value>) {
        push(&mut self.step.values, (name.into(), v.into()));
    }
    /// `lhs = rhs = substituted = {result}`; the LaTeX forms are made when
    /// rendered. Fixed text is borrowed (`&'static str`), built text owned.
    pub(super) fn f(
        &mut self,
        lhs: impl Into<Text>,
        rhs: impl Into<Text>,
        substituted: Option<impl Into<Text>>,
        result: Option<impl Into<Text>>,
    ) {
        push(
            &mut self.step.formulas,
            Formula {
                lhs: lhs.into(),
                rhs: rhs.into(),
                substituted: substituted.map(Into::into),
                result: result.map(Into::into),
            },
        );
    }
    pub(super) fn note(&mut self, text: impl Into<Text>) {
        push(&mut self.step.notes, text.into());
    }
    pub(super) fn skipped(mut self, why: impl Into<Text>) -> Step {
        self.step.skipped = Some(why.into());
        self.step
    }
    pub(super) fn done(self) -> Step {
        self.step
    }
}

/// Pushes onto one of a step's lists, making room for 8 at the first push: a
/// stage's lists hold a few to a few dozen entries, and growing from 4 by
/// doubling would reallocate each list two or three times.
fn push<X>(list: &mut Vec<X>, x: X) {
    if list.capacity() == 0 {
        list.reserve_exact(8);
    }
    list.push(x);
}

pub(super) fn skip_reason(skip: Skip) -> &'static str {
    match skip {
        Skip::Separating => {
            "the contact is separating or at rest (Δv ≤ 0): the resolver applies no impulse"
        }
        Skip::NoFriction => "no friction (μ = 0): the impulse acts along the normal only",
        Skip::NoPenetration => "no penetration (d_pen ≤ 0): nothing to project",
        Skip::NoRotation => "the projection rotates no body (no angular share)",
        Skip::NotAsked => {
            "not asked (solve --exact newton|poisson|stronge, or exact in the lesson's settings)"
        }
        Skip::NotClosing => "the contact is not closing (u_n ≥ 0): there is no impact to integrate",
    }
}

/// True when the normal passes through the centre to within the data's
/// rounding: the angle between r and d̂ has sine below 10⁻⁴ (the lecture's
/// four-digit data leaves about 5·10⁻⁵).
pub(super) fn through_centre(r: &Vector3<f64>, d: &Vector3<f64>) -> bool {
    stable_norm(&r.cross(d)) <= 1e-4 * stable_norm(r)
}

/// `Some((axis letter, counter_clockwise))` when `v` lies along one world axis.
pub(super) fn about_one_axis(v: &Vector3<f64>) -> Option<(char, bool)> {
    let n = stable_norm(v);
    if n == 0.0 {
        return None;
    }
    let i = v.iamax();
    let others = (0..3)
        .filter(|&j| j != i)
        .map(|j| v[j].abs())
        .fold(0.0, f64::max);
    (others <= 1e-9 * n).then(|| (['x', 'y', 'z'][i], v[i] > 0.0))
}

pub(super) fn sense(ccw: bool) -> &'static str {
    if ccw {
        "counter-clockwise"
    } else {
        "clockwise"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_axis_is_found_with_its_sense() {
        assert_eq!(
            about_one_axis(&Vector3::new(0.0, 0.0, 2.0)),
            Some(('z', true))
        );
        assert_eq!(
            about_one_axis(&Vector3::new(0.0, -1.0, 0.0)),
            Some(('y', false))
        );
        assert_eq!(about_one_axis(&Vector3::new(0.0, 1.0, 1e-3)), None);
        assert_eq!(about_one_axis(&Vector3::zeros()), None);
        assert_eq!(sense(true), "counter-clockwise");
    }

    #[test]
    fn through_centre_allows_the_data_rounding_only() {
        let d = Vector3::y();
        assert!(through_centre(&Vector3::new(5e-5, -1.0, 0.0), &d));
        assert!(!through_centre(&Vector3::new(1e-3, -1.0, 0.0), &d));
    }
}
