//! What a step reports: its numbers, the events worth a line of their own,
//! and why a run stopped early.

use crate::physics::detect::ToiMethod;
use crate::physics::{to_f64, Body, BodyId, Real, World};

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
    /// A sleeper wakes, and why.
    Wakes {
        body: BodyId,
        cause: WakeCause,
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
    /// The step raised the total energy (kinetic + potential) of the bodies
    /// in contact by `gained` J, over the audit's `tolerance` J and beyond
    /// projection's lift (reported when it starts, not again while it goes
    /// on; [`super::total_audit`]), and the causes the replay shows.
    EnergyRise {
        gained: f64,
        tolerance: f64,
        cause: super::audit::EnergyCause,
    },
    /// A body is wholly inside another: the contact's penetration reaches
    /// the smaller body's `width` along the normal (reported when it starts).
    WhollyInside {
        body1: BodyId,
        body2: Option<BodyId>,
        penetration: f64,
        width: f64,
    },
    /// A pair wholly inside one another for more than one step is no longer
    /// (reported when it ends, with how long it lasted: the start was a
    /// [`Event::WhollyInside`]; a one-step burial has that event alone).
    WhollyInsideEnded {
        body1: BodyId,
        body2: Option<BodyId>,
        steps: u64,
    },
    /// A burial still going at the run's end: the pair has been wholly
    /// inside one another for `steps` steps (given by the run, after its
    /// last step: [`super::Simulation::burials_going`]).
    StillWhollyInside {
        body1: BodyId,
        body2: Option<BodyId>,
        steps: u64,
    },
    /// The position phase is about to push `body` out through the far side
    /// of `through` (the thinner of the two): last step `body` was on the
    /// other side of `through`'s centre.
    PushedThrough {
        body: BodyId,
        through: BodyId,
    },
    /// The position phase lifted bodies out of penetration, adding `gained`
    /// J of potential energy beyond the settling of resting contacts
    /// (reported when it starts, not again while it goes on).
    ProjectionLift {
        gained: f64,
    },
    /// Rolling back time (`rollback = "rollback"`) moved bodies back along
    /// their motion against gravity, adding `gained` J of potential energy
    /// (measured: the potential energy after the roll-back less before it;
    /// reported when it starts, not again while it goes on). The
    /// total-energy audit starts from the rolled-back poses, so this lift
    /// is named here and not counted again as a rise.
    RollbackLift {
        gained: f64,
    },
    /// Two bodies met inside the step and were apart again at its end
    /// without a contact (the tunnelling auditor, [`super::ccd`]): at `time`
    /// (s, the run's clock), near `point`.
    Tunnelled {
        body1: BodyId,
        body2: BodyId,
        time: f64,
        point: [f64; 3],
    },
    /// Continuous detection resolved a collision inside the step.
    Toi(ToiEvent),
}

/// Why a sleeper woke: every `wakes` event names one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WakeCause {
    /// An awake body pressed on it (a contact the resolver acts on), or its
    /// island was woken through that body.
    Touched { by: BodyId },
    /// The resolution changed its velocity through contact `contact` (the
    /// index among the step's contacts), shared with the awake body `with`.
    Impulse { contact: usize, with: BodyId },
    /// Continuous detection resolved a collision with `by` inside the step.
    Struck { by: BodyId },
    /// An edit of the scene changed it.
    Edit,
}

/// A collision continuous detection found inside a step and resolved at
/// its time ([`super::substep`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToiEvent {
    pub body1: BodyId,
    pub body2: BodyId,
    pub method: ToiMethod,
    /// The run's clock (s); time into the step while the sub-steps hold it
    /// (`Spent::hits`), until the step adds its start.
    pub time: f64,
    /// The search's tests (GJK calls).
    pub tests: usize,
    pub point: [f64; 3],
    pub normal: [f64; 3],
    /// Normal speeds before and after (m/s): closing > 0 approaches, separating > 0 leaves.
    pub closing: f64,
    pub separating: f64,
    /// The world's kinetic energy before and after the resolution (J).
    pub kinetic_before: f64,
    pub kinetic_after: f64,
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
    /// Continuous detection's work: the GJK calls of its time-of-collision
    /// searches this step (0 with `ccd = "none"`).
    pub ccd_tests: usize,
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
    /// The kinetic energy is over [`ENERGY_FACTOR`] times what the run could
    /// have given it ([`energy_blown_up`]).
    #[error("step {step}: the kinetic energy {energy:e} J is over 10⁶ times the scene's starting energy scale {scale:e} J and the {released:e} J gravity has released since the start; body {body} moves fastest")]
    Energy {
        step: u64,
        body: usize,
        energy: f64,
        scale: f64,
        released: f64,
    },
    /// One step's kinetic energy rose more than [`SURGE_FACTOR`] times what
    /// the step could give (see [`surge_bound`]).
    #[error("step {step}: the kinetic energy rose from {before:e} J to {after:e} J in one step, over {SURGE_FACTOR} times the {bound:e} J that the bodies' speeds and one step of acceleration account for")]
    Surge {
        step: u64,
        before: f64,
        after: f64,
        bound: f64,
        /// The bodies that sped up most: (body, speed before, speed after),
        /// fastest first, at most five.
        bodies: Vec<(usize, f64, f64)>,
    },
}

/// How many times what the run could have given it a run's kinetic energy
/// may reach before the run stops ([`energy_blown_up`]).
pub const ENERGY_FACTOR: f64 = 1e6;

/// Whether a run's `kinetic` energy is a blow-up: over [`ENERGY_FACTOR`]
/// times the scene's starting energy `scale` plus the energy gravity has
/// `released` since the start (the potential energy the bodies lost, summed
/// step by step: free fall turns it into kinetic energy without bound, and
/// that is never a blow-up). The energy the resolution adds is the
/// [`BlowUp::Surge`] rule's and the energy audits' to judge.
pub fn energy_blown_up(kinetic: f64, scale: f64, released: f64) -> bool {
    kinetic > ENERGY_FACTOR * (scale + released.max(0.0))
}

/// How many times the step's own bound a step's kinetic energy may reach
/// before the run stops. The bound holds the energy the bodies brought and
/// what one step of gravity (and last frame's acceleration, for
/// compensation) can add to it; restitution ≤ 1 gives back at most what was
/// there. The lecture's ingredients that can gain energy on their own
/// (restitution with friction, the friction models' rules, compensation)
/// are `energy` events, and stay well under this factor: the worst seen,
/// velocity-scaling friction with μ = 5, multiplies a step's energy by
/// about 85. A thousand times (about 32 times the speed) is a blow-up.
pub const SURGE_FACTOR: f64 = 1000.0;

/// A step's bound: `Σ ½ m (|v| + (|g| + |a|) dt)² + K` over the movable
/// bodies at the start of the step (sleepers too: v their velocity, ω folded in as
/// `|ω| × bounding radius`, a last frame's acceleration).
pub fn surge_bound<T: Real>(world: &World<T>, gravity: f64, dt: f64) -> f64 {
    world
        .bodies
        .iter()
        .filter(|b| b.movable)
        .map(|b| {
            let s = &b.state;
            body_bound(
                b,
                gravity,
                dt,
                to_f64(s.kinetic_energy(&s.velocity, &s.angular_velocity)),
            )
        })
        .sum()
}

/// One body's term of the [`surge_bound`], its kinetic energy `kinetic` given.
fn body_bound<T: Real>(b: &Body<T>, gravity: f64, dt: f64, kinetic: f64) -> f64 {
    bound_at_speed(b, to_f64(b.state.velocity.norm()), gravity, dt, kinetic)
}

/// [`body_bound`], the body's speed `|v|` given.
fn bound_at_speed<T: Real>(b: &Body<T>, speed: f64, gravity: f64, dt: f64, kinetic: f64) -> f64 {
    let s = &b.state;
    let reach = b
        .shape
        .as_ref()
        .and_then(|sh| sh.bounding_radius())
        .unwrap_or(0.0);
    let speed = speed + to_f64(s.angular_velocity.norm()) * reach;
    let kick = (gravity + to_f64(s.acceleration.norm())) * dt;
    let e = 0.5 * to_f64(s.mass) * (speed + kick).powi(2);
    // Angular energy beyond what |ω| × radius stands for (thin bodies).
    e + kinetic
}

/// What a step's audits read at its start, in one pass over the bodies:
/// the kinetic energy of the movable bodies (as [`super::energy::kinetic`]),
/// the [`surge_bound`], each body's speed (into `speeds`) and each body's
/// world inertia (into `inertia`, for the resolution's energy audit; the
/// orientations do not change before it). Each body's `R I Rᵀ` and kinetic
/// energy are computed once; the sums are the same operations in the same order.
pub fn start_of_step<T: Real>(
    world: &World<T>,
    gravity: f64,
    dt: f64,
    speeds: &mut Vec<f64>,
    inertia: &mut Vec<nalgebra::Matrix3<T>>,
) -> (T, f64) {
    start_of_step_kept(world, gravity, dt, speeds, inertia, None)
}

/// [`start_of_step`], each body's `R I Rᵀ` and kinetic energy taken from
/// `kept` (the last step's end) where the body still holds the state they
/// were computed from: the same bits.
pub fn start_of_step_kept<T: Real>(
    world: &World<T>,
    gravity: f64,
    dt: f64,
    speeds: &mut Vec<f64>,
    inertia: &mut Vec<nalgebra::Matrix3<T>>,
    kept: Option<&super::kept_energy::KeptEnergy<T>>,
) -> (T, f64) {
    speeds.clear();
    inertia.clear();
    let mut kinetic = T::zero();
    // `Iterator::sum` of f64 starts from -0.0.
    let mut bound = -0.0f64;
    for b in &world.bodies {
        let s = &b.state;
        let speed = to_f64(s.velocity.norm());
        speeds.push(speed);
        if !b.movable {
            inertia.push(nalgebra::Matrix3::zeros());
            continue;
        }
        let (i, energy) = match kept.and_then(|k| k.of(inertia.len(), s)) {
            Some(at_hand) => at_hand,
            None => {
                let i = s.inertia_world();
                (
                    i,
                    s.kinetic_energy_with(&i, &s.velocity, &s.angular_velocity),
                )
            }
        };
        inertia.push(i);
        kinetic += energy;
        bound += bound_at_speed(b, speed, gravity, dt, to_f64(energy));
    }
    (kinetic, bound)
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

/// The bodies that sped up most in a step, fastest-gaining first (at most
/// five): (body, speed before, speed after).
pub fn sped_up<T: Real>(world: &World<T>, before: &[f64]) -> Vec<(usize, f64, f64)> {
    let mut rows: Vec<(usize, f64, f64)> = world
        .bodies
        .iter()
        .zip(before)
        .enumerate()
        .filter(|(_, (b, _))| b.movable)
        .map(|(i, (b, v0))| (i, *v0, to_f64(b.state.velocity.norm())))
        .collect();
    rows.sort_by(|a, b| (b.2 - b.1).total_cmp(&(a.2 - a.1)));
    rows.truncate(5);
    rows
}
