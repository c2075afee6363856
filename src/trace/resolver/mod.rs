//! The resolver trace: what `resolve` shows of a scene's contacts resolved
//! together. A [`Recorder`] (a resolver observer) keeps each iteration — the
//! contact taken, its penetration or desired Δv, the moves or the impulse,
//! every other contact it changed from → to — and [`describe`] turns the
//! resolver's records into the trace the renderers read. [`describe_world`]
//! does the same for any world with its [`Names`] (one step of a run).

use nalgebra::Vector3;

mod thinning;
mod verdicts;
use thinning::Thinning;
pub use thinning::{Elision, ROW_BUDGET};
use verdicts::verdicts;

pub use super::names::Names;
use super::{AfterState, Verdict};
use crate::lesson::Lesson;
use crate::physics::resolver::checks::scene_checks;
use crate::physics::resolver::{
    Implementation, Observer, Phase, PhaseOutcome, PositionMoves, Resolver, ResolverBody,
    ResolverContact, VelocityImpulse,
};
use crate::physics::stages::FrictionRegime;
use crate::physics::{ResolverParams, RestitutionFrom, Solver, World};

/// One contact's bookkeeping at a moment (before or after the phases).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactRow {
    pub label: String,
    pub penetration: f64,
    /// `v_s`, the normal contact velocity (negative when closing).
    pub separating: f64,
    pub desired: f64,
}

/// Another contact an iteration changed: its value from → to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Update {
    pub contact: usize,
    pub from: f64,
    pub to: f64,
}

impl Update {
    /// Deeper into penetration, or closing faster (more Δv wanted, and some
    /// wanted at all): the iteration made this contact worse.
    pub fn worse(&self) -> bool {
        self.to > self.from && self.to > 0.0
    }
}

/// One body's move in a position iteration.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyMove {
    pub body: String,
    /// `Δp = Δ_l d`.
    pub linear: [f64; 3],
    /// `Δθ`, the rotation vector applied.
    pub angular: [f64; 3],
    /// True when the angular limit cut the angular move.
    pub limited: bool,
}

/// One body's velocity change in a velocity iteration.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyKick {
    pub body: String,
    pub dv: [f64; 3],
    pub dw: [f64; 3],
}

/// One iteration of a phase.
#[derive(Debug, Clone, PartialEq)]
pub struct Iteration {
    pub iteration: usize,
    pub contact: usize,
    /// The penetration (position) or desired Δv (velocity) it was taken at.
    pub value: f64,
    /// The taken contact's own value after the iteration.
    pub own_after: f64,
    pub moves: Vec<BodyMove>,
    pub kicks: Vec<BodyKick>,
    pub impulse_contact: Option<[f64; 3]>,
    pub impulse_world: Option<[f64; 3]>,
    /// `"static"` or `"dynamic"` for a contact with friction.
    pub regime: Option<&'static str>,
    /// The other contacts it changed, by contact number (empty when elided).
    pub updated: Vec<Update>,
    /// How many other contacts it changed, and how many for the worse
    /// (counted even when the rows are elided).
    pub changed: usize,
    pub worse: usize,
    /// True when a huge step's recording did not keep this iteration's rows
    /// (`updated`, and the bodies at its stop): see [`ROW_BUDGET`].
    pub elided: bool,
}

/// One phase: its outcome, its notes and (when recorded) its iterations.
#[derive(Debug, Clone, PartialEq)]
pub struct PhaseTrace {
    pub phase: Phase,
    pub iterations_used: usize,
    pub iteration_limit: usize,
    pub epsilon: f64,
    pub max_before: f64,
    pub max_after: f64,
    pub max_after_contact: usize,
    pub limit_reached: bool,
    /// Iterations that made at least one other contact worse.
    pub worsening_iterations: usize,
    pub log: Vec<Iteration>,
    /// The solver that ran the phase (iterations are contact visits for both).
    pub solver: Solver,
    /// How many contacts the phase had to resolve.
    pub contacts: usize,
}

/// The worked resolution of a whole scene.
#[derive(Debug, Clone, PartialEq)]
pub struct ResolverTrace {
    pub lesson: String,
    pub title: String,
    pub source: String,
    pub summary: String,
    pub implementation: Implementation,
    pub restitution_from: RestitutionFrom,
    pub before: Vec<ContactRow>,
    pub position: PhaseTrace,
    pub velocity: PhaseTrace,
    pub contacts_after: Vec<ContactRow>,
    /// Every movable body, in file order.
    pub after: Vec<(String, AfterState)>,
    pub verdicts: Vec<Verdict>,
    pub warnings: Vec<String>,
    /// Set when the step was too large to keep every iteration's rows.
    pub elision: Option<Elision>,
    /// The simultaneous velocity phase's LCPs (`solver = "lcp"`).
    pub lcp: Option<crate::physics::lcp::Record<f64>>,
}

/// A resolver observer that keeps every iteration (for the trace).
#[derive(Debug, Clone, Default)]
pub struct Recorder {
    /// Names of the resolver's bodies, by resolver body index.
    names: Vec<String>,
    position: Vec<Iteration>,
    velocity: Vec<Iteration>,
    phase: Option<Phase>,
    /// When kept: the resolver's bodies before each iteration, per phase.
    keep_bodies: bool,
    /// Before each iteration, per phase (empty at a stop whose rows were elided).
    pub(crate) bodies: [Vec<Vec<ResolverBody<f64>>>; 2],
    thinning: Thinning,
}

impl Recorder {
    /// A recorder for `resolver`'s bodies, named from `lesson`.
    pub fn new(lesson: &Lesson, resolver: &Resolver<f64>) -> Self {
        let names: Vec<String> = lesson.bodies.iter().map(|b| b.name.clone()).collect();
        Recorder::named(&names, resolver)
    }

    /// A recorder for `resolver`'s bodies, named by world body index.
    pub fn named(names: &[String], resolver: &Resolver<f64>) -> Self {
        let names = resolver
            .bodies
            .iter()
            .map(|b| names.get(b.id.0).cloned().unwrap_or_default())
            .collect();
        Recorder {
            names,
            ..Recorder::default()
        }
    }

    /// Also keep the bodies as each iteration finds them.
    pub fn keeping_bodies(mut self) -> Self {
        self.keep_bodies = true;
        self
    }

    fn current(&mut self) -> Option<&mut Iteration> {
        match self.phase? {
            Phase::Position => self.position.last_mut(),
            Phase::Velocity => self.velocity.last_mut(),
        }
    }

    fn updated(&mut self, contact: usize, from: f64, to: f64) {
        let Some(it) = self.current() else { return };
        if contact == it.contact {
            it.own_after = to;
            return;
        }
        if to == from {
            return;
        }
        let u = Update { contact, from, to };
        it.changed += 1;
        it.worse += usize::from(u.worse());
        if !it.elided {
            it.updated.push(u);
            self.thinning.kept += 1;
            self.thin();
        }
    }

    fn iteration(&self, iteration: usize, contact: usize, value: f64) -> Iteration {
        Iteration {
            iteration,
            contact,
            value,
            own_after: value,
            moves: vec![],
            kicks: vec![],
            impulse_contact: None,
            impulse_world: None,
            regime: None,
            updated: vec![],
            changed: 0,
            worse: 0,
            elided: !self.thinning.keeps(iteration),
        }
    }

    fn slot_name(&self, slots: &[Option<usize>; 2], i: usize) -> String {
        slots[i].map_or_else(String::new, |b| self.names[b].clone())
    }
}

fn arr(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

impl Observer<f64> for Recorder {
    fn before_position(&mut self, i: usize, _k: usize, bodies: &[ResolverBody<f64>]) {
        self.keep_bodies_at(0, i, bodies);
    }

    fn before_velocity(&mut self, i: usize, _k: usize, bodies: &[ResolverBody<f64>]) {
        self.keep_bodies_at(1, i, bodies);
    }

    fn position_taken(&mut self, i: usize, k: usize, penetration: f64, moves: &PositionMoves<f64>) {
        self.phase = Some(Phase::Position);
        let mut it = self.iteration(i, k, penetration);
        for (slot, m) in moves.bodies.iter().enumerate() {
            if let Some(m) = m {
                it.moves.push(BodyMove {
                    body: self.slot_name(&moves.slots, slot),
                    linear: arr(&m.linear_change),
                    angular: arr(&m.angular_change),
                    limited: m.limited,
                });
            }
        }
        self.position.push(it);
    }

    fn penetration_updated(&mut self, contact: usize, from: f64, to: f64) {
        self.updated(contact, from, to);
    }

    fn velocity_taken(&mut self, i: usize, k: usize, desired: f64, impulse: &VelocityImpulse<f64>) {
        self.phase = Some(Phase::Velocity);
        let mut it = self.iteration(i, k, desired);
        it.impulse_contact = Some(arr(&impulse.impulse_contact));
        it.impulse_world = Some(arr(&impulse.impulse_world));
        it.regime = impulse.regime.map(|r| match r {
            FrictionRegime::Static => "static",
            FrictionRegime::Dynamic => "dynamic",
        });
        for (slot, b) in impulse.bodies.iter().enumerate() {
            if let Some(b) = b {
                it.kicks.push(BodyKick {
                    body: self.slot_name(&impulse.slots, slot),
                    dv: arr(&b.dv),
                    dw: arr(&b.dw),
                });
            }
        }
        self.velocity.push(it);
    }

    fn desired_updated(&mut self, contact: usize, from: f64, to: f64) {
        self.updated(contact, from, to);
    }
}

/// Each iteration's updates in contact order (the indexed resolver visits
/// them in adjacency order, the scan in file order).
fn sort_updates(log: &mut [Iteration]) {
    for it in log.iter_mut() {
        it.updated.sort_by_key(|u| u.contact);
    }
}

fn rows(names: &Names, contacts: &[ResolverContact<f64>]) -> Vec<ContactRow> {
    contacts
        .iter()
        .enumerate()
        .map(|(k, c)| ContactRow {
            label: names
                .contacts
                .get(k)
                .cloned()
                .unwrap_or_else(|| k.to_string()),
            penetration: c.penetration,
            separating: c.velocity.x,
            desired: c.desired,
        })
        .collect()
}

fn phase_trace(
    outcome: &PhaseOutcome<f64>,
    log: Vec<Iteration>,
    solver: Solver,
    contacts: usize,
) -> PhaseTrace {
    let worsening_iterations = log.iter().filter(|it| it.worse > 0).count();
    PhaseTrace {
        phase: outcome.phase,
        iterations_used: outcome.iterations_used,
        iteration_limit: outcome.iteration_limit,
        epsilon: outcome.epsilon,
        max_before: outcome.max_before,
        max_after: outcome.max_after,
        max_after_contact: outcome.max_after_contact,
        limit_reached: outcome.limit_reached,
        worsening_iterations,
        log,
        solver,
        contacts,
    }
}

/// Resolves `lesson`'s contacts together and describes it; with `record`
/// the iterations are kept (text and Markdown show them, JSON with `--log`).
pub fn describe(
    lesson: &Lesson,
    params: &ResolverParams,
    implementation: Implementation,
    record: bool,
) -> ResolverTrace {
    let world: World<f64> = lesson.world();
    let names = Names::of_lesson(lesson);
    describe_world(&world, &names, params, implementation, record, false).0
}

/// Resolves `world`'s contacts together and describes it with `names`; with
/// `record` the iterations are kept, with `bodies` also the resolver's
/// bodies before each iteration (position phase, velocity phase).
pub fn describe_world(
    world: &World<f64>,
    names: &Names,
    params: &ResolverParams,
    implementation: Implementation,
    record: bool,
    bodies: bool,
) -> (ResolverTrace, [Vec<Vec<ResolverBody<f64>>>; 2]) {
    let resolver = Resolver::prepare(world, params);
    describe_prepared(
        world,
        resolver,
        names,
        params,
        implementation,
        record,
        bodies,
    )
}

/// As [`describe_world`], from `resolver` as prepared for `world` (a time
/// step's, warm-started where it is).
pub fn describe_prepared(
    world: &World<f64>,
    mut resolver: Resolver<f64>,
    names: &Names,
    params: &ResolverParams,
    implementation: Implementation,
    record: bool,
    bodies: bool,
) -> (ResolverTrace, [Vec<Vec<ResolverBody<f64>>>; 2]) {
    let before = rows(names, &resolver.contacts);
    let mut recorder = Recorder::named(&names.bodies, &resolver);
    recorder.keep_bodies = bodies;
    let [position, velocity] = if record {
        [
            resolver.position_phase(implementation, &mut recorder),
            resolver.velocity_phase(implementation, &mut recorder),
        ]
    } else {
        let mut silent = crate::physics::resolver::Silent;
        [
            resolver.position_phase(implementation, &mut silent),
            resolver.velocity_phase(implementation, &mut silent),
        ]
    };
    let mut position_log = std::mem::take(&mut recorder.position);
    let mut velocity_log = std::mem::take(&mut recorder.velocity);
    sort_updates(&mut position_log);
    sort_updates(&mut velocity_log);
    if params.solver == Solver::Lcp {
        // The simultaneous impulses act together: what one of them alone
        // did to the other contacts on the way is bookkeeping, not an
        // iteration making a contact worse (the record's velocities after
        // are the answer).
        for it in &mut velocity_log {
            it.updated.clear();
            (it.changed, it.worse) = (0, 0);
        }
    }
    if bodies {
        // The bodies after both phases close the velocity list.
        recorder.bodies[1].push(resolver.bodies.clone());
    }
    let checks = scene_checks(world, &resolver);
    let trace = ResolverTrace {
        lesson: names.lesson.clone(),
        title: names.title.clone(),
        source: names.source.clone(),
        summary: names.summary.clone(),
        implementation,
        restitution_from: params.restitution_from,
        before,
        position: phase_trace(
            &position,
            position_log,
            params.solver,
            resolver.contacts.len(),
        ),
        velocity: phase_trace(
            &velocity,
            velocity_log,
            params.solver,
            resolver.contacts.len(),
        ),
        contacts_after: rows(names, &resolver.contacts),
        after: after(&names.bodies, &resolver.bodies),
        verdicts: verdicts(
            &names.bodies,
            &checks,
            &position,
            &velocity,
            resolver.contacts.len(),
        ),
        warnings: names.warnings.clone(),
        elision: recorder.thinning.elision(),
        lcp: resolver.lcp.clone(),
    };
    (trace, std::mem::take(&mut recorder.bodies))
}

/// Every movable body's state after both phases (orientation normalised),
/// named by world body index.
pub fn after(names: &[String], bodies: &[ResolverBody<f64>]) -> Vec<(String, AfterState)> {
    bodies
        .iter()
        .map(|b| {
            let q = b.unit_orientation();
            (
                names.get(b.id.0).cloned().unwrap_or_default(),
                AfterState {
                    position: arr(&b.position),
                    orientation: [q.w, q.i, q.j, q.k],
                    velocity: arr(&b.velocity),
                    angular_velocity: arr(&b.angular_velocity),
                },
            )
        })
        .collect()
}
