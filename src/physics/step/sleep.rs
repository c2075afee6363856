//! Sleep, as the lecture teaches it: per body a recency-weighted average of
//! the motion `v·v + ω·ω` with bias `0.5^dt` (a 1 s half-life at any frame
//! rate); below `epsilon` the body sleeps and its velocities are zeroed, and
//! the average is clamped to `10·epsilon` so a fast body can fall asleep soon
//! after it stops. The alternative the best engines use sleeps whole islands
//! of touching bodies once every body in the island has been slow for a while.

use crate::physics::{c, Real, RigidBody};

pub use crate::physics::params::SleepMode;

/// One body's sleep bookkeeping.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SleepState<T: Real> {
    pub awake: bool,
    /// Recency-weighted average of `v·v + ω·ω`.
    pub motion: T,
    /// Seconds the body has been continuously below `epsilon` (island mode).
    pub slow_for: T,
}

impl<T: Real> SleepState<T> {
    /// A body that has just been woken: its average starts at 2·epsilon so
    /// it does not fall straight back to sleep.
    pub fn awake(epsilon: T) -> Self {
        SleepState {
            awake: true,
            motion: epsilon * c(2.0),
            slow_for: T::zero(),
        }
    }

    pub fn wake(&mut self, epsilon: T) {
        *self = Self::awake(epsilon);
    }
}

/// `v·v + ω·ω`, the motion of one body now.
pub fn current_motion<T: Real>(body: &RigidBody<T>) -> T {
    body.velocity.dot(&body.velocity) + body.angular_velocity.dot(&body.angular_velocity)
}

/// Updates the average after a step of `dt` (lecture: "recency-weighted
/// average", bias `0.5^dt`); returns true when the body should fall asleep.
pub fn update_motion<T: Real>(
    state: &mut SleepState<T>,
    body: &RigidBody<T>,
    epsilon: T,
    dt: T,
) -> bool {
    let now = current_motion(body);
    let bias = c::<T>(0.5).powf(dt);
    state.motion = bias * state.motion + (T::one() - bias) * now;
    state.slow_for = if now < epsilon {
        state.slow_for + dt
    } else {
        T::zero()
    };
    if state.motion < epsilon {
        return true;
    }
    let cap = epsilon * c(10.0);
    if state.motion > cap {
        state.motion = cap;
    }
    false
}

/// Puts a body to sleep: velocities and last frame's acceleration zeroed.
pub fn put_to_sleep<T: Real>(state: &mut SleepState<T>, body: &mut RigidBody<T>) {
    state.awake = false;
    body.velocity.fill(T::zero());
    body.angular_velocity.fill(T::zero());
    body.acceleration.fill(T::zero());
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::world::groups;
    use nalgebra::{Matrix3, Quaternion, Vector3};

    fn body(speed: f64) -> RigidBody<f64> {
        RigidBody {
            mass: 1.0,
            inverse_mass: 1.0,
            inertia_body: Matrix3::identity(),
            inverse_inertia_body: Matrix3::identity(),
            position: Vector3::zeros(),
            orientation: Quaternion::identity(),
            velocity: Vector3::new(speed, 0.0, 0.0),
            angular_velocity: Vector3::zeros(),
            acceleration: Vector3::new(0.0, -9.81, 0.0),
        }
    }

    #[test]
    fn the_average_has_a_one_second_half_life_at_any_frame_rate() {
        for dt in [1.0_f64 / 30.0, 1.0 / 60.0, 1.0 / 240.0] {
            let mut s = SleepState {
                awake: true,
                motion: 1.0,
                slow_for: 0.0,
            };
            let still = body(0.0);
            let steps = (1.0 / dt).round() as usize;
            for _ in 0..steps {
                update_motion(&mut s, &still, 0.2, dt);
            }
            assert!((s.motion - 0.5).abs() < 1e-9, "dt {dt}: {}", s.motion);
        }
    }

    #[test]
    fn a_body_falls_asleep_below_epsilon_and_the_average_is_clamped() {
        let mut s = SleepState::awake(0.3);
        assert_eq!(s.motion, 0.6);
        // Fast: clamped to 10 ε.
        assert!(!update_motion(&mut s, &body(100.0), 0.3, 0.1));
        assert_eq!(s.motion, 3.0);
        // Still: decays below ε in a few seconds.
        let mut steps = 0;
        while !update_motion(&mut s, &body(0.0), 0.3, 0.1) {
            steps += 1;
        }
        // 3.0 · 0.5^t < 0.3 ⇒ t > log2(10) = 3.32 s.
        assert_eq!(steps + 1, 34);
        let mut b = body(0.01);
        put_to_sleep(&mut s, &mut b);
        assert!(!s.awake && b.velocity == Vector3::zeros() && b.acceleration == Vector3::zeros());
    }

    #[test]
    fn islands_join_bodies_through_chains_of_contacts() {
        let roots = groups(6, [(0, 1), (1, 2), (4, 5)].into_iter());
        assert_eq!(roots, vec![0, 0, 0, 3, 4, 4]);
        assert_eq!(groups(3, std::iter::empty()), vec![0, 1, 2]);
    }
}
