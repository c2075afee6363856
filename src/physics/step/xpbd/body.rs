//! XPBD's working bodies: each world body's pose and velocities, its pose
//! at the substep's start, and its inverse mass and world inverse inertia
//! (zero for a body that does not move this step).

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};

use crate::physics::stages::orientation::add_scaled_rotation;
use crate::physics::step::integrate::Kept;
use crate::physics::{c, Real, World};

#[derive(Debug, Clone)]
pub(super) struct XBody<T: Real> {
    pub moving: bool,
    pub inverse_mass: T,
    inverse_inertia_body: Matrix3<T>,
    /// The world inverse inertia at the current orientation.
    pub inverse_inertia: Matrix3<T>,
    pub x: Vector3<T>,
    pub q: Quaternion<T>,
    pub v: Vector3<T>,
    pub w: Vector3<T>,
    pub x_prev: Vector3<T>,
    pub q_prev: Quaternion<T>,
}

impl<T: Real> XBody<T> {
    /// The rotation of orientation `q`.
    pub fn rotation_of(q: &Quaternion<T>) -> Matrix3<T> {
        UnitQuaternion::new_unchecked(*q)
            .to_rotation_matrix()
            .into_inner()
    }

    fn refresh_inertia(&mut self) {
        if self.moving {
            let r = Self::rotation_of(&self.q);
            self.inverse_inertia = r * self.inverse_inertia_body * r.transpose();
        }
    }

    /// The generalized inverse mass of a push along `dir` at arm `r`:
    /// m⁻¹ + (r × dir)ᵀ I⁻¹ (r × dir) (0 for a body that does not move).
    pub fn w(&self, r: &Vector3<T>, dir: &Vector3<T>) -> T {
        if !self.moving {
            return T::zero();
        }
        let rn = r.cross(dir);
        self.inverse_mass + rn.dot(&(self.inverse_inertia * rn))
    }

    /// Moves the pose by the positional impulse `p` at arm `r` (sign: +1 or −1).
    pub fn push(&mut self, r: &Vector3<T>, p: &Vector3<T>, sign: T) {
        if !self.moving {
            return;
        }
        self.x += p * (self.inverse_mass * sign);
        let turn = self.inverse_inertia * r.cross(p) * sign;
        let q = add_scaled_rotation(&self.q, &turn);
        let norm = q.norm();
        if norm > T::zero() && norm.is_finite() {
            self.q = q / norm;
        }
    }

    /// Changes the velocities by the impulse `p` at arm `r` (sign: +1 or −1).
    pub fn kick(&mut self, r: &Vector3<T>, p: &Vector3<T>, sign: T) {
        if !self.moving {
            return;
        }
        self.v += p * (self.inverse_mass * sign);
        self.w += self.inverse_inertia * r.cross(p) * sign;
    }

    /// The velocity of the point at arm `r`.
    pub fn point_velocity(&self, r: &Vector3<T>) -> Vector3<T> {
        self.v + self.w.cross(r)
    }
}

/// Every world body, by index.
#[derive(Debug, Clone)]
pub(super) struct Bodies<T: Real>(pub Vec<XBody<T>>);

impl<T: Real> Bodies<T> {
    pub fn of_world(world: &World<T>, moving: &[bool]) -> Self {
        Bodies(
            (world.bodies.iter().enumerate())
                .map(|(i, b)| {
                    let s = &b.state;
                    let moving = b.movable && moving.get(i).copied().unwrap_or(false);
                    let mut x = XBody {
                        moving,
                        inverse_mass: if moving { s.inverse_mass } else { T::zero() },
                        inverse_inertia_body: s.inverse_inertia_body,
                        inverse_inertia: Matrix3::zeros(),
                        x: s.position,
                        q: s.orientation,
                        v: if moving { s.velocity } else { Vector3::zeros() },
                        w: if moving {
                            s.angular_velocity
                        } else {
                            Vector3::zeros()
                        },
                        x_prev: s.position,
                        q_prev: s.orientation,
                    };
                    x.refresh_inertia();
                    x
                })
                .collect(),
        )
    }

    /// The substep's integration: velocities under gravity and damping,
    /// then the predicted pose (the start kept as the previous pose).
    pub fn predict(&mut self, gravity: &Vector3<T>, kept: &Kept<T>, h: T) {
        for b in self.0.iter_mut().filter(|b| b.moving) {
            b.x_prev = b.x;
            b.q_prev = b.q;
            b.v += gravity * h;
            if let Some(k) = kept.linear {
                b.v *= k;
            }
            if let Some(k) = kept.angular {
                b.w *= k;
            }
            b.x += b.v * h;
            let q = add_scaled_rotation(&b.q, &(b.w * h));
            let norm = q.norm();
            if norm > T::zero() && norm.is_finite() {
                b.q = q / norm;
            }
            b.refresh_inertia();
        }
    }

    /// v = (x − x_prev)/h, ω = 2 vec(q q_prev⁻¹)/h (the shorter way round).
    pub fn velocities_from_positions(&mut self, h: T) {
        let two: T = c(2.0);
        for b in self.0.iter_mut().filter(|b| b.moving) {
            b.v = (b.x - b.x_prev) / h;
            let dq = b.q * b.q_prev.conjugate();
            let spin = Vector3::new(dq.i, dq.j, dq.k) * (two / h);
            b.w = if dq.w >= T::zero() { spin } else { -spin };
            b.refresh_inertia();
        }
    }

    /// Writes the moving bodies' poses and velocities into `world`.
    pub fn write_back(&self, world: &mut World<T>, gravity: &Vector3<T>) {
        for (b, body) in self.0.iter().zip(world.bodies.iter_mut()) {
            if b.moving {
                let s = &mut body.state;
                s.position = b.x;
                s.orientation = b.q;
                s.velocity = b.v;
                s.angular_velocity = b.w;
                s.acceleration = *gravity;
            }
        }
    }
}
