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
//!   impulse), `g ← g + Δg`, `g_n ← max(g_n, 0)`, and where `|g_t| > μ g_n`
//!   the tangential part is scaled to `μ g_n` (circular cone). Each contact
//!   has ONE cone for the step: `μ = μ_s` if it sticks when the step begins
//!   (slip `|v_t - a_t Δt| ≤ slip_speed`, by default the velocity epsilon), `μ_d` if it slides (Coulomb);
//!   an iterate that leaves the cone is scaled back onto the same cone. A
//!   SLIDING contact's clamped iterate is put on the rim against its slip
//!   velocity, with the normal part solved again so the normal target holds
//!   ([`on_the_rim`], the lecture's dynamic impulse accumulated): friction
//!   then opposes the slip (Coulomb) and does not push the bodies apart.
//!
//! The first visit of a contact therefore applies exactly the lecture's impulse.

use nalgebra::{Matrix3, Vector3};

use super::super::observer::{Observer, VelocityImpulse};
use super::super::velocity::apply_impulse;
use super::super::Resolver;
use super::body_velocity;
use crate::physics::stages::desired_velocity::{applied_restitution, desired_toward_bounce};
use crate::physics::stages::FrictionRegime;
use crate::physics::{c, Real};

/// Clamps an accumulated contact-space impulse: normal ≥ 0, tangential inside
/// the cone of radius `mu` (`|g_t| ≤ μ g_n`, else scaled to `μ g_n`). The
/// regime is static where the tangential part was inside, dynamic where scaled.
pub fn clamp_accumulated<T: Real>(
    g: Vector3<T>,
    mu: Option<T>,
) -> (Vector3<T>, Option<FrictionRegime>) {
    let n = g.x.max(T::zero());
    let Some(mu) = mu else {
        return (Vector3::new(n, T::zero(), T::zero()), None);
    };
    let planar = (g.y * g.y + g.z * g.z).sqrt();
    if planar <= mu * n {
        (Vector3::new(n, g.y, g.z), Some(FrictionRegime::Static))
    } else {
        let scale = mu * n / planar;
        (
            Vector3::new(n, g.y * scale, g.z * scale),
            Some(FrictionRegime::Dynamic),
        )
    }
}

/// The accumulated impulse of a clamped visit with the friction on the rim
/// in the direction `u` of `along`'s tangential part (`g_t = μ g_n u`) and the normal part that
/// meets the Δv wanted along the normal: row 0 of `M (g - g_old) = Δv` gives
/// `g_n = (Δv + M₀·g_old) / (M₀₀ + μ (M₀₁ u_y + M₀₂ u_z))` (the lecture's
/// dynamic friction for `g_old = 0`). `None` where the denominator or `g_n`
/// is not positive (jamming): the plain clamp stands.
pub fn on_the_rim<T: Real>(
    old: &Vector3<T>,
    along: &Vector3<T>,
    mu: T,
    m: &Matrix3<T>,
    desired: T,
) -> Option<Vector3<T>> {
    let planar = (along.y * along.y + along.z * along.z).sqrt();
    if planar <= T::zero() {
        return None;
    }
    let (uy, uz) = (along.y / planar, along.z / planar);
    let per_unit = m[(0, 0)] + mu * (m[(0, 1)] * uy + m[(0, 2)] * uz);
    let gn = (desired + m.row(0).dot(&old.transpose())) / per_unit;
    (per_unit > T::zero() && gn > T::zero() && gn.is_finite())
        .then(|| Vector3::new(gn, mu * gn * uy, mu * gn * uz))
}

/// The radius of contact `k`'s friction cone this step (Coulomb): `μ_s` if
/// its slip before this step's accelerations is within `slip_speed`,
/// else `μ_d`; `None` without friction.
pub fn cone<T: Real>(r: &Resolver<T>, k: usize) -> Option<T> {
    let setup = &r.setups[k];
    let f = &r.friction[setup.friction?];
    if sliding(r, k) {
        Some(f.dynamic_friction)
    } else {
        Some(f.static_friction)
    }
}

/// Whether contact `k` slides when the step begins: its slip before this
/// step's accelerations exceeds `slip_speed` (the stick/slip threshold).
pub fn sliding<T: Real>(r: &Resolver<T>, k: usize) -> bool {
    r.setups[k].slip > c::<T>(r.params.slip())
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
    let mu = cone(r, k);
    let inverse = setup.friction.and_then(|f| r.sequential.inverse[f]);
    let step = match inverse {
        Some(m_inv) => m_inv * Vector3::new(desired, -v.y, -v.z),
        // Frictionless (or an M that cannot be inverted): along the normal only.
        None => Vector3::new(desired / setup.unit_total, T::zero(), T::zero()),
    };
    let (mut total, regime) = clamp_accumulated(old + step, mu);
    // A sliding contact pushed off its cone: friction on the rim against the
    // slip now, the normal part solved again so the normal target holds.
    if let (Some(FrictionRegime::Dynamic), Some(mu), Some(f)) = (regime, mu, setup.friction) {
        if sliding(r, k) {
            let against = Vector3::new(T::zero(), -v.y, -v.z);
            let m = &r.friction[f].matrix.matrix;
            if let Some(g) = on_the_rim(&old, &against, mu, m, desired) {
                total = g;
            }
        }
    }
    let delta = total - old;
    if delta == Vector3::zeros() {
        return T::zero();
    }
    obs.before_velocity(visit, k, &r.bodies);
    r.sequential.accumulated[k] = total;
    let mut impulse = apply(r, k, &delta);
    impulse.regime = regime;
    obs.velocity_taken(visit, k, desired, &impulse);
    // The visited contact's own Δv wanted after the visit (≈ 0 unless
    // clamped): for the reports only.
    if O::RECORDS {
        let after = body_velocity(&r.contacts[k], &r.bodies).x + r.sequential.offset[k].x;
        obs.desired_updated(k, desired, desired - (after - v.x));
    }
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
        let (g, _) = clamp_accumulated(r.contacts[k].basis.tr_mul(&world), cone(r, k));
        if g == Vector3::zeros() {
            continue;
        }
        r.sequential.accumulated[k] = g;
        apply(r, k, &g);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_clamp_scales_onto_the_one_cone_it_is_given() {
        let g = Vector3::new(2.0, 1.5, 0.0);
        let (inside, regime) = clamp_accumulated(g, Some(0.8));
        assert_eq!((inside, regime), (g, Some(FrictionRegime::Static)));
        // |g_t| = 1.5 > 0.5 · 2: scaled to 1.0, not to some other radius.
        let (rim, regime) = clamp_accumulated(g, Some(0.5));
        assert_eq!(regime, Some(FrictionRegime::Dynamic));
        assert!(
            (rim - Vector3::new(2.0, 1.0, 0.0)).norm() < 1e-15,
            "{rim:?}"
        );
    }

    #[test]
    fn on_the_rim_meets_the_normal_target_with_friction_against_the_slip() {
        let m: Matrix3<f64> = Matrix3::new(2.0, 0.5, 0.1, 0.5, 3.0, 0.2, 0.1, 0.2, 2.5);
        let old = Vector3::new(0.3, -0.1, 0.05);
        let (mu, desired): (f64, f64) = (0.4, 0.7);
        let against = Vector3::new(0.0, -3.0, 4.0);
        let g = on_the_rim(&old, &against, mu, &m, desired).unwrap();
        // Row 0 of M (g - g_old) is the Δv wanted along the normal.
        assert!((m.row(0).dot(&(g - old).transpose()) - desired).abs() < 1e-12);
        // The tangential part is μ g_n along (-3, 4)/5.
        let t = Vector3::new(0.0, -0.6 * mu * g.x, 0.8 * mu * g.x);
        assert!((Vector3::new(0.0, g.y, g.z) - t).norm() < 1e-12, "{g:?}");
        // No slip direction: no rim.
        assert_eq!(on_the_rim(&old, &Vector3::x(), mu, &m, desired), None);
    }
}
