//! The impact integration of one contact of a [`Problem`]: K and u0 from the
//! existing stages, the integrated impulse applied to the bodies, and the
//! one-shot impulse of `physics::solve` beside it.

use nalgebra::Vector3;

use super::{integrate, ExactError, ImpactInput, ImpactOutcome, RestitutionLaw, Tolerance};
use crate::physics::stages::{
    apply_impulse, contact_frame, desired_delta_velocity, unit_impulse, AppliedImpulse,
    ContactFrame,
};
use crate::physics::{c, Problem, Real};

/// The integrated impact of one contact, with the one-shot answer beside it.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactImpact<T: Real> {
    /// What was integrated: K (the friction stage's matrix), u0 (contact
    /// space), μ_s, μ_d and the contact's restitution as given.
    pub input: ImpactInput<T>,
    pub outcome: ImpactOutcome<T>,
    pub frame: ContactFrame<T>,
    /// The integrated impulse on body 1, world space.
    pub impulse_world: Vector3<T>,
    /// Velocities after the integrated impulse (same formulas as `apply_impulse`).
    pub applied: AppliedImpulse<T>,
    /// The one-shot impulse of `physics::solve` (after its friction clamp;
    /// zero when it applies none), world and contact space.
    pub one_shot_world: Vector3<T>,
    pub one_shot_contact: Vector3<T>,
    /// Kinetic energy of the movable bodies before, after the integrated
    /// impulse and after the one-shot impulse.
    pub energy_before: T,
    pub energy_after: T,
    pub energy_after_one_shot: T,
}

impl<T: Real> ExactImpact<T> {
    /// `P - P_one-shot`, contact space.
    pub fn impulse_difference(&self) -> Vector3<T> {
        self.outcome.impulse - self.one_shot_contact
    }

    /// `|P - P_one-shot|`.
    pub fn impulse_difference_abs(&self) -> T {
        self.impulse_difference().norm()
    }

    /// `|P - P_one-shot| / |P|` (the absolute difference when P = 0).
    pub fn impulse_difference_relative(&self) -> T {
        let size = self.outcome.impulse.norm();
        let diff = self.impulse_difference_abs();
        if size > T::zero() {
            diff / size
        } else {
            diff
        }
    }

    /// `E_one-shot - E_exact` after the impact.
    pub fn energy_difference(&self) -> T {
        self.energy_after_one_shot - self.energy_after
    }

    /// `E_after - E_before`.
    pub fn energy_change(&self) -> T {
        self.energy_after - self.energy_before
    }

    /// True when the integrated impulse raised the kinetic energy by more than
    /// round-off (`1e4 ε` of the energy before, the tolerance of `checks`).
    pub fn gains_energy(&self) -> bool {
        gains(self.energy_before, self.energy_after)
    }

    /// The same for the one-shot impulse.
    pub fn one_shot_gains_energy(&self) -> bool {
        gains(self.energy_before, self.energy_after_one_shot)
    }
}

fn gains<T: Real>(before: T, after: T) -> bool {
    after - before > T::default_epsilon() * c::<T>(1e4) * before.abs()
}

/// [`super::exact_impact_with`] beside a one-shot impulse already computed (world
/// space, zero when none is applied): what `physics::solve` runs for the
/// `exact_impact` stage.
pub fn exact_impact_beside<T: Real>(
    problem: &Problem<T>,
    law: RestitutionLaw,
    tolerance: Tolerance<T>,
    one_shot_world: Vector3<T>,
) -> Result<ExactImpact<T>, ExactError> {
    let frame = contact_frame(problem);
    let unit = unit_impulse(problem, &frame, true);
    let desired = desired_delta_velocity(problem, &frame);
    let contact = &problem.contact;
    let input = ImpactInput {
        k: unit.matrix.ok_or(ExactError::NotPositiveDefinite {
            reason: "no collision matrix",
        })?,
        u0: desired.contact_velocity,
        static_friction: contact.static_friction,
        dynamic_friction: contact.dynamic_friction,
        restitution: contact.restitution,
        law,
        tolerance,
    };
    let outcome = integrate(&input)?;
    let impulse_world = frame.to_world(&outcome.impulse);
    let applied = apply_impulse(problem, &frame, &impulse_world);
    let one_shot = apply_impulse(problem, &frame, &one_shot_world);
    let energy = |applied: Option<&AppliedImpulse<T>>| {
        let mut sum = T::zero();
        for (i, body) in problem.bodies.iter().enumerate() {
            if let Some(b) = body {
                let after = applied.and_then(|a| a.bodies[i].as_ref());
                let (v, w) = after.map_or((b.velocity, b.angular_velocity), |a| (a.v, a.w));
                sum += b.kinetic_energy(&v, &w);
            }
        }
        sum
    };
    Ok(ExactImpact {
        energy_before: energy(None),
        energy_after: energy(Some(&applied)),
        energy_after_one_shot: energy(Some(&one_shot)),
        one_shot_contact: frame.to_contact(&one_shot_world),
        one_shot_world,
        impulse_world,
        applied,
        input,
        outcome,
        frame,
    })
}
