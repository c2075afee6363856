//! Runs the stages of one contact in the lecture's order: [`solve_stages`]
//! computes the stage records alone (what the resolver's maths and the
//! `stages_f64` bench time), [`solve`] adds the physical checks (momentum,
//! energy, …) that only the trace, the worked solution and the reports read.

use nalgebra::{Quaternion, Vector3};

use super::checks::{run_checks, CheckInputs, Checks};
use super::stages::*;
use super::{Problem, Real, StageId};
use crate::physics::exact::{exact_impact_beside, ExactError, ExactImpact, Tolerance};

/// Every stage record of one resolved contact. A stage the contact does not
/// need is `None`; [`Stages::skip`] says why.
#[derive(Debug, Clone, PartialEq)]
pub struct Stages<T: Real> {
    pub frame: ContactFrame<T>,
    pub unit: UnitImpulse<T>,
    pub desired: DesiredVelocity<T>,
    /// `None` when the contact is separating (Δv ≤ 0): no impulse is applied.
    pub impulse: Option<Impulse<T>>,
    /// `None` without friction or without an impulse.
    pub friction: Option<FrictionClamp<T>>,
    pub applied: Option<AppliedImpulse<T>>,
    /// `None` without penetration.
    pub projection: Option<Projection<T>>,
    /// `None` when projection rotates nothing.
    pub orientation: Option<OrientationUpdate<T>>,
    /// The impact integrated under the contact's `settings.exact` law beside
    /// the one-shot impulse; `None` unless asked. An integration that cannot
    /// finish is an error here, never NaN. Boxed: the record is large
    /// (about 0.9 kB) and rarely asked for, and `Stages` is moved whole.
    pub exact: Option<Result<Box<ExactImpact<T>>, ExactError>>,
}

/// One resolved contact: its stage records and the checks of its result.
/// The stage records are read through it as its own fields
/// (`solution.frame`, `solution.skip(..)`: it dereferences to [`Stages`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Solution<T: Real> {
    pub stages: Stages<T>,
    pub checks: Checks<T>,
}

impl<T: Real> std::ops::Deref for Solution<T> {
    type Target = Stages<T>;
    fn deref(&self) -> &Stages<T> {
        &self.stages
    }
}

impl<T: Real> std::ops::DerefMut for Solution<T> {
    fn deref_mut(&mut self) -> &mut Stages<T> {
        &mut self.stages
    }
}

/// Why a stage was skipped.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Skip {
    Separating,
    NoFriction,
    NoPenetration,
    NoRotation,
    /// The exact impact integration was not asked for.
    NotAsked,
    /// The exact integration found no closing velocity (u_n ≥ 0).
    NotClosing,
}

/// A body's state after the contact is resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyAfter<T: Real> {
    pub position: Vector3<T>,
    pub orientation: Quaternion<T>,
    pub velocity: Vector3<T>,
    pub angular_velocity: Vector3<T>,
}

/// The stages and their checks.
pub fn solve<T: Real>(problem: &Problem<T>) -> Solution<T> {
    let stages = solve_stages(problem);
    let checks = checks_of(problem, &stages);
    Solution { stages, checks }
}

/// The physical checks of a contact's stage records (momentum, restitution,
/// energy, the friction cone, slip, penetration removed, unit quaternions).
pub fn checks_of<T: Real>(problem: &Problem<T>, s: &Stages<T>) -> Checks<T> {
    run_checks(&CheckInputs {
        problem,
        frame: &s.frame,
        matrix: s.unit.matrix.as_ref(),
        desired: &s.desired,
        impulse: s.impulse.as_ref(),
        applied: s.applied.as_ref(),
        friction: s.friction.as_ref(),
        projection: s.projection.as_ref(),
        orientation: s.orientation.as_ref(),
    })
}

/// The stage records alone, in the lecture's order (no checks).
///
/// Inlined where it is called, so the records are written straight into
/// the caller's `Stages` (the compiler merges this one with the place the
/// result goes: no 1.8 kB copy on return).
#[inline]
pub fn solve_stages<T: Real>(problem: &Problem<T>) -> Stages<T> {
    let mut s = Stages::empty();
    solve_stages_into(problem, &mut s);
    s
}

/// [`solve_stages`] written into `s`, every field of it: each stage writes
/// its record into its own field (its `_into` form), and the stages after it
/// read it there. No record is built elsewhere and moved in.
#[inline(never)]
pub fn solve_stages_into<T: Real>(problem: &Problem<T>, s: &mut Stages<T>) {
    let contact = &problem.contact;
    contact_frame_into(problem, &mut s.frame);
    // Each body's R I⁻¹ Rᵀ once, for every stage that reads it.
    let inverse_inertias = problem.inverse_inertias();
    let with_matrix = contact.has_friction();
    unit_impulse_into(
        problem,
        &inverse_inertias,
        &s.frame,
        with_matrix,
        &mut s.unit,
    );
    desired_delta_velocity_into(problem, &s.frame, &mut s.desired);
    s.impulse = None;
    s.friction = None;
    if s.desired.desired > T::zero() {
        // M factored once, for the impulse and the clamp; no eigenvalues
        // here (κ(M) is computed where it is shown: `Stages::condition_number`).
        let factored = s.unit.matrix.map(FactoredMatrix::new);
        let g = s.impulse.insert(Impulse::empty());
        impulse_factored_into(
            problem,
            &inverse_inertias,
            &s.frame,
            &s.unit,
            &s.desired,
            factored.as_ref(),
            g,
        );
        if with_matrix {
            friction_clamp_factored_into(
                problem,
                &s.frame,
                &s.unit,
                &s.desired,
                g,
                factored.as_ref(),
                &mut s.friction,
            );
        }
    }
    let final_impulse = s.final_impulse_world();
    s.applied = None;
    if let Some(g) = &final_impulse {
        let applied = s.applied.insert(AppliedImpulse {
            bodies: [None, None],
        });
        apply_impulse_into(problem, &inverse_inertias, &s.frame, g, applied);
    }
    s.projection = None;
    s.orientation = None;
    if contact.penetration > T::zero() {
        let p = s.projection.insert(Projection {
            method: contact.settings.projection,
            resolved_depth: T::zero(),
            total_inertia: T::zero(),
            bodies: [None, None],
        });
        nonlinear_projection_into(problem, &inverse_inertias, &s.frame, p);
        if p.bodies
            .iter()
            .flatten()
            .any(|b| b.angular_change != Vector3::zeros())
        {
            let o = s.orientation.insert(OrientationUpdate {
                bodies: [None, None],
            });
            orientation_update_into(problem, p, o);
        }
    }
    s.exact = contact.settings.exact.map(|law| {
        let one_shot = final_impulse.unwrap_or_else(Vector3::zeros);
        exact_impact_beside(problem, law, Tolerance::default(), one_shot).map(Box::new)
    });
}

impl<T: Real> Stages<T> {
    /// Records to be written by [`solve_stages_into`].
    pub fn empty() -> Self {
        Stages {
            frame: ContactFrame::empty(),
            unit: UnitImpulse::empty(),
            desired: DesiredVelocity::empty(),
            impulse: None,
            friction: None,
            applied: None,
            projection: None,
            orientation: None,
            exact: None,
        }
    }

    /// The reason a stage was skipped; `None` when it ran.
    pub fn skip(&self, stage: StageId) -> Option<Skip> {
        match stage {
            StageId::Impulse | StageId::ApplyImpulse if self.impulse.is_none() => {
                Some(Skip::Separating)
            }
            StageId::FrictionClamp if self.friction.is_none() => Some(if self.impulse.is_none() {
                Skip::Separating
            } else {
                Skip::NoFriction
            }),
            StageId::NonlinearProjection if self.projection.is_none() => Some(Skip::NoPenetration),
            StageId::OrientationUpdate if self.orientation.is_none() => {
                Some(if self.projection.is_none() {
                    Skip::NoPenetration
                } else {
                    Skip::NoRotation
                })
            }
            StageId::ExactImpact => match &self.exact {
                None => Some(Skip::NotAsked),
                Some(Ok(x)) if !x.outcome.closing => Some(Skip::NotClosing),
                Some(_) => None,
            },
            _ => None,
        }
    }

    /// The impulse actually applied (after the friction clamp), world space.
    pub fn final_impulse_world(&self) -> Option<Vector3<T>> {
        final_impulse_world(self.impulse.as_ref(), self.friction.as_ref())
    }

    /// The impulse actually applied, contact space.
    pub fn final_impulse_contact(&self) -> Option<Vector3<T>> {
        self.friction
            .as_ref()
            .map(|f| f.impulse_contact)
            .or(self.impulse.as_ref().map(|g| g.impulse_contact))
    }

    /// Whether the contact sticks or slides, when friction ran.
    pub fn regime(&self) -> Option<FrictionRegime> {
        self.friction.as_ref().map(|f| f.regime)
    }

    /// True when the contact is closing, so an impulse is applied.
    pub fn closing(&self) -> bool {
        self.impulse.is_some()
    }

    /// κ(M) of the friction matrix (exact: its symmetric eigenvalues), when
    /// the 3×3 system was solved. Computed here, for whoever shows it: the
    /// stage path factors M without it.
    pub fn condition_number(&self) -> Option<T> {
        self.impulse.as_ref()?.solve.as_ref()?;
        self.unit.matrix.as_ref().map(condition_number)
    }

    /// State of body slot `i` after velocity and position resolution.
    pub fn after(&self, problem: &Problem<T>, i: usize) -> Option<BodyAfter<T>> {
        let body = problem.bodies[i].as_ref()?;
        let applied = self.applied.as_ref().and_then(|a| a.bodies[i].as_ref());
        let moved = self.projection.as_ref().and_then(|p| p.bodies[i].as_ref());
        let turned = self.orientation.as_ref().and_then(|o| o.bodies[i].as_ref());
        Some(BodyAfter {
            position: moved.map_or(body.position, |m| m.position),
            orientation: turned.map_or(body.orientation, |o| o.normalised),
            velocity: applied.map_or(body.velocity, |a| a.v),
            angular_velocity: applied.map_or(body.angular_velocity, |a| a.w),
        })
    }
}

/// The impulse applied: the friction clamp's when it ran, else the impulse stage's.
fn final_impulse_world<T: Real>(
    impulse: Option<&Impulse<T>>,
    friction: Option<&FrictionClamp<T>>,
) -> Option<Vector3<T>> {
    friction
        .map(|f| f.impulse_world)
        .or(impulse.map(|g| g.impulse_world))
}
