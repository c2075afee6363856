//! What the resolver reports while it works: an [`Observer`] whose methods do
//! nothing by default, so the fast path ([`Silent`]) builds nothing and
//! allocates nothing. The trace's recording observer implements it.

use super::{Phase, PhaseOutcome, ResolverBody};
use crate::physics::stages::{BodyProjection, BodyVelocityChange, FrictionRegime};
use crate::physics::Real;
use nalgebra::Vector3;

/// The moves one position iteration applied: per slot of the taken contact,
/// the stage record of the nonlinear projection (`position` is the body's new position).
#[derive(Debug, Clone, PartialEq)]
pub struct PositionMoves<T: Real> {
    /// The resolver body of each slot (`None`: the world or an immovable body).
    pub slots: [Option<usize>; 2],
    pub bodies: [Option<BodyProjection<T>>; 2],
    /// New orientation of each moved body (normalised), where it turned.
    pub orientations: [Option<nalgebra::Quaternion<T>>; 2],
}

/// The impulse one velocity iteration applied.
#[derive(Debug, Clone, PartialEq)]
pub struct VelocityImpulse<T: Real> {
    /// The resolver body of each slot (`None`: the world or an immovable body).
    pub slots: [Option<usize>; 2],
    /// The impulse applied, contact space (after any friction clamp).
    pub impulse_contact: Vector3<T>,
    pub impulse_world: Vector3<T>,
    /// Stick or slide, for a contact with friction.
    pub regime: Option<FrictionRegime>,
    /// Per slot of the taken contact: the stage record of the velocity change.
    pub bodies: [Option<BodyVelocityChange<T>>; 2],
}

/// Receives each iteration of the resolver. Every method does nothing unless
/// overridden; contacts are numbered in file order.
pub trait Observer<T: Real> {
    /// Whether the observer keeps what it is told: when false (the fast
    /// path, [`Silent`]), the resolver skips work done only for the reports.
    const RECORDS: bool = true;
    /// Called before position iteration `iteration` takes `contact`, with the
    /// bodies as they are at that moment.
    fn before_position(&mut self, _iteration: usize, _contact: usize, _bodies: &[ResolverBody<T>]) {
    }
    /// Position iteration `iteration` took `contact` at `penetration` and moved its bodies.
    fn position_taken(
        &mut self,
        _iteration: usize,
        _contact: usize,
        _penetration: T,
        _moves: &PositionMoves<T>,
    ) {
    }
    /// The penetration of `contact` (the taken one included) went from `from` to `to`.
    fn penetration_updated(&mut self, _contact: usize, _from: T, _to: T) {}
    /// Called before velocity iteration `iteration` takes `contact`.
    fn before_velocity(&mut self, _iteration: usize, _contact: usize, _bodies: &[ResolverBody<T>]) {
    }
    /// Velocity iteration `iteration` took `contact` at desired Δv `desired`.
    fn velocity_taken(
        &mut self,
        _iteration: usize,
        _contact: usize,
        _desired: T,
        _impulse: &VelocityImpulse<T>,
    ) {
    }
    /// The desired Δv of `contact` (the taken one included) went from `from` to `to`.
    fn desired_updated(&mut self, _contact: usize, _from: T, _to: T) {}
    /// A phase ended.
    fn phase_end(&mut self, _phase: Phase, _outcome: &PhaseOutcome<T>) {}
    /// A time step is about to resolve `world` (its contacts generated, its
    /// velocities integrated) with `resolver`, prepared (and warm-started
    /// where it is); called by the stepper, not the resolver.
    fn resolving(&mut self, _world: &crate::physics::World<T>, _resolver: &super::Resolver<T>) {}
}

/// The observer of the fast path: reports go nowhere.
#[derive(Debug, Clone, Copy, Default)]
pub struct Silent;

impl<T: Real> Observer<T> for Silent {
    const RECORDS: bool = false;
}
