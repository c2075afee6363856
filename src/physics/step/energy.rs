//! Energy of a world: kinetic `½ m v·v + ½ ωᵀ I ω` and potential `-m g·x`
//! (zero at the origin), summed over movable bodies.

use nalgebra::Vector3;

use crate::physics::{c, Real, World};

/// Kinetic energy of every movable body.
pub fn kinetic<T: Real>(world: &World<T>) -> T {
    world
        .bodies
        .iter()
        .filter_map(|b| b.dynamic())
        .fold(T::zero(), |sum, b| {
            sum + b.kinetic_energy(&b.velocity, &b.angular_velocity)
        })
}

/// Potential energy in the uniform field `gravity`, zero at the origin.
pub fn potential<T: Real>(world: &World<T>, gravity: &Vector3<T>) -> T {
    world
        .bodies
        .iter()
        .filter_map(|b| b.dynamic())
        .fold(T::zero(), |sum, b| sum - b.mass * gravity.dot(&b.position))
}

/// Total mechanical energy.
pub fn total<T: Real>(world: &World<T>, gravity: &Vector3<T>) -> T {
    kinetic(world) + potential(world, gravity) + c::<T>(0.0)
}
