//! Twin of [`super::prepare::prepare_into`] (the deepest-first full prepare),
//! held bit for bit by `tests/physics/lean_prepare.rs`
//! (`the_deepest_first_lean_prepare_is_the_full_paths_*`).
//!
//! The deepest-first order's lean prepare (the per-frame path,
//! [`super::Resolver::prepare_again`]): every contact's bookkeeping
//! ([`ResolverContact`]), what its projection and impulse read
//! ([`ContactSetup`]) and, for a contact with friction, its factored
//! contact matrix ([`FrictionData`]), in one pass per contact, each record
//! written where it lies.
//!
//! The same numbers as the full path ([`super::prepare::prepare_into`]) by
//! the same operations, with the lean pieces sequential impulses' lean
//! prepare proved bit for bit ([`super::sequential::lean`]): `|r⊥|` by
//! `arm_norm` (the stable norm's bits, the plain way where that is exact),
//! `Cᵀ(v₁ - v₂)` without the stages' optional per-slot arrays, the
//! adjacency kept when no contact's bodies changed. What differs is only
//! what nothing here reads: `M` is factored by [`FactoredMatrix::lean`]
//! (the same factor as [`FactoredMatrix::new`], its κ bound from the
//! Cholesky factor instead of `M⁻¹`); the full path stays for
//! [`super::Resolver::prepare`], whose traces report κ.
//! `tests/physics/lean_prepare.rs` holds both prepares bit for bit.

use nalgebra::{Matrix3, Vector3};

use super::prepare::{desired_of, gap_speed, lean_velocity_terms, prepare_bodies, Prepared};
use super::sequential::lean::{arm_norm, blank_contact, blank_setup};
use super::{ContactSetup, FrictionData, ResolverContact};
use crate::physics::frame::{contact_basis, skew};
use crate::physics::params::RestitutionFrom;
use crate::physics::stages::impulse::FactoredMatrix;
use crate::physics::stages::projection::{projection_inertia_parts, total_projection_inertia};
use crate::physics::stages::unit_impulse::{angular_response, total_per_unit_impulse};
use crate::physics::{Real, World};

/// [`crate::physics::stages::unit_impulse::angular_matrix`], `−[r]× I⁻¹ [r]×`,
/// the same expression inlined here (the stage's is a call per slot).
#[inline(always)]
fn angular_matrix<T: Real>(skew_r: &Matrix3<T>, inverse_inertia_world: &Matrix3<T>) -> Matrix3<T> {
    -(skew_r * inverse_inertia_world * skew_r)
}

/// [`crate::physics::stages::unit_impulse::contact_matrix`],
/// `M = Cᵀ W C + (Σ 1/m)·𝟙`, the same expression inlined here.
#[inline(always)]
fn contact_matrix<T: Real>(
    angular_world: &Matrix3<T>,
    contact_to_world: &Matrix3<T>,
    linear: T,
) -> Matrix3<T> {
    let c = contact_to_world;
    c.transpose() * angular_world * c + Matrix3::identity() * linear
}

/// Prepares `world` for the deepest-first order into `out` (storage reused;
/// nothing allocated once it has held a world this size). True when the
/// adjacency was kept (every contact's bodies and the bodies' count as in
/// the last prepare).
pub fn prepare<T: Real>(world: &World<T>, from: RestitutionFrom, out: &mut Prepared<T>) -> bool {
    let Prepared {
        bodies,
        contacts,
        setups,
        friction,
        adjacency,
        index,
    } = out;
    prepare_bodies(world, bodies, index);
    let n = world.contacts.len();
    // Friction entries are overwritten where they lie, whole (an entry a
    // sequential-impulse prepare left holds another factor).
    let mut frictions = 0;
    // The adjacency depends on the bodies' count and every contact's slots
    // alone: where they are the last prepare's, it is kept as it is.
    let mut same_slots = contacts.len() == n && adjacency.offsets.len() == bodies.len() + 1;
    contacts.truncate(n);
    contacts.resize(n, blank_contact());
    setups.truncate(n);
    setups.resize(n, blank_setup());
    let records = contacts.iter_mut().zip(setups.iter_mut());
    for (contact, (c, setup)) in world.contacts.iter().zip(records) {
        let input = &contact.input;
        let slots = contact.slots().map(|id| index[id?.0]);
        // Contact frame (stage 1): basis and arms.
        let (basis, _) = contact_basis(&input.normal);
        let d = input.normal;
        let with_friction = input.has_friction();
        let mut r = [Vector3::zeros(); 2];
        let mut projection = [None, None];
        let mut unit = [None; 2];
        let mut point_velocity = Vector3::zeros();
        let mut acceleration = [None; 2];
        // Σ −[r]× I⁻¹ [r]× over the bodies (only a contact with friction needs it).
        let mut angular_world = Matrix3::zeros();
        for (i, slot) in slots.iter().enumerate() {
            let Some(b) = *slot else { continue };
            let body = &bodies[b];
            let arm = input.point - body.position;
            // Velocity change per unit impulse (stage 2); the projection's
            // angular inertia is the same number.
            let response = angular_response(&body.inverse_inertia_world, &arm, &d);
            projection[i] = Some(projection_inertia_parts(
                body.inverse_mass,
                response.rotation,
                response.angular,
                &arm,
                &d,
                &input.settings,
                arm_norm,
            ));
            unit[i] = Some((body.inverse_mass, response.angular));
            if with_friction {
                angular_world += angular_matrix(&skew(&arm), &body.inverse_inertia_world);
            }
            // v + ω × r (stage 3), body 2's subtracted.
            let state = &world.bodies[body.id.0].state;
            let point = state.point_velocity(&arm);
            acceleration[i] = Some(state.acceleration);
            if i == 0 {
                point_velocity = point;
            } else {
                point_velocity -= point;
            }
            r[i] = arm;
        }
        let (linear, unit_total) = total_per_unit_impulse(&unit);
        let (velocity_from_acceleration, slip, velocity) = lean_velocity_terms(
            world,
            contact.duration,
            acceleration,
            &basis,
            &point_velocity,
            with_friction,
        );
        let friction_index = with_friction.then(|| {
            // M = Cᵀ W C + (Σ 1/m)·𝟙, factored once for every visit.
            let data = FrictionData {
                model: input.friction_model,
                static_friction: input.static_friction,
                dynamic_friction: input.dynamic_friction,
                matrix: FactoredMatrix::lean(contact_matrix(&angular_world, &basis, linear)),
            };
            let f = frictions;
            frictions += 1;
            if f == friction.len() {
                friction.push(data);
            } else {
                friction[f] = data;
            }
            f
        });
        same_slots &= c.bodies == slots;
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
    same_slots
}
