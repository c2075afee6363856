//! A step's contacts from the shapes: contact generation's points as the
//! resolver's contacts, with the pair's combined material and the step's
//! contact settings (and, asked for, the normal from the previous frame).

use super::super::previous_frame;
use super::Simulation;
use crate::physics::collide::Options;
use nalgebra::Vector3;

use crate::physics::params::{Material, NormalFrom, SimParams};
use crate::physics::{c, Contact, ContactInput, Real};

impl<T: Real> Simulation<T> {
    /// Replaces the world's contacts with those the shapes generate now.
    pub(super) fn generate_contacts(&mut self) {
        let options = Options {
            box_box: self.params.box_box,
            tolerance: self.params.contact_margin,
            narrow_phase: self.params.narrow_phase,
            broad_phase: self.params.broad_phase,
            internal_edges: self.params.internal_edges,
        };
        self.generator
            .generate_world(&self.world.bodies, &options, &mut self.generated);
        let p = &self.params;
        let duration = (!p.acceleration_compensation).then(T::zero);
        self.world.contacts.clear();
        for g in &self.generated {
            let m = self.materials[g.body1.0].combine(&self.materials[g.body2.0]);
            let (normal, penetration) = match p.normal_from {
                NormalFrom::Previous if g.contact.penetration > T::zero() => {
                    let bodies = &self.world.bodies;
                    let (i, j) = (g.body1.0, g.body2.0);
                    previous_frame::pair_normal(bodies, &self.previous, i, j)
                        .and_then(|n| Some((n, previous_frame::depth_along(bodies, i, j, &n)?)))
                        .unwrap_or((g.contact.normal, g.contact.penetration))
                }
                _ => (g.contact.normal, g.contact.penetration),
            };
            self.world.contacts.push(Contact {
                body1: g.body1,
                body2: Some(g.body2),
                input: contact_input(p, &m, g.contact.point, normal, penetration),
                duration,
            });
        }
    }
}

/// A contact's input from a point and normal found between two bodies: the
/// pair's combined material `m` and the step's friction model and contact
/// settings (contact generation's contacts and exact impact's alike).
pub(in crate::physics::step) fn contact_input<T: Real>(
    p: &SimParams<T>,
    m: &Material,
    point: Vector3<T>,
    normal: Vector3<T>,
    penetration: T,
) -> ContactInput<T> {
    ContactInput {
        point,
        normal,
        penetration,
        restitution: c(m.restitution),
        static_friction: c(m.static_friction),
        dynamic_friction: c(m.dynamic_friction),
        friction_model: p.friction_model,
        settings: p.contact,
    }
}
