//! Random elastic scenes and their energy audit, for the property test
//! (physics/energy_named.rs, 24 scenes) and its 200-scene version
//! (measure/energy_named.rs): spheres, boxes, cans, capsules and
//! tetrahedra thrown onto a floor and each other with restitution 1 under
//! warm sequential impulses; each step's rise of the movable bodies' total
//! energy above the total-energy audit's tolerance (summed over the bodies,
//! plus the position phase's settling lift, Σ m |g| × the step's deepest
//! penetration) must come with an `energy` event whose cause the replay
//! found, or belong to a rise named when it started that goes on among the
//! same bodies.

use contact_lab::lesson::validate::parse;
use contact_lab::physics::step::audit::EnergyCause;
use contact_lab::physics::step::{energy, total_audit, Event, Simulation};
use contact_lab::physics::Solver;

/// A small generator (the same numbers on every platform).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A scene of `n` bodies of every kind, size 0.3–0.6 m, mass 0.5–5 kg,
/// thrown at up to 4 m/s into a 3 m box of space over a half-space, with
/// restitution 1 and friction 0.4, under warm sequential impulses.
pub fn scene(seed: u64, n: usize, steps: usize) -> Simulation<f64> {
    let mut rng = Lcg(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0xD1B5);
    let mut text = format!(
        "id = \"energy-{seed}\"\ntitle = \"random\"\nsource = \"test\"\nsummary = \"test\"\n\n\
         [world]\nrestitution = 1.0\nfriction = 0.4\n\n\
         [step]\ndt = 0.016666666666666666\nsteps = {steps}\n\n\
         [[body]]\nname = \"floor\"\nmass = inf\nshape = \"half_space\"\nposition = [0, 0, 0]\n"
    );
    for i in 0..n {
        let size = 0.3 + 0.3 * rng.next();
        let shape = match (i + seed as usize) % 5 {
            0 => format!("{{ sphere = {} }}", 0.5 * size),
            1 => format!("{{ box = [{size}, {}, {}] }}", size * 1.3, size * 0.7),
            2 => format!("{{ cylinder = [{}, {size}] }}", size * 0.5),
            3 => format!("{{ capsule = [{}, {size}] }}", size * 0.3),
            _ => format!(
                "{{ convex = [[0, 0, 0], [{size}, 0, 0], [0, {size}, 0], [0, 0, {size}]] }}"
            ),
        };
        let p = [rng.next() * 3.0, 0.5 + rng.next() * 2.5, rng.next() * 3.0];
        let v = [rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5].map(|x| x * 8.0);
        let q = [1.0, rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5];
        let norm = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        let q = q.map(|x| x / norm);
        text.push_str(&format!(
            "\n[[body]]\nname = \"b{i}\"\nmass = {}\nshape = {shape}\nposition = {p:?}\n\
             velocity = {v:?}\norientation = {q:?}\nangular_velocity = [{}, 0, {}]\n",
            0.5 + 4.5 * rng.next(),
            rng.next() * 4.0,
            rng.next() * 4.0
        ));
    }
    let lesson = parse("energy_named.rs", &text).expect("a valid scene");
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    sim.params.resolver.solver = Solver::SequentialImpulse;
    sim.params.resolver.warm_start = true;
    sim
}

/// What a run showed: the steps whose rise no event named, and the energy
/// events whose cause the replay did not find.
#[derive(Debug, Default)]
pub struct Audit {
    pub unnamed: Vec<(u64, f64, f64)>,
    pub unexplained: Vec<(u64, String)>,
    pub events: usize,
    pub rises: usize,
}

/// Runs `sim` for `steps` steps and audits every rise of the total energy.
pub fn audit(mut sim: Simulation<f64>, steps: usize) -> Audit {
    let g = sim.params.world.gravity;
    let gn = g.norm();
    let dt = sim.params.dt;
    let masses: Vec<f64> = (sim.world.bodies.iter())
        .filter_map(|b| b.dynamic().map(|d| d.mass))
        .collect();
    let mass: f64 = masses.iter().sum();
    let eps_v = (sim.lowered_tolerances().iter())
        .find(|l| l.which == contact_lab::physics::step::tolerance::Tolerance::VelocityEpsilon)
        .map_or(sim.params.resolver.velocity_epsilon, |l| l.used);
    let tolerance = total_audit::tolerance(mass, gn, eps_v, dt);
    let mut before = energy::total(&sim.world, &g);
    let mut out = Audit::default();
    // A rise going on since a step that named it.
    let mut named_streak = false;
    // The bodies in contact over the steps of that rise.
    let mut streak = vec![false; sim.world.bodies.len()];
    for _ in 0..steps {
        let r = sim.advance().expect("no blow-up");
        let now = energy::total(&sim.world, &g);
        let lift = mass * gn * r.max_penetration.max(0.0);
        let rounding = 1e-9 * before.abs().max(1.0);
        let rise = now - before;
        let mut named = false;
        for e in &r.events {
            let cause = match e {
                Event::EnergyGain { cause, .. } | Event::EnergyRise { cause, .. } => Some(*cause),
                Event::ProjectionLift { .. } | Event::RollbackLift { .. } => None,
                _ => continue,
            };
            named = true;
            out.events += 1;
            if let Some(EnergyCause::Unexplained { .. }) = cause {
                out.unexplained.push((r.step, format!("{e:?}")));
            }
        }
        // A rise named at its start covers the steps after it while the
        // energy goes on rising among the same bodies (a body that joins it
        // starts a new one).
        let mut touched = vec![false; sim.world.bodies.len()];
        for k in &sim.world.contacts {
            for b in [Some(k.body1), k.body2].into_iter().flatten() {
                touched[b.0] |= sim.world.bodies[b.0].movable;
            }
        }
        let same = (touched.iter().zip(&streak)).all(|(t, s)| !t || *s);
        let covered = named || (named_streak && rise > rounding && same);
        if rise > tolerance + lift + rounding {
            out.rises += 1;
            if !covered {
                out.unnamed.push((r.step, rise, tolerance + lift));
            }
        }
        named_streak = covered && rise > rounding;
        if named {
            streak = touched;
        } else if named_streak {
            for (s, t) in streak.iter_mut().zip(&touched) {
                *s |= *t;
            }
        }
        before = now;
    }
    out
}
