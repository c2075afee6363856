//! Tests of detection (part of the lib test binary): closed forms, an
//! exhaustive feature search, the separating-axis reference, parry3d as a
//! peer, robustness cases, hulls, manifolds and the records.

mod closed_forms;
mod epa_sat;
mod exhaustive;
mod hull;
mod manifold;
mod parry;
mod records;
mod reference;
mod robust;
mod support;
mod toi;

use nalgebra::{UnitQuaternion, Vector3};

use super::{Capsule, Convex, ConvexHull};
use crate::physics::pose::Pose;

/// SplitMix64: a seeded, deterministic generator.
pub(super) struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn vector(&mut self, r: f64) -> Vector3<f64> {
        Vector3::new(self.range(-r, r), self.range(-r, r), self.range(-r, r))
    }

    /// A uniformly random rotation (normalised Gaussian-ish quaternion).
    pub fn rotation(&mut self) -> UnitQuaternion<f64> {
        loop {
            let q = nalgebra::Quaternion::new(
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
                self.range(-1.0, 1.0),
            );
            if q.norm() > 0.1 && q.norm() <= 1.0 {
                return UnitQuaternion::from_quaternion(q);
            }
        }
    }

    pub fn pose(&mut self, r: f64) -> Pose<f64> {
        let at = self.vector(r);
        Pose::from_unit(at, &self.rotation())
    }

    /// A random hull of 4 to 24 points in a ball of radius about `size`.
    pub fn hull(&mut self, size: f64) -> ConvexHull {
        loop {
            let n = 4 + (self.next_u64() % 21) as usize;
            let pts: Vec<[f64; 3]> = (0..n).map(|_| self.vector(size).into()).collect();
            if let Ok(h) = ConvexHull::new(&pts) {
                if h.mass_properties().volume > 0.05 * size * size * size {
                    return h;
                }
            }
        }
    }

    /// One of every kind of shape, chosen by `kind % 6`, sized 0.3–1.5.
    pub fn shape(&mut self, kind: u64) -> Convex {
        let mut s = || self.range(0.3, 1.5);
        match kind % 6 {
            0 => Convex::Sphere { radius: s() },
            1 => Convex::Cuboid {
                half: [s(), s(), s()],
            },
            2 => Convex::Cylinder {
                radius: s(),
                half_height: s(),
            },
            3 => Convex::Capsule(Capsule {
                radius: s() * 0.7,
                height: s() * 1.5,
            }),
            4 => {
                let size = s();
                Convex::hull(self.hull(size))
            }
            _ => {
                // A hollow sphere has a solid sphere's surface.
                let shape = crate::physics::Shape::HollowSphere { radius: s() };
                Convex::from_shape(&shape).expect("convex")
            }
        }
    }
}

/// Relative difference |x − y| / max(|y|, floor).
pub(super) fn relative(x: f64, y: f64, floor: f64) -> f64 {
    (x - y).abs() / y.abs().max(floor)
}

/// The 8 corners of a box of half sides `h`.
pub(super) fn box_points(h: [f64; 3]) -> Vec<[f64; 3]> {
    (0..8)
        .map(|i: u32| std::array::from_fn(|k| if i >> k & 1 == 1 { h[k] } else { -h[k] }))
        .collect()
}
