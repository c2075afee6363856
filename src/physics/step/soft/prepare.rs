//! One contact's soft constraint, prepared once per step (Box2D's
//! `b2PrepareContactsTask`): anchors from the bodies' centres, two
//! tangents, the normal and tangent masses, the normal velocity before the
//! solve (for restitution) and the separation the substeps update.

use nalgebra::{Matrix3, UnitQuaternion, Vector3};

use crate::physics::{Body, Contact, Real, World};

/// A contact's constraint over one step. Body 1 is pushed along +normal.
#[derive(Debug, Clone, PartialEq)]
pub struct SoftContact<T: Real> {
    /// Body indices (`None`: the world or a body that does not move).
    pub bodies: [Option<usize>; 2],
    /// Inverse masses (0 for a body that does not move).
    pub inverse_mass: [T; 2],
    /// Anchors from each body's centre at the step's start.
    pub anchors: [Vector3<T>; 2],
    /// Each body's position and orientation at the step's start.
    pub start: [(Vector3<T>, UnitQuaternion<T>); 2],
    pub normal: Vector3<T>,
    pub tangents: [Vector3<T>; 2],
    /// Separation at the step's start (−penetration, m).
    pub separation: T,
    pub normal_mass: T,
    pub tangent_mass: [T; 2],
    /// μ for this step: μ_s when the contact slips no faster than the slip
    /// speed at the start, μ_d otherwise.
    pub friction: T,
    pub restitution: T,
    /// Normal velocity before the solve (negative when closing).
    pub relative_velocity: T,
    /// Accumulated impulses: normal, then along each tangent (N·s).
    pub normal_impulse: T,
    pub tangent_impulse: [T; 2],
    /// The largest normal impulse a substep applied (restitution skips a
    /// contact that never pushed).
    pub max_normal_impulse: T,
}

fn orthonormal<T: Real>(n: &Vector3<T>) -> [Vector3<T>; 2] {
    let axis = if n.x.abs() < nalgebra::convert(0.57) {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let t1 = n.cross(&axis).normalize();
    [t1, n.cross(&t1)]
}

fn unit<T: Real>(b: &Body<T>) -> UnitQuaternion<T> {
    UnitQuaternion::new_normalize(b.state.orientation)
}

impl<T: Real> SoftContact<T> {
    pub fn prepare(
        world: &World<T>,
        k: &Contact<T>,
        moving: &[bool],
        inverse_inertia: &[Matrix3<T>],
        slip: T,
    ) -> Self {
        let zero = T::zero();
        let n = k.input.normal;
        let tangents = orthonormal(&n);
        let ids = [Some(k.body1.0), k.body2.map(|b| b.0)];
        let mut bodies = [None; 2];
        let mut inverse_mass = [zero; 2];
        let mut anchors = [Vector3::zeros(); 2];
        let mut start = [(Vector3::zeros(), UnitQuaternion::identity()); 2];
        let mut velocity = [Vector3::zeros(); 2];
        let mut ks = [zero; 3];
        for slot in 0..2 {
            let Some(i) = ids[slot] else { continue };
            let b = &world.bodies[i];
            anchors[slot] = k.input.point - b.state.position;
            start[slot] = (b.state.position, unit(b));
            velocity[slot] = b.state.point_velocity(&anchors[slot]);
            if !moving[i] {
                continue;
            }
            bodies[slot] = Some(i);
            inverse_mass[slot] = b.state.inverse_mass;
            let r = anchors[slot];
            for (j, axis) in [n, tangents[0], tangents[1]].iter().enumerate() {
                let rn = r.cross(axis);
                ks[j] += b.state.inverse_mass + rn.dot(&(inverse_inertia[i] * rn));
            }
        }
        let inv = |x: T| if x > zero { T::one() / x } else { zero };
        let dv = velocity[0] - velocity[1];
        let vn = dv.dot(&n);
        let slipping = (dv - n * vn).norm() > slip;
        let input = &k.input;
        SoftContact {
            bodies,
            inverse_mass,
            anchors,
            start,
            normal: n,
            tangents,
            separation: -input.penetration,
            normal_mass: inv(ks[0]),
            tangent_mass: [inv(ks[1]), inv(ks[2])],
            friction: if slipping {
                input.dynamic_friction
            } else {
                input.static_friction
            },
            restitution: input.restitution,
            relative_velocity: vn,
            normal_impulse: zero,
            tangent_impulse: [zero; 2],
            max_normal_impulse: zero,
        }
    }

    /// The separation now (m): the start's plus how far the anchors, moved
    /// and turned with their bodies, have come apart along the normal.
    pub fn separation_now(&self, bodies: &[Body<T>]) -> T {
        let mut d = [Vector3::zeros(); 2];
        for (slot, id) in self.bodies.iter().enumerate() {
            let Some(i) = *id else { continue };
            let b = &bodies[i];
            let (x0, q0) = self.start[slot];
            let turn = unit(b) * q0.inverse();
            d[slot] = (b.state.position - x0) + (turn * self.anchors[slot] - self.anchors[slot]);
        }
        self.separation + (d[0] - d[1]).dot(&self.normal)
    }
}
