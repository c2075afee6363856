//! Twin of the scan ([`super::scan`], the lecture's loop), held bit for bit
//! by `tests/physics/resolver_properties.rs` (random sets, every take and
//! update) and `tests/physics/lean_position.rs` (lessons, stepped scenes).
//!
//! The indexed resolver: the same contacts in the same order as the scan
//! ([`super::scan`]), found with a priority queue (below 64 contacts a scan
//! of the values kept side by side, from there on a tournament tree:
//! largest value first, lowest index on ties, [`super::queue`]) and updated
//! through the body → contacts adjacency,
//! so an iteration touches only the contacts of the bodies it moved. The
//! per-contact steps are the scan's own functions, so the results are
//! bit-identical. Nothing is allocated per iteration.
//!
//! The contacts an iteration changed are replayed in the queue together
//! (each match above them once). A value that stays at or below epsilon is
//! not replayed: it can never be taken, and the queue's stale entry for it
//! is at or below epsilon too, so the first contact above epsilon is still
//! exact.

use super::neighbours::Group;
use super::observer::Observer;
use super::phase::{PhaseWork, Velocities};
use super::queue::{Queue, SCAN_BELOW};
use super::velocity::BodyChanges;
use super::velocity_row::{VelocityRows, UNCHANGED};
use super::{position_table, Phase, PhaseOutcome, Resolver};
use crate::physics::Real;

/// Marks each contact of the taken contact's bodies once per iteration and
/// calls `visit` on it (a contact may belong to both bodies).
pub(super) fn each_neighbour<T: Real>(
    r: &mut Resolver<T>,
    taken: [Option<usize>; 2],
    stamp: usize,
    mut visit: impl FnMut(&mut Resolver<T>, usize),
) {
    for b in taken.into_iter().flatten() {
        for n in r.adjacency.offsets[b]..r.adjacency.offsets[b + 1] {
            let j = r.adjacency.contacts[n];
            if r.stamps[j] != stamp {
                r.stamps[j] = stamp;
                visit(r, j);
            }
        }
    }
}

pub fn position_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    with_queue(r, obs)
}

pub fn velocity_phase<T: Real, O: Observer<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
) -> PhaseOutcome<T> {
    if r.contacts.len() < SCAN_BELOW {
        let mut queue = std::mem::take(&mut r.scan_queue);
        let outcome = velocity_rows::<T, O, _>(r, obs, &mut queue);
        r.scan_queue = queue;
        outcome
    } else {
        let mut queue = std::mem::take(&mut r.queue);
        let outcome = velocity_rows::<T, O, _>(r, obs, &mut queue);
        r.queue = queue;
        outcome
    }
}

/// Runs the position phase ([`position_table::phase`]) on the neighbour
/// table (built here, kept for the velocity phase) with the scan queue below
/// [`SCAN_BELOW`] contacts, the tournament tree from there on (both give the
/// same order).
fn with_queue<T: Real, O: Observer<T>>(r: &mut Resolver<T>, obs: &mut O) -> PhaseOutcome<T> {
    let mut table = std::mem::take(&mut r.neighbours);
    table.build(r);
    let outcome = if r.contacts.len() < SCAN_BELOW {
        let mut queue = std::mem::take(&mut r.scan_queue);
        let outcome = position_table::phase(r, obs, &mut queue, &table);
        r.scan_queue = queue;
        outcome
    } else {
        let mut queue = std::mem::take(&mut r.queue);
        let outcome = position_table::phase(r, obs, &mut queue, &table);
        r.queue = queue;
        outcome
    };
    r.neighbours = table;
    outcome
}

/// The velocity phase, its neighbour updates on the contacts' hot rows
/// ([`VelocityRows`]: copied in at the start, the velocities and desired Δv
/// written back at the end) through the neighbour table
/// ([`Neighbours`](super::neighbours::Neighbours), built at the start: the
/// same neighbours in the same order as [`each_neighbour`], each with the
/// slots the taken contact changed); the same operations in the same order,
/// so the same results bit for bit. Where the processor has AVX2 the loop
/// is compiled for it (four neighbours' lanes in one register; the same
/// operations on each lane, so the same bits).
fn velocity_rows<T: Real, O: Observer<T>, Q: Queue<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
    queue: &mut Q,
) -> PhaseOutcome<T> {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor has AVX2 (just checked), all the function
        // needs that the baseline target lacks.
        return unsafe { velocity_rows_avx2(r, obs, queue) };
    }
    velocity_rows_on(r, obs, queue)
}

/// [`velocity_rows_on`] compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn velocity_rows_avx2<T: Real, O: Observer<T>, Q: Queue<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
    queue: &mut Q,
) -> PhaseOutcome<T> {
    velocity_rows_on(r, obs, queue)
}

/// [`velocity_rows`]' loop.
#[inline(always)]
fn velocity_rows_on<T: Real, O: Observer<T>, Q: Queue<T>>(
    r: &mut Resolver<T>,
    obs: &mut O,
    queue: &mut Q,
) -> PhaseOutcome<T> {
    let (limit, epsilon) = r.limits(Phase::Velocity);
    let mut rows = std::mem::take(&mut r.velocity_rows);
    rows.fill(&r.contacts, r.params.restitution_from);
    let mut table = std::mem::take(&mut r.neighbours);
    table.build(r);
    queue.fill((0..r.contacts.len()).map(|j| rows.desired(j)));
    let plain = rows.is_plain();
    let mut used = 0;
    while used < limit && !super::stop::asked(used) {
        let Some((k, value)) = queue.top().filter(|(_, v)| *v > epsilon) else {
            break;
        };
        // The taken contact's bookkeeping is its row's.
        let c = &mut r.contacts[k];
        c.velocity = rows.velocity(k);
        c.desired = rows.desired(k);
        let change = Velocities::take(r, used, k, value, obs);
        r.changed.clear();
        if O::RECORDS {
            for n in table.of(k) {
                let j = n.contact as usize;
                let ([before], [after]) = rows.update::<1, false>(j, n.slots, &change);
                obs.desired_updated(j, before, after);
                set_value(queue, &mut r.changed, j, before, after, epsilon);
            }
        } else {
            // Nothing is told of the updates: the neighbours by slot
            // pattern, each group's slots fixed in its loop, a whole block
            // of four contacts at a time where there is one. Each update
            // reads and writes its own row only, and the queue orders by
            // value (the tree replays its changed contacts sorted), so the
            // order of the visits changes no bit.
            let groups = table.grouped(k);
            let changed = &mut r.changed;
            if plain {
                update_groups::<T, Q, true>(&mut rows, groups, &change, epsilon, queue, changed);
            } else {
                update_groups::<T, Q, false>(&mut rows, groups, &change, epsilon, queue, changed);
            }
        }
        if Q::REPLAYS {
            queue.replay(&mut r.changed);
        }
        used += 1;
    }
    for (j, c) in r.contacts.iter_mut().enumerate() {
        c.velocity = rows.velocity(j);
        c.desired = rows.desired(j);
    }
    r.velocity_rows = rows;
    r.neighbours = table;
    r.finish(Phase::Velocity, used, obs)
}

/// Brings a taken contact's neighbours `groups` ([`Neighbours::grouped`](super::neighbours::Neighbours::grouped))
/// up to date after its `change`, and their values in the queue; `PLAIN`:
/// every row's desired Δv is plain ([`VelocityRows::is_plain`]).
#[inline(always)]
fn update_groups<T: Real, Q: Queue<T>, const PLAIN: bool>(
    rows: &mut VelocityRows<T>,
    [g0, g1, g2, g3, g4, g5]: [Group<'_>; 6],
    change: &BodyChanges<T>,
    epsilon: T,
    queue: &mut Q,
    changed: &mut Vec<usize>,
) {
    const U: u8 = UNCHANGED;
    let (c, q) = (change, queue);
    update_group::<T, Q, PLAIN, 0, 1>(rows, g0, c, epsilon, q, changed);
    update_group::<T, Q, PLAIN, 1, 0>(rows, g1, c, epsilon, q, changed);
    update_group::<T, Q, PLAIN, 0, U>(rows, g2, c, epsilon, q, changed);
    update_group::<T, Q, PLAIN, 1, U>(rows, g3, c, epsilon, q, changed);
    update_group::<T, Q, PLAIN, U, 0>(rows, g4, c, epsilon, q, changed);
    update_group::<T, Q, PLAIN, U, 1>(rows, g5, c, epsilon, q, changed);
}

/// Brings the neighbours `group` (every one with the slots `[S0, S1]`) up
/// to date after a take's `change`, its whole blocks four lanes at a time,
/// and their values in the queue.
#[inline(always)]
fn update_group<T: Real, Q: Queue<T>, const PLAIN: bool, const S0: u8, const S1: u8>(
    rows: &mut VelocityRows<T>,
    group: Group<'_>,
    change: &BodyChanges<T>,
    epsilon: T,
    queue: &mut Q,
    changed: &mut Vec<usize>,
) {
    for &j in group.blocks {
        let j = j as usize;
        let (before, after) = rows.update::<4, PLAIN>(j, [S0, S1], change);
        for l in 0..4 {
            set_value(queue, changed, j + l, before[l], after[l], epsilon);
        }
    }
    for &j in group.others {
        let j = j as usize;
        let ([before], [after]) = rows.update::<1, PLAIN>(j, [S0, S1], change);
        set_value(queue, changed, j, before, after, epsilon);
    }
}

/// Contact `j`'s value in the queue after an update from `before` to `after`.
#[inline(always)]
fn set_value<T: Real, Q: Queue<T>>(
    queue: &mut Q,
    changed: &mut Vec<usize>,
    j: usize,
    before: T,
    after: T,
    epsilon: T,
) {
    // A queue that replays nothing (the scan's) is set every time, with
    // no branch on which values stay at or below epsilon (that comes and
    // goes, and its mispredictions cost more than the stores): a value
    // left at or below epsilon is either way a key at or below it, which
    // is never taken and never beats one above it (as the position
    // phase's loop, `position_table`).
    if !(Q::REPLAYS && before <= epsilon && after <= epsilon) {
        queue.set(j, after);
        if Q::REPLAYS {
            changed.push(j);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{row::sphere_row, Implementation, Resolver, Silent};
    use crate::physics::params::ResolverParams;

    /// A resolver prepared again for other worlds (its neighbour table kept
    /// when the contacts' bodies are the same, rebuilt when they are not)
    /// resolves each as a fresh scan does, bit for bit.
    #[test]
    fn a_reused_resolver_resolves_each_world_as_the_scan_does() {
        let params = ResolverParams::default();
        let mut reused = Resolver::prepare(&sphere_row::<f64>(3), &params);
        for n in [3usize, 3, 7, 2, 7, 40, 40] {
            let world = sphere_row::<f64>(n);
            reused.prepare_again(&world, &params);
            let position = reused.position_phase(Implementation::Indexed, &mut Silent);
            let velocity = reused.velocity_phase(Implementation::Indexed, &mut Silent);
            let (scan, outcomes) =
                Resolver::resolve(&world, &params, Implementation::Scan, &mut Silent);
            assert!(outcomes[1].iterations_used > 0, "row of {n}: {outcomes:?}");
            assert_eq!([position, velocity], outcomes, "row of {n}");
            assert_eq!(reused.bodies, scan.bodies, "row of {n}");
            assert_eq!(reused.contacts, scan.contacts, "row of {n}");
        }
    }

    /// The velocity phase's loop compiled for the baseline target gives
    /// what the dispatched one (AVX2 where the processor has it) gives, bit
    /// for bit, on the 5-box stack (whole blocks of four contacts) and a row
    /// of spheres (contacts alone), step after step.
    #[test]
    fn the_baseline_loop_is_the_dispatched_one_bit_for_bit() {
        use crate::lesson::Lesson;
        use crate::physics::step::Simulation;
        let lesson = Lesson::load("stack-5").unwrap();
        let mut p = lesson.sim_params().unwrap();
        p.sleep.enabled = false;
        let mut world = lesson.world::<f64>();
        world.contacts.clear();
        let mut sim = Simulation::new(world, p, lesson.simulation.unwrap().materials);
        let mut worlds = vec![sphere_row::<f64>(9)];
        for _ in 0..40 {
            sim.advance().unwrap();
            worlds.push(sim.world.clone());
        }
        let mut taken = 0;
        for world in &worlds {
            let params = sim.params.resolver;
            let mut dispatched = Resolver::prepare(world, &params);
            dispatched.position_phase(Implementation::Indexed, &mut Silent);
            let mut baseline = dispatched.clone();
            baseline.before[1] = baseline.max(super::Phase::Velocity).0;
            let outcome = dispatched.velocity_phase(Implementation::Indexed, &mut Silent);
            let mut queue = std::mem::take(&mut baseline.scan_queue);
            let base = super::velocity_rows_on(&mut baseline, &mut Silent, &mut queue);
            assert_eq!(outcome, base);
            assert_eq!(dispatched.bodies, baseline.bodies);
            assert_eq!(dispatched.contacts, baseline.contacts);
            taken += outcome.iterations_used;
        }
        assert!(taken > 40 * 100, "{taken} takes");
    }
}
