//! A note on the desired-Δv stage when last frame's acceleration adds a
//! planar velocity to the contact velocity (kept out of the stage builder).

use crate::physics::{to_f64, Solution, StageId};

use super::{Trace, Value};

/// Adds the planar-acceleration note and its number to the
/// `desired_delta_velocity` stage, when that velocity is non-zero.
pub fn note_planar_acceleration(trace: &mut Trace, solution: &Solution<f64>) {
    let planar = solution.desired.planar_from_acceleration;
    if planar == nalgebra::Vector3::zeros() {
        return;
    }
    let Some(step) = trace
        .stages
        .iter_mut()
        .find(|s| s.id == StageId::DesiredDeltaVelocity)
    else {
        return;
    };
    step.inputs.push((
        "planar_from_acceleration".into(),
        Value::from(planar.map(to_f64)),
    ));
    step.notes.push(
        "v_c includes (0, y, z) of Cᵀ(a₁ - a₂)Δt = {planar_from_acceleration}: the sliding velocity last frame's acceleration built up, which static friction removes (as the reference engine does); its normal part is v_acc."
            .into(),
    );
}
