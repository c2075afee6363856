//! The neighbour table of the indexed phases grows as the square of one
//! body's contacts (70,000 contacts on one body asked for 4.9 × 10⁹
//! entries and panicked, "neighbours are numbered in 32 bits"): a table
//! that would outgrow its budget is not built, and the phases scan the
//! contacts instead, with the same results.

use contact_lab::physics::params::ResolverParams;
use contact_lab::physics::resolver::neighbours::TABLE_BUDGET;
use contact_lab::physics::resolver::{row::sphere_row, Implementation, Resolver, Silent};
use contact_lab::physics::Solver;

fn resolved(budget: Option<usize>, implementation: Implementation) -> (Resolver<f64>, bool) {
    let world = sphere_row::<f64>(40);
    let mut r = Resolver::prepare(&world, &ResolverParams::default());
    if let Some(b) = budget {
        r.table_budget = b;
    }
    let over = r.table_over_budget();
    r.position_phase(implementation, &mut Silent);
    r.velocity_phase(implementation, &mut Silent);
    (r, over)
}

#[test]
fn a_table_over_its_budget_falls_back_to_the_scan_with_the_same_results() {
    let (table, over) = resolved(None, Implementation::Indexed);
    assert!(!over, "a row of 40 spheres fits");
    let entries = table.table_entries();
    assert!(entries > 100 && entries < TABLE_BUDGET, "{entries}");
    let (fallback, over) = resolved(Some(entries - 1), Implementation::Indexed);
    assert!(over, "one entry over a budget of {}", entries - 1);
    let (scan, _) = resolved(None, Implementation::Scan);
    for other in [&table, &scan] {
        assert_eq!(fallback.bodies, other.bodies);
        assert_eq!(fallback.contacts, other.contacts);
    }
    // Exactly at the budget the table is built.
    let (_, over) = resolved(Some(entries), Implementation::Indexed);
    assert!(!over);
}

#[test]
fn sequential_impulses_use_no_table() {
    let world = sphere_row::<f64>(40);
    let params = ResolverParams {
        solver: Solver::SequentialImpulse,
        ..ResolverParams::default()
    };
    let mut r = Resolver::prepare(&world, &params);
    r.table_budget = 0;
    assert!(!r.table_over_budget());
    assert_eq!(r.table_entries(), 0);
}
