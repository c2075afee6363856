//! The passes over a step's soft constraints (Box2D's
//! `b2WarmStartContactsTask`, `b2SolveContactsTask` with and without bias,
//! `b2ApplyRestitutionTask`). Each applies impulses to the bodies at once
//! (Gauss–Seidel), body 1 along +n, body 2 against it.

use nalgebra::{Matrix3, Vector3};

use super::prepare::SoftContact;
use crate::physics::{to_f64, Body, Real};

/// The soft coefficients `[bias_rate, mass_scale, impulse_scale]` and the
/// push-out speed cap: the biased solve's inputs.
pub type Bias<T> = ([T; 3], T);

fn relative_velocity<T: Real>(k: &SoftContact<T>, bodies: &[Body<T>]) -> Vector3<T> {
    let v = |slot: usize| {
        k.bodies[slot].map_or(Vector3::zeros(), |i| {
            bodies[i].state.point_velocity(&k.anchors[slot])
        })
    };
    v(0) - v(1)
}

fn apply<T: Real>(
    k: &SoftContact<T>,
    bodies: &mut [Body<T>],
    inertia: &[Matrix3<T>],
    p: Vector3<T>,
) {
    for (slot, sign) in [(0, T::one()), (1, -T::one())] {
        let Some(i) = k.bodies[slot] else { continue };
        let s = &mut bodies[i].state;
        s.velocity += p * (k.inverse_mass[slot] * sign);
        s.angular_velocity += inertia[i] * k.anchors[slot].cross(&p) * sign;
    }
}

/// Applies each contact's accumulated impulses (last substep's, or last
/// step's matched ones).
pub fn warm_start<T: Real>(
    bodies: &mut [Body<T>],
    inertia: &[Matrix3<T>],
    contacts: &[SoftContact<T>],
) {
    for k in contacts {
        let p = k.normal * k.normal_impulse
            + k.tangents[0] * k.tangent_impulse[0]
            + k.tangents[1] * k.tangent_impulse[1];
        apply(k, bodies, inertia, p);
    }
}

/// One sweep: each contact's normal impulse (soft, with the bias, when
/// `bias` is given; rigid without it, the relax pass; a contact still apart
/// by s asks only s/h either way), then its friction
/// clamped to μ times the normal impulse.
pub fn solve<T: Real>(
    bodies: &mut [Body<T>],
    inertia: &[Matrix3<T>],
    contacts: &mut [SoftContact<T>],
    bias: Option<Bias<T>>,
    h: T,
) {
    let zero = T::zero();
    for k in contacts.iter_mut() {
        if k.bodies == [None, None] {
            continue;
        }
        let s = k.separation_now(bodies);
        let (mut shift, mut mass_scale, mut impulse_scale) = (zero, T::one(), zero);
        if s > zero {
            // Still apart: ask only that the gap close within the substep.
            shift = s / h;
        } else if let Some(([rate, ms, is], cap)) = bias {
            shift = (rate * s).max(-cap);
            mass_scale = ms;
            impulse_scale = is;
        }
        let vn = relative_velocity(k, bodies).dot(&k.normal);
        let impulse = -k.normal_mass * mass_scale * (vn + shift) - impulse_scale * k.normal_impulse;
        let total = (k.normal_impulse + impulse).max(zero);
        let applied = total - k.normal_impulse;
        k.normal_impulse = total;
        k.max_normal_impulse = k.max_normal_impulse.max(total);
        apply(k, bodies, inertia, k.normal * applied);
        // Friction, clamped to the cone of the normal impulse now.
        let limit = k.friction * k.normal_impulse;
        for j in 0..2 {
            let vt = relative_velocity(k, bodies).dot(&k.tangents[j]);
            let total = (k.tangent_impulse[j] - k.tangent_mass[j] * vt)
                .max(-limit)
                .min(limit);
            let applied = total - k.tangent_impulse[j];
            k.tangent_impulse[j] = total;
            apply(k, bodies, inertia, k.tangents[j] * applied);
        }
    }
}

/// The restitution pass: a contact that closed faster than `threshold`
/// before the solve and pushed is given back `e` times that speed.
pub fn restitution<T: Real>(
    bodies: &mut [Body<T>],
    inertia: &[Matrix3<T>],
    contacts: &mut [SoftContact<T>],
    threshold: T,
) {
    let zero = T::zero();
    for k in contacts.iter_mut() {
        if k.restitution == zero || k.relative_velocity > -threshold || k.max_normal_impulse == zero
        {
            continue;
        }
        let vn = relative_velocity(k, bodies).dot(&k.normal);
        let impulse = -k.normal_mass * (vn + k.restitution * k.relative_velocity);
        let total = (k.normal_impulse + impulse).max(zero);
        let applied = total - k.normal_impulse;
        k.normal_impulse = total;
        k.max_normal_impulse = k.max_normal_impulse.max(total);
        apply(k, bodies, inertia, k.normal * applied);
    }
}

/// The fastest closing normal speed (≥ 0) and the deepest penetration over
/// the contacts, with the bodies as they are.
pub fn closing_and_depth<T: Real>(contacts: &[SoftContact<T>], bodies: &[Body<T>]) -> (f64, f64) {
    contacts.iter().fold((0.0f64, 0.0f64), |(v, d), k| {
        let vn = to_f64(relative_velocity(k, bodies).dot(&k.normal));
        (v.max(-vn), d.max(-to_f64(k.separation_now(bodies))))
    })
}
