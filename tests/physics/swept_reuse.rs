//! The tunnelling audit's broad phase reusing contact generation's pairs
//! (docs/ccd.md, "Cost"): wherever it reuses them, it finds exactly the
//! pairs a fresh sort and sweep of the swept boxes finds — bodies at rest,
//! a few fast ones (tested one by one), many fast ones (swept again), after
//! a projection has moved them, boxes turning, a floor.

use std::collections::BTreeSet;

use contact_lab::physics::collide::{ContactGenerator, Options};
use contact_lab::physics::step::swept::{Earlier, SweptPairs};
use contact_lab::physics::{Body, RigidBody, Shape, World};
use nalgebra::{Matrix3, Quaternion, Vector3};

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

/// 125 bodies (spheres and boxes, some turning) 1.001 apart on a grid over
/// a floor; `fast` of them move at 100 m/s, the rest at up to 0.1 m/s.
fn world(fast: usize, seed: u64) -> World<f64> {
    let mut rng = Lcg(seed);
    let mut bodies: Vec<Body<f64>> = (0..125)
        .map(|i| {
            let p = Vector3::new((i % 5) as f64, (i / 25) as f64 + 0.5, ((i / 5) % 5) as f64);
            let mut v = Vector3::from_fn(|_, _| rng.next() - 0.5) * 0.2;
            if i % (125 / fast.max(1)) == 0 && i / (125 / fast.max(1)) < fast {
                v = v.normalize() * 100.0;
            }
            let shape = if i % 3 == 0 {
                Shape::Box {
                    sides: [0.9, 0.8, 0.7],
                }
            } else {
                Shape::Sphere { radius: 0.5 }
            };
            let w = if i % 4 == 0 {
                Vector3::new(0.3, -0.2, 0.1)
            } else {
                Vector3::zeros()
            };
            Body {
                state: RigidBody {
                    mass: 1.0,
                    inverse_mass: 1.0,
                    inertia_body: Matrix3::identity(),
                    inverse_inertia_body: Matrix3::identity(),
                    position: p * 1.001,
                    orientation: Quaternion::new(1.0, 0.1 * rng.next(), 0.0, 0.0),
                    velocity: v,
                    angular_velocity: w,
                    acceleration: Vector3::zeros(),
                },
                shape: Some(shape),
                movable: true,
            }
        })
        .collect();
    bodies.push(Body {
        state: RigidBody {
            mass: f64::INFINITY,
            inverse_mass: 0.0,
            inertia_body: Matrix3::identity(),
            inverse_inertia_body: Matrix3::zeros(),
            position: Vector3::zeros(),
            orientation: Quaternion::identity(),
            velocity: Vector3::zeros(),
            angular_velocity: Vector3::zeros(),
            acceleration: Vector3::zeros(),
        },
        shape: Some(Shape::HalfSpace {
            normal: [0.0, 1.0, 0.0],
        }),
        movable: false,
    });
    World {
        bodies,
        contacts: Vec::new(),
        step: Default::default(),
    }
}

/// A set of body pairs (i, j), i < j.
type Pairs = BTreeSet<(usize, usize)>;

/// The swept pairs found fresh and found reusing the generator's pairs
/// (generated where the bodies were before a projection of up to `shift`),
/// and whether the second reused them.
fn both(fast: usize, shift: f64, seed: u64) -> (Pairs, Pairs, bool) {
    let mut w = world(fast, seed);
    let options = Options {
        tolerance: 0.01,
        ..Options::default()
    };
    let mut generator = ContactGenerator::new();
    generator.generate_world(&w.bodies, &options, &mut Vec::new());
    let mut rng = Lcg(seed ^ 0x5eed);
    for b in w.bodies.iter_mut().filter(|b| b.movable) {
        b.state.position += Vector3::from_fn(|_, _| rng.next() - 0.5) * shift;
    }
    let moving: Vec<bool> = w.bodies.iter().map(|b| b.movable).collect();
    let dt = 1.0 / 60.0;
    let mut fresh = SweptPairs::default();
    fresh.find(&w, &moving, dt);
    let mut reusing = SweptPairs::default();
    let earlier = Earlier {
        bounds: generator.bounds(),
        pairs: generator.pairs(),
    };
    reusing.find_reusing(&w, &moving, dt, Some(earlier));
    assert!(!fresh.reused);
    assert!(fresh.pairs.iter().all(|(i, j)| i < j));
    assert!(reusing.pairs.iter().all(|(i, j)| i < j));
    let set = |p: &SweptPairs<f64>| p.pairs.iter().copied().collect::<BTreeSet<_>>();
    assert_eq!(set(&reusing).len(), reusing.pairs.len(), "a pair twice");
    (set(&fresh), set(&reusing), reusing.reused)
}

#[test]
fn slow_bodies_reuse_the_generators_pairs_and_find_the_same_pairs() {
    for seed in 1..6 {
        let (fresh, reusing, reused) = both(0, 0.0, seed);
        assert!(reused, "seed {seed}");
        assert!(fresh.len() > 50, "a dense grid: {}", fresh.len());
        assert_eq!(fresh, reusing, "seed {seed}");
    }
}

#[test]
fn a_few_fast_bodies_are_tested_one_by_one_and_the_pairs_are_the_same() {
    for seed in 1..6 {
        let (fresh, reusing, reused) = both(5, 0.0, seed);
        assert!(reused, "seed {seed}");
        assert_eq!(fresh, reusing, "seed {seed}");
    }
}

#[test]
fn many_bodies_leaving_their_boxes_sweep_again_and_the_pairs_are_the_same() {
    for seed in 1..6 {
        // A projection of up to 1 cm moves most boxes out of their earlier ones.
        let (fresh, reusing, reused) = both(0, 0.02, seed);
        assert!(!reused, "seed {seed}");
        assert_eq!(fresh, reusing, "seed {seed}");
        let (fresh, reusing, reused) = both(40, 0.0, seed);
        assert!(!reused, "seed {seed}");
        assert_eq!(fresh, reusing, "seed {seed}");
    }
}

#[test]
fn the_swept_box_is_the_box_around_both_end_poses_to_the_bit() {
    use contact_lab::physics::collide::Aabb;
    use contact_lab::physics::detect::Convex;
    use contact_lab::physics::step::swept::{motion_of, swept_aabb};
    let w = world(5, 3);
    let dt = 1.0 / 60.0;
    for (i, b) in w.bodies.iter().enumerate() {
        let shape = b.shape.as_ref().unwrap();
        let m = motion_of(&w, i, b.movable);
        // The module's definition: each end's pose, its box (a turning
        // body's bounding sphere), and the box around both.
        let end = |t: f64| {
            let pose = m.pose_at(t);
            if m.angular_velocity.norm() > 0.0 {
                let r = Convex::from_shape(shape)?.bounding_radius();
                Some(Aabb::around(&pose.position, &Vector3::repeat(r)))
            } else {
                Aabb::of(shape, &pose, 0.0)
            }
        };
        let want = end(0.0).zip(end(dt)).map(|(a, b)| Aabb {
            min: a.min.inf(&b.min),
            max: a.max.sup(&b.max),
        });
        assert_eq!(swept_aabb(shape, &m, dt), want, "body {i}");
    }
}
