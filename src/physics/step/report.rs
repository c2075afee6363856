//! What a step reports: its numbers, the events worth a line of their own,
//! and why a run stopped early.

use crate::physics::{to_f64, BodyId, Real, World};

/// Something worth a line of its own in a run's log.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Event {
    /// Two bodies (or a body and the world's immovable body) start touching.
    ContactMade {
        body1: BodyId,
        body2: Option<BodyId>,
    },
    /// They stop touching.
    ContactLost {
        body1: BodyId,
        body2: Option<BodyId>,
    },
    /// A contact closing at `closing` m/s leaves separating at `separating`.
    Bounce {
        body1: BodyId,
        body2: Option<BodyId>,
        closing: f64,
        separating: f64,
    },
    /// A touching pair's contact points stop or start sliding.
    Sticks {
        body1: BodyId,
        body2: Option<BodyId>,
    },
    Slides {
        body1: BodyId,
        body2: Option<BodyId>,
        speed: f64,
    },
    FallsAsleep {
        body: BodyId,
    },
    Wakes {
        body: BodyId,
    },
    /// The position or velocity phase used all its iterations.
    PositionLimit {
        left: f64,
    },
    VelocityLimit {
        left: f64,
    },
    /// The resolution added `gained` J of kinetic energy (reported when it
    /// starts, not again while it goes on), and the causes that the step,
    /// re-run from the same inputs with them switched off, shows.
    EnergyGain {
        gained: f64,
        cause: super::audit::EnergyCause,
    },
    /// The position phase lifted bodies out of penetration, adding `gained`
    /// J of potential energy beyond the settling of resting contacts
    /// (reported when it starts, not again while it goes on).
    ProjectionLift {
        gained: f64,
    },
}

/// What one step did.
#[derive(Debug, Clone, PartialEq)]
pub struct StepReport {
    pub step: u64,
    /// Time at the end of the step.
    pub time: f64,
    pub contacts: usize,
    pub awake: usize,
    /// Deepest penetration of the step's contacts before resolution.
    pub max_penetration: f64,
    /// Deepest penetration left (the resolver's bookkeeping).
    pub max_penetration_after: f64,
    pub kinetic_energy: f64,
    pub potential_energy: f64,
    pub position_iterations: usize,
    pub velocity_iterations: usize,
    pub events: Vec<Event>,
}

/// Why a run stopped early.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BlowUp {
    #[error("step {step}: body {body} has a non-finite {what}")]
    NonFinite {
        step: u64,
        body: usize,
        what: &'static str,
    },
    #[error("step {step}: the kinetic energy {energy:e} J is over 10⁶ times the scene's starting energy scale {scale:e} J; body {body} moves fastest")]
    Energy {
        step: u64,
        body: usize,
        energy: f64,
        scale: f64,
    },
}

/// The first movable body with a non-finite state, as a blow-up.
pub fn check_finite<T: Real>(world: &World<T>, step: u64) -> Result<(), BlowUp> {
    for (i, b) in world.bodies.iter().enumerate().filter(|(_, b)| b.movable) {
        let s = &b.state;
        let what = if !s.position.iter().all(|x| x.is_finite()) {
            "position"
        } else if !s.velocity.iter().all(|x| x.is_finite()) {
            "velocity"
        } else if !s.angular_velocity.iter().all(|x| x.is_finite()) {
            "angular velocity"
        } else if !s.orientation.coords.iter().all(|x| x.is_finite()) {
            "orientation"
        } else {
            continue;
        };
        return Err(BlowUp::NonFinite {
            step,
            body: i,
            what,
        });
    }
    Ok(())
}

/// The fastest movable body.
pub fn fastest<T: Real>(world: &World<T>) -> usize {
    let speed = |b: &crate::physics::Body<T>| to_f64(b.state.velocity.norm());
    (0..world.bodies.len())
        .filter(|i| world.bodies[*i].movable)
        .max_by(|a, b| speed(&world.bodies[*a]).total_cmp(&speed(&world.bodies[*b])))
        .unwrap_or(0)
}
