//! A step's contacts from the shapes: contact generation's points as the
//! resolver's contacts, with the pair's combined material and the step's
//! contact settings (and, asked for, the normal from the previous frame).

use super::super::previous_frame;
use super::Simulation;
use crate::physics::collide::Options;
use crate::physics::params::NormalFrom;
use crate::physics::{c, Contact, ContactInput, Real};

impl<T: Real> Simulation<T> {
    /// Replaces the world's contacts with those the shapes generate now.
    pub(super) fn generate_contacts(&mut self) {
        let options = Options {
            box_box: self.params.box_box,
            tolerance: self.params.contact_margin,
            narrow_phase: self.params.narrow_phase,
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
                input: ContactInput {
                    point: g.contact.point,
                    normal,
                    penetration,
                    restitution: c(m.restitution),
                    static_friction: c(m.static_friction),
                    dynamic_friction: c(m.dynamic_friction),
                    friction_model: p.friction_model,
                    settings: p.contact,
                },
                duration,
            });
        }
    }
}
