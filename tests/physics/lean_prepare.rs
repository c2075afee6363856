//! Sequential impulses' lean prepare (contacts and Jacobian rows in one pass)
//! against the full path (the single-contact stages, then the rows from the
//! prepared contacts): every number a phase reads agrees to 1e-12 (and, as
//! the operations are the same, bit for bit) on lessons and on stepped scenes
//! (rotated bodies, friction, sliding and sticking contacts, the world).
//! The deepest-first order's lean prepare likewise against its full path
//! (contacts, setups, friction entries with their factored matrix, bodies,
//! adjacency), then both resolved, silent and recorded.

use contact_lab::lesson::Lesson;
use contact_lab::physics::resolver::{Implementation, Observer, Resolver, Silent, VelocityImpulse};
use contact_lab::physics::{ResolverParams, Solver, World};
use nalgebra::{Matrix3, Vector3};
use std::sync::atomic::{AtomicUsize, Ordering};

use crate::common::resolver_worlds::{each_stepped_world, LESSONS};

fn si() -> ResolverParams {
    ResolverParams {
        solver: Solver::SequentialImpulse,
        ..ResolverParams::default()
    }
}

fn close(a: f64, b: f64, what: &str, k: usize) {
    assert!(
        (a - b).abs() <= 1e-12 * b.abs().max(1.0) || (a.is_nan() && b.is_nan()),
        "contact {k}, {what}: lean {a:e} against full {b:e}"
    );
}

fn close_v(a: &Vector3<f64>, b: &Vector3<f64>, what: &str, k: usize) {
    a.iter().zip(b).for_each(|(x, y)| close(*x, *y, what, k));
}

fn close_m(a: &Matrix3<f64>, b: &Matrix3<f64>, what: &str, k: usize) {
    a.iter().zip(b).for_each(|(x, y)| close(*x, *y, what, k));
}

/// Velocity visits the recorded path made that changed an impulse.
static RECORDED_VISITS: AtomicUsize = AtomicUsize::new(0);

/// An observer that keeps something (so the phases take the recorded path,
/// visit by visit through the resolver): counts the velocity visits.
struct Counting;

impl Observer<f64> for Counting {
    fn velocity_taken(&mut self, _: usize, _: usize, _: f64, _: &VelocityImpulse<f64>) {
        RECORDED_VISITS.fetch_add(1, Ordering::Relaxed);
    }
}

/// Contact `k`'s bookkeeping and setup, lean against full, field by field
/// (each prepare's test then adds what it alone holds).
fn close_records(lean: &Resolver<f64>, full: &Resolver<f64>, k: usize) {
    let (a, b) = (&lean.contacts[k], &full.contacts[k]);
    assert_eq!(a.bodies, b.bodies, "contact {k}");
    close(a.penetration, b.penetration, "penetration", k);
    close(a.desired, b.desired, "desired", k);
    close_v(&a.velocity, &b.velocity, "velocity", k);
    close_m(&a.basis, &b.basis, "basis", k);
    close(a.initial_velocity, b.initial_velocity, "v0", k);
    close(a.gap_speed, b.gap_speed, "gap speed", k);
    close(
        a.velocity_from_acceleration,
        b.velocity_from_acceleration,
        "v_acc",
        k,
    );
    for i in 0..2 {
        close_v(&a.r[i], &b.r[i], "r", k);
    }
    let (s, t) = (&lean.setups[k], &full.setups[k]);
    close(s.total_inertia, t.total_inertia, "total inertia", k);
    close(s.unit_total, t.unit_total, "Δq̇_t", k);
    close(s.slip, t.slip, "slip", k);
    assert_eq!(s.friction, t.friction, "contact {k}");
    for (p, q) in s.projection.iter().zip(&t.projection) {
        assert_eq!(p.is_some(), q.is_some(), "contact {k}");
        if let (Some(p), Some(q)) = (p, q) {
            close(p.angular, q.angular, "angular inertia", k);
            close(p.linear, q.linear, "linear inertia", k);
            close(p.r_perp_length, q.r_perp_length, "|r⊥|", k);
            close_v(&p.rotation_per_unit, &q.rotation_per_unit, "I⁻¹(r×d)", k);
            close(p.angular_limit, q.angular_limit, "angular limit", k);
        }
    }
}

/// Returns (contacts, contacts with friction, sliding contacts).
/// Prepares `world` both ways; every field the phases and reports read agrees.
fn compare(world: &World<f64>, params: &ResolverParams) -> (usize, usize, usize) {
    let full = Resolver::prepare(world, params);
    // `prepare_again` (the lean path) on a resolver that held this world
    // under deepest-first (friction matrices factored, storage this size).
    let deepest_first = ResolverParams {
        solver: Solver::DeepestFirst,
        ..*params
    };
    let mut lean = Resolver::prepare(world, &deepest_first);
    lean.prepare_again(world, params);
    assert_eq!(lean.bodies, full.bodies);
    assert_eq!(lean.contacts.len(), full.contacts.len());
    assert_eq!(lean.adjacency, full.adjacency);
    let (mut with_friction, mut sliding) = (0, 0);
    for k in 0..full.contacts.len() {
        close_records(&lean, &full, k);
        let (x, y) = (&lean.sequential.rows[k], &full.sequential.rows[k]);
        assert_eq!(x.bodies, y.bodies, "contact {k}");
        assert_eq!((x.friction, x.sliding), (y.friction, y.sliding));
        close(x.mu, y.mu, "μ", k);
        close(x.bounce, y.bounce, "bounce", k);
        close(x.unit_total, y.unit_total, "rows Δq̇_t", k);
        close_v(&x.offset, &y.offset, "offset", k);
        close_v(&x.normal_row, &y.normal_row, "M row 0", k);
        close_m(&x.inverse, &y.inverse, "M⁻¹", k);
        for i in 0..2 {
            close(x.inverse_mass[i], y.inverse_mass[i], "s m⁻¹", k);
            close_m(&x.angular[i], &y.angular[i], "A", k);
            close_m(&x.turn[i], &y.turn[i], "I⁻¹A", k);
        }
        with_friction += usize::from(y.friction);
        sliding += usize::from(y.sliding);
        // The same operations in the same order: the same bits.
        assert_eq!(x, y, "contact {k}: rows not bit for bit");
        let (a, b) = (&lean.contacts[k], &full.contacts[k]);
        assert_eq!(a, b, "contact {k}: contact not bit for bit");
    }
    for (f, g) in lean.friction.iter().zip(&full.friction) {
        assert_eq!(f.matrix.matrix, g.matrix.matrix);
    }
    // Both resolve to the same bodies.
    let mut full = full;
    let mut recorded = lean.clone();
    for r in [&mut lean, &mut full] {
        r.position_phase(Implementation::Indexed, &mut Silent);
        r.velocity_phase(Implementation::Indexed, &mut Silent);
    }
    assert_eq!(lean.bodies, full.bodies);
    // The silent velocity sweep (rows and accumulated impulses side by
    // side) and the recorded one give the same bits.
    recorded.position_phase(Implementation::Indexed, &mut Counting);
    recorded.velocity_phase(Implementation::Indexed, &mut Counting);
    assert_eq!(recorded.bodies, lean.bodies);
    assert_eq!(recorded.contacts, lean.contacts);
    assert_eq!(recorded.sequential.accumulated, lean.sequential.accumulated);
    (full.contacts.len(), with_friction, sliding)
}

#[test]
fn the_lean_rows_are_the_full_paths_on_lessons() {
    let mut totals = (0, 0);
    for id in LESSONS {
        let world = Lesson::load(id).unwrap().world::<f64>();
        let (n, f, _) = compare(&world, &si());
        totals = (totals.0 + n, totals.1 + f);
    }
    assert!(totals.0 > 10 && totals.1 > 0, "{totals:?}");
}

#[test]
fn the_lean_rows_are_the_full_paths_on_stepped_scenes() {
    let (mut contacts, mut friction, mut sliding) = (0, 0, 0);
    each_stepped_world(Solver::SequentialImpulse, true, |world, params, _| {
        let (n, f, s) = compare(world, params);
        (contacts, friction, sliding) = (contacts + n, friction + f, sliding + s);
    });
    // The recorded velocity sweeps changed impulses (they were compared).
    assert!(RECORDED_VISITS.load(Ordering::Relaxed) > 100);
    // The scenes gave contacts with friction, and some slid.
    assert!(
        contacts > 500 && friction > 100 && sliding > 0,
        "{contacts} {friction} {sliding}"
    );
}

fn df() -> ResolverParams {
    ResolverParams {
        solver: Solver::DeepestFirst,
        ..ResolverParams::default()
    }
}

/// `a` and `b` to the bit (Debug tells -0 from 0 where `==` does not).
fn same_bits<D: std::fmt::Debug>(a: &D, b: &D, what: &str) {
    assert_eq!(
        format!("{a:?}"),
        format!("{b:?}"),
        "{what}: not bit for bit"
    );
}

/// The deepest-first lean prepare (`lean`, by `prepare_again`) against the
/// full one of `world`: field by field, then bit for bit, then resolved.
/// Returns (contacts, contacts with friction).
fn compare_deepest_first(lean: &mut Resolver<f64>, world: &World<f64>) -> (usize, usize) {
    let params = lean.params;
    let full = Resolver::prepare(world, &params);
    same_bits(&lean.bodies, &full.bodies, "bodies");
    assert_eq!(lean.contacts.len(), full.contacts.len());
    assert_eq!(lean.adjacency.offsets, full.adjacency.offsets);
    assert_eq!(lean.adjacency.contacts, full.adjacency.contacts);
    for k in 0..full.contacts.len() {
        close_records(lean, &full, k);
        let (a, b) = (&lean.contacts[k], &full.contacts[k]);
        let (s, t) = (&lean.setups[k], &full.setups[k]);
        same_bits(a, b, &format!("contact {k}"));
        same_bits(s, t, &format!("setup {k}"));
    }
    assert_eq!(lean.friction.len(), full.friction.len());
    for (j, (f, g)) in lean.friction.iter().zip(&full.friction).enumerate() {
        assert_eq!(f.model, g.model);
        same_bits(
            &(f.static_friction, f.dynamic_friction),
            &(g.static_friction, g.dynamic_friction),
            "μ",
        );
        close_m(&f.matrix.matrix, &g.matrix.matrix, "M", j);
        same_bits(
            &f.matrix.matrix,
            &g.matrix.matrix,
            &format!("M of entry {j}"),
        );
        // The same factor: the same g, the same way, for any right-hand side.
        for rhs in [Vector3::new(0.3, -1.2, 2.5), Vector3::new(-2.0, 0.01, 1e-3)] {
            let ((x, s), (y, t)) = (f.matrix.solve(rhs), g.matrix.solve(rhs));
            same_bits(&x, &y, &format!("g of entry {j}"));
            assert_eq!(
                (s.used_lu, s.singular),
                (t.used_lu, t.singular),
                "entry {j}"
            );
        }
        same_bits(
            &f.matrix.cholesky_inverse(),
            &g.matrix.cholesky_inverse(),
            "M⁻¹",
        );
    }
    // Both resolve to the same bits, silent and recorded.
    let mut full = full;
    let mut recorded = lean.clone();
    for r in [&mut *lean, &mut full] {
        r.position_phase(Implementation::Indexed, &mut Silent);
        r.velocity_phase(Implementation::Indexed, &mut Silent);
    }
    same_bits(&lean.bodies, &full.bodies, "resolved bodies");
    same_bits(&lean.contacts, &full.contacts, "resolved contacts");
    recorded.position_phase(Implementation::Indexed, &mut Counting);
    recorded.velocity_phase(Implementation::Indexed, &mut Counting);
    same_bits(&recorded.bodies, &lean.bodies, "recorded bodies");
    let friction = full.setups.iter().filter(|s| s.friction.is_some()).count();
    (full.contacts.len(), friction)
}

#[test]
fn the_deepest_first_lean_prepare_is_the_full_paths_on_lessons() {
    let mut totals = (0, 0);
    let other = Lesson::load("box-four-corners").unwrap().world::<f64>();
    for id in LESSONS {
        let world = Lesson::load(id).unwrap().world::<f64>();
        // Storage that held this world under either solver, and a fresh one.
        for held in [df(), si()] {
            let mut lean = Resolver::prepare(&world, &held);
            lean.prepare_again(&world, &df());
            let (n, f) = compare_deepest_first(&mut lean, &world);
            totals = (totals.0 + n, totals.1 + f);
        }
        // Storage that held another world (other sizes, other slots).
        let mut lean = Resolver::prepare(&other, &df());
        lean.prepare_again(&world, &df());
        compare_deepest_first(&mut lean, &world);
    }
    assert!(totals.0 > 20 && totals.1 > 0, "{totals:?}");
}

#[test]
fn the_deepest_first_lean_prepare_is_the_full_paths_on_stepped_scenes() {
    let (mut contacts, mut friction) = (0, 0);
    // One resolver through a scene's steps, as a simulation keeps it (the
    // adjacency kept where the contacts' bodies stay, rebuilt elsewhere); a
    // new one for each scene (the first step of each has no contact before).
    let mut kept: Option<Resolver<f64>> = None;
    each_stepped_world(Solver::DeepestFirst, false, |world, params, step| {
        if step == 0 {
            kept = None;
        }
        let lean = kept.get_or_insert_with(|| Resolver::prepare(world, params));
        lean.prepare_again(world, params);
        let mut run = lean.clone();
        let (n, f) = compare_deepest_first(&mut run, world);
        (contacts, friction) = (contacts + n, friction + f);
    });
    assert!(RECORDED_VISITS.load(Ordering::Relaxed) > 100);
    assert!(contacts > 500 && friction > 100, "{contacts} {friction}");
}
