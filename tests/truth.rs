//! Scenes that never lie (issue 23): every energy event's cause verified by
//! re-running the step with that cause switched off, blow-ups that stop the
//! run, bodies pushed through or wholly inside others reported, and sleep
//! that needs a contact.

use contact_lab::lesson::Lesson;
use contact_lab::physics::step::audit::{gain, EnergyCause, Switches};
use contact_lab::physics::step::{Event, Simulation};
use contact_lab::physics::Solver;

/// The simulation of an embedded scene or of a file in tests/truth/.
fn simulation(id: &str) -> Simulation<f64> {
    let path = format!("{}/tests/truth/{id}.toml", env!("CARGO_MANIFEST_DIR"));
    let name = if std::path::Path::new(&path).exists() {
        path
    } else {
        id.to_string()
    };
    let lesson = Lesson::load(&name).unwrap();
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.unwrap().materials;
    Simulation::new(world, params, materials)
}

/// One energy event and what re-running its step showed.
#[derive(Debug)]
struct Verified {
    step: u64,
    cause: EnergyCause,
}

/// Runs `steps` steps; at every energy event, re-runs the step from its
/// inputs: as it was (the gain must come back) and with the named causes
/// switched off (the gain must go). Returns the events.
fn verified_run(sim: &mut Simulation<f64>, steps: usize, what: &str) -> Vec<Verified> {
    let mut found = Vec::new();
    for _ in 0..steps {
        let before = sim.clone();
        let report = match sim.advance() {
            Ok(r) => r,
            Err(e) => panic!("{what}: {e}"),
        };
        for e in &report.events {
            let Event::EnergyGain { gained, cause } = *e else {
                continue;
            };
            let scale = sim.energy_scale();
            let again = before.replay_next(Switches::empty());
            let regained = gain(again.kinetic_before, again.kinetic_after, scale);
            assert_eq!(
                regained,
                Some(gained),
                "{what} step {}: the replay does not reproduce the gain",
                report.step
            );
            let checks: Vec<Switches> = match cause {
                EnergyCause::Each(s) => s.iter().map(Switches::one).collect(),
                EnergyCause::Together(s) => vec![s],
                EnergyCause::Unexplained { .. } => vec![],
            };
            for off in checks {
                let e = before.replay_next(off);
                assert_eq!(
                    gain(e.kinetic_before, e.kinetic_after, scale),
                    None,
                    "{what} step {}: {off:?} switched off, the step still gains ({} → {} J)",
                    report.step,
                    e.kinetic_before,
                    e.kinetic_after
                );
            }
            found.push(Verified {
                step: report.step,
                cause,
            });
        }
    }
    found
}

#[test]
fn every_scene_under_every_solver_names_only_causes_its_switches_confirm() {
    for id in contact_lab::lesson::embedded::scene_ids() {
        // Each scene for its default length, at most 600 steps (10 s).
        let steps = Lesson::load(id).unwrap().simulation.unwrap().steps.min(600) as usize;
        for solver in [Solver::DeepestFirst, Solver::SequentialImpulse] {
            for warm in [false, true] {
                if warm && solver == Solver::DeepestFirst {
                    continue;
                }
                for compensation in [true, false] {
                    let mut sim = simulation(id);
                    sim.params.resolver.solver = solver;
                    sim.params.resolver.warm_start = warm;
                    sim.params.acceleration_compensation = compensation;
                    let what = format!("{id} {solver:?} warm {warm} compensation {compensation}");
                    for v in verified_run(&mut sim, steps, &what) {
                        assert!(
                            !matches!(v.cause, EnergyCause::Unexplained { .. }),
                            "{what} step {}: {:?}",
                            v.step,
                            v.cause
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn a_rod_gaining_under_a_friction_model_blames_the_model_not_compensation() {
    use contact_lab::physics::step::audit::Switch;
    for (id, model) in [
        ("rod-velocity-scaling", Switch::VelocityScaling),
        ("rod-kinetic-direction", Switch::KineticDirection),
    ] {
        for compensation in [true, false] {
            let mut sim = simulation(id);
            sim.params.acceleration_compensation = compensation;
            let events = verified_run(&mut sim, 180, id);
            let blamed: Vec<_> = events
                .iter()
                .filter(|v| v.cause.switches().contains(model))
                .collect();
            assert!(!blamed.is_empty(), "{id}: {events:?}");
            for v in &events {
                assert!(
                    !v.cause
                        .switches()
                        .contains(Switch::AccelerationCompensation),
                    "{id} step {}: {:?}",
                    v.step,
                    v.cause
                );
                assert!(!matches!(v.cause, EnergyCause::Unexplained { .. }));
            }
        }
    }
}
