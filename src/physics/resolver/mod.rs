//! A SET of contacts resolved together, as the lecture ("Resolving
//! Penetration", "Updating Penetration Depths") and its reference engine do:
//!
//! 1. [`prepare`] every contact once: basis, r, contact velocity, desired Δv;
//! 2. the **position phase**: up to `position_iterations` times, take the
//!    contact with the largest penetration above `position_epsilon` (first in
//!    file order on ties), resolve it by projection, update the penetration of
//!    every contact sharing a moved body;
//! 3. the **velocity phase**: up to `velocity_iterations` times, take the
//!    contact with the largest desired Δv above `velocity_epsilon`, apply its
//!    impulse, update the contact velocity (and desired Δv) of every contact
//!    sharing a changed body.
//!
//! Two implementations give bit-identical results: [`scan`] (the lecture's
//! loop, O(contacts) per iteration) and [`indexed`] (a priority queue and a
//! body → contacts adjacency). [`sequential`] is the alternative solver
//! (sequential impulses, `solver = "sequential_impulse"`). Each iteration is reported to an
//! [`Observer`]; [`Silent`] reports nowhere.

pub mod adjacent;
pub mod checks;
pub mod indexed;
pub mod lcp_friction;
pub mod lcp_matrix;
mod lean_prepare;
mod lean_take;
pub mod neighbours;
pub mod observer;
mod phase;
pub mod position;
mod position_table;
pub mod prepare;
pub mod queue;
pub mod row;
pub mod scan;
pub mod sequential;
pub mod simultaneous;
pub mod stop;
pub mod velocity;
pub mod velocity_row;

pub use observer::{Observer, PositionMoves, Silent, VelocityImpulse};
pub use prepare::{
    desired_of, Adjacency, ContactSetup, FrictionData, Prepared, ResolverBody, ResolverContact,
};

use crate::physics::params::{ResolverParams, Solver};
use crate::physics::{c, Real, World};
use queue::{ScanQueue, TournamentTree};

/// Which of the two implementations runs the phases.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Implementation {
    /// The lecture's loop: scan every contact, twice per iteration.
    Scan,
    /// Priority queue and adjacency: touches only the contacts of moved bodies.
    #[default]
    Indexed,
}

impl Implementation {
    pub fn name(self) -> &'static str {
        match self {
            Implementation::Scan => "scan",
            Implementation::Indexed => "indexed",
        }
    }
}

/// The two phases.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    Position,
    Velocity,
}

impl Phase {
    pub fn name(self) -> &'static str {
        match self {
            Phase::Position => "position",
            Phase::Velocity => "velocity",
        }
    }
}

/// What a phase did. `max_before` / `max_after` are the resolver's own
/// bookkeeping (the linearly updated penetrations or desired Δv).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PhaseOutcome<T: Real> {
    pub phase: Phase,
    pub iterations_used: usize,
    pub iteration_limit: usize,
    pub epsilon: T,
    pub max_before: T,
    /// The largest value left and its contact (the first on ties).
    pub max_after: T,
    pub max_after_contact: usize,
    /// True when the limit stopped the phase with a value still above epsilon.
    pub limit_reached: bool,
}

/// The resolver's state: prepared bodies and contacts, and storage allocated
/// once for the indexed implementation.
#[derive(Debug, Clone)]
pub struct Resolver<T: Real> {
    pub bodies: Vec<ResolverBody<T>>,
    pub contacts: Vec<ResolverContact<T>>,
    pub setups: Vec<ContactSetup<T>>,
    pub friction: Vec<FrictionData<T>>,
    pub adjacency: Adjacency,
    pub params: ResolverParams,
    /// World body → resolver body (kept for the next prepare).
    index: Vec<Option<usize>>,
    queue: TournamentTree<T>,
    scan_queue: ScanQueue<T>,
    /// The contacts one iteration changed (scratch, sized at prepare).
    changed: Vec<usize>,
    /// The indexed velocity phase's hot rows (sized at prepare).
    velocity_rows: velocity_row::VelocityRows<T>,
    /// Each contact's neighbours, for the indexed velocity phase (sized at prepare).
    neighbours: neighbours::Neighbours,
    stamps: Vec<usize>,
    stamp: usize,
    /// The largest value of each phase before it ran.
    before: [T; 2],
    /// Sequential impulses' accumulated impulses and moves.
    pub sequential: sequential::State<T>,
    /// The most entries the indexed phases' neighbour table may hold
    /// ([`neighbours::TABLE_BUDGET`]; lower it to try the fallback on a
    /// small scene): beyond it they go through the adjacency ([`Resolver::table_over_budget`]).
    pub table_budget: usize,
    /// The simultaneous (lcp) velocity phase's record, once it ran.
    pub lcp: Option<crate::physics::lcp::Record<T>>,
}

impl<T: Real> Resolver<T> {
    /// Prepares every contact of `world` (nothing in `world` changes).
    pub fn prepare(world: &World<T>, params: &ResolverParams) -> Self {
        let mut r = Resolver {
            bodies: Vec::new(),
            contacts: Vec::new(),
            setups: Vec::new(),
            friction: Vec::new(),
            adjacency: Adjacency::default(),
            params: *params,
            index: Vec::new(),
            queue: TournamentTree::default(),
            scan_queue: ScanQueue::default(),
            changed: Vec::new(),
            velocity_rows: velocity_row::VelocityRows::default(),
            neighbours: neighbours::Neighbours::default(),
            stamps: Vec::new(),
            stamp: 0,
            before: [T::zero(); 2],
            sequential: sequential::State::default(),
            table_budget: neighbours::TABLE_BUDGET,
            lcp: None,
        };
        r.prepare_full_again(world, params);
        r
    }

    /// Prepares `world` again in this resolver's storage: once it has held a
    /// world this size, nothing is allocated (as an engine resolving every
    /// frame would run it). Both solvers take a lean prepare, the same bits
    /// as [`Resolver::prepare_full_again`]: sequential impulses
    /// [`sequential::lean`] (contacts and rows in one pass), the deepest-first
    /// order [`lean_prepare`] (contacts, setups and factored friction
    /// matrices in one pass; κ not computed, as nothing here reports it).
    pub fn prepare_again(&mut self, world: &World<T>, params: &ResolverParams) {
        if params.solver != Solver::SequentialImpulse {
            let mut prepared = self.take_prepared();
            let kept = lean_prepare::prepare(world, params.restitution_from, &mut prepared);
            // The same adjacency as a deepest-first prepare sized the scratch for.
            let sized = kept && self.params.solver != Solver::SequentialImpulse;
            return self.put_prepared(prepared, params, sized);
        }
        if self.params.solver != Solver::SequentialImpulse {
            // Factored by a deepest-first prepare: the lean one keeps only unfactored entries.
            self.friction.clear();
        }
        let mut prepared = self.take_prepared();
        sequential::lean::prepare(
            world,
            params.restitution_from,
            c(params.slip()),
            &mut prepared,
            &mut self.sequential,
        );
        self.put_prepared(prepared, params, false);
    }

    /// [`Resolver::prepare_again`] the full way for either solver: every
    /// contact with the single-contact stages' functions, then (sequential
    /// impulses) the rows from the prepared contacts. What [`Resolver::prepare`]
    /// (the lessons' traces) builds.
    pub fn prepare_full_again(&mut self, world: &World<T>, params: &ResolverParams) {
        let mut prepared = self.take_prepared();
        let inverse_only = params.solver == Solver::SequentialImpulse;
        prepare::prepare_into(world, params.restitution_from, inverse_only, &mut prepared);
        self.put_prepared(prepared, params, false);
        if params.solver == Solver::SequentialImpulse {
            self.sequential.prepare(
                &self.contacts,
                &self.setups,
                &self.bodies,
                &mut self.friction,
                c(params.slip()),
            );
        }
    }

    /// The prepared storage, taken to be filled again.
    fn take_prepared(&mut self) -> prepare::Prepared<T> {
        prepare::Prepared {
            bodies: std::mem::take(&mut self.bodies),
            contacts: std::mem::take(&mut self.contacts),
            setups: std::mem::take(&mut self.setups),
            friction: std::mem::take(&mut self.friction),
            adjacency: std::mem::take(&mut self.adjacency),
            index: std::mem::take(&mut self.index),
        }
    }

    /// Puts `prepared` back and sizes the phases' scratch for it (`sized`:
    /// the deepest-first scratch already fits it, as the last prepare was a
    /// deepest-first one of the same adjacency and contact count).
    fn put_prepared(
        &mut self,
        prepared: prepare::Prepared<T>,
        params: &ResolverParams,
        sized: bool,
    ) {
        let n = prepared.contacts.len();
        self.bodies = prepared.bodies;
        self.contacts = prepared.contacts;
        self.setups = prepared.setups;
        self.friction = prepared.friction;
        self.adjacency = prepared.adjacency;
        self.index = prepared.index;
        self.params = *params;
        // The deepest-first order's scratch (sequential impulses read none of it).
        if params.solver != Solver::SequentialImpulse && !sized {
            self.velocity_rows.reserve(n);
            let mut neighbours = std::mem::take(&mut self.neighbours);
            neighbours.reserve(self);
            self.neighbours = neighbours;
            if n < queue::SCAN_BELOW {
                self.scan_queue.reserve(n);
            } else {
                self.queue.reserve(n);
            }
            // An iteration changes at most the contacts of the taken contact's two bodies.
            let widest = (0..self.bodies.len())
                .map(|b| self.adjacency.of(b).len())
                .max()
                .unwrap_or(0);
            self.changed
                .reserve((2 * widest).saturating_sub(self.changed.len()));
        }
        self.stamps.clear();
        self.stamps.resize(n, 0);
        self.stamp = 0;
        self.before = [T::zero(); 2];
    }

    /// Whether the deepest-first order's neighbour table for these contacts
    /// would hold more entries than [`Resolver::table_budget`]: then the
    /// indexed implementation finds each taken contact's neighbours through
    /// the body → contacts adjacency instead ([`adjacent`]: the same
    /// contacts in the same order, so the same results; one body with tens
    /// of thousands of contacts asks for billions of entries).
    pub fn table_over_budget(&self) -> bool {
        self.params.solver != Solver::SequentialImpulse
            && self.neighbours.wanted() > self.table_budget.min(neighbours::TABLE_BUDGET)
    }

    /// The entries the neighbour table of these contacts would hold (0
    /// under sequential impulses, which use none).
    pub fn table_entries(&self) -> usize {
        if self.params.solver == Solver::SequentialImpulse {
            0
        } else {
            self.neighbours.wanted()
        }
    }

    /// Runs the position phase (the solver of the params; `implementation`
    /// chooses how deepest-first runs).
    pub fn position_phase<O: Observer<T>>(
        &mut self,
        implementation: Implementation,
        obs: &mut O,
    ) -> PhaseOutcome<T> {
        self.before[0] = self.max(Phase::Position).0;
        if self.params.solver == Solver::SequentialImpulse {
            return sequential::position_phase(self, obs);
        }
        match implementation {
            Implementation::Indexed if self.table_over_budget() => {
                adjacent::position_phase(self, obs)
            }
            Implementation::Scan => scan::position_phase(self, obs),
            Implementation::Indexed => indexed::position_phase(self, obs),
        }
    }

    /// Runs the velocity phase.
    pub fn velocity_phase<O: Observer<T>>(
        &mut self,
        implementation: Implementation,
        obs: &mut O,
    ) -> PhaseOutcome<T> {
        self.before[1] = self.max(Phase::Velocity).0;
        if self.params.solver == Solver::SequentialImpulse {
            return sequential::velocity_phase(self, obs);
        }
        if self.params.solver == Solver::Lcp {
            return simultaneous::velocity_phase(self, obs);
        }
        match implementation {
            Implementation::Indexed if self.table_over_budget() => {
                adjacent::velocity_phase(self, obs)
            }
            Implementation::Scan => scan::velocity_phase(self, obs),
            Implementation::Indexed => indexed::velocity_phase(self, obs),
        }
    }

    /// Prepare, position phase, velocity phase.
    pub fn resolve<O: Observer<T>>(
        world: &World<T>,
        params: &ResolverParams,
        implementation: Implementation,
        obs: &mut O,
    ) -> (Self, [PhaseOutcome<T>; 2]) {
        let mut r = Self::prepare(world, params);
        let position = r.position_phase(implementation, obs);
        let velocity = r.velocity_phase(implementation, obs);
        (r, [position, velocity])
    }

    /// Writes the bodies' new state into `world`.
    pub fn write_back(&self, world: &mut World<T>) {
        for b in &self.bodies {
            let state = &mut world.body_mut(b.id).state;
            state.position = b.position;
            state.orientation = b.orientation;
            state.velocity = b.velocity;
            state.angular_velocity = b.angular_velocity;
        }
    }

    /// The iteration limit and epsilon of a phase.
    fn limits(&self, phase: Phase) -> (usize, T) {
        let n = self.contacts.len();
        match phase {
            Phase::Position => (
                self.params.position_limit(n),
                c(self.params.position_epsilon),
            ),
            Phase::Velocity => (
                self.params.velocity_limit(n),
                c(self.params.velocity_epsilon),
            ),
        }
    }

    /// The phase's largest bookkeeping value and its contact (first on ties).
    pub fn max(&self, phase: Phase) -> (T, usize) {
        let value = |c: &ResolverContact<T>| match phase {
            Phase::Position => c.penetration,
            Phase::Velocity => c.desired,
        };
        // With no contacts nothing penetrates and nothing is wanted: 0.
        let Some(first) = self.contacts.first() else {
            return (T::zero(), 0);
        };
        let mut best = (value(first), 0);
        for (k, contact) in self.contacts.iter().enumerate() {
            if value(contact) > best.0 {
                best = (value(contact), k);
            }
        }
        best
    }

    pub(crate) fn finish<O: Observer<T>>(
        &self,
        phase: Phase,
        used: usize,
        obs: &mut O,
    ) -> PhaseOutcome<T> {
        let (limit, epsilon) = self.limits(phase);
        let (max_after, max_after_contact) = self.max(phase);
        let outcome = PhaseOutcome {
            phase,
            iterations_used: used,
            iteration_limit: limit,
            epsilon,
            max_before: self.before[phase as usize],
            max_after,
            max_after_contact,
            limit_reached: used == limit && max_after > epsilon,
        };
        obs.phase_end(phase, &outcome);
        outcome
    }
}
