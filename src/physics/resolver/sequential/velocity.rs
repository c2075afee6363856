//! One visit of the sequential-impulse velocity phase (projected Gauss–Seidel):
//! the impulse that would meet the contact's target velocity now is added to
//! its accumulated impulse, the total is clamped, and only the change is
//! applied to the bodies.
//!
//! - target normal velocity `-e (v₀ - v_acc)` from the pre-solve velocity `v₀`
//!   (restitution from the initial velocity, as Box2D does), so the Δv wanted
//!   now is `-v - e (v₀ - v_acc)`;
//! - frictionless: `Δλ = Δv / Δq̇_t`, then `λ ← max(λ + Δλ, 0)`;
//! - with friction: `Δg = M⁻¹ (Δv, -v_t0, -v_t1)` (the lecture's sticking
//!   impulse), `g ← g + Δg`, `g_n ← max(g_n, 0)`, and where
//!   `|g_t| > μ_s g_n` the tangential part is scaled to `μ_d g_n` (circular cone).
//!
//! The first visit of a contact therefore applies exactly the lecture's impulse.

use nalgebra::Vector3;

use super::super::observer::{Observer, VelocityImpulse};
use super::super::velocity::apply_impulse;
use super::super::Resolver;
use super::body_velocity;
use crate::physics::stages::desired_velocity::{applied_restitution, desired_toward_bounce};
use crate::physics::stages::FrictionRegime;
use crate::physics::Real;

/// Clamps an accumulated contact-space impulse: normal ≥ 0, tangential inside
/// the cone (`|g_t| ≤ μ_s g_n`, else scaled to `μ_d g_n`).
pub fn clamp_accumulated<T: Real>(
    g: Vector3<T>,
    friction: Option<(T, T)>,
) -> (Vector3<T>, Option<FrictionRegime>) {
    let n = g.x.max(T::zero());
    let Some((mu_s, mu_d)) = friction else {
        return (Vector3::new(n, T::zero(), T::zero()), None);
    };
    let planar = (g.y * g.y + g.z * g.z).sqrt();
    if planar <= mu_s * n {
        (Vector3::new(n, g.y, g.z), Some(FrictionRegime::Static))
    } else {
        let scale = mu_d * n / planar;
        (
            Vector3::new(n, g.y * scale, g.z * scale),
            Some(FrictionRegime::Dynamic),
        )
    }
}

/// Applies the contact-space impulse `delta` of contact `k` to its bodies.
fn apply<T: Real>(r: &mut Resolver<T>, k: usize, delta: &Vector3<T>) -> VelocityImpulse<T> {
    apply_impulse(&r.contacts[k], &mut r.bodies, *delta, None)
}

/// Visits contact `k` (visit number `visit`): returns how much it changed the
/// contact's velocity, `|Δg| Δq̇_t`.
pub fn visit<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    k: usize,
    visit: usize,
    obs: &mut O,
) -> T {
    let contact = &r.contacts[k];
    let setup = &r.setups[k];
    let v = body_velocity(contact, &r.bodies) + r.sequential.offset[k];
    let v0 = contact.initial_velocity;
    let (e, _) = applied_restitution(v0, contact.restitution, contact.velocity_limit);
    let desired = desired_toward_bounce(v.x, v0, e, contact.velocity_from_acceleration);
    let old = r.sequential.accumulated[k];
    let friction = setup.friction.map(|f| &r.friction[f]);
    let inverse = setup.friction.and_then(|f| r.sequential.inverse[f]);
    let (total, regime) = match (friction, inverse) {
        (Some(f), Some(m_inv)) => {
            let step = m_inv * Vector3::new(desired, -v.y, -v.z);
            clamp_accumulated(old + step, Some((f.static_friction, f.dynamic_friction)))
        }
        // Frictionless (or an M that cannot be inverted): along the normal only.
        _ => {
            let step = Vector3::new(desired / setup.unit_total, T::zero(), T::zero());
            let cone = friction.map(|f| (f.static_friction, f.dynamic_friction));
            clamp_accumulated(old + step, cone)
        }
    };
    let delta = total - old;
    if delta == Vector3::zeros() {
        return T::zero();
    }
    obs.before_velocity(visit, k, &r.bodies);
    r.sequential.accumulated[k] = total;
    let mut impulse = apply(r, k, &delta);
    impulse.regime = regime;
    obs.velocity_taken(visit, k, desired, &impulse);
    // The visited contact's own Δv wanted after the visit (≈ 0 unless clamped).
    let after = body_velocity(&r.contacts[k], &r.bodies).x + r.sequential.offset[k].x;
    obs.desired_updated(k, desired, desired - (after - v.x));
    delta.norm() * r.setups[k].unit_total
}

/// Applies the warm-start impulses (world space, set by
/// [`Resolver::warm_start`]) as the contacts' starting accumulated impulses,
/// clamped to the contact's cone in its new basis.
pub fn apply_warm_start<T: Real>(r: &mut Resolver<T>) {
    for k in 0..r.contacts.len() {
        let Some(world) = r.sequential.warm[k].take() else {
            continue;
        };
        let contact = &r.contacts[k];
        let friction = r.setups[k].friction.map(|f| {
            (
                r.friction[f].static_friction,
                r.friction[f].dynamic_friction,
            )
        });
        let (g, _) = clamp_accumulated(contact.basis.tr_mul(&world), friction);
        if g == Vector3::zeros() {
            continue;
        }
        r.sequential.accumulated[k] = g;
        apply(r, k, &g);
    }
}
