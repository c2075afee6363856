//! The velocity phase's two per-contact steps, shared by both implementations
//! so they perform the same floating-point operations:
//! - [`take`]: the impulse of one contact (frictionless `Δv/Δq̇_t`, or the
//!   3×3 sticking impulse and the friction clamp of its model), applied to its bodies;
//! - [`updated_velocity`]: a contact's velocity after the taken contact changed
//!   bodies it shares, `v_j += s·Cⱼᵀ(Δv + Δω × r_j)` (s = +1 for body 1 of
//!   contact j, -1 for body 2); its desired Δv is then recomputed.

use nalgebra::Vector3;

use super::lean_take as lean;
use super::observer::VelocityImpulse;
use super::{ContactSetup, FrictionData, ResolverBody, ResolverContact};
use crate::physics::stages::apply_impulse::{body_velocity_change, BodyVelocityChange};
use crate::physics::stages::friction::{clamp, ClampInputs};
use crate::physics::stages::impulse::impulse_contact;
use crate::physics::stages::FrictionRegime;
use crate::physics::{FrictionModel, Problem, Real};

/// The impulse of contact `c` for its bookkeeping desired Δv and velocity,
/// applied to its bodies.
pub fn take<T: Real>(
    c: &ResolverContact<T>,
    setup: &ContactSetup<T>,
    friction: Option<&FrictionData<T>>,
    bodies: &mut [ResolverBody<T>],
) -> VelocityImpulse<T> {
    let (impulse_contact, regime) = impulse_of(c, setup, friction);
    apply_impulse(c, bodies, impulse_contact, regime)
}

/// [`take`] on the fast path (nothing records): the same impulse applied
/// with the same operations, returning only the compact changes the
/// neighbour updates read (no [`VelocityImpulse`] record is built).
pub fn take_changes<T: Real>(
    c: &ResolverContact<T>,
    setup: &ContactSetup<T>,
    friction: Option<&FrictionData<T>>,
    bodies: &mut [ResolverBody<T>],
) -> BodyChanges<T> {
    let impulse_contact = match friction {
        // The lecture's clamp, lean (one solve, inlined here).
        Some(f) if f.model == FrictionModel::Millington => {
            let (g, _) = impulse_contact(
                c.desired,
                &c.velocity,
                setup.unit_total,
                Some(&f.matrix),
                true,
            );
            lean::millington_clamp(g, f, c.desired, setup.unit_total)
        }
        _ => impulse_elsewise(c, setup, friction),
    };
    let impulse_world = c.basis * impulse_contact;
    let mut out = BodyChanges {
        bodies: [usize::MAX; 2],
        dv: [Vector3::zeros(); 2],
        dw: [Vector3::zeros(); 2],
    };
    apply_world(c, bodies, &impulse_world, |i, b, change| {
        out.bodies[i] = b;
        out.dv[i] = change.dv;
        out.dw[i] = change.dw;
    });
    out
}

/// Applies `impulse_world` of contact `c` to each of its bodies (body 2
/// the negated impulse), handing `record` the slot, the resolver body and
/// its change.
#[inline(always)]
fn apply_world<T: Real>(
    c: &ResolverContact<T>,
    bodies: &mut [ResolverBody<T>],
    impulse_world: &Vector3<T>,
    mut record: impl FnMut(usize, usize, BodyVelocityChange<T>),
) {
    for (i, slot) in c.bodies.iter().enumerate() {
        let Some(b) = *slot else { continue };
        let body = &mut bodies[b];
        let change = body_velocity_change(
            body.inverse_mass,
            &body.inverse_inertia_world,
            &c.r[i],
            impulse_world,
            Problem::<T>::sign(i),
            (&body.velocity, &body.angular_velocity),
        );
        body.velocity = change.v;
        body.angular_velocity = change.w;
        record(i, b, change);
    }
}

/// [`impulse_of`]'s impulse for [`take_changes`] without Millington
/// friction, kept out of line (so the lean path's solve is inlined there).
#[inline(never)]
fn impulse_elsewise<T: Real>(
    c: &ResolverContact<T>,
    setup: &ContactSetup<T>,
    friction: Option<&FrictionData<T>>,
) -> Vector3<T> {
    impulse_of(c, setup, friction).0
}

/// The contact-space impulse of contact `c` (frictionless `Δv/Δq̇_t`, or the
/// sticking impulse and its friction clamp) and the friction regime.
#[inline(always)]
fn impulse_of<T: Real>(
    c: &ResolverContact<T>,
    setup: &ContactSetup<T>,
    friction: Option<&FrictionData<T>>,
) -> (Vector3<T>, Option<FrictionRegime>) {
    let sticking = friction.is_some_and(|f| f.model != FrictionModel::KineticDirection);
    let (g, _) = impulse_contact(
        c.desired,
        &c.velocity,
        setup.unit_total,
        friction.map(|f| &f.matrix),
        sticking,
    );
    match friction {
        None => (g, None),
        Some(f) => {
            let clamped = clamp(ClampInputs {
                model: f.model,
                static_friction: f.static_friction,
                dynamic_friction: f.dynamic_friction,
                impulse_contact: g,
                contact_velocity: c.velocity,
                desired: c.desired,
                total: setup.unit_total,
                matrix: Some(&f.matrix),
                // The normal impulse that meets Δv (the closed form's j without acceleration).
                closed_form_j: c.desired / setup.unit_total,
                contact_to_world: &c.basis,
            });
            (clamped.impulse_contact, Some(clamped.regime))
        }
    }
}

/// Applies the contact-space impulse `impulse_contact` of contact `c` to its
/// bodies (body 2 receives the negated impulse) and records the changes.
#[inline]
pub fn apply_impulse<T: Real>(
    c: &ResolverContact<T>,
    bodies: &mut [ResolverBody<T>],
    impulse_contact: Vector3<T>,
    regime: Option<FrictionRegime>,
) -> VelocityImpulse<T> {
    let impulse_world = c.basis * impulse_contact;
    let mut changes = [None, None];
    apply_world(c, bodies, &impulse_world, |i, _, change| {
        changes[i] = Some(change)
    });
    VelocityImpulse {
        slots: c.bodies,
        impulse_contact,
        impulse_world,
        regime,
        bodies: changes,
    }
}

/// The velocity changes one taken contact made, by resolver body, compact
/// for the neighbour updates (a slot with no body holds `usize::MAX`, which
/// no contact's body equals).
#[derive(Debug, Clone, Copy)]
pub struct BodyChanges<T: Real> {
    pub bodies: [usize; 2],
    pub dv: [Vector3<T>; 2],
    pub dw: [Vector3<T>; 2],
}

impl<T: Real> BodyChanges<T> {
    /// The changes `impulse` records for the slots `taken`.
    pub fn of(taken: &[Option<usize>; 2], impulse: &VelocityImpulse<T>) -> Self {
        let mut out = BodyChanges {
            bodies: [usize::MAX; 2],
            dv: [Vector3::zeros(); 2],
            dw: [Vector3::zeros(); 2],
        };
        for (d, (slot, change)) in taken.iter().zip(&impulse.bodies).enumerate() {
            if let (Some(b), Some(m)) = (slot, change) {
                out.bodies[d] = *b;
                out.dv[d] = m.dv;
                out.dw[d] = m.dw;
            }
        }
        out
    }

    /// The slot of the taken contact that changed `body` (a body is in at
    /// most one slot of a contact).
    #[inline(always)]
    fn slot_of(&self, body: Option<usize>) -> Option<usize> {
        let body = body?;
        if self.bodies[0] == body {
            Some(0)
        } else if self.bodies[1] == body {
            Some(1)
        } else {
            None
        }
    }
}

/// The contact velocity of `c` after the taken contact (slots `taken`)
/// applied `impulse`, in the reference engine's order (slot of `c`, then
/// slot of the taken contact).
pub fn updated_velocity<T: Real>(
    c: &ResolverContact<T>,
    taken: &[Option<usize>; 2],
    impulse: &VelocityImpulse<T>,
) -> Vector3<T> {
    velocity_after(c, &BodyChanges::of(taken, impulse))
}

/// [`updated_velocity`] from the compact changes: `v_j += s·Cⱼᵀ(Δv + Δω × r_j)`
/// for each slot of `c` whose body changed, slot 1 first (the same operations
/// in the same order).
#[inline(always)]
pub fn velocity_after<T: Real>(c: &ResolverContact<T>, changes: &BodyChanges<T>) -> Vector3<T> {
    let mut velocity = c.velocity;
    // Body 1 of `c` gains the change, body 2 loses it (`a − b` is `a + (−b)` exactly).
    if let Some(d) = changes.slot_of(c.bodies[0]) {
        velocity += to_contact(&c.basis, &(changes.dv[d] + changes.dw[d].cross(&c.r[0])));
    }
    if let Some(d) = changes.slot_of(c.bodies[1]) {
        velocity -= to_contact(&c.basis, &(changes.dv[d] + changes.dw[d].cross(&c.r[1])));
    }
    velocity
}

/// `Cᵀ v`: a world vector in the contact's basis, each component the dot
/// product of a basis column with `v` (as `tr_mul` forms it, unrolled).
#[inline(always)]
fn to_contact<T: Real>(basis: &nalgebra::Matrix3<T>, v: &Vector3<T>) -> Vector3<T> {
    let dot = |k: usize| basis[(0, k)] * v.x + basis[(1, k)] * v.y + basis[(2, k)] * v.z;
    Vector3::new(dot(0), dot(1), dot(2))
}
