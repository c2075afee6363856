//! Twin of [`super::velocity::velocity_after`] and [`super::desired_of`],
//! four contacts at a time, held bit for bit by the tests below
//! (`the_rows_update_lane_by_lane_as_velocity_after_and_desired_of`,
//! `the_desired_rule_is_desired_of_to_the_bit`) and, whole phases against
//! the scan, `tests/physics/lean_position.rs`.
//!
//! The deepest-first velocity phase's hot rows ([`VelocityRows`]): what a
//! neighbour update reads and writes of each contact, in blocks of four
//! contacts field by field (a field of the four side by side, so four
//! neighbours in a block are updated lane by lane, four numbers to an
//! operation), with the desired Δv's fixed terms worked out once
//! ([`DesiredRule`]); every lane performs
//! [`super::velocity::velocity_after`]'s and [`super::desired_of`]'s
//! operations in their order, so the results are theirs bit for bit.

use nalgebra::Vector3;

use super::velocity::BodyChanges;
use super::ResolverContact;
use crate::physics::params::RestitutionFrom;
use crate::physics::stages::desired_velocity::{applied_restitution, desired_from};
use crate::physics::Real;

/// A neighbour's slot that the taken contact did not change.
pub const UNCHANGED: u8 = u8::MAX;

/// The fields of a row, each four lanes of a [`Block`]: the contact
/// velocity (3), the desired Δv, the basis `C[(i, k)]` at `BASIS + 3i + k`,
/// the arms `r_s[k]` at `ARMS + 3s + k`, the velocity from acceleration.
const VELOCITY: usize = 0;
const DESIRED: usize = 3;
const BASIS: usize = 4;
const ARMS: usize = 13;
const ACCELERATION: usize = 19;
const FIELDS: usize = 20;

/// Contacts `4b..4b + 4`'s rows: `block[f][l]` is field `f` of contact
/// `4b + l` (a last block's lanes past the contacts are unused zeros).
type Block<T> = [[T; 4]; FIELDS];

/// What a velocity-phase neighbour update reads and writes of every
/// contact (the indexed loop's hot data, copied from the contacts at the
/// phase's start, the velocities and desired Δv written back at its end),
/// in [`Block`]s of four contacts: a field of contacts `4b..4b + 4` is one
/// run of four numbers at a fixed place, so the four are updated together
/// ([`VelocityRows::update`] on 4 lanes), a contact alone on 1. None of the
/// contact's other fields, no body to match (the neighbour table has the
/// slots), and the desired Δv's terms that do not change during the phase
/// worked out once ([`DesiredRule`]).
#[derive(Debug, Clone)]
pub struct VelocityRows<T: Real> {
    blocks: Vec<Block<T>>,
    rules: Vec<DesiredRule<T>>,
}

impl<T: Real> Default for VelocityRows<T> {
    /// No rows, nothing allocated.
    fn default() -> Self {
        VelocityRows {
            blocks: Vec::new(),
            rules: Vec::new(),
        }
    }
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

impl<T: Real> VelocityRows<T> {
    /// Room for `n` contacts (allocates only if there is less).
    pub fn reserve(&mut self, n: usize) {
        self.blocks
            .reserve(n.div_ceil(4).saturating_sub(self.blocks.len()));
        self.rules.reserve(n.saturating_sub(self.rules.len()));
    }

    /// The rows of `contacts`, the desired Δv by `from`.
    pub fn fill(&mut self, contacts: &[ResolverContact<T>], from: RestitutionFrom) {
        let n = contacts.len();
        self.blocks.clear();
        self.blocks.resize(n.div_ceil(4), [[T::zero(); 4]; FIELDS]);
        for (j, c) in contacts.iter().enumerate() {
            let mut set = |f: usize, x: T| self.blocks[j / 4][f][j % 4] = x;
            for k in 0..3 {
                set(VELOCITY + k, c.velocity[k]);
                for i in 0..3 {
                    set(BASIS + 3 * i + k, c.basis[(i, k)]);
                }
                for s in 0..2 {
                    set(ARMS + 3 * s + k, c.r[s][k]);
                }
            }
            set(DESIRED, c.desired);
            set(ACCELERATION, c.velocity_from_acceleration);
        }
        self.rules.clear();
        self.rules
            .extend(contacts.iter().map(|c| DesiredRule::of(c, from)));
    }

    /// Whether every row's desired Δv is [`plain_desired`]'s (restitution 0
    /// from the current velocity, no gap).
    pub fn is_plain(&self) -> bool {
        self.rules.iter().all(DesiredRule::is_plain)
    }

    /// Contact `k`'s velocity.
    #[inline(always)]
    pub fn velocity(&self, k: usize) -> Vector3<T> {
        let b = &self.blocks[k / 4];
        Vector3::new(b[0][k % 4], b[1][k % 4], b[2][k % 4])
    }

    /// Contact `k`'s desired Δv.
    #[inline(always)]
    pub fn desired(&self, k: usize) -> T {
        self.blocks[k / 4][DESIRED][k % 4]
    }

    /// Field `f` of contacts `j..j + N` (within one block: `N` is 4 from a
    /// block's first contact, or 1).
    #[inline(always)]
    fn lanes<const N: usize>(&self, f: usize, j: usize) -> [T; N] {
        let mut x = [T::zero(); N];
        x.copy_from_slice(&self.blocks[j / 4][f][j % 4..j % 4 + N]);
        x
    }

    #[inline(always)]
    fn set_lanes<const N: usize>(&mut self, f: usize, j: usize, x: [T; N]) {
        self.blocks[j / 4][f][j % 4..j % 4 + N].copy_from_slice(&x);
    }

    /// [`velocity_after`](super::velocity::velocity_after) and
    /// [`super::desired_of`] on the `N` rows from `j` (4 from a block's
    /// first contact, or 1), each lane the same
    /// operations in the same order. `slots[s]`: the taken contact's slot
    /// that changed the rows' slot `s` ([`UNCHANGED`] for none; the same
    /// for every lane). Returns the desired Δv before and after. With
    /// `PLAIN` (only where [`VelocityRows::is_plain`]) the desired Δv is
    /// [`plain_desired`]'s, the rules not matched.
    #[inline(always)]
    pub fn update<const N: usize, const PLAIN: bool>(
        &mut self,
        j: usize,
        slots: [u8; 2],
        changes: &BodyChanges<T>,
    ) -> ([T; N], [T; N]) {
        let before = self.lanes::<N>(DESIRED, j);
        let mut velocity = [
            self.lanes::<N>(VELOCITY, j),
            self.lanes::<N>(VELOCITY + 1, j),
            self.lanes::<N>(VELOCITY + 2, j),
        ];
        for (s, slot) in slots.into_iter().enumerate() {
            if slot == UNCHANGED {
                continue;
            }
            let d = usize::from(slot & 1);
            let (dv, dw) = (changes.dv[d], changes.dw[d]);
            let arm = |k: usize| self.lanes::<N>(ARMS + 3 * s + k, j);
            let (rx, ry, rz) = (arm(0), arm(1), arm(2));
            // `Δv + Δω × r` (nalgebra's cross: `a_y b_z − a_z b_y`, …).
            let mut w = [[T::zero(); N]; 3];
            for l in 0..N {
                w[0][l] = dv.x + (dw.y * rz[l] - dw.z * ry[l]);
                w[1][l] = dv.y + (dw.z * rx[l] - dw.x * rz[l]);
                w[2][l] = dv.z + (dw.x * ry[l] - dw.y * rx[l]);
            }
            for (k, v) in velocity.iter_mut().enumerate() {
                let basis = |i: usize| self.lanes::<N>(BASIS + 3 * i + k, j);
                let (c0, c1, c2) = (basis(0), basis(1), basis(2));
                // `Cᵀw`, component k: `C[(0, k)] w_x + C[(1, k)] w_y + C[(2, k)] w_z`;
                // body 1 of the row gains it, body 2 loses it.
                for l in 0..N {
                    let turned = c0[l] * w[0][l] + c1[l] * w[1][l] + c2[l] * w[2][l];
                    v[l] = if s == 0 { v[l] + turned } else { v[l] - turned };
                }
            }
        }
        let mut after = [T::zero(); N];
        if PLAIN {
            let acceleration = self.lanes::<N>(ACCELERATION, j);
            for l in 0..N {
                after[l] = plain_desired(velocity[0][l], acceleration[l]);
            }
        } else {
            for l in 0..N {
                after[l] = self.rules[j + l].desired(velocity[0][l]);
            }
        }
        for (k, v) in velocity.into_iter().enumerate() {
            self.set_lanes(VELOCITY + k, j, v);
        }
        self.set_lanes(DESIRED, j, after);
        (before, after)
    }
}

/// [`DesiredRule::NoBounce`]'s desired Δv without a gap at contact velocity
/// `v` (velocity from acceleration `acceleration`), its operations (no rule
/// to match).
#[inline(always)]
fn plain_desired<T: Real>(v: T, acceleration: T) -> T {
    desired_from(v, T::zero(), acceleration)
}

#[cfg(test)]
mod tests {
    use nalgebra::{Matrix3, Vector3};

    use super::{plain_desired, DesiredRule, VelocityRows, UNCHANGED};
    use crate::physics::params::RestitutionFrom;
    use crate::physics::resolver::lean_take::tests::spread;
    use crate::physics::resolver::neighbours::SLOT_PATTERNS;
    use crate::physics::resolver::prepare::{desired_of, ResolverContact};
    use crate::physics::resolver::velocity::{velocity_after, BodyChanges};

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
                            if rule.is_plain() {
                                plain += 1;
                                let plain = plain_desired(v, c.velocity_from_acceleration);
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

    /// A contact with every field from `spread`, bodies 1 and 2.
    fn contact(seed: u64, restitution: f64) -> ResolverContact<f64> {
        let v = |i: u64| Vector3::new(spread(i), spread(i + 1), spread(i + 2));
        ResolverContact {
            penetration: 0.01,
            desired: spread(seed + 40),
            bodies: [Some(1), Some(2)],
            normal: v(seed),
            r: [v(seed + 3), v(seed + 6)],
            velocity: v(seed + 9),
            basis: Matrix3::from_columns(&[v(seed + 12), v(seed + 15), v(seed + 18)]),
            initial_velocity: spread(seed + 21),
            velocity_from_acceleration: spread(seed + 22),
            restitution,
            velocity_limit: 0.25,
            gap_speed: 0.0,
        }
    }

    /// A block's four rows updated lane by lane, and each row alone, give
    /// `velocity_after` and `desired_of` to the bit, for every slot pattern,
    /// plain rows and rows with restitution.
    #[test]
    fn the_rows_update_lane_by_lane_as_velocity_after_and_desired_of() {
        let mut checked = 0;
        for case in 0..40u64 {
            let restitution = if case % 2 == 0 { 0.0 } else { 0.4 };
            let contacts: Vec<_> = (0..9)
                .map(|j| contact(100 * case + 30 * j, restitution))
                .collect();
            let v = |i: u64| Vector3::new(spread(i), spread(i + 1), spread(i + 2));
            let changes = BodyChanges {
                bodies: [1, 2],
                dv: [v(7000 + case), v(7100 + case)],
                dw: [v(7200 + case), v(7300 + case)],
            };
            for slots in SLOT_PATTERNS {
                // The bodies each row's slots hold for this pattern.
                let bodies = slots.map(|s| (s != UNCHANGED).then(|| 1 + usize::from(s)));
                let contacts: Vec<_> = contacts
                    .iter()
                    .map(|c| ResolverContact {
                        bodies: [bodies[0].or(Some(5)), bodies[1].or(Some(6))],
                        ..c.clone()
                    })
                    .collect();
                let from = RestitutionFrom::Current;
                let (mut lanes, mut alone) = (VelocityRows::default(), VelocityRows::default());
                lanes.fill(&contacts, from);
                alone.fill(&contacts, from);
                let plain = lanes.is_plain();
                assert_eq!(plain, restitution == 0.0);
                let (before, after) = if plain {
                    lanes.update::<4, true>(4, slots, &changes)
                } else {
                    lanes.update::<4, false>(4, slots, &changes)
                };
                for l in 0..4 {
                    let j = 4 + l;
                    let (b, a) = alone.update::<1, false>(j, slots, &changes);
                    let mut c = contacts[j].clone();
                    c.velocity = velocity_after(&c, &changes);
                    let desired = desired_of(&c, from);
                    assert_eq!(b[0].to_bits(), contacts[j].desired.to_bits());
                    assert_eq!(before[l].to_bits(), b[0].to_bits());
                    for (got, want) in [(after[l], desired), (a[0], desired)] {
                        assert_eq!(
                            got.to_bits(),
                            want.to_bits(),
                            "case {case}, {slots:?}, lane {l}"
                        );
                    }
                    for rows in [&lanes, &alone] {
                        assert_eq!(
                            rows.velocity(j).map(f64::to_bits),
                            c.velocity.map(f64::to_bits)
                        );
                        assert_eq!(rows.desired(j).to_bits(), desired.to_bits());
                    }
                    checked += 1;
                }
                // The rows of the other blocks are left alone.
                for j in [0, 1, 2, 3, 8] {
                    assert_eq!(lanes.velocity(j), contacts[j].velocity);
                    assert_eq!(lanes.desired(j), contacts[j].desired);
                }
            }
        }
        assert_eq!(checked, 40 * 6 * 4);
    }
}
