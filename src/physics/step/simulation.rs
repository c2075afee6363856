//! One time step of a world, as the reference engine runs it: integrate the
//! awake bodies, generate contacts from the shapes, wake sleepers that an
//! awake body presses on, resolve the contacts together (position phase,
//! then velocity phase), update sleep. What happened is reported per step.

use nalgebra::Vector3;

pub(super) mod contacts;
mod events;
mod resolve;
mod soft;
mod xpbd;

use super::audit::Switches;
use super::audits::Audits;
use super::ccd_mode::Rollback;
use super::contact_events::{ContactEvents, PairSet};
use super::integrate::{integrate_velocity_kept, Kept, Loads};
use super::kept_energy::KeptEnergy;
use super::previous_frame::PoseOf;
pub use super::report::{BlowUp, Event, StepReport, ToiEvent, WakeCause};
use super::sleep::SleepState;
use super::substep::{Spent, Substeps};
use super::{energy, replay, rollback, tolerance, wake_sleep};
use crate::physics::collide::{BodyContact, ContactGenerator};
use crate::physics::params::Material;
pub use crate::physics::params::SimParams;
use crate::physics::resolver::sequential::WarmCache;
use crate::physics::resolver::PhaseOutcome;
use crate::physics::resolver::{Implementation, Observer, Resolver, Silent};
use crate::physics::{c, to_f64, BodyId, Real, Solver, World};
use events::Ending;

/// A step's phases, its energy audits' events and what its move spent.
type Resolved<T> = (PhaseOutcome<T>, PhaseOutcome<T>, [Option<Event>; 3], Spent);

/// A world stepping in time.
#[derive(Debug, Clone)]
pub struct Simulation<T: Real> {
    /// The bodies; `contacts` holds the last step's generated contacts.
    pub world: World<T>,
    pub params: SimParams<T>,
    /// Each body's coefficients.
    pub materials: Vec<Material>,
    pub sleep: Vec<SleepState<T>>,
    pub step: u64,
    pub time: f64,
    generator: ContactGenerator<T>,
    generated: Vec<BodyContact<T>>,
    /// The resolver, kept so its storage is reused from step to step.
    resolver: Option<Resolver<T>>,
    /// Sequential impulses with warm start: last step's accumulated impulses.
    warm: WarmCache<T>,
    /// Touching pairs of the last step and whether they slid (and the
    /// events' buffers).
    touching: ContactEvents,
    /// Each contact's normal relative speed before the resolution (only
    /// where some contact can bounce), and its (normal, tangential) speed
    /// after it (storage kept).
    closing_before: Vec<T>,
    closing_after: Vec<(T, T)>,
    /// The energy scale blow-ups are measured against.
    energy_scale: f64,
    /// The potential energy gravity has released since the start (J; the
    /// potential lost, summed step by step): what the run could have given
    /// the kinetic energy beyond its scale.
    released: f64,
    /// Whether the position and velocity phases hit their limits last step
    /// (a limit is an event when it starts being hit).
    limits_hit: [bool; 2],
    /// The energy audits' state and storage (audits.rs).
    audits: Audits<T>,
    /// Each body's speed at the start of the step (storage kept).
    speeds: Vec<f64>,
    /// Each body's world inertia at the start of the step (storage kept).
    inertia: Vec<nalgebra::Matrix3<T>>,
    /// Each body's world inertia and kinetic energy at the last step's end
    /// (kept_energy.rs: the next start takes them).
    kept: KeptEnergy<T>,
    /// The smallest half-width of a movable body (the tolerances' scale).
    size: Option<f64>,
    /// The parameters the scaled ones were made from, and the scaled ones.
    scaled_for: Option<SimParams<T>>,
    scaled: SimParams<T>,
    /// The whole step's dt while its substeps run (the tolerances' step).
    substep_of: Option<f64>,
    /// Pairs wholly inside one another this step and the last.
    inside: PairSet,
    inside_before: PairSet,
    /// Steps each pair now wholly inside has been so (its burial's length).
    inside_steps: super::contact_events::PairMap<u64>,
    /// Continuous detection's scratch.
    substeps: Substeps<T>,
    /// Each body's pose at the start of this step, and at the start of the
    /// last one: the previous frame (t − Δt) of this step's contacts.
    frame_start: Vec<PoseOf<T>>,
    previous: Vec<PoseOf<T>>,
    /// Whether the last step's roll-back lifted bodies (an event when it starts).
    rolling_lift: bool,
    /// Sleepers an edit woke since the last step (its first events).
    edited: Vec<BodyId>,
    /// The soft step's storage (`solver = "soft-step"`), and its record of
    /// the next step when one is asked for (simulation/soft.rs).
    soft: super::soft::SoftSolver<T>,
    pub soft_trace: Option<super::soft::SoftTrace>,
    /// XPBD's record of the next step's substeps when one is asked for
    /// (emptied and filled by the step; simulation/xpbd.rs).
    pub xpbd_trace: Option<Vec<super::xpbd::SubstepRecord>>,
    /// XPBD's own switches (`solver = "xpbd"`; the erratum's experiment).
    pub xpbd: super::xpbd::XpbdOptions,
}

impl<T: Real> Simulation<T> {
    pub fn new(world: World<T>, params: SimParams<T>, materials: Vec<Material>) -> Self {
        let sleep = vec![SleepState::awake(params.sleep.epsilon); world.bodies.len()];
        let mut sim = Simulation {
            world,
            params,
            materials,
            sleep,
            step: 0,
            time: 0.0,
            generator: ContactGenerator::new(),
            generated: Vec::new(),
            resolver: None,
            warm: WarmCache::default(),
            touching: ContactEvents::default(),
            closing_before: Vec::new(),
            closing_after: Vec::new(),
            energy_scale: 0.0,
            released: 0.0,
            limits_hit: [false; 2],
            audits: Audits::default(),
            speeds: Vec::new(),
            inertia: Vec::new(),
            kept: KeptEnergy::default(),
            size: None,
            scaled_for: None,
            substep_of: None,
            scaled: SimParams::default(),
            inside: PairSet::default(),
            inside_before: PairSet::default(),
            inside_steps: Default::default(),
            substeps: Substeps::default(),
            frame_start: Vec::new(),
            previous: Vec::new(),
            rolling_lift: false,
            edited: Vec::new(),
            soft: Default::default(),
            soft_trace: None,
            xpbd_trace: None,
            xpbd: Default::default(),
        };
        sim.world.contacts.clear();
        sim.size = tolerance::smallest_size(&sim.world);
        let g = sim.params.world.gravity;
        let scale = energy::kinetic(&sim.world) + potential_scale(&sim.world, &g);
        sim.energy_scale = to_f64(scale).abs().max(1e-9);
        sim
    }

    /// Number of awake movable bodies.
    pub fn awake(&self) -> usize {
        self.world
            .bodies
            .iter()
            .zip(&self.sleep)
            .filter(|(b, s)| b.movable && s.awake)
            .count()
    }

    /// Whether movable body `i` is awake (an immovable body never sleeps).
    pub fn is_awake(&self, i: usize) -> bool {
        self.sleep.get(i).is_none_or(|s| s.awake)
    }

    /// Wakes movable body `i` because an edit changed it: a sleeper's
    /// `wakes` event (cause: an edit) opens the next step's events.
    pub fn wake_for_edit(&mut self, i: usize) {
        let epsilon = self.params.sleep.epsilon;
        if let Some(s) = self.sleep.get_mut(i) {
            if !s.awake && self.world.bodies[i].movable {
                self.edited.push(BodyId(i));
            }
            *s = SleepState::awake(epsilon);
        }
    }

    /// Advances one step without recording the resolver.
    pub fn advance(&mut self) -> Result<StepReport, BlowUp> {
        self.advance_observed(&mut Silent)
    }

    /// Advances one step; the resolver reports each iteration to `observer`.
    pub fn advance_observed<O: Observer<T>>(
        &mut self,
        observer: &mut O,
    ) -> Result<StepReport, BlowUp> {
        let Some(split) = self.split() else {
            return self.with_scaled_tolerances(|sim| sim.advance_scaled(observer));
        };
        // Small bodies: the step spent as substeps (split.rs), reported as
        // one step.
        let (dt, step, time) = (self.params.dt, self.step, self.time);
        let n = split.substeps;
        self.params.dt = dt / c::<T>(f64::from(n));
        self.substep_of = Some(to_f64(dt));
        let mut whole: Option<StepReport> = None;
        let mut result = Ok(());
        for _ in 0..n {
            self.step = step;
            match self.with_scaled_tolerances(|sim| sim.advance_scaled(observer)) {
                Ok(r) => whole = Some(merge(whole, r)),
                Err(e) => {
                    result = Err(e);
                    break;
                }
            }
        }
        self.params.dt = dt;
        self.substep_of = None;
        self.step = step + 1;
        self.time = time + to_f64(dt);
        result?;
        let mut r = whole.expect("at least one substep");
        r.time = self.time;
        Ok(r)
    }

    /// How this scene's steps are split into substeps (`None`: they are
    /// not; see [`super::split`]).
    pub fn split(&self) -> Option<super::split::Split> {
        let g = self.params.world.gravity.norm();
        super::split::split(to_f64(g), to_f64(self.params.dt), self.size)
    }

    /// The tolerances the scene's sizes lowered (see [`tolerance`]), for
    /// the parameters as they are now.
    pub fn lowered_tolerances(&self) -> Vec<tolerance::Lowered> {
        tolerance::scaled(&self.params, self.size).1
    }

    /// The movable bodies smaller than ten times the rounding of their
    /// position (see [`tolerance::below_rounding`]).
    pub fn below_rounding(&self) -> Vec<tolerance::BelowRounding> {
        tolerance::below_rounding(&self.world)
    }

    /// Runs `f` with the tolerances scaled to the bodies in `params`, and
    /// the parameters as given restored after it.
    fn with_scaled_tolerances<R>(&mut self, f: impl FnOnce(&mut Self) -> R) -> R {
        if self.scaled_for.as_ref() != Some(&self.params) {
            let step_dt = (self.substep_of).unwrap_or_else(|| to_f64(self.params.dt));
            self.scaled = tolerance::scaled_in_step(&self.params, self.size, step_dt).0;
            self.scaled_for = Some(self.params);
        }
        let given = std::mem::replace(&mut self.params, self.scaled);
        let result = f(self);
        self.params = given;
        result
    }

    fn advance_scaled<O: Observer<T>>(&mut self, observer: &mut O) -> Result<StepReport, BlowUp> {
        let p = self.params;
        let mut events: Vec<Event> = (self.edited.drain(..))
            .map(|body| Event::Wakes {
                body,
                cause: WakeCause::Edit,
            })
            .collect();
        // What this step may give at most (the blow-up rule), and each
        // body's speed to name the ones that blew up.
        let (kinetic_start, surge_bound) = super::report::start_of_step_kept(
            &self.world,
            to_f64(p.world.gravity.norm()),
            to_f64(p.dt),
            &mut self.speeds,
            &mut self.inertia,
            Some(&self.kept),
        );
        let kinetic_start = to_f64(kinetic_start);
        let potential_start = to_f64(energy::potential(&self.world, &p.world.gravity));
        self.audits
            .total
            .begin(&self.world, &p.world.gravity, &self.inertia);
        self.begin_step(&mut events);
        let max_penetration = self
            .world
            .contacts
            .iter()
            .fold(0.0f64, |m, k| m.max(to_f64(k.input.penetration)));
        let mut closing_before = std::mem::take(&mut self.closing_before);
        self.closing_speeds(&mut closing_before);
        // 4. Resolve the contacts together, 5. move the bodies.
        let (position, velocity, audits, spent) = match p.resolver.solver {
            Solver::SoftStep => self.soft_step(&mut events),
            Solver::Xpbd => self.xpbd_step(&mut events),
            _ => self.resolve_and_move(observer, &mut events),
        };
        // 6. Sleep.
        if p.sleep.enabled {
            wake_sleep::update_sleep(&mut self.world, &self.params, &mut self.sleep, &mut events);
            // A pair with no awake body is at rest: its last impulses would
            // only wake its sleepers next step (warm starting forgets them).
            let (world, sleep) = (&self.world, &self.sleep);
            self.warm.retain_pairs(|b1, b2| {
                let awake = |b: BodyId| world.body(b).movable && sleep[b.0].awake;
                awake(b1) || b2.is_some_and(awake)
            });
        }
        self.step += 1;
        self.time += to_f64(p.dt);
        // The step's end: its events in their order (simulation/events.rs).
        let end = Ending {
            closing_before: &closing_before,
            spent: &spent,
            audits,
            position: &position,
            velocity: &velocity,
        };
        self.ending_events(end, &mut events);
        self.closing_before = closing_before;
        super::report::check_finite(&self.world, self.step)?;
        // As energy::kinetic, each body's share kept for the next start.
        let kinetic = to_f64(self.kept.kinetic(&self.world));
        if kinetic > super::report::SURGE_FACTOR * surge_bound + 1e-9 * self.energy_scale {
            return Err(BlowUp::Surge {
                step: self.step,
                before: kinetic_start,
                after: kinetic,
                bound: surge_bound,
                bodies: super::report::sped_up(&self.world, &self.speeds),
            });
        }
        let potential = to_f64(energy::potential(&self.world, &p.world.gravity));
        self.released += potential_start - potential;
        if super::report::energy_blown_up(kinetic, self.energy_scale, self.released) {
            return Err(BlowUp::Energy {
                step: self.step,
                body: super::report::fastest(&self.world),
                energy: kinetic,
                scale: self.energy_scale,
                released: self.released.max(0.0),
            });
        }
        Ok(StepReport {
            step: self.step,
            time: self.time,
            contacts: self.world.contacts.len(),
            awake: self.awake(),
            max_penetration,
            max_penetration_after: to_f64(position.max_after).max(0.0),
            kinetic_energy: kinetic,
            potential_energy: potential,
            position_iterations: position.iterations_used,
            velocity_iterations: velocity.iterations_used,
            ccd_tests: spent.tests,
            events,
        })
    }

    /// The step up to its resolution: contacts generated, velocities
    /// integrated, sleepers woken.
    fn begin_step(&mut self, events: &mut Vec<Event>) {
        let p = self.params;
        // The poses one frame before this step's (previous_frame.rs).
        std::mem::swap(&mut self.previous, &mut self.frame_start);
        self.frame_start.clear();
        self.frame_start
            .extend((self.world.bodies.iter()).map(|b| (b.state.position, b.state.orientation)));
        // 1. Contacts from the shapes where the bodies are now.
        self.generate_contacts();
        if p.rollback == Rollback::Rollback {
            // Back to the time of collision instead of projection (rollback.rs).
            let (sleep, enabled) = (&self.sleep, p.sleep.enabled);
            let eps = c::<T>(p.resolver.position_epsilon);
            let moving = |i: usize| sleep[i].awake || !enabled;
            let back = &mut self.substeps.back;
            let g = p.world.gravity;
            let before = energy::potential(&self.world, &g);
            let lifted = if rollback::roll_back(&mut self.world, moving, eps, p.dt, back) > 0 {
                self.generate_contacts();
                // The audits start from the rolled-back poses: the lift is
                // named on its own (below), not counted again as a rise.
                self.audits.total.begin(&self.world, &g, &self.inertia);
                let after = energy::potential(&self.world, &g);
                super::audit::gain(to_f64(before), to_f64(after), self.energy_scale)
            } else {
                None
            };
            if let (Some(gained), false) = (lifted, self.rolling_lift) {
                events.push(Event::RollbackLift { gained });
            }
            self.rolling_lift = lifted.is_some();
        }
        self.overlap_events(events);
        // 2. Velocities of the awake bodies: gravity and damping over the
        // step (the soft step and XPBD integrate them in their substeps).
        let substepped = matches!(p.resolver.solver, Solver::SoftStep | Solver::Xpbd);
        let kept = Kept::over(p.world.linear_damping, p.world.angular_damping, p.dt);
        for (body, sleep) in self.world.bodies.iter_mut().zip(&self.sleep) {
            if body.movable && (sleep.awake || !p.sleep.enabled) && !substepped {
                let loads = Loads::default();
                integrate_velocity_kept(&mut body.state, &p.world.gravity, &loads, &kept, p.dt);
            }
        }
        self.world.step.duration = p.dt;
        // Resolved between the velocity and the position update, the
        // contacts see this step's build-up already: nothing to anticipate.
        self.world.step.anticipate_planar_acceleration = false;
        // Gap contacts as speculative ones (deepest-first: sequential
        // impulses clamp their accumulated impulses their own way).
        self.world.step.speculative =
            p.speculative && p.resolver.solver == crate::physics::Solver::DeepestFirst;
        // 3. Wake sleepers that an awake body presses on.
        if p.sleep.enabled {
            wake_sleep::wake_touched(&self.world, &self.params, &mut self.sleep, events);
        }
    }

    /// The next step's resolution re-run from its inputs with `off`
    /// switched off (the experiment behind an energy event), leaving this
    /// simulation as it is.
    pub fn replay_next(&self, off: Switches) -> replay::Resolved {
        let mut sim = self.clone();
        sim.params = tolerance::scaled(&self.params, self.size).0;
        sim.begin_step(&mut Vec::new());
        replay::StepInputs {
            world: &sim.world,
            params: &sim.params.resolver,
            warm: &sim.warm,
            gravity: sim.params.world.gravity,
            scale: sim.energy_scale,
        }
        .replay(off)
    }

    /// The next step up to where it moves the bodies (contacts resolved,
    /// positions not yet updated: what continuous detection sweeps), and
    /// which bodies move, leaving this simulation as it is. Warm starting
    /// is left out.
    pub fn resolved_next(&self) -> (World<T>, Vec<bool>) {
        let mut sim = self.clone();
        sim.params = tolerance::scaled(&self.params, self.size).0;
        sim.begin_step(&mut Vec::new());
        let mut resolver = Resolver::prepare(&sim.world, &sim.params.resolver);
        resolver.position_phase(Implementation::Indexed, &mut Silent);
        resolver.velocity_phase(Implementation::Indexed, &mut Silent);
        resolver.write_back(&mut sim.world);
        let enabled = sim.params.sleep.enabled;
        let moving = (sim.world.bodies.iter().zip(&sim.sleep))
            .map(|(b, s)| b.movable && (s.awake || !enabled))
            .collect();
        (sim.world, moving)
    }

    /// Each body's movement bounds over the last step, as its first swept
    /// broad phase made them (`None`: not moving then, or no convex shape).
    pub fn movement_bounds(&self) -> &[Option<super::swept::MovementBound<T>>] {
        &self.substeps.bounds
    }

    /// Each body's pose one frame before the last step's contacts were
    /// generated (empty before the second step): their previous frame.
    pub fn previous_poses(&self) -> &[PoseOf<T>] {
        &self.previous
    }

    /// The scene's energy scale (J): what gains and blow-ups are measured against.
    pub fn energy_scale(&self) -> f64 {
        self.energy_scale
    }
}

/// A step's report from its substeps' (`whole` so far, and the next).
fn merge(whole: Option<StepReport>, next: StepReport) -> StepReport {
    let Some(mut w) = whole else { return next };
    w.contacts = next.contacts;
    w.awake = next.awake;
    w.max_penetration = w.max_penetration.max(next.max_penetration);
    w.max_penetration_after = w.max_penetration_after.max(next.max_penetration_after);
    w.kinetic_energy = next.kinetic_energy;
    w.potential_energy = next.potential_energy;
    w.position_iterations += next.position_iterations;
    w.velocity_iterations += next.velocity_iterations;
    w.ccd_tests += next.ccd_tests;
    w.events.extend(next.events);
    w
}

/// A potential-energy scale: m |g| (the body's height above the lowest body + 1).
fn potential_scale<T: Real>(world: &World<T>, g: &Vector3<T>) -> T {
    world
        .bodies
        .iter()
        .filter_map(|b| b.dynamic())
        .fold(T::zero(), |s, b| {
            s + b.mass * g.norm() * (b.position.norm() + T::one())
        })
}
