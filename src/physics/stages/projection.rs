//! Stage 7: nonlinear projection (lecture: "Resolving Interpenetration").
//!
//! Per body: linear inertia `1/m`, angular inertia `((I⁻¹(r×d))×r)·d`; the
//! penetration is shared in proportion, `Δ_l = (−1)^(i+1) d_pen I_l/I_t`,
//! `Δ_a = (−1)^(i+1) d_pen I_a/I_t`; the angular move is limited to
//! `angular_limit·|r − (r·d)d|` with the excess moved to the linear share.

use nalgebra::Vector3;

use super::ContactFrame;
use crate::physics::scale::stable_norm;
use crate::physics::{Problem, ProjectionMethod, Real};

#[derive(Debug, Clone, PartialEq)]
pub struct BodyProjection<T: Real> {
    pub linear_inertia: T,
    pub angular_inertia: T,
    /// Moves before the angular limit.
    pub linear_move_unlimited: T,
    pub angular_move_unlimited: T,
    /// `|r − (r·d)d|`, the lever arm across the normal.
    pub r_perp_length: T,
    /// `angular_limit·|r⊥|`.
    pub angular_limit: T,
    /// True when the limit cut the angular move.
    pub limited: bool,
    pub linear_move: T,
    pub angular_move: T,
    /// `Δ_l d`.
    pub linear_change: Vector3<T>,
    /// `I⁻¹(r×d)`, rotation per unit impulse (Δθ of the lecture).
    pub rotation_per_unit: Vector3<T>,
    /// `Δθ (Δ_a / I_a)`, the rotation vector applied.
    pub angular_change: Vector3<T>,
    pub position: Vector3<T>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Projection<T: Real> {
    pub method: ProjectionMethod,
    /// `d_pen · relaxation`, the depth this step resolves.
    pub resolved_depth: T,
    pub total_inertia: T,
    pub bodies: [Option<BodyProjection<T>>; 2],
}

pub fn nonlinear_projection<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
) -> Projection<T> {
    let settings = &problem.contact.settings;
    let d = frame.normal();
    let depth = problem.contact.penetration * settings.relaxation;
    let nonlinear = settings.projection == ProjectionMethod::Nonlinear;

    let inertias = [0, 1].map(|i| {
        let body = problem.bodies[i].as_ref()?;
        let r = frame.r[i]?;
        let rotation_per_unit = body.inverse_inertia_world() * r.cross(&d);
        let angular = if nonlinear {
            rotation_per_unit.cross(&r).dot(&d)
        } else {
            T::zero()
        };
        Some((body.inverse_mass, angular, rotation_per_unit))
    });
    let total_inertia = inertias
        .iter()
        .flatten()
        .fold(T::zero(), |s, (l, a, _)| s + *l + *a);

    let bodies = [0, 1].map(|i| {
        let (linear_inertia, angular_inertia, rotation_per_unit) = inertias[i]?;
        let body = problem.bodies[i].as_ref()?;
        let r = frame.r[i]?;
        let sign = Problem::<T>::sign(i);
        let linear_move_unlimited = sign * depth * linear_inertia / total_inertia;
        let angular_move_unlimited = sign * depth * angular_inertia / total_inertia;

        // Avoiding excessive rotation: scale the limit by the lever arm's size.
        let r_perp = r - d * r.dot(&d);
        let r_perp_length = stable_norm(&r_perp);
        // `inf` switches the limit off (and must not become inf · 0 = NaN).
        let angular_limit = if settings.angular_limit.is_finite() {
            settings.angular_limit * r_perp_length
        } else {
            settings.angular_limit
        };
        let limited = angular_move_unlimited.abs() > angular_limit;
        let angular_move = if limited {
            angular_limit * angular_move_unlimited.signum()
        } else {
            angular_move_unlimited
        };
        let linear_move = linear_move_unlimited + (angular_move_unlimited - angular_move);

        let angular_change = if angular_move == T::zero() || angular_inertia == T::zero() {
            Vector3::zeros()
        } else {
            rotation_per_unit * (angular_move / angular_inertia)
        };
        let linear_change = d * linear_move;
        Some(BodyProjection {
            linear_inertia,
            angular_inertia,
            linear_move_unlimited,
            angular_move_unlimited,
            r_perp_length,
            angular_limit,
            limited,
            linear_move,
            angular_move,
            linear_change,
            rotation_per_unit,
            angular_change,
            position: body.position + linear_change,
        })
    });
    Projection {
        method: settings.projection,
        resolved_depth: depth,
        total_inertia,
        bodies,
    }
}
