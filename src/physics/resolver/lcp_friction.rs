//! Coulomb friction beside the simultaneous impact (`solver = "lcp"`):
//! after the normal LCP's impulses are applied, projected Gauss–Seidel
//! sweeps over the contacts with friction. At each visit a contact takes the
//! tangential impulse that would stop its contact point's slip (the
//! tangential 2×2 block of its contact-space matrix M, inverted); kept
//! when the accumulated impulse stays inside μ_s λ_n (sticking), else
//! projected onto the disk's edge μ_d λ_n in its direction (sliding).
//! λ_n is the normal impulse the LCP gave the contact, held fixed (the
//! normal LCP is not solved again); a contact friction leaves closing is
//! recorded. This is Coulomb's cone at the impulse level with the normal
//! impulse frozen, so it is exact where friction does not feed back into
//! the normal velocities (a sphere on a plane) and an approximation where
//! it does (an edge or corner of a box, coupled contacts).

use nalgebra::{Matrix2, Vector2, Vector3};

use super::{desired_of, velocity, Resolver};
use crate::physics::lcp::{Friction, FrictionRow, FRICTION_SWEEP_CAP};
use crate::physics::{c, Real};

/// Applies a contact-space impulse at contact `k` and updates every
/// contact's velocity (and desired Δv) with what it changed.
fn apply<T: Real>(r: &mut Resolver<T>, k: usize, impulse: Vector3<T>) {
    let applied = velocity::apply_impulse(&r.contacts[k], &mut r.bodies, impulse, None);
    let changes = velocity::BodyChanges::of(&r.contacts[k].bodies, &applied);
    let from = r.params.restitution_from;
    for cj in r.contacts.iter_mut() {
        let v = velocity::velocity_after(cj, &changes);
        if v != cj.velocity {
            cj.velocity = v;
            cj.desired = desired_of(cj, from);
        }
    }
}

/// The friction pass after the normal impulses `normal`; None when no
/// contact has friction.
pub fn pass<T: Real>(r: &mut Resolver<T>, normal: &[T]) -> Option<Friction<T>> {
    let with: Vec<usize> = (0..r.contacts.len())
        .filter(|&k| r.setups[k].friction.is_some())
        .collect();
    if with.is_empty() {
        return None;
    }
    let scale = normal.iter().fold(T::one(), |m, &x| m.max(x.abs()));
    let tol = c::<T>(1e-13) * scale;
    let mut acc = vec![Vector2::<T>::zeros(); with.len()];
    let mut sliding = vec![false; with.len()];
    let mut sweeps = 0;
    let mut converged = false;
    while sweeps < FRICTION_SWEEP_CAP && !converged {
        sweeps += 1;
        let mut largest = T::zero();
        for (i, &k) in with.iter().enumerate() {
            let f = &r.friction[r.setups[k].friction.unwrap_or(0)];
            let m = f.matrix.matrix;
            let block = Matrix2::new(m[(1, 1)], m[(1, 2)], m[(2, 1)], m[(2, 2)]);
            let Some(inverse) = block.try_inverse() else {
                continue;
            };
            let slip = Vector2::new(r.contacts[k].velocity.y, r.contacts[k].velocity.z);
            let stick = acc[i] - inverse * slip;
            let lambda_n = normal[k].max(T::zero());
            let (next, slides) = if stick.norm() <= f.static_friction * lambda_n {
                (stick, false)
            } else if stick.norm() > T::zero() {
                (stick * (f.dynamic_friction * lambda_n / stick.norm()), true)
            } else {
                (Vector2::zeros(), false)
            };
            let delta = next - acc[i];
            sliding[i] = slides;
            if delta.norm() > T::zero() {
                apply(r, k, Vector3::new(T::zero(), delta.x, delta.y));
                acc[i] = next;
            }
            largest = largest.max(delta.norm());
        }
        converged = largest <= tol;
    }
    let rows = with
        .iter()
        .enumerate()
        .map(|(i, &k)| {
            let f = &r.friction[r.setups[k].friction.unwrap_or(0)];
            let v = r.contacts[k].velocity;
            FrictionRow {
                contact: k,
                static_friction: f.static_friction,
                dynamic_friction: f.dynamic_friction,
                normal: normal[k],
                tangential: [acc[i].x, acc[i].y],
                sliding: sliding[i],
                slip_after: [v.y, v.z],
            }
        })
        .collect();
    let closing = (0..r.contacts.len())
        .filter(|&k| r.contacts[k].velocity.x < -c::<T>(1e-9))
        .collect();
    Some(Friction {
        rows,
        sweeps,
        converged,
        closing,
    })
}
