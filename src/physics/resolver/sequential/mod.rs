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

pub mod position;
pub mod velocity;
pub mod warm;

use nalgebra::{Matrix3, Vector3};

use super::observer::Observer;
use super::{Phase, PhaseOutcome, Resolver, ResolverBody, ResolverContact};
use crate::physics::Real;

pub use warm::WarmCache;

/// What sequential impulses keep per contact beside the resolver's own
/// bookkeeping (storage reused from step to step).
#[derive(Debug, Clone)]
pub struct State<T: Real> {
    /// Accumulated impulse per contact, contact space (x along the normal).
    pub accumulated: Vec<Vector3<T>>,
    /// Accumulated projection per contact (depth moved apart so far).
    pub pushed: Vec<T>,
    /// `M⁻¹` of each contact with friction (indexed like the friction data).
    pub inverse: Vec<Option<Matrix3<T>>>,
    /// The part of the prepared contact velocity the bodies do not give
    /// (the anticipated planar acceleration).
    pub offset: Vec<Vector3<T>>,
    /// Impulses (world space) to start from, set by [`Resolver::warm_start`].
    pub warm: Vec<Option<Vector3<T>>>,
}

impl<T: Real> Default for State<T> {
    fn default() -> Self {
        State {
            accumulated: Vec::new(),
            pushed: Vec::new(),
            inverse: Vec::new(),
            offset: Vec::new(),
            warm: Vec::new(),
        }
    }
}

impl<T: Real> State<T> {
    /// Sets the state up for the prepared contacts of `r`.
    pub fn prepare(
        &mut self,
        contacts: &[ResolverContact<T>],
        bodies: &[ResolverBody<T>],
        friction: &[super::FrictionData<T>],
    ) {
        let n = contacts.len();
        self.accumulated.clear();
        self.accumulated.resize(n, Vector3::zeros());
        self.pushed.clear();
        self.pushed.resize(n, T::zero());
        self.warm.clear();
        self.warm.resize(n, None);
        self.offset.clear();
        self.offset.extend(
            contacts
                .iter()
                .map(|k| k.velocity - body_velocity(k, bodies)),
        );
        self.inverse.clear();
        self.inverse
            .extend(friction.iter().map(|f| f.matrix.cholesky_inverse()));
    }
}

/// The contact velocity the bodies give now, contact space:
/// `Cᵀ Σ s_i (v_i + ω_i × r_i)` (s = +1 for body 1, -1 for body 2).
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
    if r.params.warm_start {
        velocity::apply_warm_start(r);
    }
    let n = r.contacts.len();
    let mut used = 0;
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
    // The bookkeeping velocities and desired Δv, from the bodies as they are now.
    let from = r.params.restitution_from;
    for (k, contact) in r.contacts.iter_mut().enumerate() {
        contact.velocity = body_velocity(contact, &r.bodies) + r.sequential.offset[k];
        contact.desired = super::desired_of(contact, from);
    }
    r.finish(Phase::Velocity, used, obs)
}
