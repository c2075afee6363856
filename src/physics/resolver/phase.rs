//! What the position and velocity phases do differently, for the loops that
//! run them ([`super::scan`], [`super::indexed`]): the value that orders the
//! contacts (penetration, desired Δv), taking one contact, and updating a
//! contact that shares a body with it. The loops are written once.

use super::observer::{Observer, PositionMoves};
use super::velocity::BodyChanges;
use super::{desired_of, position, velocity, Phase, Resolver, ResolverContact};
use crate::physics::Real;

pub(super) trait PhaseWork<T: Real> {
    const PHASE: Phase;
    /// What taking a contact changed (its bodies' moves or velocity changes).
    type Change;
    /// The value the phase orders contacts by.
    fn value(c: &ResolverContact<T>) -> T;
    /// Iteration `used` takes contact `k` at `value`: changes its bodies.
    fn take<O: Observer<T>>(
        r: &mut Resolver<T>,
        used: usize,
        k: usize,
        value: T,
        obs: &mut O,
    ) -> Self::Change;
    /// Brings contact `j` up to date after the taken contact (slots `taken`)
    /// made `change`; returns its value before and after.
    fn update<O: Observer<T>>(
        r: &mut Resolver<T>,
        j: usize,
        taken: &[Option<usize>; 2],
        change: &Self::Change,
        obs: &mut O,
    ) -> (T, T);
}

/// The position phase: penetrations, resolved by projection.
pub(super) struct Positions;

impl<T: Real> PhaseWork<T> for Positions {
    const PHASE: Phase = Phase::Position;
    type Change = PositionMoves<T>;

    fn value(c: &ResolverContact<T>) -> T {
        c.penetration
    }

    fn take<O: Observer<T>>(
        r: &mut Resolver<T>,
        used: usize,
        k: usize,
        penetration: T,
        obs: &mut O,
    ) -> PositionMoves<T> {
        obs.before_position(used, k, &r.bodies);
        let moves = position::take(&r.contacts[k], &r.setups[k], penetration, &mut r.bodies);
        obs.position_taken(used, k, penetration, &moves);
        moves
    }

    fn update<O: Observer<T>>(
        r: &mut Resolver<T>,
        j: usize,
        taken: &[Option<usize>; 2],
        moves: &PositionMoves<T>,
        obs: &mut O,
    ) -> (T, T) {
        let c = &mut r.contacts[j];
        let from = c.penetration;
        c.penetration = position::updated_penetration(c, taken, moves);
        obs.penetration_updated(j, from, c.penetration);
        (from, c.penetration)
    }
}

/// The velocity phase: desired Δv, resolved by impulses.
pub(super) struct Velocities;

impl<T: Real> PhaseWork<T> for Velocities {
    const PHASE: Phase = Phase::Velocity;
    /// The taken contact's body changes, compact (the observer has the full record).
    type Change = BodyChanges<T>;

    fn value(c: &ResolverContact<T>) -> T {
        c.desired
    }

    fn take<O: Observer<T>>(
        r: &mut Resolver<T>,
        used: usize,
        k: usize,
        desired: T,
        obs: &mut O,
    ) -> BodyChanges<T> {
        obs.before_velocity(used, k, &r.bodies);
        let friction = r.setups[k].friction.map(|f| &r.friction[f]);
        let impulse = velocity::take(&r.contacts[k], &r.setups[k], friction, &mut r.bodies);
        obs.velocity_taken(used, k, desired, &impulse);
        BodyChanges::of(&impulse.slots, &impulse)
    }

    #[inline(always)]
    fn update<O: Observer<T>>(
        r: &mut Resolver<T>,
        j: usize,
        _taken: &[Option<usize>; 2],
        changes: &BodyChanges<T>,
        obs: &mut O,
    ) -> (T, T) {
        let from = r.params.restitution_from;
        let c = &mut r.contacts[j];
        let before = c.desired;
        c.velocity = velocity::velocity_after(c, changes);
        c.desired = desired_of(c, from);
        obs.desired_updated(j, before, c.desired);
        (before, c.desired)
    }
}
