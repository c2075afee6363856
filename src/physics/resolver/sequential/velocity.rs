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
//! The first visit of a contact therefore applies the lecture's impulse (its
//! arithmetic reordered through the contact's Jacobian rows, [`super::rows`]:
//! equal to the last bits).

use nalgebra::Vector3;

use super::super::observer::{Observer, VelocityImpulse};
use super::super::Resolver;
use super::{Rows, SolverBody, State};
use crate::physics::stages::{BodyVelocityChange, FrictionRegime};
use crate::physics::{Problem, Real};

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
/// meets the Δv wanted along the normal: row 0 of `M (g - g_old) = Δv`
/// (`m0` is that row) gives
/// `g_n = (Δv + M₀·g_old) / (M₀₀ + μ (M₀₁ u_y + M₀₂ u_z))` (the lecture's
/// dynamic friction for `g_old = 0`). `None` where the denominator or `g_n`
/// is not positive (jamming): the plain clamp stands.
pub fn on_the_rim<T: Real>(
    old: &Vector3<T>,
    along: &Vector3<T>,
    mu: T,
    m0: &Vector3<T>,
    desired: T,
) -> Option<Vector3<T>> {
    let planar = (along.y * along.y + along.z * along.z).sqrt();
    if planar <= T::zero() {
        return None;
    }
    let (uy, uz) = (along.y / planar, along.z / planar);
    let per_unit = m0.x + mu * (m0.y * uy + m0.z * uz);
    let gn = (desired + m0.dot(old)) / per_unit;
    (per_unit > T::zero() && gn > T::zero() && gn.is_finite())
        .then(|| Vector3::new(gn, mu * gn * uy, mu * gn * uz))
}

/// The radius of contact `k`'s friction cone this step (Coulomb): `μ_s` if
/// its slip before this step's accelerations is within `slip_speed`,
/// else `μ_d`; `None` without friction.
pub fn cone<T: Real>(r: &Resolver<T>, k: usize) -> Option<T> {
    let rows = &r.sequential.rows[k];
    rows.friction.then_some(rows.mu)
}

/// Whether contact `k` slides when the step begins: its slip before this
/// step's accelerations exceeds `slip_speed` (the stick/slip threshold).
pub fn sliding<T: Real>(r: &Resolver<T>, k: usize) -> bool {
    r.sequential.rows[k].sliding
}

/// What a recording observer is told of an impulse `g` (contact space,
/// world `p`) the rows of contact `k` applied; the bodies' velocities after
/// it are copied into the resolver's bodies.
fn recorded<T: Real>(
    r: &mut Resolver<T>,
    k: usize,
    g: &Vector3<T>,
    p: &Vector3<T>,
) -> VelocityImpulse<T> {
    let slots = r.contacts[k].bodies;
    let rows = &r.sequential.rows[k];
    let mut changes = [None, None];
    for (i, slot) in slots.iter().enumerate() {
        let Some(b) = *slot else { continue };
        let s = r.sequential.solver[b];
        let impulse = p * Problem::<T>::sign(i);
        changes[i] = Some(BodyVelocityChange {
            impulse,
            impulsive_torque: r.contacts[k].r[i].cross(&impulse),
            dv: p * rows.inverse_mass[i],
            dw: rows.turn[i] * g,
            v: s.v,
            w: s.w,
        });
        r.bodies[b].velocity = s.v;
        r.bodies[b].angular_velocity = s.w;
    }
    VelocityImpulse {
        slots,
        impulse_contact: *g,
        impulse_world: *p,
        regime: None,
        bodies: changes,
    }
}

/// The visit's arithmetic on contact rows `rows` with accumulated impulse
/// `old`: the contact velocity now, the Δv wanted along the normal, the new
/// accumulated impulse (clamped; on the rim for a sliding contact pushed off
/// its cone) and the regime. Both visits ([`visit`], [`silent_visit`]) run
/// it, so they give the same bits.
#[inline(always)]
fn solve<T: Real>(
    rows: &Rows<T>,
    solver: &[SolverBody<T>],
    old: &Vector3<T>,
) -> (Vector3<T>, T, Vector3<T>, Option<FrictionRegime>) {
    let v = rows.velocity(solver);
    let desired = -v.x - rows.bounce;
    let step = rows.inverse * Vector3::new(desired, -v.y, -v.z);
    let (mut total, regime) = clamp_accumulated(old + step, rows.friction.then_some(rows.mu));
    // A sliding contact pushed off its cone: friction on the rim against the
    // slip now, the normal part solved again so the normal target holds.
    if rows.sliding && regime == Some(FrictionRegime::Dynamic) {
        let against = Vector3::new(T::zero(), -v.y, -v.z);
        if let Some(g) = on_the_rim(old, &against, rows.mu, &rows.normal_row, desired) {
            total = g;
        }
    }
    (v, desired, total, regime)
}

/// A visit nothing records: [`visit`]'s arithmetic on the contact's rows,
/// its accumulated impulse and the solver bodies alone (no resolver, no
/// index into the contacts); returns `|Δg| Δq̇_t`.
#[inline(always)]
pub fn silent_visit<T: Real>(
    rows: &Rows<T>,
    accumulated: &mut Vector3<T>,
    solver: &mut [SolverBody<T>],
) -> T {
    let old = *accumulated;
    let (_, _, total, _) = solve(rows, solver, &old);
    let delta = total - old;
    if delta == Vector3::zeros() {
        return T::zero();
    }
    *accumulated = total;
    rows.apply(solver, &delta);
    delta.norm() * rows.unit_total
}

/// Visits contact `k` (visit number `visit`): returns how much it changed the
/// contact's velocity, `|Δg| Δq̇_t`. Straight-line on the contact's rows
/// and the solver bodies (`g ← clamp(g + M⁻¹ (Δv, -v_t0, -v_t1))`).
#[inline]
pub fn visit<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    k: usize,
    visit: usize,
    obs: &mut O,
) -> T {
    let state = &mut r.sequential;
    let old = state.accumulated[k];
    let (v, desired, total, regime) = solve(&state.rows[k], &state.solver, &old);
    let delta = total - old;
    if delta == Vector3::zeros() {
        return T::zero();
    }
    let change = delta.norm() * state.rows[k].unit_total;
    if O::RECORDS {
        obs.before_velocity(visit, k, &r.bodies);
    }
    let state = &mut r.sequential;
    state.accumulated[k] = total;
    let p = state.rows[k].apply(&mut state.solver, &delta);
    if O::RECORDS {
        let mut impulse = recorded(r, k, &delta, &p);
        impulse.regime = regime;
        obs.velocity_taken(visit, k, desired, &impulse);
        // The visited contact's own Δv wanted after the visit (≈ 0 unless
        // clamped): for the reports only.
        let after = r.sequential.rows[k].velocity(&r.sequential.solver).x;
        obs.desired_updated(k, desired, desired - (after - v.x));
    }
    change
}

/// Applies the warm-start impulses (world space, set by
/// [`Resolver::warm_start`]) as the contacts' starting accumulated impulses,
/// clamped to the contact's cone in its new basis, through the contacts' rows.
pub fn apply_warm_start<T: Real>(r: &mut Resolver<T>) {
    let State {
        rows,
        accumulated,
        solver,
        warm,
        ..
    } = &mut r.sequential;
    for ((rows, warm), accumulated) in rows.iter().zip(warm.iter_mut()).zip(accumulated) {
        let Some(world) = warm.take() else {
            continue;
        };
        let (g, _) = clamp_accumulated(rows.basis.tr_mul(&world), rows.friction.then_some(rows.mu));
        if g == Vector3::zeros() {
            continue;
        }
        *accumulated = g;
        rows.apply(solver, &g);
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
        use nalgebra::Matrix3;
        let m: Matrix3<f64> = Matrix3::new(2.0, 0.5, 0.1, 0.5, 3.0, 0.2, 0.1, 0.2, 2.5);
        let old = Vector3::new(0.3, -0.1, 0.05);
        let (mu, desired): (f64, f64) = (0.4, 0.7);
        let against = Vector3::new(0.0, -3.0, 4.0);
        let g = on_the_rim(&old, &against, mu, &m.row(0).transpose(), desired).unwrap();
        // Row 0 of M (g - g_old) is the Δv wanted along the normal.
        assert!((m.row(0).dot(&(g - old).transpose()) - desired).abs() < 1e-12);
        // The tangential part is μ g_n along (-3, 4)/5.
        let t = Vector3::new(0.0, -0.6 * mu * g.x, 0.8 * mu * g.x);
        assert!((Vector3::new(0.0, g.y, g.z) - t).norm() < 1e-12, "{g:?}");
        // No slip direction: no rim.
        assert_eq!(
            on_the_rim(&old, &Vector3::x(), mu, &m.row(0).transpose(), desired),
            None
        );
    }
}
