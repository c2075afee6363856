//! Waking and sleeping over a step's contacts: a sleeper an awake body
//! presses on wakes (with its island in island mode), a sleeper the
//! resolution moved through a contact with an awake body wakes, and a body
//! that touches something and has been slow long enough falls asleep
//! (sleep.rs holds the lecture's per-body bookkeeping). Every wake names
//! its cause; a sleeper's contacts with immovable bodies and other
//! sleepers never wake it.

use nalgebra::Vector3;

use super::report::{Event, WakeCause};
use super::sleep::{put_to_sleep, update_motion, SleepMode, SleepState};
use crate::physics::params::SimParams;
use crate::physics::world::groups;
use crate::physics::{c, BodyId, Contact, Real, World};

/// The velocity of body 1's material point at the contact relative to
/// body 2's (lecture eq. A for each body).
#[inline]
pub(super) fn relative_point_velocity<T: Real>(world: &World<T>, k: &Contact<T>) -> Vector3<T> {
    let v = |id: BodyId| {
        let b = &world.body(id).state;
        b.point_velocity(&(k.input.point - b.position))
    };
    // Without a body 2 its velocity is zero (subtracted all the same).
    let v2 = k.body2.map_or(Vector3::zeros(), v);
    v(k.body1) - v2
}

/// A contact between an awake and a sleeping movable body that the
/// resolver will act on (penetrating beyond the position epsilon, or
/// closing faster than the velocity epsilon) wakes the sleeper, as the
/// reference engine wakes the bodies of a contact it resolves; the world
/// wakes nobody.
pub(super) fn wake_touched<T: Real>(
    world: &World<T>,
    params: &SimParams<T>,
    sleep: &mut [SleepState<T>],
    events: &mut Vec<Event>,
) {
    let eps = params.sleep.epsilon;
    let (pen_eps, vel_eps) = (
        c::<T>(params.resolver.position_epsilon),
        c::<T>(params.resolver.velocity_epsilon),
    );
    // Each sleeper to wake and the awake body that presses on it.
    let mut woken: Vec<(BodyId, BodyId)> = Vec::new();
    for k in &world.contacts {
        let Some(b2) = k.body2.filter(|b| world.body(*b).movable) else {
            continue;
        };
        let (a, b) = (sleep[k.body1.0].awake, sleep[b2.0].awake);
        let acts = k.input.penetration > pen_eps
            || -relative_point_velocity(world, k).dot(&k.input.normal) > vel_eps;
        if a != b && acts {
            woken.push(if a { (b2, k.body1) } else { (k.body1, b2) });
        }
    }
    if params.sleep.mode == SleepMode::Island && !woken.is_empty() {
        let roots = contact_islands(world);
        let asleep: Vec<(usize, BodyId)> = woken.iter().map(|(b, by)| (roots[b.0], *by)).collect();
        for (i, r) in roots.iter().enumerate() {
            let through = asleep.iter().find(|(root, _)| root == r);
            if let (Some((_, by)), false) = (through, sleep[i].awake) {
                woken.push((BodyId(i), *by));
            }
        }
    }
    for (id, by) in woken {
        if !sleep[id.0].awake {
            sleep[id.0].wake(eps);
            let cause = WakeCause::Touched { by };
            events.push(Event::Wakes { body: id, cause });
        }
    }
}

/// A sleeper the resolver changed (its velocity is no longer a sleeper's
/// zero) through a contact it shares with an awake body is awake, as the
/// reference engine wakes the bodies of every contact it takes; asleep, it
/// would carry that velocity without moving, and its contacts would read
/// it. The event names that contact. A sleeper whose contacts are all with
/// immovable bodies or other sleepers is at rest by definition: what the
/// resolver gave it there (a warm-start impulse, a solver's push-out
/// speed, the round-off of resting contacts) is taken back and it sleeps on.
pub(super) fn wake_changed<T: Real>(
    world: &mut World<T>,
    sleep: &mut [SleepState<T>],
    epsilon: T,
    events: &mut Vec<Event>,
) {
    for i in 0..world.bodies.len() {
        let body = &world.bodies[i];
        let moved = body.state.velocity != Vector3::zeros()
            || body.state.angular_velocity != Vector3::zeros();
        if !body.movable || sleep[i].awake || !moved {
            continue;
        }
        match shared_with_awake(world, sleep, BodyId(i)) {
            Some((contact, with)) => {
                sleep[i].wake(epsilon);
                let cause = WakeCause::Impulse { contact, with };
                events.push(Event::Wakes {
                    body: BodyId(i),
                    cause,
                });
            }
            None => {
                let s = &mut world.bodies[i].state;
                s.velocity.fill(T::zero());
                s.angular_velocity.fill(T::zero());
            }
        }
    }
}

/// The first of this step's contacts between `body` and an awake movable
/// body, and that body.
fn shared_with_awake<T: Real>(
    world: &World<T>,
    sleep: &[SleepState<T>],
    body: BodyId,
) -> Option<(usize, BodyId)> {
    let awake = |b: BodyId| world.body(b).movable && sleep[b.0].awake;
    world.contacts.iter().enumerate().find_map(|(n, k)| {
        let other = match k.body2 {
            Some(b2) if k.body1 == body => b2,
            Some(b2) if b2 == body => k.body1,
            _ => return None,
        };
        awake(other).then_some((n, other))
    })
}

/// Island roots of the movable bodies, joined by this step's contacts (a
/// contact with the world or an immovable body joins nothing).
fn contact_islands<T: Real>(world: &World<T>) -> Vec<usize> {
    let links = world.contacts.iter().filter_map(|k| {
        let b2 = k.body2?;
        (world.body(k.body1).movable && world.body(b2).movable).then_some((k.body1.0, b2.0))
    });
    groups(world.bodies.len(), links)
}

/// Sleep after the step. A body falls asleep only while it touches
/// something (one of this step's contacts, the margin included): sleep
/// is for resting contacts, and a body in flight or coasting in free
/// space is not resting however slowly it moves. In island mode an
/// island needs every body slow for at least one step and `island_time`.
pub(super) fn update_sleep<T: Real>(
    world: &mut World<T>,
    params: &SimParams<T>,
    sleep: &mut [SleepState<T>],
    events: &mut Vec<Event>,
) {
    let p = params.sleep;
    let dt = params.dt;
    let n = world.bodies.len();
    let mut touching = vec![false; n];
    for k in &world.contacts {
        touching[k.body1.0] = true;
        if let Some(b) = k.body2 {
            touching[b.0] = true;
        }
    }
    let mut falls = vec![false; n];
    for (i, (body, state)) in world.bodies.iter().zip(sleep.iter_mut()).enumerate() {
        if body.movable && state.awake {
            falls[i] = update_motion(state, &body.state, p.epsilon, dt) && touching[i];
        }
    }
    if p.mode == SleepMode::Island {
        let roots = contact_islands(world);
        let long_enough = if p.island_time > dt {
            p.island_time
        } else {
            dt
        };
        let mut ready = vec![true; n];
        for i in 0..n {
            let (b, s) = (&world.bodies[i], &sleep[i]);
            if b.movable && s.awake {
                ready[roots[i]] &= s.slow_for >= long_enough && touching[i];
            }
        }
        for (i, fall) in falls.iter_mut().enumerate() {
            *fall = world.bodies[i].movable && sleep[i].awake && ready[roots[i]];
        }
    }
    for (i, fall) in falls.into_iter().enumerate() {
        if fall {
            put_to_sleep(&mut sleep[i], &mut world.bodies[i].state);
            events.push(Event::FallsAsleep { body: BodyId(i) });
        }
    }
}
