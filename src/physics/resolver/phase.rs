//! What the position and velocity phases do differently, for the loops that
//! run them ([`super::scan`], [`super::indexed`]): the value that orders the
//! contacts (penetration, desired Δv), taking one contact, and updating a
//! contact that shares a body with it. The loops are written once.

use super::observer::Observer;
use super::position::BodyMoves;
use super::velocity::BodyChanges;
use super::{desired_of, position, velocity, Phase, Resolver, ResolverContact};
use crate::physics::params::RestitutionFrom;
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
    /// Brings contact `j` (`c`) up to date after the taken contact (slots
    /// `taken`) made `change`; returns its value before and after. It reads
    /// only the contact (and the resolver's `restitution_from`), so the loops
    /// can hold the adjacency and the contacts apart.
    fn update<O: Observer<T>>(
        c: &mut ResolverContact<T>,
        j: usize,
        taken: &[Option<usize>; 2],
        change: &Self::Change,
        from: RestitutionFrom,
        obs: &mut O,
    ) -> (T, T);
}

/// The position phase: penetrations, resolved by projection.
pub(super) struct Positions;

impl<T: Real> PhaseWork<T> for Positions {
    const PHASE: Phase = Phase::Position;
    /// The taken contact's body moves, compact (the observer has the full record).
    type Change = BodyMoves<T>;

    fn value(c: &ResolverContact<T>) -> T {
        c.penetration
    }

    fn take<O: Observer<T>>(
        r: &mut Resolver<T>,
        used: usize,
        k: usize,
        penetration: T,
        obs: &mut O,
    ) -> BodyMoves<T> {
        obs.before_position(used, k, &r.bodies);
        if !O::RECORDS {
            // Nothing keeps the record: the compact moves only.
            return position::take_moves(&r.contacts[k], &r.setups[k], penetration, &mut r.bodies);
        }
        let moves = position::take(&r.contacts[k], &r.setups[k], penetration, &mut r.bodies);
        obs.position_taken(used, k, penetration, &moves);
        BodyMoves::of(&moves)
    }

    #[inline(always)]
    fn update<O: Observer<T>>(
        c: &mut ResolverContact<T>,
        j: usize,
        _taken: &[Option<usize>; 2],
        moves: &BodyMoves<T>,
        _from: RestitutionFrom,
        obs: &mut O,
    ) -> (T, T) {
        let from = c.penetration;
        c.penetration = position::penetration_after(c, moves);
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
        if !O::RECORDS {
            // Nothing keeps the impulse record: the compact changes only.
            return velocity::take_changes(&r.contacts[k], &r.setups[k], friction, &mut r.bodies);
        }
        let impulse = velocity::take(&r.contacts[k], &r.setups[k], friction, &mut r.bodies);
        obs.velocity_taken(used, k, desired, &impulse);
        BodyChanges::of(&impulse.slots, &impulse)
    }

    #[inline(always)]
    fn update<O: Observer<T>>(
        c: &mut ResolverContact<T>,
        j: usize,
        _taken: &[Option<usize>; 2],
        changes: &BodyChanges<T>,
        from: RestitutionFrom,
        obs: &mut O,
    ) -> (T, T) {
        let before = c.desired;
        c.velocity = velocity::velocity_after(c, changes);
        c.desired = desired_of(c, from);
        obs.desired_updated(j, before, c.desired);
        (before, c.desired)
    }
}
