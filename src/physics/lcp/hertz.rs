//! Finite stiffness as the arbiter of sequence against simultaneous: balls
//! on a line (a row, or a stack on a floor) whose neighbours touch through
//! Hertz contacts, a force k·δ^(3/2) on an overlap δ (no damping: e = 1),
//! integrated through the whole impact by the classical Runge–Kutta method
//! (RK4) with a small fixed step, until no contact overlaps and no pair
//! closes. Gravity and friction are left out (the impact is short). A body
//! of inverse mass 0 is a fixed wall (the floor). The rigid solvers' two
//! answers are its limits: gaps much wider than the compression make the
//! impacts one at a time (the sequence); no gaps make them act together,
//! though not as the LCP's rigid simultaneous answer says.

/// A line of bodies: along the line, each body's inverse mass, position
/// and velocity; between neighbours i and i + 1 the distance at which they
/// touch (`rest[i]`), and the contact stiffness k (N/m^1.5).
#[derive(Debug, Clone, PartialEq)]
pub struct Chain {
    pub inverse_mass: Vec<f64>,
    pub position: Vec<f64>,
    pub velocity: Vec<f64>,
    pub rest: Vec<f64>,
    pub stiffness: f64,
}

/// The velocities after the impact, how many steps it took, and whether it
/// ended (every contact open and separating) before the step cap.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    pub velocity: Vec<f64>,
    pub steps: usize,
    pub time: f64,
    pub ended: bool,
}

impl Chain {
    /// The overlap of contact i at positions `x` (positive: compressed).
    fn overlap(&self, x: &[f64], i: usize) -> f64 {
        self.rest[i] - (x[i + 1] - x[i])
    }

    /// Each body's acceleration at positions `x`.
    fn acceleration(&self, x: &[f64]) -> Vec<f64> {
        let mut a = vec![0.0; x.len()];
        for i in 0..self.rest.len() {
            let d = self.overlap(x, i);
            if d > 0.0 {
                let f = self.stiffness * d * d.sqrt();
                a[i] -= f * self.inverse_mass[i];
                a[i + 1] += f * self.inverse_mass[i + 1];
            }
        }
        a
    }

    /// Kinetic energy plus the energy stored in the contacts, k·(2/5)·δ^(5/2).
    pub fn energy(&self, x: &[f64], v: &[f64]) -> f64 {
        let kinetic: f64 = v
            .iter()
            .zip(&self.inverse_mass)
            .filter(|(_, &w)| w > 0.0)
            .map(|(v, w)| 0.5 * v * v / w)
            .sum();
        let stored: f64 = (0..self.rest.len())
            .map(|i| self.overlap(x, i).max(0.0))
            .map(|d| 0.4 * self.stiffness * d * d * d.sqrt())
            .sum();
        kinetic + stored
    }

    /// Σ m v over the bodies that are not walls.
    pub fn momentum(&self, v: &[f64]) -> f64 {
        v.iter()
            .zip(&self.inverse_mass)
            .filter(|(_, &w)| w > 0.0)
            .map(|(v, w)| v / w)
            .sum()
    }

    /// Whether the impact is over: no contact compressed, none closing.
    fn over(&self, x: &[f64], v: &[f64]) -> bool {
        (0..self.rest.len()).all(|i| self.overlap(x, i) <= 0.0 && v[i + 1] - v[i] >= 0.0)
    }

    /// Integrates through the impact with step `h`, at most `cap` steps.
    pub fn impact(&self, h: f64, cap: usize) -> Outcome {
        let (mut x, mut v) = (self.position.clone(), self.velocity.clone());
        let n = x.len();
        let axpy = |y: &[f64], a: f64, d: &[f64]| -> Vec<f64> {
            y.iter().zip(d).map(|(y, d)| y + a * d).collect()
        };
        let mut steps = 0;
        while steps < cap && !(steps > 0 && self.over(&x, &v)) {
            let a1 = self.acceleration(&x);
            let (x2, v2) = (axpy(&x, h / 2.0, &v), axpy(&v, h / 2.0, &a1));
            let a2 = self.acceleration(&x2);
            let (x3, v3) = (axpy(&x, h / 2.0, &v2), axpy(&v, h / 2.0, &a2));
            let a3 = self.acceleration(&x3);
            let (x4, v4) = (axpy(&x, h, &v3), axpy(&v, h, &a3));
            let a4 = self.acceleration(&x4);
            for i in 0..n {
                x[i] += h / 6.0 * (v[i] + 2.0 * v2[i] + 2.0 * v3[i] + v4[i]);
                v[i] += h / 6.0 * (a1[i] + 2.0 * a2[i] + 2.0 * a3[i] + a4[i]);
            }
            steps += 1;
        }
        Outcome {
            ended: self.over(&x, &v),
            velocity: v,
            steps,
            time: steps as f64 * h,
        }
    }
}
