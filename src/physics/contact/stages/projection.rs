//! Stage 7: nonlinear projection (lecture: "Resolving Interpenetration").
//!
//! Per body: linear inertia `1/m`, angular inertia `((I⁻¹(r×d))×r)·d`; the
//! penetration is shared in proportion, `Δ_l = (-1)^(i+1) d_pen I_l/I_t`,
//! `Δ_a = (-1)^(i+1) d_pen I_a/I_t`; the angular move is limited to
//! `angular_limit·|r - (r·d)d|` with the excess moved to the linear share.

use nalgebra::{Matrix3, Vector3};

use super::unit_impulse::{angular_response, AngularResponse};
use super::ContactFrame;
use crate::physics::contact::problem::InverseInertias;
use crate::physics::scale::stable_norm;
use crate::physics::{ContactParams, Problem, ProjectionMethod, Real};

#[derive(Debug, Clone, PartialEq)]
pub struct BodyProjection<T: Real> {
    pub linear_inertia: T,
    pub angular_inertia: T,
    /// Moves before the angular limit.
    pub linear_move_unlimited: T,
    pub angular_move_unlimited: T,
    /// `|r - (r·d)d|`, the lever arm across the normal.
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

/// The part of one body's projection that does not depend on the depth: its
/// linear and angular inertia along `d`, `I⁻¹(r×d)`, and the angular limit
/// `angular_limit·|r⊥|`. The resolver prepares this once per contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProjectionInertia<T: Real> {
    pub linear: T,
    /// `((I⁻¹(r×d))×r)·d`, 0 for the linear projection.
    pub angular: T,
    /// `I⁻¹(r×d)`.
    pub rotation_per_unit: Vector3<T>,
    /// `|r - (r·d)d|`.
    pub r_perp_length: T,
    /// `angular_limit·|r⊥|` (`inf` when there is no limit).
    pub angular_limit: T,
}

/// One body's [`ProjectionInertia`] from its inverse mass, world inverse inertia and arm.
#[inline]
pub fn projection_inertia<T: Real>(
    inverse_mass: T,
    inverse_inertia_world: &Matrix3<T>,
    r: &Vector3<T>,
    d: &Vector3<T>,
    settings: &ContactParams<T>,
) -> ProjectionInertia<T> {
    let response = angular_response(inverse_inertia_world, r, d);
    projection_inertia_from(inverse_mass, &response, r, d, settings)
}

/// [`projection_inertia`] from the body's [`AngularResponse`] (the same
/// numbers as the velocity change per unit impulse).
#[inline]
pub fn projection_inertia_from<T: Real>(
    inverse_mass: T,
    response: &AngularResponse<T>,
    r: &Vector3<T>,
    d: &Vector3<T>,
    settings: &ContactParams<T>,
) -> ProjectionInertia<T> {
    projection_inertia_parts(
        inverse_mass,
        response.rotation,
        response.angular,
        r,
        d,
        settings,
        stable_norm,
    )
}

/// [`projection_inertia_from`] from the response's parts, `|r⊥|` by `norm`
/// (the resolver's lean prepare passes a norm that gives `stable_norm`'s
/// bits more cheaply).
#[inline(always)]
pub fn projection_inertia_parts<T: Real>(
    inverse_mass: T,
    rotation_per_unit: Vector3<T>,
    angular: T,
    r: &Vector3<T>,
    d: &Vector3<T>,
    settings: &ContactParams<T>,
    norm: impl Fn(&Vector3<T>) -> T,
) -> ProjectionInertia<T> {
    let angular = if settings.projection == ProjectionMethod::Nonlinear {
        angular
    } else {
        T::zero()
    };
    // Avoiding excessive rotation: scale the limit by the lever arm's size.
    let r_perp = r - d * r.dot(d);
    let r_perp_length = norm(&r_perp);
    // `inf` switches the limit off (and must not become inf · 0 = NaN).
    let angular_limit = if settings.angular_limit.is_finite() {
        settings.angular_limit * r_perp_length
    } else {
        settings.angular_limit
    };
    ProjectionInertia {
        linear: inverse_mass,
        angular,
        rotation_per_unit,
        r_perp_length,
        angular_limit,
    }
}

/// `Σ (I_l + I_a)` over the bodies present.
pub fn total_projection_inertia<T: Real>(inertias: &[Option<ProjectionInertia<T>>; 2]) -> T {
    inertias
        .iter()
        .flatten()
        .fold(T::zero(), |s, i| s + i.linear + i.angular)
}

/// One body's moves for `depth` (lecture: `Δ_l = (-1)^(i+1) d_pen I_l/I_t`,
/// `Δ_a = (-1)^(i+1) d_pen I_a/I_t`, then the angular limit). `position` is
/// the body's position before the move.
#[inline]
pub fn body_projection<T: Real>(
    inertia: &ProjectionInertia<T>,
    sign: T,
    depth: T,
    total_inertia: T,
    d: &Vector3<T>,
    position: &Vector3<T>,
) -> BodyProjection<T> {
    let linear_move_unlimited = sign * depth * inertia.linear / total_inertia;
    let angular_move_unlimited = sign * depth * inertia.angular / total_inertia;
    let angular_limit = inertia.angular_limit;
    let limited = angular_move_unlimited.abs() > angular_limit;
    let angular_move = if limited {
        angular_limit * angular_move_unlimited.signum()
    } else {
        angular_move_unlimited
    };
    let linear_move = linear_move_unlimited + (angular_move_unlimited - angular_move);

    let angular_change = if angular_move == T::zero() || inertia.angular == T::zero() {
        Vector3::zeros()
    } else {
        inertia.rotation_per_unit * (angular_move / inertia.angular)
    };
    let linear_change = d * linear_move;
    BodyProjection {
        linear_inertia: inertia.linear,
        angular_inertia: inertia.angular,
        linear_move_unlimited,
        angular_move_unlimited,
        r_perp_length: inertia.r_perp_length,
        angular_limit,
        limited,
        linear_move,
        angular_move,
        linear_change,
        rotation_per_unit: inertia.rotation_per_unit,
        angular_change,
        position: position + linear_change,
    }
}

pub fn nonlinear_projection<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
) -> Projection<T> {
    nonlinear_projection_with(problem, &problem.inverse_inertias(), frame)
}

/// [`nonlinear_projection`] with each slot's world inverse inertia already at hand.
pub fn nonlinear_projection_with<T: Real>(
    problem: &Problem<T>,
    inverse_inertias: &InverseInertias<T>,
    frame: &ContactFrame<T>,
) -> Projection<T> {
    let mut projection = Projection {
        method: problem.contact.settings.projection,
        resolved_depth: T::zero(),
        total_inertia: T::zero(),
        bodies: [None, None],
    };
    nonlinear_projection_into(problem, inverse_inertias, frame, &mut projection);
    projection
}

/// [`nonlinear_projection_with`] written into `out` (the stage path's form:
/// each body's record is written into its slot, no array of records moved).
#[inline]
pub fn nonlinear_projection_into<T: Real>(
    problem: &Problem<T>,
    inverse_inertias: &InverseInertias<T>,
    frame: &ContactFrame<T>,
    out: &mut Projection<T>,
) {
    let settings = &problem.contact.settings;
    let d = frame.normal();
    let depth = problem.contact.penetration * settings.relaxation;

    let mut inertias = [None, None];
    for (i, inertia) in inertias.iter_mut().enumerate() {
        if let (Some(body), Some(r), Some(inverse_inertia)) = (
            problem.bodies[i].as_ref(),
            frame.r[i],
            inverse_inertias[i].as_ref(),
        ) {
            *inertia = Some(projection_inertia(
                body.inverse_mass,
                inverse_inertia,
                &r,
                &d,
                settings,
            ));
        }
    }
    let total_inertia = total_projection_inertia(&inertias);
    for (i, slot) in out.bodies.iter_mut().enumerate() {
        *slot = match (inertias[i].as_ref(), problem.bodies[i].as_ref()) {
            (Some(inertia), Some(body)) => Some(body_projection(
                inertia,
                Problem::<T>::sign(i),
                depth,
                total_inertia,
                &d,
                &body.position,
            )),
            _ => None,
        };
    }
    out.method = settings.projection;
    out.resolved_depth = depth;
    out.total_inertia = total_inertia;
}
