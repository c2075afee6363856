//! A contact-lab simulation's scene built again in rapier3d: the same shapes,
//! masses, poses, velocities, gravity, time step and coefficients (restitution:
//! the larger of a pair, friction: the geometric mean, as contact-lab combines
//! them), rapier's default integration parameters otherwise, sleep off.

use contact_lab::physics::step::Simulation;
use contact_lab::physics::Shape;
use nalgebra::UnitQuaternion;
use rapier3d::na::Unit;
use rapier3d::prelude::*;

fn v(x: &nalgebra::Vector3<f64>) -> Vector {
    Vector::new(x.x as f32, x.y as f32, x.z as f32)
}

/// The rapier world of `sim`'s bodies (at `sim`'s state now).
pub fn from(sim: &Simulation<f64>) -> PhysicsWorld {
    let mut world = PhysicsWorld::default();
    let p = &sim.params;
    world.gravity = v(&p.world.gravity);
    world.integration_parameters.dt = p.dt as f32;
    for (body, material) in sim.world.bodies.iter().zip(&sim.materials) {
        let Some(shape) = &body.shape else { continue };
        let s = &body.state;
        let collider = match shape {
            Shape::Sphere { radius } | Shape::HollowSphere { radius } => {
                ColliderBuilder::ball(*radius as f32)
            }
            Shape::Box { sides } => ColliderBuilder::cuboid(
                sides[0] as f32 / 2.0,
                sides[1] as f32 / 2.0,
                sides[2] as f32 / 2.0,
            ),
            Shape::Cylinder { radius, height } => {
                ColliderBuilder::cylinder(*height as f32 / 2.0, *radius as f32)
            }
            // Along body y, `height` between the hemispheres' centres.
            Shape::Capsule { radius, height } => {
                ColliderBuilder::capsule_y(*height as f32 / 2.0, *radius as f32)
            }
            // The hull's vertices, in the body frame (its centroid).
            Shape::Hull(hull) => {
                let points: Vec<_> = hull
                    .vertices()
                    .iter()
                    .map(|p| Vector::new(p.x as f32, p.y as f32, p.z as f32))
                    .collect();
                ColliderBuilder::convex_hull(&points).expect("a hull the lesson accepted")
            }
            Shape::HalfSpace { normal } => ColliderBuilder::halfspace(Unit::new_unchecked(
                Vector::new(normal[0] as f32, normal[1] as f32, normal[2] as f32),
            )),
        }
        .restitution(material.restitution as f32)
        .restitution_combine_rule(CoefficientCombineRule::Max)
        .friction(material.static_friction as f32)
        .friction_combine_rule(CoefficientCombineRule::GeometricMean);
        let rotation = UnitQuaternion::from_quaternion(s.orientation).scaled_axis();
        let builder = if body.movable {
            RigidBodyBuilder::dynamic()
                .linvel(v(&s.velocity))
                .angvel(v(&s.angular_velocity))
                // Fraction kept per second → rapier's damping coefficient.
                .linear_damping(-(p.world.linear_damping.ln()) as f32)
                .angular_damping(-(p.world.angular_damping.ln()) as f32)
                .can_sleep(false)
        } else {
            RigidBodyBuilder::fixed()
        }
        .translation(v(&s.position))
        .rotation(v(&rotation));
        let collider = if body.movable {
            collider.mass(s.mass as f32)
        } else {
            collider
        };
        world.insert(builder, collider);
    }
    world
}

/// The highest dynamic body's height.
pub fn top(world: &PhysicsWorld) -> f64 {
    world
        .bodies
        .iter()
        .filter(|(_, b)| b.is_dynamic())
        .map(|(_, b)| b.translation().y as f64)
        .fold(f64::MIN, f64::max)
}

/// The dynamic bodies' positions, in the order they were inserted (the
/// movable bodies of the contact-lab scene, in its order).
pub fn positions(world: &PhysicsWorld) -> Vec<nalgebra::Vector3<f64>> {
    world
        .bodies
        .iter()
        .filter(|(_, b)| b.is_dynamic())
        .map(|(_, b)| {
            let t = b.translation();
            nalgebra::Vector3::new(t.x as f64, t.y as f64, t.z as f64)
        })
        .collect()
}
