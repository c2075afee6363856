//! Integration of one body over a step, as the reference engine does it
//! (`RigidBody::integrate`): last frame's acceleration, velocities, damping
//! as the fraction kept per second, position, orientation, normalise.

use nalgebra::Vector3;

use crate::physics::stages::orientation::add_scaled_rotation;
use crate::physics::{Real, RigidBody};

/// Forces on a body over the step, beyond gravity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Loads<T: Real> {
    pub force: Vector3<T>,
    pub torque: Vector3<T>,
}

impl<T: Real> Default for Loads<T> {
    fn default() -> Self {
        Loads {
            force: Vector3::zeros(),
            torque: Vector3::zeros(),
        }
    }
}

/// Advances `body` by `dt`:
/// `a = g + F/m` (kept as last frame's acceleration), `v += a·dt`,
/// `ω += I⁻¹τ·dt`, `v *= d_lin^dt`, `ω *= d_ang^dt`, `x += v·dt`,
/// `θ += ½[0, ω·dt]θ`, then `θ` normalised.
pub fn integrate<T: Real>(
    body: &mut RigidBody<T>,
    gravity: &Vector3<T>,
    loads: &Loads<T>,
    linear_damping: T,
    angular_damping: T,
    dt: T,
) {
    integrate_velocity(body, gravity, loads, linear_damping, angular_damping, dt);
    integrate_position(body, dt);
}

/// The velocity half of [`integrate`]: `a = g + F/m`, `v += a·dt`,
/// `ω += I⁻¹τ·dt`, then damping.
pub fn integrate_velocity<T: Real>(
    body: &mut RigidBody<T>,
    gravity: &Vector3<T>,
    loads: &Loads<T>,
    linear_damping: T,
    angular_damping: T,
    dt: T,
) {
    let kept = Kept::over(linear_damping, angular_damping, dt);
    integrate_velocity_kept(body, gravity, loads, &kept, dt);
}

/// The fractions of linear and angular velocity damping keeps over a step,
/// `d_lin^dt` and `d_ang^dt` (`None`: no damping, no pow); the same for
/// every body of a step, so a step raises them to the power once.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kept<T: Real> {
    pub linear: Option<T>,
    pub angular: Option<T>,
}

impl<T: Real> Kept<T> {
    pub fn over(linear_damping: T, angular_damping: T, dt: T) -> Self {
        // 1ʸ = 1: no damping, no pow.
        let kept = |d: T| (d != T::one()).then(|| d.powf(dt));
        Kept {
            linear: kept(linear_damping),
            angular: kept(angular_damping),
        }
    }
}

/// [`integrate_velocity`] with the step's damping fractions `kept` already raised.
pub fn integrate_velocity_kept<T: Real>(
    body: &mut RigidBody<T>,
    gravity: &Vector3<T>,
    loads: &Loads<T>,
    kept: &Kept<T>,
    dt: T,
) {
    body.acceleration = gravity + loads.force * body.inverse_mass;
    body.velocity += body.acceleration * dt;
    // Without torque I⁻¹τ is zero: R I⁻¹ Rᵀ is not built (most bodies, most steps).
    if loads.torque != Vector3::zeros() {
        let angular_acceleration = body.inverse_inertia_world() * loads.torque;
        body.angular_velocity += angular_acceleration * dt;
    }
    // Damping as the fraction of velocity kept per second.
    if let Some(k) = kept.linear {
        body.velocity *= k;
    }
    if let Some(k) = kept.angular {
        body.angular_velocity *= k;
    }
}

/// The position half of [`integrate`]: `x += v·dt`, `θ += ½[0, ω·dt]θ`, normalised.
pub fn integrate_position<T: Real>(body: &mut RigidBody<T>, dt: T) {
    body.position += body.velocity * dt;
    let turned = add_scaled_rotation(&body.orientation, &(body.angular_velocity * dt));
    let norm = turned.norm();
    body.orientation = if norm > T::zero() && norm.is_finite() {
        turned / norm
    } else {
        body.orientation
    };
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::{Matrix3, Quaternion};

    fn ball() -> RigidBody<f64> {
        RigidBody {
            mass: 2.0,
            inverse_mass: 0.5,
            inertia_body: Matrix3::identity() * 0.4,
            inverse_inertia_body: Matrix3::identity() * 2.5,
            position: Vector3::new(0.0, 1.0, 0.0),
            orientation: Quaternion::identity(),
            velocity: Vector3::new(1.0, 0.0, 0.0),
            angular_velocity: Vector3::new(0.0, 0.0, 2.0),
            acceleration: Vector3::zeros(),
        }
    }

    #[test]
    fn semi_implicit_euler_with_gravity() {
        let mut b = ball();
        let g = Vector3::new(0.0, -9.81, 0.0);
        integrate(&mut b, &g, &Loads::default(), 1.0, 1.0, 0.1);
        assert_eq!(b.acceleration, g);
        assert!((b.velocity - Vector3::new(1.0, -0.981, 0.0)).norm() < 1e-15);
        // Position uses the new velocity (symplectic Euler, as the reference engine).
        assert!((b.position - Vector3::new(0.1, 1.0 - 0.0981, 0.0)).norm() < 1e-15);
        assert!((b.orientation.norm() - 1.0).abs() < 1e-15);
        // ω·dt = 0.2 rad about z: the small-angle update turns by about 0.2 rad.
        let angle = 2.0 * b.orientation.k.atan2(b.orientation.w);
        assert!((angle - 0.2).abs() < 2e-3, "{angle}");
    }

    #[test]
    fn damping_is_the_fraction_kept_per_second() {
        let mut b = ball();
        // Ten steps of 0.1 s with d = 0.5 keep half the speed after one second.
        for _ in 0..10 {
            integrate(&mut b, &Vector3::zeros(), &Loads::default(), 0.5, 0.25, 0.1);
        }
        assert!((b.velocity.x - 0.5).abs() < 1e-12);
        assert!((b.angular_velocity.z - 0.5).abs() < 1e-12);
    }

    #[test]
    fn the_kept_fractions_raised_once_per_step_are_the_damping_to_the_bit() {
        let kept = Kept::over(0.5, 0.25, 0.1);
        assert_eq!(kept.linear, Some(0.5f64.powf(0.1)));
        assert_eq!(Kept::over(1.0, 0.25, 0.1).linear, None);
        let g = Vector3::new(0.0, -9.81, 0.0);
        let (mut a, mut b) = (ball(), ball());
        // What a step's bodies share: the same numbers as each raising its own.
        let loads = Loads::default();
        integrate_velocity_kept(&mut a, &g, &loads, &kept, 0.1);
        let (lin, ang) = (0.5f64, 0.25f64);
        b.velocity = (b.velocity + g * 0.1) * lin.powf(0.1);
        b.angular_velocity *= ang.powf(0.1);
        assert_eq!(a.velocity, b.velocity);
        assert_eq!(a.angular_velocity, b.angular_velocity);
    }

    #[test]
    fn a_force_adds_to_gravity_in_last_frames_acceleration() {
        let mut b = ball();
        let loads = Loads {
            force: Vector3::new(4.0, 0.0, 0.0),
            torque: Vector3::new(0.0, 0.0, 1.0),
        };
        integrate(
            &mut b,
            &Vector3::new(0.0, -10.0, 0.0),
            &loads,
            1.0,
            1.0,
            0.5,
        );
        assert_eq!(b.acceleration, Vector3::new(2.0, -10.0, 0.0));
        assert!((b.angular_velocity.z - (2.0 + 2.5 * 0.5)).abs() < 1e-12);
    }
}
