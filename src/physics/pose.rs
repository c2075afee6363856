//! Where a body is ([`Pose`]) and which of a pair it is ([`Side`]): shared by
//! contact generation (`collide`, which re-exports both) and detection
//! (`detect`), so that neither folder imports the other's.

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};

use super::{Real, Shape};

/// Where a body is and how it is turned. `rotation` is the rotation matrix of
/// the orientation quaternion `[w, x, y, z]`: its columns are the body's axes
/// in world coordinates, so `world = position + rotation · local`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose<T: Real> {
    pub position: Vector3<T>,
    pub rotation: Matrix3<T>,
}

impl<T: Real> Pose<T> {
    /// Pose from a position and an orientation quaternion (normalised here).
    pub fn new(position: Vector3<T>, orientation: &Quaternion<T>) -> Self {
        Self::from_unit(position, &UnitQuaternion::new_normalize(*orientation))
    }

    /// Pose from a position and a unit quaternion.
    pub fn from_unit(position: Vector3<T>, orientation: &UnitQuaternion<T>) -> Self {
        Pose {
            position,
            rotation: orientation.to_rotation_matrix().into_inner(),
        }
    }

    /// Unrotated pose at `position`.
    pub fn at(position: Vector3<T>) -> Self {
        Pose {
            position,
            rotation: Matrix3::identity(),
        }
    }

    /// Body axis `i` (0 = x, 1 = y, 2 = z) in world coordinates.
    pub fn axis(&self, i: usize) -> Vector3<T> {
        self.rotation.column(i).into_owned()
    }

    /// World point → body frame: `Rᵀ (p - x)`.
    pub fn to_local(&self, world: &Vector3<T>) -> Vector3<T> {
        self.rotation.tr_mul(&(world - self.position))
    }

    /// Body-frame point → world: `x + R p`.
    pub fn to_world(&self, local: &Vector3<T>) -> Vector3<T> {
        self.position + self.rotation * local
    }

    /// A world point in the frame `Shape::surface_distance` expects for
    /// `shape`: the body frame, or for a half-space (whose normal is a world
    /// vector) the offset from the plane's point.
    pub fn shape_frame(&self, shape: &Shape, world: &Vector3<T>) -> Vector3<T> {
        match shape {
            Shape::HalfSpace { .. } => world - self.position,
            _ => self.to_local(world),
        }
    }
}

/// Which of the two bodies of [`collide`]: A is body 1, B is body 2.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    A,
    B,
}

impl Side {
    /// The other body.
    pub fn other(self) -> Side {
        match self {
            Side::A => Side::B,
            Side::B => Side::A,
        }
    }
}
