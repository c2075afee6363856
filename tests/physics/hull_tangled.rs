//! Nearly coplanar hull points (issue 39, "huge and degenerate inputs
//! answer"): a grid on a cube's faces jittered by about the build's
//! tolerance (1e-10 of the extent) panicked the conflict-list build (an
//! edge with no reverse) and made the older build loop without end. Now the
//! build widens its tolerance tenfold at a time and the lesson says so, or
//! refuses the points; never a panic, never a hang.

use contact_lab::physics::hull::{ConvexHull, HullError};
use contact_lab::physics::step::Simulation;

#[test]
fn the_tangled_grid_loads_with_a_widened_tolerance_said_and_runs() {
    let text = include_str!("hull-tangled.toml");
    let lesson = contact_lab::lesson::validate::parse("hull-tangled.toml", text).unwrap();
    let said: Vec<&str> = lesson.warnings.iter().map(|w| w.message.as_str()).collect();
    assert!(
        said.iter()
            .any(|m| m.contains("nearly coplanar") && m.contains("built at tolerance")),
        "{said:?}"
    );
    let params = lesson.sim_params().expect("a scene");
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let mut sim = Simulation::new(world, params, lesson.simulation.unwrap().materials);
    for _ in 0..2 {
        sim.advance().expect("no blow-up");
    }
}

/// A small generator (no dependency): the same grids on every machine.
struct Lcg(u64);
impl Lcg {
    fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
}

#[test]
fn jittered_cube_grids_build_or_are_refused_never_panic() {
    let mut rng = Lcg(39);
    let (mut built, mut widened, mut off) = (0, 0, 0);
    for n in [3usize, 5, 8] {
        for noise in [1e-11, 3e-11, 1e-10, 3e-10, 1e-9] {
            for scale in [1e-3, 1.0, 1e3] {
                let mut pts = vec![];
                for face in 0..6 {
                    let (axis, sign) = (face / 2, if face % 2 == 1 { 1.0 } else { -1.0 });
                    let others: Vec<usize> = (0..3).filter(|&a| a != axis).collect();
                    for i in 0..=n {
                        for j in 0..=n {
                            let mut p = [0.0; 3];
                            p[axis] = 0.5 * sign;
                            p[others[0]] = -0.5 + i as f64 / n as f64;
                            p[others[1]] = -0.5 + j as f64 / n as f64;
                            pts.push(p.map(|x| (x + noise * rng.unit()) * scale));
                        }
                    }
                }
                // Edge points are shared by two faces: keep the first.
                let mut seen = std::collections::HashSet::new();
                pts.retain(|p| seen.insert(p.map(f64::to_bits)));
                match ConvexHull::new(&pts) {
                    Ok(hull) => {
                        built += 1;
                        widened += hull.widened_tolerance().is_some() as usize;
                        // Known open (issue 39): a few grids build a closed
                        // hull whose volume is off (3.6 % at n 8, noise 1e-11,
                        // scale 1e3): counted and printed, not yet held.
                        let v = hull.mass_properties().volume;
                        off += ((v / (scale * scale * scale) - 1.0).abs() > 1e-6) as usize;
                    }
                    Err(e) => assert!(matches!(e, HullError::Tangled { .. }), "{e}"),
                }
            }
        }
    }
    println!("{built} of 45 grids built, {widened} at a widened tolerance, {off} with a volume off by over 1e-6");
    assert!(built >= 40, "{built} of 45 built");
}
