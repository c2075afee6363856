//! The energy check of one step: the velocity phase must not add kinetic
//! energy unless a stated cause explains it. Impulses of one contact with
//! restitution ≤ 1 and Coulomb friction remove energy; two things in the
//! lecture's model can add it: restitution with friction (Newton's law with
//! sticking friction is not energetically consistent, the Kane example) and
//! acceleration compensation (a desired Δv built from last frame's
//! acceleration, which can ask for more bounce than the closing speed gives).
//! The trace (`trace::run`) says the cause in words.
//! Projection lifting bodies out of penetration raises the potential energy;
//! that is expected and not reported here.

use crate::physics::{Real, World};

/// Why the velocity phase may add energy.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EnergyCause {
    /// A contact has both restitution and friction.
    RestitutionWithFriction,
    /// Acceleration compensation is on.
    AccelerationCompensation,
    /// Both of the above.
    Both,
    /// None of the causes applies: a defect of the model or of the code.
    Unexplained,
}

/// The causes that apply to this step's contacts (compensation only when
/// some body has an acceleration to compensate).
pub fn cause<T: Real>(world: &World<T>, compensation: bool) -> EnergyCause {
    let compensation = compensation
        && world
            .bodies
            .iter()
            .filter_map(|b| b.dynamic())
            .any(|b| b.acceleration.iter().any(|a| *a != T::zero()));
    let kane = world
        .contacts
        .iter()
        .any(|k| k.input.restitution > T::zero() && k.input.has_friction());
    match (kane, compensation) {
        (true, true) => EnergyCause::Both,
        (true, false) => EnergyCause::RestitutionWithFriction,
        (false, true) => EnergyCause::AccelerationCompensation,
        (false, false) => EnergyCause::Unexplained,
    }
}

/// The velocity phase's gain worth reporting: above rounding, relative to
/// the scene's energy scale and to the kinetic energy it acted on.
pub fn gain(before: f64, after: f64, scale: f64) -> Option<f64> {
    let gained = after - before;
    let rounding = 1e-9 * scale.max(before.abs()).max(1e-12);
    (gained > rounding).then_some(gained)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_is_not_a_gain_and_a_real_gain_is() {
        assert_eq!(gain(1.0, 1.0 + 1e-12, 10.0), None);
        assert_eq!(gain(1.0, 0.5, 10.0), None);
        assert_eq!(gain(1.0, 1.5, 10.0), Some(0.5));
        // A tiny scene's gain is judged against its own scale.
        assert_eq!(gain(1e-6, 2e-6, 1e-6), Some(1e-6));
    }
}
