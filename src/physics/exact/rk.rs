//! One Dormand–Prince 5(4) step (Dormand & Prince 1980; Hairer, Nørsett &
//! Wanner, Solving ODEs I, table 5.2) for an autonomous system `y' = f(y)`,
//! with its embedded error estimate and the step-size rule.

use nalgebra::SVector;

use crate::physics::{c, Real};

/// State of the slipping integration: `[P_n, P_t0, P_t1, W_n, W_t]`.
pub(super) type State<T> = SVector<T, 5>;

/// The result of one trial step.
pub(super) struct Trial<T: Real> {
    /// Fifth-order solution (propagated: local extrapolation).
    pub y: State<T>,
    /// `f(y)` at the new point (first stage of the next step: FSAL).
    pub f: State<T>,
    /// The embedded error estimate (fifth- minus fourth-order solution).
    pub error: State<T>,
}

const A: [[f64; 6]; 6] = [
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];

/// Fifth-order weights minus fourth-order weights (the error estimate).
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// Right-hand side evaluations per step (the first is reused from the last step).
pub(super) const EVALS_PER_STEP: usize = 6;

/// One step of size h from y, where `f0 = f(y)`.
pub(super) fn step<T: Real>(
    f: &impl Fn(&State<T>) -> State<T>,
    y: &State<T>,
    f0: &State<T>,
    h: T,
) -> Trial<T> {
    let mut k: [State<T>; 7] = [*f0; 7];
    for stage in 1..7 {
        let mut yi = *y;
        for (j, kj) in k.iter().enumerate().take(stage) {
            let a = A[stage - 1][j];
            if a != 0.0 {
                yi += kj * (h * c::<T>(a));
            }
        }
        k[stage] = f(&yi);
    }
    // The 7th stage is evaluated at the fifth-order solution (FSAL).
    let mut y5 = *y;
    for (j, kj) in k.iter().enumerate().take(6) {
        let b = A[5][j];
        if b != 0.0 {
            y5 += kj * (h * c::<T>(b));
        }
    }
    let mut err = State::<T>::zeros();
    for (j, kj) in k.iter().enumerate() {
        if E[j] != 0.0 {
            err += kj * (h * c::<T>(E[j]));
        }
    }
    Trial {
        y: y5,
        f: k[6],
        error: err,
    }
}

/// The next step size after a step with this error: `0.9 err^(-1/5)`,
/// between 0.2× and 5× (Hairer–Nørsett–Wanner's standard controller).
pub(super) fn next_size<T: Real>(h: T, error: T) -> T {
    let factor = if error > T::zero() {
        c::<T>(0.9) * error.powf(c(-0.2))
    } else {
        c(5.0)
    };
    h * factor.max(c(0.2)).min(c(5.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponential_decay_to_fifth_order() {
        // y' = -y: one step of h = 0.1 matches e^{-0.1} to O(h⁶).
        let f = |y: &State<f64>| -y;
        let y = State::from_element(1.0);
        let t = step(&f, &y, &f(&y), 0.1);
        let exact = (-0.1f64).exp();
        assert!((t.y[0] - exact).abs() < 1e-9, "{}", t.y[0]);
        assert!((t.f[0] + t.y[0]).abs() < 1e-15);
        // The estimate is of the fourth-order solution's error: larger than
        // the fifth-order one's, and of the order h⁵/1000.
        let fifth = (t.y[0] - exact).abs();
        assert!(
            t.error[0].abs() > fifth && t.error[0].abs() < 1e-6,
            "{}",
            t.error[0]
        );
    }
}
