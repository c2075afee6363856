//! The deepest-first position phase's fast path against the path it
//! replaced, bit for bit (`to_bits`), on lessons and on stepped scenes:
//! - the silent take ([`position::take_moves`]: the compact moves only)
//!   against the recorded one ([`position::take`], then `BodyMoves::of`):
//!   the same moves and the same bodies;
//! - a neighbour's penetration from the neighbour table's slots
//!   ([`position::penetration_after_slots`]) against
//!   [`position::penetration_after`] and the recorded
//!   [`position::updated_penetration`];
//! - the whole phases: the indexed resolver silent and recorded, and the
//!   scan, leave the same bits and the same reports.

use contact_lab::lesson::Lesson;
use contact_lab::physics::resolver::position::{
    penetration_after, penetration_after_slots, take, take_moves, updated_penetration, BodyMoves,
};
use contact_lab::physics::resolver::velocity_row::UNCHANGED;
use contact_lab::physics::resolver::{
    Implementation, Observer, PositionMoves, Resolver, ResolverBody, Silent,
};
use contact_lab::physics::{ResolverParams, Solver, World};
use nalgebra::Vector3;

use crate::common::resolver_worlds::{each_stepped_world, LESSONS};

fn bits_v(v: &Vector3<f64>) -> [u64; 3] {
    [v.x.to_bits(), v.y.to_bits(), v.z.to_bits()]
}

fn bodies_bits(bodies: &[ResolverBody<f64>]) -> Vec<u64> {
    bodies
        .iter()
        .flat_map(|b| {
            let mut out = bits_v(&b.position).to_vec();
            out.extend(b.orientation.coords.iter().map(|x| x.to_bits()));
            out.extend(bits_v(&b.velocity));
            out.extend(bits_v(&b.angular_velocity));
            out
        })
        .collect()
}

fn moves_bits(m: &BodyMoves<f64>) -> (Vec<usize>, Vec<[u64; 3]>) {
    let vectors = m.linear.iter().chain(&m.angular).map(bits_v).collect();
    (m.bodies.to_vec(), vectors)
}

/// The neighbour table's slots of contact `c_bodies` for a taken contact
/// with slots `taken` (the rule of `neighbours::Neighbours`).
fn slots(c_bodies: [Option<usize>; 2], taken: [Option<usize>; 2]) -> [u8; 2] {
    c_bodies.map(|body| match body {
        Some(_) if body == taken[0] => 0,
        Some(_) if body == taken[1] => 1,
        _ => UNCHANGED,
    })
}

/// Every contact of `world` taken at its penetration (and at a few other
/// depths) from the prepared bodies, both ways; every other contact's
/// penetration updated both ways. Returns (takes, slot updates that moved
/// a penetration).
fn compare_takes(world: &World<f64>) -> (usize, usize) {
    let r = Resolver::prepare(world, &ResolverParams::default());
    let (mut takes, mut updates) = (0, 0);
    for (k, c) in r.contacts.iter().enumerate() {
        for depth in [c.penetration, 0.01, -0.003, 1.5] {
            let mut recorded_bodies = r.bodies.clone();
            let mut silent_bodies = r.bodies.clone();
            let recorded: PositionMoves<f64> = take(c, &r.setups[k], depth, &mut recorded_bodies);
            let compact = BodyMoves::of(&recorded);
            let silent = take_moves(c, &r.setups[k], depth, &mut silent_bodies);
            assert_eq!(moves_bits(&silent), moves_bits(&compact), "contact {k}");
            assert_eq!(
                bodies_bits(&silent_bodies),
                bodies_bits(&recorded_bodies),
                "contact {k}: bodies"
            );
            takes += 1;
            for (j, n) in r.contacts.iter().enumerate() {
                let from_slots = penetration_after_slots(n, slots(n.bodies, c.bodies), &silent);
                let compact_after = penetration_after(n, &compact);
                let full_after = updated_penetration(n, &c.bodies, &recorded);
                assert_eq!(from_slots.to_bits(), compact_after.to_bits(), "{k} → {j}");
                assert_eq!(from_slots.to_bits(), full_after.to_bits(), "{k} → {j}");
                updates += usize::from(from_slots.to_bits() != n.penetration.to_bits());
            }
        }
    }
    (takes, updates)
}

/// One report, as bits.
type Report = (u8, usize, usize, u64, u64);

/// Keeps every position report, an update with its iteration (so the
/// phases take the recorded path).
#[derive(Default)]
struct Log {
    iteration: usize,
    reports: Vec<Report>,
}

impl Observer<f64> for Log {
    fn position_taken(&mut self, i: usize, k: usize, p: f64, _: &PositionMoves<f64>) {
        self.iteration = i;
        self.reports.push((0, i, k, p.to_bits(), 0));
    }
    fn penetration_updated(&mut self, k: usize, from: f64, to: f64) {
        let i = self.iteration;
        self.reports.push((1, i, k, from.to_bits(), to.to_bits()));
    }
}

/// The phases on `world`: indexed silent, indexed recorded and the scan
/// (recorded) leave the same bits; the two recordings are the same.
/// Returns the position iterations used.
fn compare_phases(world: &World<f64>) -> usize {
    let params = ResolverParams::default();
    let run = |implementation, log: Option<&mut Log>| {
        let mut r = Resolver::prepare(world, &params);
        let outcomes = match log {
            Some(log) => [
                r.position_phase(implementation, log),
                r.velocity_phase(implementation, log),
            ],
            None => [
                r.position_phase(implementation, &mut Silent),
                r.velocity_phase(implementation, &mut Silent),
            ],
        };
        let mut state = bodies_bits(&r.bodies);
        state.extend(r.contacts.iter().flat_map(|c| {
            let mut out = vec![c.penetration.to_bits(), c.desired.to_bits()];
            out.extend(bits_v(&c.velocity));
            out
        }));
        (state, format!("{outcomes:?}"), outcomes[0].iterations_used)
    };
    let (mut indexed_log, mut scan_log) = (Log::default(), Log::default());
    let silent = run(Implementation::Indexed, None);
    let recorded = run(Implementation::Indexed, Some(&mut indexed_log));
    let scan = run(Implementation::Scan, Some(&mut scan_log));
    assert_eq!(silent, recorded, "indexed: silent against recorded");
    assert_eq!(silent, scan, "indexed against the scan");
    // The scan reports the taken contact's neighbours in file order, the
    // indexed one in the neighbour table's: compare them sorted.
    let sorted = |log: &Log| {
        let mut v = log.reports.clone();
        v.sort();
        v
    };
    assert_eq!(sorted(&indexed_log), sorted(&scan_log));
    assert_eq!(indexed_log.reports.len(), scan_log.reports.len());
    silent.2
}

/// Worlds of stepped scenes under deepest-first: each step's contacts.
fn stepped(each: &mut impl FnMut(&World<f64>)) {
    each_stepped_world(Solver::DeepestFirst, false, |world, _, _| each(world));
}

#[test]
fn the_silent_take_and_the_table_update_are_the_recorded_ones_on_lessons() {
    let (mut takes, mut updates) = (0, 0);
    for id in LESSONS {
        let world = Lesson::load(id).unwrap().world::<f64>();
        let (t, u) = compare_takes(&world);
        (takes, updates) = (takes + t, updates + u);
    }
    assert!(takes > 40 && updates > 40, "{takes} {updates}");
}

#[test]
fn the_silent_take_and_the_table_update_are_the_recorded_ones_on_stepped_scenes() {
    let (mut takes, mut updates) = (0, 0);
    stepped(&mut |world| {
        let (t, u) = compare_takes(world);
        (takes, updates) = (takes + t, updates + u);
    });
    assert!(takes > 1000 && updates > 1000, "{takes} {updates}");
}

#[test]
fn the_indexed_phases_silent_and_recorded_are_the_scan_on_lessons_and_stepped_scenes() {
    let mut iterations = 0;
    for id in LESSONS {
        iterations += compare_phases(&Lesson::load(id).unwrap().world::<f64>());
    }
    stepped(&mut |world| iterations += compare_phases(world));
    assert!(iterations > 150, "{iterations}");
}
