//! The world of a scene: bodies by id, their shapes, and contacts that refer
//! to bodies by id. A single contact's [`Problem`] is a by-value view of it.

use nalgebra::{Matrix3, Quaternion, Vector3};

use super::{c, ContactInput, Problem, Real, RigidBody, Shape, StepParams};

/// A body's place in [`World::bodies`]; the same index as in the lesson file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct BodyId(pub usize);

/// One body of the world. An immovable body keeps its pose (for drawing and
/// contact generation) and has zero inverse mass and inverse inertia.
#[derive(Debug, Clone, PartialEq)]
pub struct Body<T: Real> {
    pub state: RigidBody<T>,
    pub shape: Option<Shape>,
    pub movable: bool,
}

impl<T: Real> Body<T> {
    /// An immovable body at a pose: infinite mass, nothing to invert.
    pub fn immovable(
        position: Vector3<T>,
        orientation: Quaternion<T>,
        shape: Option<Shape>,
    ) -> Self {
        Body {
            state: RigidBody {
                mass: c(f64::INFINITY),
                inverse_mass: T::zero(),
                inertia_body: Matrix3::zeros(),
                inverse_inertia_body: Matrix3::zeros(),
                position,
                orientation,
                velocity: Vector3::zeros(),
                angular_velocity: Vector3::zeros(),
                acceleration: Vector3::zeros(),
            },
            shape,
            movable: false,
        }
    }

    /// The movable body's state, `None` for an immovable one.
    pub fn dynamic(&self) -> Option<&RigidBody<T>> {
        self.movable.then_some(&self.state)
    }
}

/// A contact between body 1 and, unless it is against the world, body 2.
#[derive(Debug, Clone, PartialEq)]
pub struct Contact<T: Real> {
    pub body1: BodyId,
    pub body2: Option<BodyId>,
    pub input: ContactInput<T>,
    /// This contact's own last-frame duration, overriding the step's.
    pub duration: Option<T>,
}

impl<T: Real> Contact<T> {
    /// `[body 1, body 2]`, `None` where the slot is empty.
    pub fn slots(&self) -> [Option<BodyId>; 2] {
        [Some(self.body1), self.body2]
    }
}

/// Bodies, contacts and the step's parameters.
#[derive(Debug, Clone, PartialEq)]
pub struct World<T: Real> {
    pub bodies: Vec<Body<T>>,
    pub contacts: Vec<Contact<T>>,
    pub step: StepParams<T>,
}

impl<T: Real> World<T> {
    pub fn body(&self, id: BodyId) -> &Body<T> {
        &self.bodies[id.0]
    }

    pub fn body_mut(&mut self, id: BodyId) -> &mut Body<T> {
        &mut self.bodies[id.0]
    }

    /// The by-value view of contact `k`: copies of its movable bodies (an
    /// immovable body becomes an empty slot), the contact, the duration.
    pub fn problem(&self, k: usize) -> Problem<T> {
        let contact = &self.contacts[k];
        let body = |id: Option<BodyId>| self.body(id?).dynamic().cloned();
        Problem {
            bodies: [body(Some(contact.body1)), body(contact.body2)],
            contact: contact.input.clone(),
            duration: contact.duration.unwrap_or(self.step.duration),
        }
    }

    /// The contacts each body takes part in, by body index (a body→contacts adjacency).
    pub fn contacts_of_bodies(&self) -> Vec<Vec<usize>> {
        let mut adjacency = vec![Vec::new(); self.bodies.len()];
        for (k, contact) in self.contacts.iter().enumerate() {
            for id in contact.slots().into_iter().flatten() {
                if adjacency[id.0].last() != Some(&k) {
                    adjacency[id.0].push(k);
                }
            }
        }
        adjacency
    }
}

/// Groups of `bodies` joined by `links` (pairs of body indices): each body's
/// group root, the smallest index of its group (union–find with path halving).
/// Islands for sleep and the resolver's momentum check both use it.
pub fn groups(bodies: usize, links: impl Iterator<Item = (usize, usize)>) -> Vec<usize> {
    let mut parent: Vec<usize> = (0..bodies).collect();
    fn find(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for (a, b) in links {
        let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
        if ra != rb {
            parent[ra.max(rb)] = ra.min(rb);
        }
    }
    (0..bodies).map(|i| find(&mut parent, i)).collect()
}
