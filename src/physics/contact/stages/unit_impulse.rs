//! Stage 2: velocity change at the contact per unit impulse along the normal
//! (lecture: "Velocity Change By Unit Impulse"), and with friction the full
//! 3×3 contact-space matrix `M = Cᵀ(Σ -[r]× I⁻¹ [r]×)C + (Σ 1/m)·𝟙`.

use nalgebra::{Matrix3, Vector3};

use super::ContactFrame;
use crate::physics::contact::problem::InverseInertias;
use crate::physics::frame::skew;
use crate::physics::{Problem, Real};

/// One body's response to a unit impulse along d. Its world inverse inertia
/// `R I_b⁻¹ Rᵀ` and its part `-[r]× I⁻¹ [r]×` of the friction matrix are not
/// kept: the trace, which shows them, takes them from the body (the same
/// functions, the same numbers); only their sum `M` is kept.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyUnitResponse<T: Real> {
    pub inverse_mass: T,
    /// `u = r × d`, impulsive torque per unit impulse.
    pub torque_per_unit_impulse: Vector3<T>,
    /// `Δθ̇ = I⁻¹ u`, rotation per unit impulse.
    pub rotation_per_unit_impulse: Vector3<T>,
    /// `Δq̇ = Δθ̇ × r`, velocity of the contact point per unit impulse.
    pub velocity_per_unit_impulse: Vector3<T>,
    /// `Δq̇ · d`, the angular component along the normal.
    pub angular: T,
}

#[derive(Debug, Clone, PartialEq)]
pub struct UnitImpulse<T: Real> {
    pub bodies: [Option<BodyUnitResponse<T>>; 2],
    /// `Δṗ_d = Σ 1/m_i`.
    pub linear: T,
    /// `Δq̇_t = Σ 1/m_i + Σ Δq̇_d,i`.
    pub total: T,
    /// Contact-space velocity change per unit impulse (built only with friction).
    pub matrix: Option<Matrix3<T>>,
}

/// The angular part of one body's response to a unit impulse along `d`
/// (lecture: "Velocity Change By Unit Impulse"): `u = r × d`, `Δθ̇ = I⁻¹ u`,
/// `Δq̇ = Δθ̇ × r` and its normal component `Δq̇ · d`. The projection's
/// angular inertia is the same number.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngularResponse<T: Real> {
    pub torque: Vector3<T>,
    pub rotation: Vector3<T>,
    pub velocity: Vector3<T>,
    pub angular: T,
}

#[inline]
pub fn angular_response<T: Real>(
    inverse_inertia_world: &Matrix3<T>,
    r: &Vector3<T>,
    d: &Vector3<T>,
) -> AngularResponse<T> {
    let torque = r.cross(d);
    let rotation = inverse_inertia_world * torque;
    let velocity = rotation.cross(r);
    AngularResponse {
        torque,
        rotation,
        velocity,
        angular: velocity.dot(d),
    }
}

/// `Δq̇_t = Σ 1/mᵢ + Σ Δq̇_dᵢ` over the bodies present (`(1/m, Δq̇_d)` each),
/// the linear terms summed first as the lecture writes it.
pub fn total_per_unit_impulse<T: Real>(bodies: &[Option<(T, T)>; 2]) -> (T, T) {
    let linear = bodies
        .iter()
        .flatten()
        .fold(T::zero(), |s, (inverse_mass, _)| s + *inverse_mass);
    let total = bodies
        .iter()
        .flatten()
        .fold(linear, |s, (_, angular)| s + *angular);
    (linear, total)
}

/// One body's response to a unit impulse along `d`, from its inverse mass,
/// world inverse inertia and arm `r`.
#[inline]
pub fn body_unit_response<T: Real>(
    inverse_mass: T,
    inverse_inertia_world: &Matrix3<T>,
    r: &Vector3<T>,
    d: &Vector3<T>,
) -> BodyUnitResponse<T> {
    let AngularResponse {
        torque,
        rotation,
        velocity,
        angular,
    } = angular_response(inverse_inertia_world, r, d);
    BodyUnitResponse {
        inverse_mass,
        torque_per_unit_impulse: torque,
        rotation_per_unit_impulse: rotation,
        velocity_per_unit_impulse: velocity,
        angular,
    }
}

/// One body's angular part of the world-space response matrix, `−[r]× I⁻¹ [r]×`.
pub fn angular_matrix<T: Real>(
    skew_r: &Matrix3<T>,
    inverse_inertia_world: &Matrix3<T>,
) -> Matrix3<T> {
    -(skew_r * inverse_inertia_world * skew_r)
}

/// The contact-space matrix `M = Cᵀ W C + (Σ 1/m)·𝟙` from the bodies' summed
/// angular parts `W` (velocity change per unit impulse, contact space).
pub fn contact_matrix<T: Real>(
    angular_world: &Matrix3<T>,
    contact_to_world: &Matrix3<T>,
    linear: T,
) -> Matrix3<T> {
    let c = contact_to_world;
    c.transpose() * angular_world * c + Matrix3::identity() * linear
}

pub fn unit_impulse<T: Real>(
    problem: &Problem<T>,
    frame: &ContactFrame<T>,
    with_matrix: bool,
) -> UnitImpulse<T> {
    unit_impulse_with(problem, &problem.inverse_inertias(), frame, with_matrix)
}

/// [`unit_impulse`] with each slot's world inverse inertia already at hand.
pub fn unit_impulse_with<T: Real>(
    problem: &Problem<T>,
    inverse_inertias: &InverseInertias<T>,
    frame: &ContactFrame<T>,
    with_matrix: bool,
) -> UnitImpulse<T> {
    let mut unit = UnitImpulse::empty();
    unit_impulse_into(problem, inverse_inertias, frame, with_matrix, &mut unit);
    unit
}

impl<T: Real> UnitImpulse<T> {
    /// A record to be written by [`unit_impulse_into`].
    pub fn empty() -> Self {
        UnitImpulse {
            bodies: [None, None],
            linear: T::zero(),
            total: T::zero(),
            matrix: None,
        }
    }
}

/// [`unit_impulse_with`] written into `out` (the stage path's form: each
/// response is written into its slot where it stays, no record moved).
#[inline]
pub fn unit_impulse_into<T: Real>(
    problem: &Problem<T>,
    inverse_inertias: &InverseInertias<T>,
    frame: &ContactFrame<T>,
    with_matrix: bool,
    out: &mut UnitImpulse<T>,
) {
    let d = frame.normal();
    // Σ -[rᵢ]× Iᵢ⁻¹ [rᵢ]× in world space, body 1 first (friction only).
    let mut angular_world = Matrix3::zeros();
    for (i, slot) in out.bodies.iter_mut().enumerate() {
        let (Some(body), Some(r), Some(inverse_inertia)) = (
            problem.bodies[i].as_ref(),
            frame.r[i],
            inverse_inertias[i].as_ref(),
        ) else {
            *slot = None;
            continue;
        };
        *slot = Some(body_unit_response(
            body.inverse_mass,
            inverse_inertia,
            &r,
            &d,
        ));
        if with_matrix {
            angular_world += angular_matrix(&skew(&r), inverse_inertia);
        }
    }
    let (linear, total) = total_per_unit_impulse(&[
        out.bodies[0].as_ref().map(|b| (b.inverse_mass, b.angular)),
        out.bodies[1].as_ref().map(|b| (b.inverse_mass, b.angular)),
    ]);
    out.linear = linear;
    out.total = total;
    out.matrix =
        with_matrix.then(|| contact_matrix(&angular_world, &frame.contact_to_world, linear));
}
