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
use crate::physics::params::RestitutionFrom;
use crate::physics::stages::apply_impulse::{body_velocity_change, BodyVelocityChange};
use crate::physics::stages::desired_velocity::{applied_restitution, desired_from};
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

/// [`to_contact`] from the basis by rows: component k is
/// `C[(0, k)]·v.x + C[(1, k)]·v.y + C[(2, k)]·v.z` as there (the same
/// operations in the same order), the three components side by side.
#[inline(always)]
fn to_contact_rows<T: Real>(rows: &[Vector3<T>; 3], v: &Vector3<T>) -> Vector3<T> {
    rows[0] * v.x + rows[1] * v.y + rows[2] * v.z
}

/// A neighbour's slot that the taken contact did not change.
pub const UNCHANGED: u8 = u8::MAX;

/// What a velocity-phase neighbour update reads and writes of one contact,
/// side by side (the indexed loop's hot data, copied from the contacts at
/// the phase's start, written back at its end): none of the contact's
/// other fields, no body to match (the neighbour table has the slots), and
/// the desired Δv's terms that do not change during the phase worked out
/// once ([`DesiredRule`]).
#[derive(Debug, Clone, Copy)]
#[repr(C)]
pub struct VelocityRow<T: Real> {
    pub velocity: Vector3<T>,
    pub desired: T,
    /// The basis by rows (`basis_rows[i][k]` is `C[(i, k)]`): [`to_contact`]'s
    /// three dot products as one sum of rows, lane by lane.
    basis_rows: [Vector3<T>; 3],
    r: [Vector3<T>; 2],
    /// The contact's velocity from acceleration, for [`VelocityRow::plain_desired`].
    acceleration: T,
    rule: DesiredRule<T>,
}

/// [`super::desired_of`] for one contact during the velocity phase, with
/// what does not depend on the contact velocity worked out at its start
/// (each form performs the operations `desired_of` performs, in its order).
#[derive(Debug, Clone, Copy)]
enum DesiredRule<T: Real> {
    /// Restitution 0, from the current velocity: `e = 0` whatever the
    /// velocity, so `Δv = -v_acc - (1 + 0)(v - v_acc)` (`(1 + 0)·x` is `x`
    /// exactly), less the gap speed where there is one.
    NoBounce { acceleration: T, gap: Option<T> },
    /// From the initial velocity: `e` is fixed, so is `e(v₀ - v_acc)`;
    /// `Δv = -v - e(v₀ - v_acc)`, less the gap speed where `e = 0`.
    Initial { bounce: T, gap: Option<T> },
    /// From the current velocity with restitution: `desired_of` as it is.
    Current {
        acceleration: T,
        restitution: T,
        velocity_limit: T,
        gap_speed: T,
    },
}

impl<T: Real> DesiredRule<T> {
    fn of(c: &ResolverContact<T>, from: RestitutionFrom) -> Self {
        let gap = |e: T| (c.gap_speed > T::zero() && e == T::zero()).then_some(c.gap_speed);
        match from {
            RestitutionFrom::Current if c.restitution == T::zero() => DesiredRule::NoBounce {
                acceleration: c.velocity_from_acceleration,
                gap: gap(T::zero()),
            },
            RestitutionFrom::Current => DesiredRule::Current {
                acceleration: c.velocity_from_acceleration,
                restitution: c.restitution,
                velocity_limit: c.velocity_limit,
                gap_speed: c.gap_speed,
            },
            RestitutionFrom::Initial => {
                let v0 = c.initial_velocity;
                let (e, _) = applied_restitution(v0, c.restitution, c.velocity_limit);
                DesiredRule::Initial {
                    bounce: e * (v0 - c.velocity_from_acceleration),
                    gap: gap(e),
                }
            }
        }
    }

    /// Whether the rule is [`DesiredRule::NoBounce`] without a gap: the
    /// desired Δv is then [`VelocityRow::plain_desired`]'s.
    fn is_plain(&self) -> bool {
        matches!(self, DesiredRule::NoBounce { gap: None, .. })
    }

    /// The desired Δv at contact velocity `v` (along the normal).
    #[inline(always)]
    fn desired(&self, v: T) -> T {
        let (desired, gap) = match *self {
            DesiredRule::NoBounce { acceleration, gap } => {
                (desired_from(v, T::zero(), acceleration), gap)
            }
            DesiredRule::Initial { bounce, gap } => (-v - bounce, gap),
            DesiredRule::Current {
                acceleration,
                restitution,
                velocity_limit,
                gap_speed,
            } => {
                let (e, _) = applied_restitution(v, restitution, velocity_limit);
                let gap = (gap_speed > T::zero() && e == T::zero()).then_some(gap_speed);
                (desired_from(v, e, acceleration), gap)
            }
        };
        match gap {
            Some(g) => desired - g,
            None => desired,
        }
    }
}

impl<T: Real> VelocityRow<T> {
    pub fn of(c: &ResolverContact<T>, from: RestitutionFrom) -> Self {
        VelocityRow {
            velocity: c.velocity,
            desired: c.desired,
            basis_rows: [0, 1, 2].map(|i| c.basis.row(i).transpose()),
            r: c.r,
            acceleration: c.velocity_from_acceleration,
            rule: DesiredRule::of(c, from),
        }
    }

    /// Whether the desired Δv is [`VelocityRow::plain_desired`]'s (restitution 0
    /// from the current velocity, no gap).
    pub fn is_plain(&self) -> bool {
        self.rule.is_plain()
    }

    /// [`DesiredRule::NoBounce`]'s desired Δv without a gap at contact
    /// velocity `v`, its operations (no rule to match).
    #[inline(always)]
    fn plain_desired(&self, v: T) -> T {
        desired_from(v, T::zero(), self.acceleration)
    }

    /// [`velocity_after`] and [`super::desired_of`] on the row: the same
    /// operations in the same order. `slots[s]`: the taken contact's slot
    /// that changed this contact's slot `s` ([`UNCHANGED`] for none).
    /// Returns the desired Δv before and after.
    /// With `PLAIN` (only for a row that [`VelocityRow::is_plain`]) the
    /// desired Δv is [`VelocityRow::plain_desired`]'s, its rule not matched.
    #[inline(always)]
    pub fn update<const PLAIN: bool>(
        &mut self,
        slots: [u8; 2],
        changes: &BodyChanges<T>,
    ) -> (T, T) {
        let before = self.desired;
        let mut velocity = self.velocity;
        if slots[0] != UNCHANGED {
            let d = usize::from(slots[0] & 1);
            velocity += to_contact_rows(
                &self.basis_rows,
                &(changes.dv[d] + changes.dw[d].cross(&self.r[0])),
            );
        }
        if slots[1] != UNCHANGED {
            let d = usize::from(slots[1] & 1);
            velocity -= to_contact_rows(
                &self.basis_rows,
                &(changes.dv[d] + changes.dw[d].cross(&self.r[1])),
            );
        }
        self.velocity = velocity;
        self.desired = if PLAIN {
            self.plain_desired(velocity.x)
        } else {
            self.rule.desired(velocity.x)
        };
        (before, self.desired)
    }
}

#[cfg(test)]
mod tests {
    use nalgebra::{Matrix3, Vector3};

    use super::{DesiredRule, VelocityRow};
    use crate::physics::params::RestitutionFrom;
    use crate::physics::resolver::prepare::{desired_of, ResolverContact};

    /// The fast path's desired Δv (fixed terms worked out once) is
    /// `desired_of`'s to the bit, for every rule, bouncing or not, with and
    /// without a gap, under and over the velocity limit.
    #[test]
    fn the_desired_rule_is_desired_of_to_the_bit() {
        let (mut checked, mut plain) = (0, 0);
        for from in [RestitutionFrom::Current, RestitutionFrom::Initial] {
            for restitution in [0.0, 0.4] {
                for gap_speed in [0.0, 0.07] {
                    for initial_velocity in [-2.0, -0.3, -0.01, 0.2] {
                        for v in [-3.1, -0.7, -0.05, 0.0, 0.013, 0.9] {
                            let c: ResolverContact<f64> = ResolverContact {
                                penetration: 0.01,
                                desired: 0.0,
                                bodies: [Some(0), None],
                                normal: Vector3::y(),
                                r: [Vector3::zeros(); 2],
                                velocity: Vector3::new(v, 0.0, 0.0),
                                basis: Matrix3::identity(),
                                initial_velocity,
                                velocity_from_acceleration: -0.1635,
                                restitution,
                                velocity_limit: 0.25,
                                gap_speed,
                            };
                            let rule = DesiredRule::of(&c, from);
                            let (fast, reference) = (rule.desired(v), desired_of(&c, from));
                            let row = VelocityRow::of(&c, from);
                            if row.is_plain() {
                                plain += 1;
                                let plain = row.plain_desired(v);
                                assert_eq!(plain.to_bits(), reference.to_bits(), "plain, v {v}");
                            }
                            assert_eq!(
                                fast.to_bits(),
                                reference.to_bits(),
                                "{from:?}, e {restitution}, gap {gap_speed}, v₀ {initial_velocity}, v {v}: {fast} against {reference}"
                            );
                            checked += 1;
                        }
                    }
                }
            }
        }
        assert_eq!((checked, plain), (192, 24));
    }
}
