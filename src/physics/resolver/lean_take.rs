//! Twin of the friction stage's [`clamp`](crate::physics::stages::friction::clamp)
//! and of [`stable_hypot`], held bit for bit by the tests below
//! (`the_lean_clamp_is_the_stage_clamp_to_the_bit`,
//! `the_planar_norm_is_stable_hypot_to_the_bit`).
//!
//! The velocity phase's take on the fast path (nothing records), leaner than
//! the friction stage's [`clamp`](crate::physics::stages::friction::clamp)
//! and bit for bit the same impulse (tests below): the lecture's clamp
//! (Millington: stick if `|g_planar| ≤ μ_s g_n`, else slide with
//! `g_t = μ_d g_n u`, `g_n = Δv / (M₀₀ + μ_d (M₀₁ u_y + M₀₂ u_z))`) without
//! the record (regime, direction, world impulses), its planar norm `√(g_y² +
//! g_z²)` formed directly where neither square can underflow or overflow
//! (there the scaled norm of [`stable_hypot`] is that number to the bit; elsewhere
//! it is `stable_hypot` itself).

use nalgebra::Vector3;

use super::FrictionData;
use crate::physics::scale::stable_hypot;
use crate::physics::{c, Real};

/// `√(a² + b²)`, bit for bit [`stable_hypot`]: directly when each of `|a|`,
/// `|b|` is 0 or in [2⁻⁵¹¹, 2⁵¹¹] (every square normal, nothing
/// overflows: scaling by a power of two, as `stable_hypot` does, is then
/// exact at every step), else `stable_hypot`.
#[inline(always)]
pub fn planar_norm<T: Real>(a: T, b: T) -> T {
    // 2⁻⁵¹¹ and 2⁵¹¹ (exponent bits alone); a narrower float (where they
    // are 0 or inf) always takes `stable_hypot`.
    let low = c::<T>(f64::from_bits((1023 - 511) << 52));
    let high = c::<T>(f64::from_bits((1023 + 511) << 52));
    let fits = low > T::zero() && high.is_finite();
    let safe = |x: T| {
        let x = x.abs();
        x == T::zero() || (x >= low && x <= high)
    };
    if fits && safe(a) && safe(b) {
        (a * a + b * b).sqrt()
    } else {
        stable_hypot(a, b)
    }
}

/// The Millington clamp of the sticking impulse `g` of a contact with
/// friction `f` (desired Δv `desired`, `Δq̇_t` `total`): the impulse the
/// friction stage's clamp gives, by the same operations.
#[inline(always)]
pub fn millington_clamp<T: Real>(
    g: Vector3<T>,
    f: &FrictionData<T>,
    desired: T,
    total: T,
) -> Vector3<T> {
    let (mu_s, mu_d) = (f.static_friction, f.dynamic_friction);
    let planar = planar_norm(g.y, g.z);
    // Sticks unless the planar part is above the cone (NaN included: sticks).
    if planar.partial_cmp(&(mu_s * g.x)) != Some(std::cmp::Ordering::Greater) {
        return g;
    }
    let m = &f.matrix.matrix;
    let (uy, uz) = (g.y / planar, g.z / planar);
    let per_unit = m[(0, 0)] + mu_d * (m[(0, 1)] * uy + m[(0, 2)] * uz);
    if per_unit > T::zero() {
        let gn = desired / per_unit;
        Vector3::new(gn, mu_d * gn * uy, mu_d * gn * uz)
    } else {
        Vector3::new(desired / total, T::zero(), T::zero())
    }
}

#[cfg(test)]
pub(super) mod tests {
    use nalgebra::{Matrix3, Vector3};

    use super::{millington_clamp, planar_norm};
    use crate::physics::resolver::FrictionData;
    use crate::physics::scale::stable_hypot;
    use crate::physics::stages::friction::{clamp, ClampInputs};
    use crate::physics::stages::FactoredMatrix;
    use crate::physics::FrictionModel;

    /// A number spread over many magnitudes and both signs (a fixed scramble).
    pub(in crate::physics::resolver) fn spread(i: u64) -> f64 {
        let mut x = i.wrapping_mul(0x9E37_79B9_7F4A_7C15);
        x ^= x >> 29;
        x = x.wrapping_mul(0xBF58_476D_1CE4_E5B9);
        x ^= x >> 32;
        let mantissa = 1.0 + (x >> 12) as f64 / (1u64 << 52) as f64;
        let exponent = ((x % 64) as i32) - 32;
        let sign = if x & (1 << 7) == 0 { 1.0 } else { -1.0 };
        sign * mantissa * 2f64.powi(exponent)
    }

    /// The direct norm is `stable_hypot` to the bit, at the edges of its
    /// range and across it, zeros, subnormals, infinities and NaN included.
    #[test]
    fn the_planar_norm_is_stable_hypot_to_the_bit() {
        let edges = [
            0.0,
            -0.0,
            2f64.powi(-511),
            2f64.powi(-511) * (1.0 + f64::EPSILON),
            2f64.powi(-511) * (1.0 - f64::EPSILON / 2.0),
            2f64.powi(511),
            2f64.powi(511) * (1.0 + f64::EPSILON),
            2f64.powi(-600),
            1e300,
            5e-324,
            1.0,
            3.0,
            f64::INFINITY,
            f64::NAN,
        ];
        let mut values: Vec<f64> = edges.iter().flat_map(|x| [*x, -*x]).collect();
        values.extend((0..400).map(spread));
        let mut checked = 0;
        for &a in &values {
            for &b in &values {
                let (lean, stable) = (planar_norm(a, b), stable_hypot(a, b));
                assert!(
                    lean.to_bits() == stable.to_bits() || (lean.is_nan() && stable.is_nan()),
                    "({a:e}, {b:e}): {lean:e} against {stable:e}"
                );
                checked += 1;
            }
        }
        assert!(checked > 150_000, "{checked}");
    }

    /// The lean clamp gives the friction stage's impulse to the bit:
    /// sticking, sliding, jamming (no positive normal impulse per unit),
    /// over a spread of impulses, friction coefficients and matrices.
    #[test]
    fn the_lean_clamp_is_the_stage_clamp_to_the_bit() {
        let mut regimes = [0usize; 3];
        for i in 0..3000u64 {
            let g = Vector3::new(
                spread(3 * i).abs() % 4.0,
                spread(3 * i + 1),
                spread(3 * i + 2),
            );
            let g = g.map(|x| if x.is_finite() { x } else { 0.5 });
            let mu = [0.0, 0.2, 0.4, 1.3][(i % 4) as usize];
            let skew = if i % 7 == 0 { 5.0 } else { 0.3 };
            let matrix = Matrix3::new(
                1.0 + (i % 5) as f64 * 0.1,
                skew,
                -0.2,
                skew,
                2.0,
                0.1,
                -0.2,
                0.1,
                1.5,
            );
            let f = FrictionData {
                model: FrictionModel::Millington,
                static_friction: mu,
                dynamic_friction: mu * 0.9,
                matrix: FactoredMatrix::new(matrix),
            };
            let (desired, total) = (0.3 + (i % 3) as f64, 1.7);
            let stage = clamp(ClampInputs {
                model: f.model,
                static_friction: f.static_friction,
                dynamic_friction: f.dynamic_friction,
                impulse_contact: g,
                contact_velocity: Vector3::new(-0.4, 0.1, 0.2),
                desired,
                total,
                matrix: Some(&f.matrix),
                closed_form_j: desired / total,
                contact_to_world: &Matrix3::identity(),
            });
            let lean = millington_clamp(g, &f, desired, total);
            assert_eq!(
                lean.map(f64::to_bits),
                stage.impulse_contact.map(f64::to_bits),
                "case {i}: g {g}, μ {mu}"
            );
            let planar = stable_hypot(g.y, g.z);
            let per_unit = matrix[(0, 0)]
                + f.dynamic_friction
                    * (matrix[(0, 1)] * g.y / planar + matrix[(0, 2)] * g.z / planar);
            regimes[match (planar > mu * g.x, per_unit > 0.0) {
                (false, _) => 0,
                (true, true) => 1,
                (true, false) => 2,
            }] += 1;
        }
        assert!(
            regimes.iter().all(|n| *n > 20),
            "stick, slide, jam: {regimes:?}"
        );
    }
}
