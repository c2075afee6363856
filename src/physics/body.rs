//! Rigid body state as the stages see it.

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};

use super::Real;

/// One movable body of a contact. Immovable bodies are not represented: a
/// contact slot holding `None` contributes nothing and costs nothing.
#[derive(Debug, Clone, PartialEq)]
pub struct RigidBody<T: Real> {
    pub mass: T,
    pub inverse_mass: T,
    /// Body-frame inertia tensor (needed for momentum and energy checks).
    pub inertia_body: Matrix3<T>,
    /// Body-frame inverse inertia tensor.
    pub inverse_inertia_body: Matrix3<T>,
    pub position: Vector3<T>,
    /// Orientation `[w, x, y, z]`, unit length.
    pub orientation: Quaternion<T>,
    pub velocity: Vector3<T>,
    pub angular_velocity: Vector3<T>,
    /// Last frame's acceleration, for the micro-collision compensation.
    pub acceleration: Vector3<T>,
}

impl<T: Real> RigidBody<T> {
    /// Rotation matrix R of the body's orientation.
    pub fn rotation(&self) -> Matrix3<T> {
        UnitQuaternion::new_normalize(self.orientation)
            .to_rotation_matrix()
            .into_inner()
    }

    /// World inverse inertia `I_w⁻¹ = R I_b⁻¹ Rᵀ`.
    pub fn inverse_inertia_world(&self) -> Matrix3<T> {
        to_world(&self.rotation(), &self.inverse_inertia_body)
    }

    /// World inertia `I_w = R I_b Rᵀ`.
    pub fn inertia_world(&self) -> Matrix3<T> {
        to_world(&self.rotation(), &self.inertia_body)
    }

    /// Velocity of the material point at offset `r` from the centre: `ω × r + v` (lecture eq. A).
    pub fn point_velocity(&self, r: &Vector3<T>) -> Vector3<T> {
        self.angular_velocity.cross(r) + self.velocity
    }

    /// Kinetic energy `½ m v·v + ½ ωᵀ I ω`.
    pub fn kinetic_energy(&self, velocity: &Vector3<T>, angular_velocity: &Vector3<T>) -> T {
        self.kinetic_energy_with(&self.inertia_world(), velocity, angular_velocity)
    }

    /// [`RigidBody::kinetic_energy`] with the world inertia `I` already at hand.
    pub fn kinetic_energy_with(
        &self,
        inertia_world: &Matrix3<T>,
        velocity: &Vector3<T>,
        angular_velocity: &Vector3<T>,
    ) -> T {
        let half = super::c::<T>(0.5);
        half * self.mass * velocity.dot(velocity)
            + half * angular_velocity.dot(&(inertia_world * angular_velocity))
    }

    /// Angular momentum about the world point `q`: `I ω + (p - q) × m v`.
    pub fn angular_momentum_about(
        &self,
        q: &Vector3<T>,
        velocity: &Vector3<T>,
        angular_velocity: &Vector3<T>,
    ) -> Vector3<T> {
        self.angular_momentum_about_with(&self.inertia_world(), q, velocity, angular_velocity)
    }

    /// [`RigidBody::angular_momentum_about`] with the world inertia `I` already at hand.
    pub fn angular_momentum_about_with(
        &self,
        inertia_world: &Matrix3<T>,
        q: &Vector3<T>,
        velocity: &Vector3<T>,
        angular_velocity: &Vector3<T>,
    ) -> Vector3<T> {
        inertia_world * angular_velocity + (self.position - q).cross(&(velocity * self.mass))
    }
}

/// `R A Rᵀ` for a symmetric `A`, made exactly symmetric, with entries at
/// round-off level (below 8ε of the largest) set to zero: a turned cube's
/// isotropic tensor stays diagonal instead of growing ±1e-19 noise.
///
/// Straight-line, and the same bits as nalgebra's `r * a * r.transpose()`
/// followed by `(m + mᵀ)·½`, `amax` and `map`: nalgebra's static 3×3
/// product (`gemm` → `gemv` → `axcpy`, column by column) sums entry
/// `(i, j)` as `(x₀y₀ + x₁y₁) + x₂y₂` with `k` in order, which is what
/// [`dot3`] writes; `amax` folds the entries column by column. The test
/// `to_world_is_nalgebras_bit_for_bit` holds it to the general form.
fn to_world<T: Real>(r: &Matrix3<T>, a: &Matrix3<T>) -> Matrix3<T> {
    // S = R A, then M = S Rᵀ: M[i][j] = Σₖ S[i][k] R[j][k].
    let s = Matrix3::from_fn(|i, j| {
        dot3(
            [r[(i, 0)], r[(i, 1)], r[(i, 2)]],
            [a[(0, j)], a[(1, j)], a[(2, j)]],
        )
    });
    let row = |m: &Matrix3<T>, i: usize| [m[(i, 0)], m[(i, 1)], m[(i, 2)]];
    let m = Matrix3::from_fn(|i, j| dot3(row(&s, i), row(r, j)));
    let half = super::c::<T>(0.5);
    let h = Matrix3::from_fn(|i, j| (m[(i, j)] + m[(j, i)]) * half);
    // amax in storage (column-major) order, as nalgebra folds it.
    let mut amax = h[0].abs();
    for k in 1..9 {
        amax = amax.max(h[k].abs());
    }
    let floor = amax * T::default_epsilon() * super::c::<T>(8.0);
    h.map(|x| if x.abs() <= floor { T::zero() } else { x })
}

/// `(x₀y₀ + x₁y₁) + x₂y₂`: one entry of a 3×3 product in nalgebra's order.
#[inline(always)]
fn dot3<T: Real>(x: [T; 3], y: [T; 3]) -> T {
    x[0] * y[0] + x[1] * y[1] + x[2] * y[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn momentum_with_the_inertia_at_hand_is_the_same_bit_for_bit() {
        let body = RigidBody {
            mass: 2.0,
            inverse_mass: 0.5,
            inertia_body: Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
            inverse_inertia_body: Matrix3::from_diagonal(&Vector3::new(1.0, 0.5, 1.0 / 3.0)),
            position: Vector3::new(0.1, 0.2, 0.3),
            orientation: Quaternion::new(0.9, 0.1, -0.3, 0.2),
            velocity: Vector3::new(1.0, -2.0, 0.5),
            angular_velocity: Vector3::new(0.3, 0.7, -1.1),
            acceleration: Vector3::zeros(),
        };
        let inertia = body.inertia_world();
        assert_ne!(inertia, body.inertia_body, "the rotation turns the tensor");
        let q = Vector3::new(-0.4, 0.0, 0.9);
        let (v, w) = (body.velocity, body.angular_velocity);
        assert_eq!(
            body.angular_momentum_about_with(&inertia, &q, &v, &w),
            body.angular_momentum_about(&q, &v, &w)
        );
    }

    /// The general form `to_world` replaced: nalgebra's products and maps.
    fn to_world_general<T: Real>(r: &Matrix3<T>, a: &Matrix3<T>) -> Matrix3<T> {
        let m = r * a * r.transpose();
        let m = (m + m.transpose()) * crate::physics::c::<T>(0.5);
        let floor = m.amax() * T::default_epsilon() * crate::physics::c::<T>(8.0);
        m.map(|x| if x.abs() <= floor { T::zero() } else { x })
    }

    /// SplitMix64 in [-1, 1).
    fn uniform(state: &mut u64) -> f64 {
        *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = *state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    fn same_bits<T: Real>(r: &Matrix3<T>, a: &Matrix3<T>, bits: impl Fn(T) -> u64) {
        let (fast, general) = (to_world(r, a), to_world_general(r, a));
        for k in 0..9 {
            assert_eq!(
                bits(fast[k]),
                bits(general[k]),
                "entry {k} of R A Rᵀ, R = {r}, A = {a}"
            );
        }
    }

    #[test]
    fn to_world_is_nalgebras_bit_for_bit() {
        let mut state = 26u64;
        let mut cases = 0;
        for n in 0..20_000 {
            let mut u = || uniform(&mut state);
            let q = Quaternion::new(u(), u(), u(), u());
            let body = RigidBody {
                mass: 1.0,
                inverse_mass: 1.0,
                inertia_body: Matrix3::identity(),
                inverse_inertia_body: Matrix3::identity(),
                position: Vector3::zeros(),
                orientation: q,
                velocity: Vector3::zeros(),
                angular_velocity: Vector3::zeros(),
                acceleration: Vector3::zeros(),
            };
            let r = body.rotation();
            // Diagonal tensors over many magnitudes, symmetric full ones,
            // isotropic ones (where the floor zeroes the noise) and
            // unsymmetric ones (the product's order shows most there).
            let scale = 10f64.powi((u() * 12.0) as i32);
            let a = match n % 4 {
                0 => Matrix3::from_diagonal(&Vector3::new(u().abs(), u().abs(), u().abs())),
                1 => {
                    let b = Matrix3::from_fn(|_, _| u());
                    b * b.transpose()
                }
                2 => Matrix3::identity() * u().abs(),
                _ => Matrix3::from_fn(|_, _| u()),
            } * scale;
            same_bits(&r, &a, f64::to_bits);
            let (r32, a32) = (r.map(|x| x as f32), a.map(|x| x as f32));
            same_bits(&r32, &a32, |x: f32| u64::from(x.to_bits()));
            cases += 1;
        }
        // Exact rotations (quarter turns) and signed zeros, where -0 and +0 differ in bits.
        let quarter = Matrix3::new(0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);
        let a = Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, -0.0));
        same_bits(&quarter, &a, f64::to_bits);
        same_bits(&-quarter, &(-a), f64::to_bits);
        // A diagonal tensor written with -0 off the diagonal, and zeros on it.
        let mut b = Matrix3::from_diagonal(&Vector3::new(0.0, 3.0, 0.5));
        b[(0, 1)] = -0.0;
        b[(2, 0)] = -0.0;
        same_bits(&quarter, &b, f64::to_bits);
        same_bits(&Matrix3::identity(), &b, f64::to_bits);
        assert_eq!(cases, 20_000);
    }
}
