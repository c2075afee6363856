//! The deepest-first velocity phase's hot rows ([`VelocityRow`]): what a
//! neighbour update reads and writes of one contact, side by side, with the
//! desired Δv's fixed terms worked out once ([`DesiredRule`]); the updates
//! perform [`super::velocity::velocity_after`]'s and
//! [`super::desired_of`]'s operations in their order.

use nalgebra::Vector3;

use super::velocity::BodyChanges;
use super::ResolverContact;
use crate::physics::params::RestitutionFrom;
use crate::physics::stages::desired_velocity::{applied_restitution, desired_from};
use crate::physics::Real;

/// `Cᵀv` (the velocity module's `to_contact`) from the basis by rows: component k is
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
