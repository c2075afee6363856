//! The random placements the detection benches share: SplitMix64, uniform
//! numbers, vectors in a cube and rotations (a normalised uniform quaternion).

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// SplitMix64.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
    #[allow(dead_code)]
    pub fn vector(&mut self, r: f64) -> Vector3<f64> {
        Vector3::new(self.range(-r, r), self.range(-r, r), self.range(-r, r))
    }
    pub fn rotation(&mut self) -> UnitQuaternion<f64> {
        let q = Quaternion::new(
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
            self.range(-1.0, 1.0),
        );
        UnitQuaternion::from_quaternion(q)
    }
}
