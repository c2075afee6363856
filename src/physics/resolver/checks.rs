//! What a resolved scene is checked against: the linear momentum of the
//! bodies that touch nothing immovable (impulses between them are internal,
//! so Σ m v must not change), the kinetic energy before and after, and the
//! penetration and closing velocity the resolver's bookkeeping leaves.

use nalgebra::Vector3;

use super::Resolver;
use crate::physics::causes::tolerance;
use crate::physics::{BodyId, Real, World};

#[derive(Debug, Clone, PartialEq)]
pub struct SceneChecks<T: Real> {
    /// Movable bodies whose contacts (through other bodies) never reach the
    /// world or an immovable body, in body order.
    pub free_bodies: Vec<BodyId>,
    /// Σ m v of the free bodies, before and after.
    pub momentum_before: Vector3<T>,
    pub momentum_after: Vector3<T>,
    /// |after - before| / (Σ m|v| before + Σ m|v| after), 0 without free bodies.
    pub momentum_error: T,
    pub momentum_conserved: bool,
    /// Kinetic energy of every movable body.
    pub energy_before: T,
    pub energy_after: T,
    /// True unless the energy rose by more than round-off.
    pub energy_not_gained: bool,
    /// The deepest bookkeeping penetration left, and its contact.
    pub penetration_left: (T, usize),
    /// The largest closing speed left (-v_s, 0 when every contact separates), and its contact.
    pub closing_left: (T, usize),
}

/// Checks the resolver's result against the world it was prepared from.
pub fn scene_checks<T: Real>(before: &World<T>, resolver: &Resolver<T>) -> SceneChecks<T> {
    let n = before.bodies.len();
    // Node n stands for the world: a contact with one body links it there.
    let links = before.contacts.iter().map(|c| {
        let a = c.body1.0;
        let b = c.body2.map_or(n, |b| b.0);
        (a, b)
    });
    let root = crate::physics::world::groups(n + 1, links);
    let anchored: Vec<bool> = (0..=n)
        .map(|i| root[i] == root[n] || (i < n && !before.bodies[i].movable))
        .collect();
    // A group is anchored when any member is the world or immovable.
    let mut group_anchored = vec![false; n + 1];
    for i in 0..=n {
        if anchored[i] {
            group_anchored[root[i]] = true;
        }
    }
    let free_bodies: Vec<BodyId> = (0..n)
        .filter(|&i| before.bodies[i].movable && !group_anchored[root[i]])
        .map(BodyId)
        .collect();

    let mut momentum_before = Vector3::zeros();
    let mut momentum_after = Vector3::zeros();
    let mut scale = T::zero();
    let mut energy_before = T::zero();
    let mut energy_after = T::zero();
    for b in &resolver.bodies {
        let state = &before.body(b.id).state;
        energy_before += state.kinetic_energy(&state.velocity, &state.angular_velocity);
        let mut moved = state.clone();
        moved.orientation = b.orientation;
        energy_after += moved.kinetic_energy(&b.velocity, &b.angular_velocity);
        if free_bodies.contains(&b.id) {
            momentum_before += state.velocity * state.mass;
            momentum_after += b.velocity * state.mass;
            scale += (state.velocity.norm() + b.velocity.norm()) * state.mass;
        }
    }
    let momentum_error = if scale > T::zero() {
        (momentum_after - momentum_before).norm() / scale
    } else {
        T::zero()
    };
    let tol = tolerance::<T>();
    let closing = resolver
        .contacts
        .iter()
        .enumerate()
        .fold((T::zero(), 0), |best, (k, c)| {
            if -c.velocity.x > best.0 {
                (-c.velocity.x, k)
            } else {
                best
            }
        });
    let penetration = resolver.max(super::Phase::Position);
    SceneChecks {
        momentum_conserved: momentum_error <= tol,
        free_bodies,
        momentum_before,
        momentum_after,
        momentum_error,
        energy_not_gained: energy_after <= energy_before * (T::one() + tol) + tol,
        energy_before,
        energy_after,
        penetration_left: (penetration.0, penetration.1),
        closing_left: closing,
    }
}
