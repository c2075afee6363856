//! Sequential impulses: the alternative to the lecture's deepest-first order,
//! as Box2D and most engines since resolve a set of contacts. Projected
//! Gauss–Seidel: every contact in file order, sweep after sweep, each visit
//! adding to the contact's ACCUMULATED impulse and clamping the total (normal
//! ≥ 0, friction inside the circular cone μ·P_n), so a later visit can take
//! back what an earlier one over-did. Positions: a Gauss–Seidel sweep over the
//! penetrations, the lecture's projection per contact, accumulated (a contact
//! never pulls its bodies together by more than it pushed them apart).
//!
//! Work is counted in contact visits, the unit of the deepest-first resolver's
//! iterations: a limit of 8 × contacts is 8 sweeps. A phase stops early when a
//! whole sweep changes nothing by more than its epsilon.

pub mod lean;
pub mod position;
pub mod rows;
pub mod velocity;
pub mod warm;

use nalgebra::Vector3;

use super::observer::Observer;
use super::{ContactSetup, Phase, PhaseOutcome, Resolver, ResolverBody, ResolverContact};
use crate::physics::Real;

pub use rows::{Rows, SolverBody};
pub use warm::WarmCache;

/// What sequential impulses keep per contact beside the resolver's own
/// bookkeeping (storage reused from step to step).
#[derive(Debug, Clone)]
pub struct State<T: Real> {
    /// Accumulated impulse per contact, contact space (x along the normal).
    pub accumulated: Vec<Vector3<T>>,
    /// Accumulated projection per contact (depth moved apart so far).
    pub pushed: Vec<T>,
    /// Each contact's Jacobian rows and constants for the velocity visits.
    pub rows: Vec<Rows<T>>,
    /// The bodies' velocities while the velocity phase runs (the world last).
    pub solver: Vec<SolverBody<T>>,
    /// Impulses (world space) to start from, set by [`Resolver::warm_start`].
    pub warm: Vec<Option<Vector3<T>>>,
    /// Whether the velocity phase's end brings each contact's whole
    /// bookkeeping velocity up to date (the default), or, when nothing
    /// records, only its normal part, all that its desired Δv reads: for a
    /// caller that reads nothing else of the contacts' velocities after the
    /// phase (a time step).
    pub whole_velocities: bool,
}

impl<T: Real> Default for State<T> {
    fn default() -> Self {
        State {
            accumulated: Vec::new(),
            pushed: Vec::new(),
            rows: Vec::new(),
            solver: Vec::new(),
            warm: Vec::new(),
            whole_velocities: true,
        }
    }
}

impl<T: Real> State<T> {
    /// Sets the state up for the prepared contacts of `r` (`slip_speed`:
    /// the stick/slip threshold).
    pub fn prepare(
        &mut self,
        contacts: &[ResolverContact<T>],
        setups: &[ContactSetup<T>],
        bodies: &[ResolverBody<T>],
        friction: &mut [super::FrictionData<T>],
        slip_speed: T,
    ) {
        let n = contacts.len();
        self.accumulated.clear();
        self.accumulated.resize(n, Vector3::zeros());
        self.pushed.clear();
        self.pushed.resize(n, T::zero());
        self.warm.clear();
        self.warm.resize(n, None);
        rows::solver_bodies(bodies, &mut self.solver);
        rows::build(
            contacts,
            setups,
            bodies,
            friction,
            &self.solver,
            slip_speed,
            &mut self.rows,
        );
    }

    /// The solver bodies' velocities into the resolver's bodies.
    pub fn write_velocities(&self, bodies: &mut [ResolverBody<T>]) {
        for (body, s) in bodies.iter_mut().zip(&self.solver) {
            body.velocity = s.v;
            body.angular_velocity = s.w;
        }
    }
}

/// The contact velocity the bodies give now, contact space, as the stage
/// maths write it: `Cᵀ Σ s_i (v_i + ω_i × r_i)` (s = +1 for body 1, -1 for
/// body 2). The visits read [`Rows::velocity`] instead; this is the
/// reference the rows are checked against.
pub fn body_velocity<T: Real>(k: &ResolverContact<T>, bodies: &[ResolverBody<T>]) -> Vector3<T> {
    let mut v = Vector3::zeros();
    for (i, slot) in k.bodies.iter().enumerate() {
        if let Some(b) = slot {
            let b = &bodies[*b];
            let point = b.velocity + b.angular_velocity.cross(&k.r[i]);
            v += if i == 0 { point } else { -point };
        }
    }
    k.basis.tr_mul(&v)
}

/// The position phase: Gauss–Seidel sweeps over the penetrations.
pub fn position_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(Phase::Position);
    let n = r.contacts.len();
    let mut used = 0;
    'sweeps: while n > 0 && used < limit {
        let mut moved = false;
        for k in 0..n {
            if used == limit {
                break 'sweeps;
            }
            moved |= position::visit(r, k, used, epsilon, obs);
            used += 1;
        }
        if !moved {
            break;
        }
    }
    r.finish(Phase::Position, used, obs)
}

/// The velocity phase: warm start (if asked), then projected Gauss–Seidel sweeps.
pub fn velocity_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(Phase::Velocity);
    rows::solver_bodies(&r.bodies, &mut r.sequential.solver);
    if r.params.warm_start {
        velocity::apply_warm_start(r);
        if O::RECORDS {
            r.sequential.write_velocities(&mut r.bodies);
        }
    }
    let n = r.contacts.len();
    let mut used = 0;
    if O::RECORDS {
        'sweeps: while n > 0 && used < limit {
            let mut largest = T::zero();
            for k in 0..n {
                if used == limit {
                    break 'sweeps;
                }
                largest = largest.max(velocity::visit(r, k, used, obs));
                used += 1;
            }
            if largest <= epsilon {
                break;
            }
        }
    } else {
        // Nothing records: the same visits in the same order, each sweep
        // over the rows and accumulated impulses side by side (a sweep the
        // limit cuts short stops there, as above).
        let State {
            rows,
            accumulated,
            solver,
            ..
        } = &mut r.sequential;
        while n > 0 && used < limit {
            let sweep = n.min(limit - used);
            let mut largest = T::zero();
            for (rows, accumulated) in rows[..sweep].iter().zip(&mut accumulated[..sweep]) {
                largest = largest.max(velocity::silent_visit(rows, accumulated, solver));
            }
            used += sweep;
            if sweep < n || largest <= epsilon {
                break;
            }
        }
    }
    r.sequential.write_velocities(&mut r.bodies);
    let State {
        rows,
        solver,
        whole_velocities,
        ..
    } = &r.sequential;
    // The bookkeeping velocities and desired Δv, from the bodies as they are now.
    let from = r.params.restitution_from;
    let whole = O::RECORDS || *whole_velocities;
    for (contact, rows) in r.contacts.iter_mut().zip(rows) {
        if whole {
            contact.velocity = rows.velocity(solver);
        } else {
            contact.velocity.x = rows.normal_velocity(solver);
        }
        contact.desired = super::desired_of(contact, from);
    }
    r.finish(Phase::Velocity, used, obs)
}
