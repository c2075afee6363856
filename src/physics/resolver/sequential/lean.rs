//! Twin of [`super::super::prepare::prepare_into`] then [`super::rows::build`]
//! (sequential impulses' full prepare), held bit for bit by
//! `tests/physics/lean_prepare.rs` (`the_lean_rows_are_the_full_paths_*`).
//!
//! The lean prepare of sequential impulses: every contact's bookkeeping
//! ([`ResolverContact`]), what its projection reads ([`ContactSetup`]) and
//! its Jacobian rows ([`Rows`]) in ONE pass per contact, from the contact
//! and its bodies' world inverse inertia (computed once per body per step).
//!
//! The full path ([`super::super::prepare::prepare_into`], then
//! [`super::rows::build`]) builds the contact first and its rows after,
//! partly from the contact: `r × d` twice, `I⁻¹(r × d)` twice, and the
//! stages' optional per-slot arrays. Here each slot's arm rows
//! `A = [r × d, r × t₀, r × t₁]` are built once; the projection's
//! `I⁻¹(r × d)` is the first column of `T = I⁻¹ A` and its angular inertia
//! `((I⁻¹(r × d)) × r)·d` (the lecture's nonlinear projection) is read from
//! it. The operations on every number are those of the full path, in the
//! same order, so both give the same bits (`tests/physics/lean_prepare.rs`).
//!
//! What only the deepest-first order reads (the friction matrix factored
//! with a condition number) is not built.

use nalgebra::{Matrix3, Vector3};

use super::super::prepare::{desired_of, gap_speed, lean_velocity_terms, prepare_bodies, Prepared};
use super::super::{ContactSetup, FrictionData, ResolverContact};
use super::rows::{solver_bodies, symmetric_inverse, Rows};
use super::State;
use crate::physics::params::RestitutionFrom;
use crate::physics::scale::stable_norm;
use crate::physics::stages::desired_velocity::applied_restitution;
use crate::physics::stages::impulse::FactoredMatrix;
use crate::physics::stages::projection::{projection_inertia_parts, total_projection_inertia};
use crate::physics::stages::unit_impulse::total_per_unit_impulse;
use crate::physics::{c, Real, World};

/// `[r × d, r × t₀, r × t₁]`, each column `r ×` the basis column.
#[inline(always)]
fn arm_rows<T: Real>(r: &Vector3<T>, basis: &Matrix3<T>) -> Matrix3<T> {
    Matrix3::from_columns(&[
        r.cross(&basis.column(0).into_owned()),
        r.cross(&basis.column(1).into_owned()),
        r.cross(&basis.column(2).into_owned()),
    ])
}

/// `|v|` as [`crate::physics::scale::stable_norm`] gives it, the plain way
/// where that is the same bits: the stable norm divides by a power of two
/// `s` first, and where the plain sum of squares stays far from underflow
/// (above `8 m / ε²`, `m` the smallest normal, so a square that underflows
/// is below half an ulp of the largest) and overflow, every square, sum and
/// square root differs from the plain one by an exact power of two; only
/// otherwise the stable way.
#[inline(always)]
pub(in crate::physics::resolver) fn arm_norm<T: Real>(v: &Vector3<T>) -> T {
    let sq = v.x * v.x + v.y * v.y + v.z * v.z;
    let (Some(max), e) = (T::max_value(), T::default_epsilon()) else {
        return stable_norm(v);
    };
    // 4/max is the smallest normal for IEEE floats.
    let floor = c::<T>(32.0) / max / (e * e);
    if sq >= floor && sq < max {
        sq.sqrt()
    } else {
        stable_norm(v)
    }
}

/// A contact record to be overwritten (storage for a new contact).
pub(in crate::physics::resolver) fn blank_contact<T: Real>() -> ResolverContact<T> {
    ResolverContact {
        penetration: T::zero(),
        desired: T::zero(),
        bodies: [None; 2],
        normal: Vector3::zeros(),
        r: [Vector3::zeros(); 2],
        velocity: Vector3::zeros(),
        basis: Matrix3::zeros(),
        initial_velocity: T::zero(),
        velocity_from_acceleration: T::zero(),
        restitution: T::zero(),
        velocity_limit: T::zero(),
        gap_speed: T::zero(),
    }
}

/// A setup record to be overwritten.
pub(in crate::physics::resolver) fn blank_setup<T: Real>() -> ContactSetup<T> {
    ContactSetup {
        relaxation: T::zero(),
        projection: [None, None],
        total_inertia: T::zero(),
        unit_total: T::zero(),
        friction: None,
        slip: T::zero(),
    }
}

/// Prepares `world` for sequential impulses into `out` and `state` (storage
/// reused; nothing allocated once it has held a world this size).
/// `slip_speed`: the stick/slip threshold.
pub fn prepare<T: Real>(
    world: &World<T>,
    from: RestitutionFrom,
    slip_speed: T,
    out: &mut Prepared<T>,
    state: &mut State<T>,
) {
    let Prepared {
        bodies,
        contacts,
        setups,
        friction,
        adjacency,
        index,
    } = out;
    prepare_bodies(world, bodies, index);
    let State {
        accumulated,
        pushed,
        rows: all_rows,
        solver,
        warm,
        ..
    } = state;
    solver_bodies(bodies, solver);
    let world_slot = bodies.len();
    let n = world.contacts.len();
    // Friction entries of the last prepare are overwritten where they lie
    // (the caller clears entries a deepest-first prepare factored).
    let mut frictions = 0;
    // Every record is written where it lies (no record built, then copied).
    all_rows.resize(n, Rows::empty());
    // The adjacency depends on the bodies' count and every contact's slots
    // alone: where they are the last prepare's, it is kept as it is.
    let mut same_slots = contacts.len() == n && adjacency.offsets.len() == bodies.len() + 1;
    contacts.truncate(n);
    contacts.resize(n, blank_contact());
    setups.truncate(n);
    setups.resize(n, blank_setup());
    let records = contacts.iter_mut().zip(setups.iter_mut());
    for ((contact, rows), (c, setup)) in world.contacts.iter().zip(all_rows.iter_mut()).zip(records)
    {
        let input = &contact.input;
        let slots = contact.slots().map(|id| index[id?.0]);
        // Contact frame (stage 1): basis and arms.
        let (basis, _) = crate::physics::frame::contact_basis(&input.normal);
        let d = input.normal;
        let with_friction = input.has_friction();
        // Written field by field where it lies (no 500-byte copy per contact).
        rows.reset(world_slot, basis);
        let mut r = [Vector3::zeros(); 2];
        let mut projection = [None, None];
        let mut unit = [None; 2];
        let mut point_velocity = Vector3::zeros();
        let mut acceleration = [None; 2];
        for (i, slot) in slots.iter().enumerate() {
            let Some(b) = *slot else { continue };
            let body = &bodies[b];
            let arm = input.point - body.position;
            // The Jacobian's angular rows and Δω per unit impulse, once.
            let rows_of_arm = arm_rows(&arm, &basis);
            let turn = body.inverse_inertia_world * rows_of_arm;
            // Velocity change per unit impulse along d (stage 2): I⁻¹(r × d)
            // is T's first column; the projection's angular inertia is the same.
            let rotation = turn.column(0).into_owned();
            let angular = rotation.cross(&arm).dot(&d);
            projection[i] = Some(projection_inertia_parts(
                body.inverse_mass,
                rotation,
                angular,
                &arm,
                &d,
                &input.settings,
                arm_norm,
            ));
            unit[i] = Some((body.inverse_mass, angular));
            // v + ω × r (stage 3), body 2's subtracted.
            let state = &world.bodies[body.id.0].state;
            let point = state.point_velocity(&arm);
            acceleration[i] = Some(state.acceleration);
            rows.bodies[i] = b;
            if i == 0 {
                point_velocity = point;
                rows.inverse_mass[0] = body.inverse_mass;
                rows.angular[0] = rows_of_arm;
                rows.turn[0] = turn;
            } else {
                point_velocity -= point;
                rows.inverse_mass[1] = -body.inverse_mass;
                rows.angular[1] = -rows_of_arm;
                rows.turn[1] = -turn;
            }
            r[i] = arm;
        }
        let (_, unit_total) = total_per_unit_impulse(&unit);
        rows.unit_total = unit_total;
        rows.inverse[(0, 0)] = T::one() / unit_total;
        let (velocity_from_acceleration, slip, velocity) = lean_velocity_terms(
            world,
            contact.duration,
            acceleration,
            &basis,
            &point_velocity,
            with_friction,
        );
        let friction_index = with_friction.then(|| {
            // M = Σ A_iᵀ T_i + Σ m_i⁻¹ 𝟙 (= Cᵀ(Σ -[r_i]× I_i⁻¹ [r_i]×)C + Σ m_i⁻¹ 𝟙).
            let linear = rows.inverse_mass[0] - rows.inverse_mass[1];
            let m = rows.angular[0].tr_mul(&rows.turn[0])
                + rows.angular[1].tr_mul(&rows.turn[1])
                + Matrix3::from_diagonal_element(linear);
            rows.friction = true;
            rows.sliding = slip > slip_speed;
            rows.mu = if rows.sliding {
                input.dynamic_friction
            } else {
                input.static_friction
            };
            rows.normal_row = m.row(0).transpose();
            if let Some(m_inv) = symmetric_inverse(&m) {
                rows.inverse = m_inv;
            }
            // `M` kept for the reports; never factored (the rows hold `M⁻¹`).
            let f = frictions;
            frictions += 1;
            if f == friction.len() {
                friction.push(FrictionData {
                    model: input.friction_model,
                    static_friction: input.static_friction,
                    dynamic_friction: input.dynamic_friction,
                    matrix: FactoredMatrix::for_inverse(Matrix3::zeros()),
                });
            }
            let data = &mut friction[f];
            data.model = input.friction_model;
            data.static_friction = input.static_friction;
            data.dynamic_friction = input.dynamic_friction;
            data.matrix.matrix = m;
            f
        });
        // Slot by slot (an array compare goes through a slice loop).
        same_slots &= c.bodies[0] == slots[0] && c.bodies[1] == slots[1];
        *c = ResolverContact {
            penetration: input.penetration,
            desired: T::zero(),
            bodies: slots,
            normal: d,
            r,
            velocity,
            basis,
            initial_velocity: velocity.x,
            velocity_from_acceleration,
            restitution: input.restitution,
            velocity_limit: input.settings.velocity_limit,
            gap_speed: gap_speed(world, input.penetration),
        };
        c.desired = desired_of(c, from);
        let (e, _) = applied_restitution(c.initial_velocity, c.restitution, c.velocity_limit);
        rows.bounce = e * (c.initial_velocity - c.velocity_from_acceleration);
        rows.offset = c.velocity - rows.velocity(solver);
        *setup = ContactSetup {
            relaxation: input.settings.relaxation,
            total_inertia: total_projection_inertia(&projection),
            projection,
            unit_total,
            friction: friction_index,
            slip,
        };
    }
    friction.truncate(frictions);
    if !same_slots {
        adjacency.build_into(bodies.len(), contacts.iter().map(|c| c.bodies));
    }
    accumulated.clear();
    accumulated.resize(n, Vector3::zeros());
    pushed.clear();
    pushed.resize(n, T::zero());
    warm.clear();
    warm.resize(n, None);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_arm_norm_is_the_stable_norm_bit_for_bit() {
        // Components over f64's whole range (each a power of ten times an
        // irregular mantissa, with either sign), near and at the fallback.
        let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let mut plain = 0;
        for _ in 0..200_000 {
            let mut v = Vector3::zeros();
            for k in 0..3 {
                let bits = next();
                let mantissa = 1.0 + (bits >> 11) as f64 / (1u64 << 53) as f64;
                let exponent = (bits % 700) as i32 - 350;
                let scale = match bits % 5 {
                    0 => 0.0,
                    1 => 10f64.powi(exponent),
                    _ => 10f64.powi(exponent / 20),
                };
                v[k] = if bits & 1 == 0 { mantissa } else { -mantissa } * scale;
            }
            let sq = v.norm_squared();
            plain += usize::from(sq >= 1e-270 && sq.is_finite());
            assert_eq!(arm_norm(&v).to_bits(), stable_norm(&v).to_bits(), "{v:?}");
        }
        assert!(plain > 100_000, "{plain}");
        for v in [
            Vector3::new(1e-160, 0.0, 0.0),
            Vector3::new(1e200, 1e200, 0.0),
            Vector3::new(f64::MAX, 1.0, 0.0),
            Vector3::new(f64::MIN_POSITIVE, 0.0, 5e-324),
            Vector3::zeros(),
        ] {
            assert_eq!(arm_norm(&v).to_bits(), stable_norm(&v).to_bits(), "{v:?}");
        }
        let v: Vector3<f32> = Vector3::new(1e-20, 3e-21, 0.0);
        assert_eq!(arm_norm(&v).to_bits(), stable_norm(&v).to_bits());
    }
}
