//! The XPBD paper's erratum (Müller, Macklin, Chentanez, Jeschke, Kim 2020,
//! "Detailed rigid body simulation with extended position based dynamics",
//! eq. 30): its dynamic-friction Δv has the units of an impulse, not a speed.
//! Measured when asked: a 1 m box sliding at 3 m/s on a floor (μ 0.5,
//! Δt 1/60 s, 4 substeps) under the printed formula and under the corrected
//! one (Solver2D's), at several masses — the printed deceleration depends on
//! the mass, the corrected one does not.

use crate::lesson::validate::parse;
use crate::physics::step::xpbd::DynamicFriction;
use crate::physics::step::Simulation;

/// The coefficient of dynamic friction of the sliding box and its floor.
pub const MU_D: f64 = 0.5;
/// The gravity of the experiment (m/s², the scene's default).
pub const G: f64 = 9.81;
/// The masses (kg) the box is slid at.
pub const MASSES: [f64; 4] = [1.0, 2.0, 4.0, 10.0];

/// The paper's formula, as printed.
pub const PRINTED: &str = "Δv = -(v_t/|v_t|) min(h μ_d |f_n|, |v_t|), f_n = λ_n/h²";
/// Solver2D's correction: the impulse times the generalized inverse mass.
pub const CORRECTED: &str = "Δv = -(v_t/|v_t|) min(h μ_d |f_n| (w₁ + w₂), |v_t|)";
/// Why the printed one is wrong.
pub const WHY: &str = "h μ_d |f_n| = μ_d λ_n/h is an impulse (kg·m/s), not a speed: \
the printed Δv is the corrected one divided by (w₁ + w₂) in kg, so the deceleration \
grows with the body's mass";

/// The deceleration of one mass under both formulas.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measured {
    /// The box's mass (kg).
    pub mass: f64,
    /// The deceleration under the printed formula (m/s²).
    pub printed: f64,
    /// The deceleration under the corrected formula (m/s²).
    pub corrected: f64,
}

/// The erratum with its measurement.
#[derive(Debug, Clone, PartialEq)]
pub struct Erratum {
    pub rows: Vec<Measured>,
}

impl Erratum {
    /// μ_d g, the closed form's deceleration (m/s²).
    pub fn mu_g(&self) -> f64 {
        MU_D * G
    }
}

/// The sliding box, under XPBD with `formula`.
fn sliding_box(mass: f64, formula: DynamicFriction) -> Simulation<f64> {
    let text = format!(
        r#"id = "xpbd-sliding-box"
title = "A box sliding on a floor under XPBD"
source = "Müller et al. 2020"
summary = "A 1 m box sliding at 3 m/s on a floor, mu 0.5."

[settings]
solver = "xpbd"

[world]
restitution = 0
friction = {MU_D}
linear_damping = 1
angular_damping = 1

[step]
dt = 0.016666666666666666
steps = 120

[sleep]
enabled = false

[[body]]
name = "box"
mass = {mass}
shape = {{ box = [1, 1, 1] }}
position = [0, 0.5, 0]
velocity = [3, 0, 0]

[[body]]
name = "floor"
mass = inf
shape = "half_space"
position = [0, 0, 0]
"#
    );
    let lesson = parse("xpbd-sliding-box", &text).expect("the built-in scene parses");
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    sim.xpbd.dynamic_friction = formula;
    sim
}

/// The box's deceleration (m/s²) under `formula`: measured between 0.05 s
/// and the last step before it slows below 0.3 m/s. `None` if it never
/// slid that long or the step blew up (nothing to report, said by the caller).
pub fn sliding_deceleration(mass: f64, formula: DynamicFriction) -> Option<f64> {
    let mut sim = sliding_box(mass, formula);
    let mut first: Option<(f64, f64)> = None;
    let mut last = (0.0, 0.0);
    for _ in 0..120 {
        sim.advance().ok()?;
        let v = sim.world.bodies[0].state.velocity.x;
        if v < 0.3 {
            break;
        }
        if sim.time >= 0.05 - 1e-9 {
            first.get_or_insert((sim.time, v));
            last = (sim.time, v);
        }
    }
    let (t0, v0) = first?;
    (last.0 > t0).then(|| (v0 - last.1) / (last.0 - t0))
}

/// The erratum, measured now at every mass of [`MASSES`] (a mass whose run
/// gives no figure is left out).
pub fn measure() -> Erratum {
    let rows = MASSES
        .iter()
        .filter_map(|&mass| {
            Some(Measured {
                mass,
                printed: sliding_deceleration(mass, DynamicFriction::Printed)?,
                corrected: sliding_deceleration(mass, DynamicFriction::Corrected)?,
            })
        })
        .collect();
    Erratum { rows }
}
