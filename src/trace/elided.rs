//! A huge step's stop tables for the resolver screen: its recording was
//! thinned (see [`crate::trace::resolver::ROW_BUDGET`]), so the whole
//! contact table is kept only where it is known without replaying every
//! iteration — at the first and last stop of each phase, from the contacts
//! before and after — and the other stops keep what changed.

use super::resolver::{ContactRow, ResolverTrace};
use super::stop::{Stop, Table};
use crate::physics::resolver::Phase;

/// A huge step's stops: the whole table at the first and last stop of each
/// phase (from the contacts before and after), what changed at the others.
pub(super) fn tables(trace: &ResolverTrace) -> Vec<Table> {
    let before = |f: fn(&ContactRow) -> f64| trace.before.iter().map(f).collect::<Vec<f64>>();
    let after =
        |f: fn(&ContactRow) -> f64| trace.contacts_after.iter().map(f).collect::<Vec<f64>>();
    // The position phase changes only penetrations, the velocity phase only desired Δv.
    let ends = [
        (before(|r| r.penetration), after(|r| r.penetration)),
        (before(|r| r.desired), after(|r| r.desired)),
    ];
    let mut out = vec![];
    for (phase, log) in [
        (Phase::Position, &trace.position.log),
        (Phase::Velocity, &trace.velocity.log),
    ] {
        for i in 0..=log.len() {
            let changed = match i.checked_sub(1).and_then(|p| log.get(p)) {
                None => vec![],
                Some(it) => std::iter::once((it.contact, it.value, it.own_after))
                    .chain(it.updated.iter().map(|u| (u.contact, u.from, u.to)))
                    .collect(),
            };
            let whole = i == 0 || i == log.len();
            let (penetration, desired) = match (phase, whole, i == 0) {
                (_, false, _) => (vec![], vec![]),
                (Phase::Position, true, true) => (ends[0].0.clone(), ends[1].0.clone()),
                (Phase::Position, true, false) | (Phase::Velocity, true, true) => {
                    (ends[0].1.clone(), ends[1].0.clone())
                }
                (Phase::Velocity, true, false) => (ends[0].1.clone(), ends[1].1.clone()),
            };
            out.push(Table {
                stop: Stop {
                    phase,
                    iteration: i,
                },
                penetration,
                desired,
                next: log.get(i).map(|it| it.contact),
                changed,
                elided: !whole,
            });
            if i == log.len() {
                break;
            }
        }
    }
    out
}
