//! The events of a step, assembled in the order a step lists them: bodies
//! wholly inside others and bodies about to be pushed through a thin body
//! (from the step's contacts, before the resolution), then at the step's
//! end the contact events (made, lost, bounces, sticking, sliding), the
//! collisions continuous detection resolved, the tunnelling audit's pairs,
//! the energy audits' events and the phases' limits.

use nalgebra::Vector3;

use super::super::contact_events::PairSet;
use super::super::overlap;
use super::super::report::{Event, ToiEvent};
use super::super::substep::Spent;
use super::super::wake_sleep;
use super::Simulation;
use crate::physics::resolver::PhaseOutcome;
use crate::physics::{to_f64, Contact, Real};

/// What the end of a step reports besides its contacts' events.
pub(super) struct Ending<'a, T: Real> {
    /// Each contact's normal relative speed before the resolution (empty
    /// when no contact can bounce: [`Simulation::closing_speeds`]).
    pub closing_before: &'a [T],
    /// What continuous detection and the tunnelling audit found.
    pub spent: &'a Spent,
    /// The energy audits' events: the projection's lift, a kinetic gain, a
    /// total-energy rise.
    pub audits: [Option<Event>; 3],
    pub position: &'a PhaseOutcome<T>,
    pub velocity: &'a PhaseOutcome<T>,
}

impl<T: Real> Simulation<T> {
    /// Bodies wholly inside others (when it starts) and bodies about to be
    /// pushed through a thin body, from this step's contacts and the
    /// velocities that brought the bodies here.
    pub(super) fn overlap_events(&mut self, events: &mut Vec<Event>) {
        std::mem::swap(&mut self.inside, &mut self.inside_before);
        self.inside.clear();
        let mut pushed = PairSet::default();
        // The last contact's pair, its thinnest width and its normal: a
        // pair's contacts follow one another and mostly share the normal.
        let mut last: Option<(&Contact<T>, f64)> = None;
        for k in &self.world.contacts {
            let same_pair = last.filter(|(l, _)| (l.body1, l.body2) == (k.body1, k.body2));
            let thin = match same_pair {
                Some((_, thin)) => thin,
                None => overlap::thinnest_of_pair(&self.world, k),
            };
            // The same pair along the same normal: pushed through or not as
            // the last contact (and reported once per pair already).
            let same_normal = same_pair.is_some_and(|(l, _)| l.input.normal == k.input.normal);
            last = Some((k, thin));
            if let Some(width) = overlap::wholly_inside_below(&self.world, k, thin) {
                // Once per pair when it starts (a manifold has several
                // points, each of them deep).
                let pair = (k.body1, k.body2);
                if self.inside.insert(pair) && !self.inside_before.contains(&pair) {
                    events.push(Event::WhollyInside {
                        body1: k.body1,
                        body2: k.body2,
                        penetration: to_f64(k.input.penetration),
                        width,
                    });
                }
            }
            if same_normal {
                continue;
            }
            if let Some((body, through)) = overlap::pushed_through(&self.world, k, self.params.dt) {
                // Once per pair of bodies (a manifold has several points).
                if pushed.insert((body, Some(through))) {
                    events.push(Event::PushedThrough { body, through });
                }
            }
        }
        self.burials_ended(events);
    }

    /// The burials still going (pairs wholly inside one another at the
    /// last step's contacts), with how many steps each has lasted, as
    /// events a run adds after its last step.
    pub fn burials_going(&self) -> Vec<Event> {
        let mut going: Vec<_> = self.inside.iter().copied().collect();
        going.sort_unstable();
        (going.into_iter())
            .map(|(body1, body2)| Event::StillWhollyInside {
                body1,
                body2,
                steps: self.inside_steps.get(&(body1, body2)).copied().unwrap_or(1),
            })
            .collect()
    }

    /// Each burial's length: a pair wholly inside last step and not now
    /// ended a burial, said with its length when it lasted over a step.
    fn burials_ended(&mut self, events: &mut Vec<Event>) {
        for pair in &self.inside {
            *self.inside_steps.entry(*pair).or_insert(0) += 1;
        }
        if self.inside_before.is_empty() {
            return;
        }
        let mut ended: Vec<_> = (self.inside_before.iter())
            .filter(|pair| !self.inside.contains(pair))
            .copied()
            .collect();
        ended.sort_unstable();
        for (body1, body2) in ended {
            let steps = self.inside_steps.remove(&(body1, body2)).unwrap_or(0);
            if steps > 1 {
                events.push(Event::WhollyInsideEnded {
                    body1,
                    body2,
                    steps,
                });
            }
        }
    }

    /// The events of the step's end, in their order (module docs); the
    /// clock has been moved on to the step's end.
    pub(super) fn ending_events(&mut self, end: Ending<'_, T>, events: &mut Vec<Event>) {
        self.contact_events(end.closing_before, events);
        let start = self.time - to_f64(self.params.dt);
        events.extend(end.spent.hits.iter().map(|h| {
            Event::Toi(ToiEvent {
                time: start + h.time,
                ..*h
            })
        }));
        events.extend(end.spent.crossed.iter().map(|t| Event::Tunnelled {
            body1: t.body1,
            body2: t.body2,
            time: start + t.time,
            point: t.point,
        }));
        events.extend(end.audits.into_iter().flatten());
        let (position, velocity) = (end.position, end.velocity);
        if position.limit_reached && !self.limits_hit[0] {
            events.push(Event::PositionLimit {
                left: to_f64(position.max_after),
            });
        }
        if velocity.limit_reached && !self.limits_hit[1] {
            events.push(Event::VelocityLimit {
                left: to_f64(velocity.max_after),
            });
        }
        self.limits_hit = [position.limit_reached, velocity.limit_reached];
    }

    /// Each contact's relative normal velocity (negative when closing)
    /// before the resolution, into `out`: the contact events read it for a
    /// pair's fastest closing, and only where the pair can bounce. With no
    /// contact that can bounce (restitution 0) nothing reads it, and `out`
    /// is left empty; its tangential speed is never read.
    pub(super) fn closing_speeds(&self, out: &mut Vec<T>) {
        out.clear();
        let contacts = &self.world.contacts;
        if !contacts
            .iter()
            .any(super::super::contact_events::can_bounce)
        {
            return;
        }
        out.extend(
            contacts
                .iter()
                .map(|k| self.point_velocity(k).dot(&k.input.normal)),
        );
    }

    /// Relative normal velocity at each contact (negative when closing),
    /// and the tangential speed, into `out`.
    pub(super) fn normal_velocities(&self, out: &mut Vec<(T, T)>) {
        out.clear();
        out.extend(self.world.contacts.iter().map(|k| {
            let v = self.point_velocity(k);
            let n = k.input.normal;
            let normal = v.dot(&n);
            let tangential = (v - n * normal).norm();
            (normal, tangential)
        }));
    }

    fn point_velocity(&self, k: &Contact<T>) -> Vector3<T> {
        wake_sleep::relative_point_velocity(&self.world, k)
    }

    /// Each contact's relative normal and tangential speed as the step's
    /// resolution left them, kept for the contact events: read before the
    /// bodies move (a contact's point is where it was generated, and a
    /// collision continuous detection resolves later in the step is its
    /// own event), so a bounce's "separating" is the velocity that
    /// resolution gave the pair, not one measured at a point the body has
    /// since left (a spinning body's ω × v Δt) or after another collision.
    pub(super) fn keep_resolved_speeds(&mut self) {
        let mut after = std::mem::take(&mut self.closing_after);
        self.normal_velocities(&mut after);
        self.closing_after = after;
    }

    /// Contact made or lost, bounces, sticking and sliding, per touching
    /// pair, from the speeds [`Self::keep_resolved_speeds`] kept.
    fn contact_events(&mut self, before: &[T], events: &mut Vec<Event>) {
        let after = std::mem::take(&mut self.closing_after);
        let limit = to_f64(self.params.contact.velocity_limit).max(0.05);
        let contacts = &self.world.contacts;
        self.touching
            .report(contacts, before, &after, limit, events);
        self.closing_after = after;
    }
}
