//! Steps 4 and 5 of the lecture's resolver and sequential impulses: the
//! contacts resolved together and the bodies moved over the step, through
//! continuous detection and the tunnelling audit (the soft step's arm is
//! soft.rs).

use super::super::audits::StepAudit;
use super::super::report::{Event, WakeCause};
use super::super::substep::Spent;
use super::super::swept::Earlier;
use super::super::wake_sleep;
use super::{Resolved, Simulation};
use crate::physics::resolver::{Implementation, Observer, Resolver};
use crate::physics::{Real, Solver};

impl<T: Real> Simulation<T> {
    /// Steps 4 and 5: the contacts resolved together (position phase, then
    /// velocity phase) and the bodies moved with the resolved velocities.
    pub(super) fn resolve_and_move<O: Observer<T>>(
        &mut self,
        observer: &mut O,
        events: &mut Vec<Event>,
    ) -> Resolved<T> {
        let p = self.params;
        let resolver = match &mut self.resolver {
            Some(r) => {
                r.prepare_again(&self.world, &p.resolver);
                r
            }
            none => none.insert(Resolver::prepare(&self.world, &p.resolver)),
        };
        // Nothing in a step reads the contacts' tangential velocities after
        // the velocity phase (the audits read the bodies).
        resolver.sequential.whole_velocities = false;
        let warm = p.resolver.warm_start && p.resolver.solver == Solver::SequentialImpulse;
        if warm {
            self.warm.stage(&self.world, resolver);
        }
        observer.resolving(&self.world, resolver);
        let position = resolver.position_phase(Implementation::Indexed, observer);
        let velocity = resolver.velocity_phase(Implementation::Indexed, observer);
        // The audits, while the world still holds the step's inputs.
        let audits = self.audits.run(StepAudit {
            world: &self.world,
            resolver,
            params: &p,
            warm: &self.warm,
            sleep: &self.sleep,
            inertia: &self.inertia,
            scale: self.energy_scale,
        });
        if warm {
            self.warm.store(&self.world, resolver);
        }
        resolver.write_back(&mut self.world);
        if p.sleep.enabled {
            wake_sleep::wake_changed(&mut self.world, &mut self.sleep, p.sleep.epsilon, events);
        }
        self.keep_resolved_speeds();
        // 5. Positions of the awake bodies with the resolved velocities,
        // through the step's collisions with continuous detection on, and
        // the tunnelling audit of each pair's swept motion (substep.rs).
        let spent = self.move_bodies(events);
        (position, velocity, audits, spent)
    }

    /// Moves the bodies over the step (substep.rs) and wakes the sleepers a
    /// collision inside it changed; what continuous detection and the
    /// tunnelling audit found.
    fn move_bodies(&mut self, events: &mut Vec<Event>) -> Spent {
        let p = self.params;
        let mut spent = Spent::default();
        self.substeps.moving.clear();
        self.substeps.moving.extend(
            (self.world.bodies.iter().zip(&self.sleep))
                .map(|(b, s)| b.movable && (s.awake || !p.sleep.enabled)),
        );
        // The audit reuses contact generation's pairs where it can (swept.rs).
        let earlier = Earlier {
            bounds: self.generator.bounds(),
            pairs: self.generator.pairs(),
        };
        self.substeps.spend(
            &mut self.world,
            &p,
            &self.materials,
            Some(earlier),
            &mut spent,
        );
        // A sleeper a collision inside the step changed is awake (its
        // velocity is no longer a sleeper's zero).
        for &(body, by) in &spent.woken {
            if !self.sleep[body.0].awake {
                self.sleep[body.0].wake(p.sleep.epsilon);
                let cause = WakeCause::Struck { by };
                events.push(Event::Wakes { body, cause });
            }
        }
        spent
    }
}
