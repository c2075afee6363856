//! Rolling back time instead of projecting ("Lecture IV Collisions": why not
//! just roll back time?). With `rollback = "rollback"`, a pair the step
//! finds interpenetrating deeper than the position epsilon and closing is
//! moved back along its motion to its time of collision, instead of being
//! projected apart by the position phase: each contact of the pair gives
//! τ = penetration / closing speed (the time since its surfaces met: exact
//! for a body moving straight, an estimate when it turns), the pair takes
//! the largest τ (at most Δt), and each moving body of it goes back by the
//! largest τ of its pairs: x ← x − v τ, q ← exp(−ω τ) q. Then the contacts
//! are generated again where the bodies now are (the rolled-back pairs
//! just touch; the velocity phase bounces them as usual).
//!
//! What it costs: the rolled-back bodies lose τ of motion (the rest of the
//! world does not roll back; the pair is late by τ), and a body rolled back
//! against gravity gains m g·v τ of potential energy. A pair that is not
//! closing (resting, or separating already) has no time of collision to go
//! back to and is projected as before.

use nalgebra::UnitQuaternion;

use crate::physics::{Real, World};

/// Moves the closing, penetrating pairs of `world`'s contacts back to their
/// time of collision (module docs); `moving(i)` says whether body i moves
/// this step. Returns how many bodies were moved.
pub fn roll_back<T: Real>(
    world: &mut World<T>,
    moving: impl Fn(usize) -> bool,
    epsilon: T,
    dt: T,
    back: &mut Vec<T>,
) -> usize {
    back.clear();
    back.resize(world.bodies.len(), T::zero());
    for k in &world.contacts {
        let pen = k.input.penetration;
        if pen <= epsilon {
            continue;
        }
        let v = |id: Option<crate::physics::BodyId>| {
            id.map_or(nalgebra::Vector3::zeros(), |id| {
                let b = &world.body(id).state;
                b.point_velocity(&(k.input.point - b.position))
            })
        };
        let closing = -(v(Some(k.body1)) - v(k.body2)).dot(&k.input.normal);
        if closing <= T::zero() {
            continue;
        }
        let tau = (pen / closing).min(dt);
        for id in k.slots().into_iter().flatten() {
            if moving(id.0) && tau > back[id.0] {
                back[id.0] = tau;
            }
        }
    }
    let mut moved = 0;
    for (body, tau) in world.bodies.iter_mut().zip(back.iter()) {
        if *tau > T::zero() {
            let s = &mut body.state;
            s.position -= s.velocity * *tau;
            let turn = UnitQuaternion::from_scaled_axis(-s.angular_velocity * *tau);
            let q = turn * UnitQuaternion::new_normalize(s.orientation);
            s.orientation = q.into_inner();
            moved += 1;
        }
    }
    moved
}
