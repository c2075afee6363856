//! Each movable body's world inertia `R I Rᵀ` and kinetic energy
//! `½ m v·v + ½ ωᵀ I ω` as a step's end computes them (its report's kinetic
//! energy), kept for the next step's start (the blow-up rule and the energy
//! audits read the same numbers there): between the two nothing moves the
//! bodies, so the start takes them instead of computing them again. Each is
//! kept with the body's state it was computed from (orientation, body
//! inertia, mass, velocities), and taken only where the body holds that
//! state bit for bit: a world edited between the steps computes afresh.

use nalgebra::{Matrix3, Quaternion, Vector3};

use crate::physics::{to_f64, Real, RigidBody, World};

/// What one body's inertia and energy were computed from, and them.
#[derive(Debug, Clone, PartialEq)]
struct Kept<T: Real> {
    orientation: Quaternion<T>,
    inertia_body: Matrix3<T>,
    mass: T,
    velocity: Vector3<T>,
    angular_velocity: Vector3<T>,
    /// `R I Rᵀ` and the kinetic energy.
    inertia: Matrix3<T>,
    energy: T,
}

/// The last step's end, by body (`None`: immovable, or nothing kept).
#[derive(Debug, Clone)]
pub struct KeptEnergy<T: Real> {
    bodies: Vec<Option<Kept<T>>>,
}

impl<T: Real> Default for KeptEnergy<T> {
    fn default() -> Self {
        KeptEnergy { bodies: Vec::new() }
    }
}

/// Where `a` and `b` differ, as the OR of their bits' XOR (0: the same
/// bits, a NaN included; `-0` and `0` differ).
fn differ<T: Real>(a: &[T], b: &[T]) -> u64 {
    let bits = |x: &T| to_f64(*x).to_bits();
    a.iter().zip(b).fold(0, |d, (x, y)| d | (bits(x) ^ bits(y)))
}

impl<T: Real> KeptEnergy<T> {
    /// Body `i`'s world inertia and kinetic energy, kept for the state `s`
    /// holds now, if any.
    pub fn of(&self, i: usize, s: &RigidBody<T>) -> Option<(Matrix3<T>, T)> {
        let k = self.bodies.get(i)?.as_ref()?;
        let d = differ(
            s.orientation.coords.as_slice(),
            k.orientation.coords.as_slice(),
        ) | differ(s.velocity.as_slice(), k.velocity.as_slice())
            | differ(s.angular_velocity.as_slice(), k.angular_velocity.as_slice())
            | differ(&[s.mass], &[k.mass])
            | differ(s.inertia_body.as_slice(), k.inertia_body.as_slice());
        (d == 0).then_some((k.inertia, k.energy))
    }

    /// Forgets everything kept.
    pub fn clear(&mut self) {
        self.bodies.clear();
    }

    /// The kinetic energy of `world`'s movable bodies, as
    /// [`super::energy::kinetic`] sums it (the same operations in the same
    /// order), each body's `R I Rᵀ` and energy kept with its state.
    pub fn kinetic(&mut self, world: &World<T>) -> T {
        self.bodies.clear();
        let mut sum = T::zero();
        for b in &world.bodies {
            let Some(s) = b.dynamic() else {
                self.bodies.push(None);
                continue;
            };
            let inertia = s.inertia_world();
            let energy = s.kinetic_energy_with(&inertia, &s.velocity, &s.angular_velocity);
            sum += energy;
            self.bodies.push(Some(Kept {
                orientation: s.orientation,
                inertia_body: s.inertia_body,
                mass: s.mass,
                velocity: s.velocity,
                angular_velocity: s.angular_velocity,
                inertia,
                energy,
            }));
        }
        sum
    }
}
