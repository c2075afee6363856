//! The world inertia and kinetic energy a step's end keeps for the next
//! step's start (`physics::step::kept_energy`): the same bits as computed
//! afresh, and nothing taken for a body whose state changed in between.

use contact_lab::lesson::Lesson;
use contact_lab::physics::step::kept_energy::KeptEnergy;
use contact_lab::physics::step::{energy, report, Simulation};
use nalgebra::Matrix3;

fn simulation(id: &str) -> Simulation<f64> {
    let lesson = Lesson::load(id).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    Simulation::new(world, params, lesson.simulation.unwrap().materials)
}

fn bits(m: &[Matrix3<f64>]) -> Vec<u64> {
    m.iter()
        .flat_map(|m| m.iter().map(|x| x.to_bits()))
        .collect()
}

#[test]
fn the_kept_end_of_step_energies_are_the_fresh_ones_bit_for_bit() {
    for id in [
        "stack-5",
        "spinning-edge",
        "tetra-on-floor",
        "sleep-and-wake",
    ] {
        let mut sim = simulation(id);
        let (g, dt) = (sim.params.world.gravity.norm(), sim.params.dt);
        let mut kept = KeptEnergy::default();
        let (mut speeds, mut inertia) = (Vec::new(), Vec::new());
        let (mut kept_speeds, mut kept_inertia) = (Vec::new(), Vec::new());
        let mut taken = 0;
        for _ in 0..60 {
            sim.advance().unwrap();
            let w = &sim.world;
            // The step's end: the report's kinetic energy, its parts kept.
            assert_eq!(
                kept.kinetic(w).to_bits(),
                energy::kinetic(w).to_bits(),
                "{id}"
            );
            // The next start, afresh and from what was kept.
            let (k, b) = report::start_of_step(w, g, dt, &mut speeds, &mut inertia);
            let (kk, kb) = report::start_of_step_kept(
                w,
                g,
                dt,
                &mut kept_speeds,
                &mut kept_inertia,
                Some(&kept),
            );
            assert_eq!(
                (k.to_bits(), b.to_bits()),
                (kk.to_bits(), kb.to_bits()),
                "{id}"
            );
            assert_eq!(bits(&inertia), bits(&kept_inertia), "{id}");
            assert_eq!(speeds, kept_speeds, "{id}");
            let movable = w.bodies.iter().enumerate().filter(|(_, b)| b.movable);
            taken += movable
                .filter(|(i, b)| kept.of(*i, &b.state).is_some())
                .count();
        }
        // Every movable body's share was taken at every step.
        let movable = sim.world.bodies.iter().filter(|b| b.movable).count();
        assert_eq!(taken, 60 * movable, "{id}");
    }
}

#[test]
fn a_body_changed_between_the_steps_is_computed_afresh() {
    let mut sim = simulation("stack-5");
    for _ in 0..10 {
        sim.advance().unwrap();
    }
    let i = sim.world.bodies.iter().position(|b| b.movable).unwrap();
    sim.world.bodies[i].state.velocity.z = 0.0;
    let mut kept = KeptEnergy::default();
    kept.kinetic(&sim.world);
    let state = sim.world.bodies[i].state.clone();
    assert!(kept.of(i, &state).is_some());
    type Edit = fn(&mut contact_lab::physics::RigidBody<f64>);
    let edits: [(&str, Edit); 6] = [
        ("turned by an ulp", |s| {
            s.orientation.w = s.orientation.w.next_up()
        }),
        ("a zero velocity's sign", |s| s.velocity.z = -0.0),
        ("spun", |s| s.angular_velocity.x += 1e-3),
        ("heavier", |s| s.mass *= 2.0),
        ("another inertia", |s| s.inertia_body[(1, 1)] *= 1.5),
        ("NaN", |s| s.velocity.x = f64::NAN),
    ];
    let (g, dt) = (sim.params.world.gravity.norm(), sim.params.dt);
    for (what, edit) in edits {
        let mut edited = sim.world.clone();
        edit(&mut edited.bodies[i].state);
        assert!(kept.of(i, &edited.bodies[i].state).is_none(), "{what}");
        let (mut s1, mut i1, mut s2, mut i2) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let fresh = report::start_of_step(&edited, g, dt, &mut s1, &mut i1);
        let reused = report::start_of_step_kept(&edited, g, dt, &mut s2, &mut i2, Some(&kept));
        assert_eq!(fresh.0.to_bits(), reused.0.to_bits(), "{what}");
        assert_eq!(bits(&i1), bits(&i2), "{what}");
    }
}
