//! One contact's position iteration and velocity pass in a substep. The
//! normal points from body 2 toward body 1 (the contacts' convention); a
//! positional impulse `p` moves body 1 by +p and body 2 by −p.

use nalgebra::Vector3;

use super::body::{Bodies, XBody};
use super::DynamicFriction;
use crate::physics::{c, Real, World};

/// A contact as XPBD keeps it over a step: its point anchored on each body
/// (body frame), its normal, its penetration when generated, its
/// coefficients, and this substep's λ.
#[derive(Debug, Clone)]
pub(super) struct Anchored<T: Real> {
    pub slots: [Option<usize>; 2],
    /// The contact point in each body's frame (the world point for an empty slot).
    pub local: [Vector3<T>; 2],
    /// The anchors' world positions when the contact was generated.
    pub start: [Vector3<T>; 2],
    pub normal: Vector3<T>,
    pub penetration0: T,
    pub restitution: T,
    pub static_friction: T,
    pub dynamic_friction: T,
    pub velocity_limit: T,
    /// This substep's normal and tangential λ (0: not active).
    pub lambda_n: T,
    pub lambda_t: T,
    /// The normal relative speed after integration, before the position pass (ṽ_n).
    pub vn_before: T,
}

/// The step's contacts, anchored on the bodies as they are now.
pub(super) fn anchors<T: Real>(world: &World<T>, bodies: &Bodies<T>) -> Vec<Anchored<T>> {
    (world.contacts.iter())
        .map(|k| {
            let slots = [Some(k.body1.0), k.body2.map(|b| b.0)];
            let p = k.input.point;
            let local = slots.map(|s| match s {
                Some(i) => {
                    let b = &bodies.0[i];
                    XBody::rotation_of(&b.q).transpose() * (p - b.x)
                }
                None => p,
            });
            Anchored {
                slots,
                local,
                start: [p, p],
                normal: k.input.normal,
                penetration0: k.input.penetration,
                restitution: k.input.restitution,
                static_friction: k.input.static_friction,
                dynamic_friction: k.input.dynamic_friction,
                velocity_limit: k.input.settings.velocity_limit,
                lambda_n: T::zero(),
                lambda_t: T::zero(),
                vn_before: T::zero(),
            }
        })
        .collect()
}

impl<T: Real> Anchored<T> {
    /// Slot `s`'s arm (world) and anchor (world) at the body's current pose.
    fn arm(&self, s: usize, bodies: &Bodies<T>) -> (Vector3<T>, Vector3<T>) {
        match self.slots[s] {
            Some(i) => {
                let b = &bodies.0[i];
                let r = XBody::rotation_of(&b.q) * self.local[s];
                (r, b.x + r)
            }
            None => (Vector3::zeros(), self.local[s]),
        }
    }

    fn w(&self, bodies: &Bodies<T>, arms: &[Vector3<T>; 2], dir: &Vector3<T>) -> T {
        let mut w = T::zero();
        for (slot, arm) in self.slots.iter().zip(arms) {
            if let Some(i) = *slot {
                w += bodies.0[i].w(arm, dir);
            }
        }
        w
    }

    fn push(&self, bodies: &mut Bodies<T>, arms: &[Vector3<T>; 2], p: &Vector3<T>) {
        for (s, sign) in [(0, T::one()), (1, -T::one())] {
            if let Some(i) = self.slots[s] {
                bodies.0[i].push(&arms[s], p, sign);
            }
        }
    }

    fn kick(&self, bodies: &mut Bodies<T>, arms: &[Vector3<T>; 2], p: &Vector3<T>) {
        for (s, sign) in [(0, T::one()), (1, -T::one())] {
            if let Some(i) = self.slots[s] {
                bodies.0[i].kick(&arms[s], p, sign);
            }
        }
    }

    /// Body 1's point velocity relative to body 2's at the contact.
    fn relative_velocity(&self, bodies: &Bodies<T>, arms: &[Vector3<T>; 2]) -> Vector3<T> {
        let v = |s: usize| {
            self.slots[s].map_or(Vector3::zeros(), |i| bodies.0[i].point_velocity(&arms[s]))
        };
        v(0) - v(1)
    }

    /// The constraint C = separation now (< 0: penetrating): the generated
    /// separation moved by the anchors' relative move along the normal.
    fn separation(&self, bodies: &Bodies<T>) -> (T, [Vector3<T>; 2]) {
        let (r1, p1) = self.arm(0, bodies);
        let (r2, p2) = self.arm(1, bodies);
        let moved = (p1 - self.start[0]) - (p2 - self.start[1]);
        (moved.dot(&self.normal) - self.penetration0, [r1, r2])
    }
}

/// The penetration of `k` at the bodies' poses now (≤ 0: apart).
pub(super) fn penetration_now<T: Real>(k: &Anchored<T>, bodies: &Bodies<T>) -> T {
    -k.separation(bodies).0
}

/// What one contact's position iteration did.
#[derive(Debug, Clone, Copy)]
pub struct PositionDone {
    /// C before the iteration (the separation; < 0 penetrating).
    pub c: f64,
    pub w: f64,
    pub lambda_n: f64,
    pub delta_lambda_n: f64,
    /// The static-friction λ_t asked for and its bound μ_s λ_n.
    pub lambda_t: f64,
    pub lambda_t_max: f64,
    /// Whether static friction held (λ_t ≤ μ_s λ_n: the correction applied).
    pub sticks: bool,
}

/// The most a contact is pushed out per second (m/s): not in the paper;
/// Solver2D's XPBD clamps C so (a body started deep in another would
/// otherwise leave at its depth over h, tens of m/s).
const PUSH_OUT_SPEED: f64 = 3.0;

/// One position iteration of contact `k` (λ reset for the substep): `None`
/// when it does not penetrate.
pub(super) fn position<T: Real>(
    k: &mut Anchored<T>,
    bodies: &mut Bodies<T>,
    alpha_tilde: T,
    h: T,
) -> Option<PositionDone> {
    k.lambda_n = T::zero();
    k.lambda_t = T::zero();
    let (cn, arms) = k.separation(bodies);
    // ṽ_n: the normal speed the substep's integration gave the contact.
    k.vn_before = k.relative_velocity(bodies, &arms).dot(&k.normal);
    if cn >= T::zero() {
        return None;
    }
    let cn = cn.max(-c::<T>(PUSH_OUT_SPEED) * h);
    let n = k.normal;
    let w = k.w(bodies, &arms, &n);
    if w + alpha_tilde <= T::zero() {
        return None;
    }
    let delta = (-cn - alpha_tilde * k.lambda_n) / (w + alpha_tilde);
    k.lambda_n += delta;
    k.push(bodies, &arms, &(n * delta));
    // Static friction: the anchors' relative tangential move since the
    // step's start (as Solver2D's XPBD: the paper's since the substep's
    // start lets each substep's last correction turn a resting box about
    // the normal, a creep of centimetres in seconds).
    let (_, arms) = k.separation(bodies);
    let (_, p1) = k.arm(0, bodies);
    let (_, p2) = k.arm(1, bodies);
    let dp = (p1 - k.start[0]) - (p2 - k.start[1]);
    let dp_t = dp - n * dp.dot(&n);
    let len = dp_t.norm();
    let bound = k.static_friction * k.lambda_n;
    let mut done = PositionDone {
        c: to(cn),
        w: to(w),
        lambda_n: to(k.lambda_n),
        delta_lambda_n: to(delta),
        lambda_t: 0.0,
        lambda_t_max: to(bound),
        sticks: false,
    };
    if len > T::zero() {
        let t = dp_t / len;
        let wt = k.w(bodies, &arms, &t);
        if wt > T::zero() {
            let lambda_t = len / wt;
            done.lambda_t = to(lambda_t);
            if lambda_t <= bound {
                k.lambda_t = lambda_t;
                k.push(bodies, &arms, &(t * -lambda_t));
                done.sticks = true;
            }
        }
    }
    Some(done)
}

/// What one contact's velocity pass did.
#[derive(Debug, Clone, Copy)]
pub struct VelocityDone {
    /// The tangential slip speed |v_t| and the speed dynamic friction removed.
    pub slip: f64,
    pub friction_dv: f64,
    /// v_n before the pass, ṽ_n, the restitution applied and the Δv_n.
    pub vn: f64,
    pub vn_before: f64,
    pub restitution: f64,
    pub restitution_dv: f64,
}

/// The velocity pass of contact `k` (only where it was active this
/// substep): dynamic friction, then restitution.
pub(super) fn velocity<T: Real>(
    k: &mut Anchored<T>,
    bodies: &mut Bodies<T>,
    h: T,
    g: T,
    formula: DynamicFriction,
) -> Option<VelocityDone> {
    if k.lambda_n <= T::zero() {
        return None;
    }
    let n = k.normal;
    let (_, arms) = k.separation(bodies);
    let v = k.relative_velocity(bodies, &arms);
    let vn = v.dot(&n);
    let vt = v - n * vn;
    let slip = vt.norm();
    let mut friction_dv = T::zero();
    if slip > T::zero() {
        let t = vt / slip;
        let wt = k.w(bodies, &arms, &t);
        // |f_n| = λ_n/h²: the printed h μ_d |f_n| is μ_d λ_n/h (an impulse).
        let reach = match formula {
            DynamicFriction::Printed => k.dynamic_friction * k.lambda_n / h,
            DynamicFriction::Corrected => k.dynamic_friction * k.lambda_n * wt / h,
        };
        friction_dv = reach.min(slip);
        if wt > T::zero() {
            k.kick(bodies, &arms, &(t * (-friction_dv / wt)));
        }
    }
    let v = k.relative_velocity(bodies, &arms);
    let vn_now = v.dot(&n);
    let closing = -k.vn_before;
    // The paper's e = 0 for a slow contact (|v_n| ≤ 2|g|h), judged on the
    // speed it closed at (after the projection v_n is the projection's own).
    let small = closing.abs() <= c::<T>(2.0) * g * h || closing <= k.velocity_limit;
    let e = if small { T::zero() } else { k.restitution };
    let target = (e * closing).max(T::zero());
    let dvn = target - vn_now;
    let wn = k.w(bodies, &arms, &n);
    if wn > T::zero() {
        k.kick(bodies, &arms, &(n * (dvn / wn)));
    }
    Some(VelocityDone {
        slip: to(slip),
        friction_dv: to(friction_dv),
        vn: to(vn),
        vn_before: to(k.vn_before),
        restitution: to(e),
        restitution_dv: to(dvn),
    })
}

fn to<T: Real>(x: T) -> f64 {
    crate::physics::to_f64(x)
}
