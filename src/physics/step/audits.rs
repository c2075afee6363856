//! The step's energy audits, run after the resolution while the world still
//! holds the step's inputs: the kinetic audit (a velocity phase that adds
//! kinetic energy, [`super::audit`]), the projection's lift, and the
//! total-energy audit of the bodies in contact ([`super::total_audit`]);
//! each is an event when it starts, its cause found by the replay.

use nalgebra::Matrix3;

use super::report::Event;
use super::sleep::SleepState;
use super::total_audit::TotalAudit;
use super::{audit, replay};
use crate::physics::params::SimParams;
use crate::physics::resolver::sequential::WarmCache;
use crate::physics::resolver::Resolver;
use crate::physics::{to_f64, Real, World};

/// The audits' state from step to step (what was reported) and storage.
#[derive(Debug, Clone)]
pub(super) struct Audits<T: Real> {
    /// Whether the last step's velocity phase added energy (reported once
    /// when it starts).
    gaining: bool,
    /// Whether the last step's position phase lifted bodies (reported once
    /// when it starts).
    lifting: bool,
    /// The total-energy audit's storage (total_audit.rs).
    pub total: TotalAudit,
    /// The total-energy rise going on, and its bodies.
    streak: super::total_audit::RiseStreak,
    /// Each resolver body's kinetic energy after this step's resolution,
    /// shared by the kinetic and the total-energy audits.
    kinetic_after: Vec<T>,
}

/// What the audits read of a step.
pub(super) struct StepAudit<'a, T: Real> {
    /// Bodies after the velocity update; this step's contacts.
    pub world: &'a World<T>,
    /// The step's resolution, not yet written back.
    pub resolver: &'a Resolver<T>,
    pub params: &'a SimParams<T>,
    pub warm: &'a WarmCache<T>,
    pub sleep: &'a [SleepState<T>],
    /// Each body's world inertia at the step's start.
    pub inertia: &'a [Matrix3<T>],
    /// The energy scale blow-ups and gains are measured against.
    pub scale: f64,
}

impl<T: Real> Default for Audits<T> {
    fn default() -> Self {
        Audits {
            gaining: false,
            lifting: false,
            total: TotalAudit::default(),
            streak: Default::default(),
            kinetic_after: Vec::new(),
        }
    }
}

impl<T: Real> Audits<T> {
    /// The step's audit events in the order a step lists them: the
    /// projection's lift, a kinetic gain, a total-energy rise.
    pub fn run(&mut self, s: StepAudit<'_, T>) -> [Option<Event>; 3] {
        let p = s.params;
        let energy = replay::resolved_with(
            s.world,
            s.resolver,
            &p.world.gravity,
            Some(s.inertia),
            &mut self.kinetic_after,
        );
        let gained = audit::gain(energy.kinetic_before, energy.kinetic_after, s.scale);
        let inputs = replay::StepInputs {
            world: s.world,
            params: &p.resolver,
            warm: s.warm,
            gravity: p.world.gravity,
            scale: s.scale,
        };
        let gain_event = match (gained, self.gaining) {
            (Some(gained), false) => Some(Event::EnergyGain {
                gained,
                cause: inputs.attribute(),
            }),
            _ => None,
        };
        self.gaining = gained.is_some();
        let lifted = projection_lift(&energy, p.resolver.position_epsilon, s.scale);
        let lift_event = match (lifted, self.lifting) {
            (Some(gained), false) => Some(Event::ProjectionLift { gained }),
            _ => None,
        };
        self.lifting = lifted.is_some();
        // The total energy of the bodies in contact (total_audit.rs).
        let enabled = p.sleep.enabled;
        let start = self.total.start(
            s.world,
            |i| s.sleep[i].awake || !enabled,
            to_f64(p.world.gravity.norm()),
            p.resolver.velocity_epsilon,
            to_f64(p.dt),
        );
        let end = replay::total_after(
            s.world,
            s.resolver,
            &p.world.gravity,
            start.dt,
            start.touched,
            Some(&self.kinetic_after),
        );
        let rise = start.rise(end);
        let rise_event = match rise {
            Some(gained) if self.streak.new_rise(true, start.touched) => Some(Event::EnergyRise {
                gained,
                tolerance: start.tolerance,
                cause: inputs.attribute_rise(&start),
            }),
            Some(_) => None,
            None => {
                self.streak.new_rise(false, start.touched);
                None
            }
        };
        [lift_event, gain_event, rise_event]
    }
}

/// The potential energy the position phase added, when it is worth an
/// event: more than rounding, and more than lifting every resolved body by
/// the position epsilon (the settling of resting contacts, which the
/// position phase leaves up to that depth and then resolves).
fn projection_lift(e: &replay::Resolved, position_epsilon: f64, scale: f64) -> Option<f64> {
    let settling = e.weight * position_epsilon;
    audit::gain(0.0, e.potential_rise, scale).filter(|rise| *rise > settling)
}
