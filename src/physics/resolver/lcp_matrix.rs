//! The LCP's data from a prepared resolver: A, the contacts' coupled
//! unit-impulse matrix (A_ij = the change in contact i's normal velocity
//! per unit normal impulse at contact j, the lecture's stage-2 response:
//! Δv = m⁻¹ d, Δω = I⁻¹(r × d) on body 1, negated on body 2; its diagonal
//! is each contact's Δq̇_t), and the b of each restitution law.

use nalgebra::Vector3;

use super::{desired_of, ResolverBody, ResolverContact};
use crate::physics::stages::desired_velocity::applied_restitution;
use crate::physics::{Real, RestitutionFrom};

/// One body's velocity change per unit impulse at a contact.
struct Response<T: Real> {
    body: usize,
    dv: Vector3<T>,
    dw: Vector3<T>,
}

/// The velocity change a unit normal impulse at `c` makes on each of its bodies.
fn unit_responses<T: Real>(c: &ResolverContact<T>, bodies: &[ResolverBody<T>]) -> Vec<Response<T>> {
    let mut out = Vec::with_capacity(2);
    for (slot, b) in c.bodies.iter().enumerate() {
        let Some(b) = *b else { continue };
        let s = if slot == 0 { T::one() } else { -T::one() };
        let body = &bodies[b];
        let n = c.normal * s;
        out.push(Response {
            body: b,
            dv: n * body.inverse_mass,
            dw: body.inverse_inertia_world * c.r[slot].cross(&n),
        });
    }
    out
}

/// Contact `c`'s normal velocity change from the responses `changes`.
fn normal_change<T: Real>(c: &ResolverContact<T>, changes: &[Response<T>]) -> T {
    let mut x = T::zero();
    for ch in changes {
        for (slot, b) in c.bodies.iter().enumerate() {
            if *b == Some(ch.body) {
                let dv = (ch.dv + ch.dw.cross(&c.r[slot])).dot(&c.normal);
                x = if slot == 0 { x + dv } else { x - dv };
            }
        }
    }
    x
}

/// A: column j is every contact's normal velocity change per unit impulse at contact j.
pub fn unit_impulse_matrix<T: Real>(
    contacts: &[ResolverContact<T>],
    bodies: &[ResolverBody<T>],
) -> Vec<Vec<T>> {
    let n = contacts.len();
    let mut a = vec![vec![T::zero(); n]; n];
    for (j, cj) in contacts.iter().enumerate() {
        let responses = unit_responses(cj, bodies);
        for (i, ci) in contacts.iter().enumerate() {
            a[i][j] = normal_change(ci, &responses);
        }
    }
    a
}

/// Newton's b: w_i = v_i' − target_i, so b_i = −desired Δv_i for a closing
/// contact (target −e v_i, the lecture's desired Δv with its velocity limit
/// and acceleration compensation) and b_i = v_i for one that is not (it
/// must not start closing).
pub fn newton_b<T: Real>(contacts: &[ResolverContact<T>], from: RestitutionFrom) -> Vec<T> {
    contacts
        .iter()
        .map(|c| {
            if c.velocity.x < T::zero() {
                -desired_of(c, from)
            } else {
                c.velocity.x
            }
        })
        .collect()
}

/// Poisson's compression b: each contact's normal velocity (the phase ends
/// at zero closing velocity, w = v' ≥ 0).
pub fn compression_b<T: Real>(contacts: &[ResolverContact<T>]) -> Vec<T> {
    contacts.iter().map(|c| c.velocity.x).collect()
}

/// Each contact's restitution as applied (0 below its velocity limit).
pub fn restitutions<T: Real>(contacts: &[ResolverContact<T>]) -> Vec<T> {
    contacts
        .iter()
        .map(|c| applied_restitution(c.velocity.x, c.restitution, c.velocity_limit).0)
        .collect()
}
