//! The input of one contact: bodies, contact geometry, coefficients, settings.

use nalgebra::Vector3;

use super::{c, Real, RigidBody};

/// How friction is modelled (issue: friction models of the seeds).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FrictionModel {
    /// The lecture and reference engine: solve for the impulse that removes all
    /// sliding, then clamp it to the Coulomb cone.
    #[default]
    Millington,
    /// Companion lectures 002/003: impulse `j(n + μ_k t)`, t against the sliding direction.
    KineticDirection,
    /// Seed 004: remove the planar velocity below `v_c μ_s`, otherwise scale it by μ_d.
    VelocityScaling,
}

impl FrictionModel {
    pub const ALL: [FrictionModel; 3] = [
        FrictionModel::Millington,
        FrictionModel::KineticDirection,
        FrictionModel::VelocityScaling,
    ];

    pub fn name(self) -> &'static str {
        match self {
            FrictionModel::Millington => "millington",
            FrictionModel::KineticDirection => "kinetic-direction",
            FrictionModel::VelocityScaling => "velocity-scaling",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }
}

/// How penetration is resolved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ProjectionMethod {
    /// Inverse-mass weighting only: no rotation.
    Linear,
    /// The lecture's nonlinear projection: linear and angular inertia share the move.
    #[default]
    Nonlinear,
}

impl ProjectionMethod {
    pub fn name(self) -> &'static str {
        match self {
            ProjectionMethod::Linear => "linear",
            ProjectionMethod::Nonlinear => "nonlinear",
        }
    }

    pub fn from_name(name: &str) -> Option<Self> {
        [ProjectionMethod::Linear, ProjectionMethod::Nonlinear]
            .into_iter()
            .find(|m| m.name() == name)
    }
}

/// Resolver parameters, each trading one thing for another.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings<T: Real> {
    /// Restitution is forced to 0 below this closing speed: trades bounce
    /// fidelity at low speed for resting contacts that do not vibrate.
    pub velocity_limit: T,
    /// Max angular move as a multiple of |r⊥| in projection: trades
    /// believable rotation for robustness against over-rotation (`inf` = off).
    pub angular_limit: T,
    /// Share of the penetration resolved in one projection, (0, 1]: trades
    /// speed of separation for stability when many contacts touch one body.
    pub relaxation: T,
    /// Last frame's duration, for acceleration compensation.
    pub duration: T,
    /// Linear or nonlinear projection.
    pub projection: ProjectionMethod,
}

impl<T: Real> Default for Settings<T> {
    fn default() -> Self {
        Settings {
            velocity_limit: T::zero(),
            angular_limit: c(0.2),
            relaxation: T::one(),
            duration: c(0.01),
            projection: ProjectionMethod::Nonlinear,
        }
    }
}

/// The contact as the stages see it. `normal` is unit length and points from
/// body 2 toward body 1.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactInput<T: Real> {
    pub point: Vector3<T>,
    pub normal: Vector3<T>,
    pub penetration: T,
    pub restitution: T,
    pub static_friction: T,
    pub dynamic_friction: T,
    pub friction_model: FrictionModel,
    pub settings: Settings<T>,
}

impl<T: Real> ContactInput<T> {
    /// A contact has friction when either coefficient is positive.
    pub fn has_friction(&self) -> bool {
        self.static_friction > T::zero() || self.dynamic_friction > T::zero()
    }
}

/// Everything one contact needs. Slot 0 is body 1, slot 1 is body 2.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem<T: Real> {
    pub bodies: [Option<RigidBody<T>>; 2],
    pub contact: ContactInput<T>,
}

impl<T: Real> Problem<T> {
    /// The sign body i takes in the contact: +1 for body 1, −1 for body 2
    /// (the lecture's (−1)^(i+1)).
    pub fn sign(i: usize) -> T {
        if i == 0 {
            T::one()
        } else {
            -T::one()
        }
    }
}
