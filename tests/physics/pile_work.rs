//! A pile of coincident spheres (the 1,000 took minutes a step with
//! no word): its step's work is the lecture's order's own, each iteration
//! visiting only the contacts of its two bodies (never every contact: on
//! 1,000 spheres that is 2,000 contacts an iteration against 500,000), both
//! with the neighbour table and with the fallback past its budget; and a
//! resolution asked to stop (Ctrl-C in `simulate`) stops at once.

use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use contact_lab::lesson::Lesson;
use contact_lab::physics::params::ResolverParams;
use contact_lab::physics::resolver::observer::Observer;
use contact_lab::physics::resolver::observer::{PositionMoves, VelocityImpulse};
use contact_lab::physics::resolver::{stop, Implementation, Phase, PhaseOutcome, Resolver};
use contact_lab::physics::step::Simulation;

/// The resolver's work, counted: iterations, contacts updated by them, and
/// each phase's (iterations used, limit).
#[derive(Debug, Default)]
struct Work {
    taken: usize,
    updates: usize,
    phases: Vec<(usize, usize)>,
}

impl Observer<f64> for Work {
    fn position_taken(&mut self, _: usize, _: usize, _: f64, _: &PositionMoves<f64>) {
        self.taken += 1;
    }
    fn penetration_updated(&mut self, _: usize, _: f64, _: f64) {
        self.updates += 1;
    }
    fn velocity_taken(&mut self, _: usize, _: usize, _: f64, _: &VelocityImpulse<f64>) {
        self.taken += 1;
    }
    fn desired_updated(&mut self, _: usize, _: f64, _: f64) {
        self.updates += 1;
    }
    fn phase_end(&mut self, _: Phase, o: &PhaseOutcome<f64>) {
        self.phases.push((o.iterations_used, o.iteration_limit));
    }
}

fn pile(n: usize) -> Simulation<f64> {
    let path = crate::common::pile::coincident("work", n);
    let lesson = Lesson::load(path.as_os_str()).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Simulation::new(world, params, lesson.simulation.unwrap().materials)
}

/// 24 coincident spheres on a floor: 300 contacts, each sphere in 24. The
/// step's phases run to their limit (8 visits a contact) and each iteration
/// updates at most the 2 × 24 contacts of its bodies, in the step and in
/// its resolution again past the table's budget.
#[test]
fn a_pile_of_coincident_spheres_costs_its_bodies_contacts_an_iteration_never_every_contact() {
    let n = 24;
    let mut sim = pile(n);
    let mut work = Work::default();
    sim.advance_observed(&mut work).expect("no blow-up");
    let contacts = n * (n - 1) / 2 + n;
    assert_eq!(sim.world.contacts.len(), contacts);
    assert_eq!(work.phases.len(), 2, "{:?}", work.phases);
    for &(used, limit) in &work.phases {
        assert_eq!(limit, 8 * contacts);
        assert!(used <= limit);
    }
    assert!(work.taken > contacts, "the pile is worked hard: {work:?}");
    // Each iteration updates the contacts of its two bodies (n each, the
    // taken one counted once in each list), never the whole list.
    assert!(work.updates <= work.taken * 2 * n, "{work:?}");
    assert!(work.updates >= work.taken * n, "{work:?}");
    // The same step's contacts resolved past the table's budget.
    let mut r = Resolver::prepare(&sim.world, &ResolverParams::default());
    r.table_budget = 0;
    assert!(r.table_over_budget());
    let mut fallback = Work::default();
    r.position_phase(Implementation::Indexed, &mut fallback);
    r.velocity_phase(Implementation::Indexed, &mut fallback);
    assert!(fallback.taken > contacts, "{fallback:?}");
    assert!(fallback.updates <= fallback.taken * 2 * n, "{fallback:?}");
}

/// A resolution asked to stop (the flag this thread watches set) ends at
/// its first poll: no iteration in either phase; unwatched, the same step
/// works as before.
#[test]
fn a_resolution_asked_to_stop_ends_at_once() {
    let flag = Arc::new(AtomicBool::new(true));
    let mut sim = pile(24);
    stop::watch(Arc::clone(&flag));
    let mut work = Work::default();
    sim.clone().advance_observed(&mut work).expect("no blow-up");
    stop::unwatch();
    assert_eq!(work.phases, vec![(0, 2400), (0, 2400)], "{work:?}");
    let mut work = Work::default();
    sim.advance_observed(&mut work).expect("no blow-up");
    assert!(work.phases.iter().all(|&(used, _)| used > 0), "{work:?}");
}
