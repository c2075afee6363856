//! Every number a contact's [`Solution`] holds, visited by field name: the
//! load-time overflow guard (`lesson::overflow`) reads them to refuse a
//! lesson whose stages leave f64's range.
//!
//! Each record lists its fields by destructuring without `..`, so a field
//! added to a stage and forgotten here does not compile.

use nalgebra::{Matrix3, Quaternion, Scalar, Vector2, Vector3};

use super::causes::Cause;
use super::checks::{CheckItem, Checks};
use super::stages::{
    AppliedImpulse, BodyOrientation, BodyProjection, BodyUnitResponse, BodyVelocityChange,
    ContactFrame, DesiredVelocity, FrictionClamp, Impulse, MatrixSolve, OrientationUpdate,
    Projection, UnitImpulse,
};
use super::{Solution, Stages};
use crate::physics::exact::{
    ExactError, ExactImpact, ImpactInput, ImpactOutcome, Phase, PhaseKind, Sample, Tolerance,
};
use crate::physics::Real;

/// A record whose numbers can be visited: `visit(field, value)` for each,
/// `field` the innermost field's name (a check's measurement by the name
/// the checks give it, `energy_after`).
pub trait Numbers {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64));
}

impl Numbers for f64 {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        visit(field, *self)
    }
}

impl Numbers for f32 {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        visit(field, f64::from(*self))
    }
}

/// Counts, flags and names hold no number that can overflow.
macro_rules! no_numbers {
    ($($t:ty),*) => {$(
        impl Numbers for $t {
            fn numbers(&self, _: &str, _: &mut dyn FnMut(&str, f64)) {}
        }
    )*};
}
no_numbers!(
    bool,
    u8,
    usize,
    &'static str,
    super::frame::GuessAxis,
    crate::physics::FrictionModel,
    crate::physics::ProjectionMethod,
    super::stages::FrictionRegime,
    super::stages::friction::FrictionIssue,
    crate::physics::exact::RestitutionLaw,
    crate::physics::exact::Cost
);

impl<T: Numbers + Scalar> Numbers for Vector2<T> {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        self.iter().for_each(|x| x.numbers(field, visit))
    }
}

impl<T: Numbers + Scalar> Numbers for Vector3<T> {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        self.iter().for_each(|x| x.numbers(field, visit))
    }
}

impl<T: Numbers + Scalar> Numbers for Matrix3<T> {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        self.iter().for_each(|x| x.numbers(field, visit))
    }
}

impl<T: Numbers + Scalar> Numbers for Quaternion<T> {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        self.coords.iter().for_each(|x| x.numbers(field, visit))
    }
}

impl<X: Numbers> Numbers for Option<X> {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        if let Some(x) = self {
            x.numbers(field, visit)
        }
    }
}

impl<X: Numbers, const N: usize> Numbers for [X; N] {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        self.iter().for_each(|x| x.numbers(field, visit))
    }
}

impl<X: Numbers> Numbers for Vec<X> {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        self.iter().for_each(|x| x.numbers(field, visit))
    }
}

impl<X: Numbers> Numbers for Box<X> {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        (**self).numbers(field, visit)
    }
}

impl<X: Numbers, E: Numbers> Numbers for Result<X, E> {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        match self {
            Ok(x) => x.numbers(field, visit),
            Err(e) => e.numbers(field, visit),
        }
    }
}

/// `Numbers` for a record generic in the float type: each field by name.
macro_rules! record {
    ($($t:ident { $($f:ident),* $(,)? })*) => {$(
        impl<T: Real + Numbers> Numbers for $t<T> {
            fn numbers(&self, _: &str, visit: &mut dyn FnMut(&str, f64)) {
                let $t { $($f),* } = self;
                $( $f.numbers(stringify!($f), visit); )*
            }
        }
    )*};
}

record! {
    Solution { stages, checks }
    Stages { frame, unit, desired, impulse, friction, applied, projection, orientation, exact }
    ContactFrame { contact_to_world, guess, r }
    UnitImpulse { bodies, linear, total, matrix }
    BodyUnitResponse {
        inverse_mass, torque_per_unit_impulse, rotation_per_unit_impulse,
        velocity_per_unit_impulse, angular,
    }
    DesiredVelocity {
        point_velocity, contact_velocity_world, contact_velocity, planar_from_acceleration,
        restitution_given, restitution, restitution_limited, velocity_from_acceleration, desired,
    }
    Impulse { impulse_contact, impulse_world, solve, closed_form_j, closed_form_relative_difference }
    MatrixSolve { rhs, condition_number, ill_conditioned, used_lu, singular }
    FrictionClamp {
        model, regime, planar, limit, sized_by, direction, normal_per_unit, impulse_contact,
        impulse_world, solve, issue,
    }
    AppliedImpulse { bodies }
    BodyVelocityChange { impulse, impulsive_torque, dv, dw, v, w }
    Projection { method, resolved_depth, total_inertia, bodies }
    BodyProjection {
        linear_inertia, angular_inertia, linear_move_unlimited, angular_move_unlimited,
        r_perp_length, angular_limit, limited, linear_move, angular_move, linear_change,
        rotation_per_unit, angular_change, position,
    }
    OrientationUpdate { bodies }
    BodyOrientation { before, rotation, unnormalised, normalised }
    ExactImpact {
        input, outcome, frame, impulse_world, applied, one_shot_world, one_shot_contact,
        energy_before, energy_after, energy_after_one_shot,
    }
    ImpactInput { k, u0, static_friction, dynamic_friction, restitution, law, tolerance }
    Tolerance { rtol, max_steps, always_integrate }
    ImpactOutcome {
        law, closing, impulse, velocity, compression_pn, work_compression, work_restitution,
        work_friction, energy_change, phases, samples, cost,
    }
    Phase { kind, from_pn, to_pn, u_from, u_to }
    Sample { p, u, work_normal }
}

impl<T: Real + Numbers> Numbers for PhaseKind<T> {
    fn numbers(&self, _: &str, visit: &mut dyn FnMut(&str, f64)) {
        match self {
            PhaseKind::Slides {
                direction,
                end_direction,
                rotating: _,
            } => {
                direction.numbers("direction", visit);
                end_direction.numbers("end_direction", visit);
            }
            PhaseKind::Sticks { ratio } => ratio.numbers("ratio", visit),
            PhaseKind::SlipReverses { direction }
            | PhaseKind::SlipResumes { direction }
            | PhaseKind::SlipStarts { direction } => direction.numbers("direction", visit),
            PhaseKind::Frictionless | PhaseKind::SlipHalts | PhaseKind::MaxCompression => {}
        }
    }
}

impl Numbers for ExactError {
    fn numbers(&self, _: &str, visit: &mut dyn FnMut(&str, f64)) {
        match self {
            ExactError::OutOfRange { value, .. } => visit("value", *value),
            ExactError::BudgetExceeded { p_n, .. }
            | ExactError::NoTermination { p_n, .. }
            | ExactError::Overflow { p_n } => visit("p_n", *p_n),
            ExactError::NonFinite { .. } | ExactError::NotPositiveDefinite { .. } => {}
        }
    }
}

/// The checks' measurements by the names the checks give them, then the
/// numbers of their causes.
impl<T: Real + Numbers> Numbers for Checks<T> {
    fn numbers(&self, field: &str, visit: &mut dyn FnMut(&str, f64)) {
        self.items.numbers(field, visit)
    }
}

impl<T: Real + Numbers> Numbers for CheckItem<T> {
    fn numbers(&self, _: &str, visit: &mut dyn FnMut(&str, f64)) {
        for (name, x) in self.named_values() {
            x.numbers(name, visit);
        }
        self.cause.numbers("cause", visit);
    }
}

impl<T: Real + Numbers> Numbers for Cause<T> {
    fn numbers(&self, _: &str, visit: &mut dyn FnMut(&str, f64)) {
        match self {
            Cause::RoundOff {
                condition,
                allowance,
            } => {
                condition.numbers("condition", visit);
                allowance.numbers("allowance", visit);
            }
            Cause::AccelerationCompensation { energy_without }
            | Cause::Friction { energy_without }
            | Cause::AccelerationAndFriction { energy_without } => {
                energy_without.numbers("energy_without", visit)
            }
            Cause::PlanarAcceleration { planar } => planar.numbers("planar", visit),
            Cause::KineticDirectionNormal
            | Cause::NoFrictionWhileNotSliding
            | Cause::FrictionlessFallback
            | Cause::VelocityScalingModel
            | Cause::Unexplained => {}
        }
    }
}
