//! The broad phase never changes a run, only what finding the pairs costs
//! (`[world] broad_phase`, docs/detect.md's mesh contract): embedded
//! scenes and random ones of every shape kind at 1 mm, 1 m and 1 km run
//! step by step under sort and sweep, the grid and the tree, and every
//! body's state and every contact is the same to the bit at every step.

use contact_lab::lesson::Lesson;
use contact_lab::physics::params::BroadPhaseMethod;
use contact_lab::physics::step::Simulation;

const METHODS: [BroadPhaseMethod; 3] = [
    BroadPhaseMethod::Sweep,
    BroadPhaseMethod::Grid,
    BroadPhaseMethod::Bvh,
];

fn simulation(lesson: &Lesson, method: BroadPhaseMethod) -> Simulation<f64> {
    let mut params = lesson.sim_params().expect("a scene");
    params.broad_phase = method;
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.clone().unwrap().materials;
    Simulation::new(world, params, materials)
}

/// Every number of a body's state and of the contacts, as bits.
fn fingerprint(sim: &Simulation<f64>) -> Vec<u64> {
    let mut bits = Vec::new();
    for b in &sim.world.bodies {
        let s = &b.state;
        bits.extend(s.position.iter().map(|x| x.to_bits()));
        bits.extend(s.orientation.coords.iter().map(|x| x.to_bits()));
        bits.extend(s.velocity.iter().map(|x| x.to_bits()));
        bits.extend(s.angular_velocity.iter().map(|x| x.to_bits()));
    }
    for c in &sim.world.contacts {
        bits.extend([c.body1.0 as u64, c.body2.map_or(u64::MAX, |b| b.0 as u64)]);
        bits.extend(c.input.point.iter().map(|x| x.to_bits()));
        bits.extend(c.input.normal.iter().map(|x| x.to_bits()));
        bits.push(c.input.penetration.to_bits());
    }
    bits
}

/// Runs `lesson` for `steps` steps under every method in lockstep; returns
/// the most contacts a step had (so a test can say it had some).
fn same_run(lesson: &Lesson, steps: usize) -> usize {
    let mut sims: Vec<_> = METHODS.iter().map(|&m| simulation(lesson, m)).collect();
    let mut most = 0;
    for step in 0..steps {
        let reports: Vec<_> = sims
            .iter_mut()
            .map(|s| s.advance().ok().map(|r| r.contacts))
            .collect();
        let first = fingerprint(&sims[0]);
        most = most.max(reports[0].unwrap_or(0));
        for (sim, (ok, method)) in sims.iter().zip(reports.iter().zip(METHODS)).skip(1) {
            assert_eq!(*ok, reports[0], "{}: step {step}, {method:?}", lesson.id);
            assert!(
                fingerprint(sim) == first,
                "{}: step {step}: {method:?} differs from the sweep",
                lesson.id
            );
        }
        if reports[0].is_none() {
            break;
        }
    }
    most
}

#[test]
fn every_embedded_scene_is_the_same_run_under_every_broad_phase() {
    for (id, steps) in [
        ("ball-drop", 600),
        ("stack-5", 90),
        ("sleep-and-wake", 90),
        ("sphere-row-20", 60),
        ("hull-stack", 60),
        ("mass-ratio-stack", 60),
        ("capsule-on-slope", 60),
        ("cradle-over-time", 60),
        ("cylinder-on-box", 40),
        ("sliding-box", 60),
    ] {
        let lesson = Lesson::load(id).unwrap();
        assert!(same_run(&lesson, steps) > 0, "{id} made no contact");
    }
}

/// A small generator of numbers in [0, 1) (a fixed sequence).
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

/// A scene of `n` bodies of every shape kind (sphere, box, cylinder,
/// capsule, hull) of size ~`s`, dropped with random speeds and spins into a
/// volume of side 3`s` over a floor slab (an immovable box wider than the
/// grid's loose limit) and a half-space, under gravity scaled by `s`.
fn random_scene(seed: u64, n: usize, s: f64) -> Lesson {
    let mut rng = Lcg(seed);
    let mut text = format!(
        "id = \"random-{seed}\"\ntitle = \"random\"\nsource = \"test\"\nsummary = \"test\"\n\n\
         [world]\ngravity = [0, {}, 0]\nfriction = 0.4\nrestitution = 0.2\n\n\
         [step]\ndt = 0.016666666666666666\nsteps = 60\n\n[sleep]\nenabled = true\n\n\
         [[body]]\nname = \"floor\"\nmass = inf\nshape = \"half_space\"\nposition = [0, {}, 0]\n\n\
         [[body]]\nname = \"slab\"\nmass = inf\nshape = {{ box = [{}, {}, {}] }}\nposition = [{}, 0, {}]\n",
        -9.81 * s,
        -0.5 * s,
        20.0 * s,
        0.2 * s,
        20.0 * s,
        1.5 * s,
        1.5 * s,
    );
    for i in 0..n {
        let size = s * (0.15 + 0.2 * rng.next());
        let shape = match i % 5 {
            0 => format!("{{ sphere = {size} }}"),
            1 => format!("{{ box = [{size}, {}, {}] }}", size * 1.3, size * 0.7),
            2 => format!("{{ cylinder = {{ radius = {}, height = {size} }} }}", size * 0.5),
            3 => format!("{{ capsule = {{ radius = {}, height = {size} }} }}", size * 0.4),
            _ => format!(
                "{{ convex = [[0, 0, 0], [{size}, 0, 0], [0, {size}, 0], [0, 0, {size}], [{h}, {h}, {h}]] }}",
                h = size * 0.6
            ),
        };
        let p = [
            rng.next() * 3.0 * s,
            (0.3 + rng.next() * 2.0) * s,
            rng.next() * 3.0 * s,
        ];
        let v = [rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5].map(|x| x * 2.0 * s);
        let q = [1.0, rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5];
        let norm = q.iter().map(|x| x * x).sum::<f64>().sqrt();
        let q = q.map(|x| x / norm);
        text.push_str(&format!(
            "\n[[body]]\nname = \"b{i}\"\nmass = 1.0\nshape = {shape}\nposition = {p:?}\nvelocity = {v:?}\n\
             orientation = {q:?}\nangular_velocity = [{}, 0, {}]\n",
            rng.next() * 3.0,
            rng.next() * 3.0
        ));
    }
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "broad-methods-{seed}-{n}-{}.toml",
        s.log10().round()
    ));
    std::fs::write(&path, text).unwrap();
    Lesson::load(path.as_os_str()).unwrap()
}

#[test]
fn random_scenes_of_every_shape_at_every_scale_are_the_same_run_under_every_broad_phase() {
    for (seed, s) in [(1, 1e-3), (2, 1.0), (3, 1e3), (4, 1.0)] {
        let lesson = random_scene(seed, 40, s);
        assert!(
            same_run(&lesson, 45) > 10,
            "seed {seed} at {s} m made few contacts"
        );
    }
}
