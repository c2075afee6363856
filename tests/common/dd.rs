//! Double-double arithmetic (~32 significant digits): a higher-precision
//! reference for the accuracy tests. Error-free transformations after
//! Dekker and Knuth; `mul_add` gives the exact product error.

use std::ops::{Add, Div, Mul, Neg, Sub};

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DD {
    pub hi: f64,
    pub lo: f64,
}

fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

fn quick_two_sum(a: f64, b: f64) -> DD {
    let s = a + b;
    DD {
        hi: s,
        lo: b - (s - a),
    }
}

impl DD {
    pub const ZERO: DD = DD { hi: 0.0, lo: 0.0 };
    pub const ONE: DD = DD { hi: 1.0, lo: 0.0 };

    pub fn from(x: f64) -> DD {
        DD { hi: x, lo: 0.0 }
    }

    pub fn to_f64(self) -> f64 {
        self.hi + self.lo
    }

    pub fn sqrt(self) -> DD {
        if self.hi <= 0.0 {
            return DD::ZERO;
        }
        let s = DD::from(self.hi.sqrt());
        s + (self - s * s) / (s * DD::from(2.0))
    }

    pub fn abs(self) -> DD {
        if self.hi < 0.0 {
            -self
        } else {
            self
        }
    }
}

impl Add for DD {
    type Output = DD;
    fn add(self, o: DD) -> DD {
        let (s, e) = two_sum(self.hi, o.hi);
        quick_two_sum(s, e + self.lo + o.lo)
    }
}

impl Neg for DD {
    type Output = DD;
    fn neg(self) -> DD {
        DD {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl Sub for DD {
    type Output = DD;
    fn sub(self, o: DD) -> DD {
        self + (-o)
    }
}

impl Mul for DD {
    type Output = DD;
    fn mul(self, o: DD) -> DD {
        let p = self.hi * o.hi;
        let e = self.hi.mul_add(o.hi, -p);
        quick_two_sum(p, e + self.hi * o.lo + self.lo * o.hi)
    }
}

impl Div for DD {
    type Output = DD;
    fn div(self, o: DD) -> DD {
        let q1 = self.hi / o.hi;
        let r = self - o * DD::from(q1);
        let q2 = r.hi / o.hi;
        let r = r - o * DD::from(q2);
        let q3 = r.hi / o.hi;
        quick_two_sum(q1, q2) + DD::from(q3)
    }
}

pub type V = [DD; 3];
pub type M = [[DD; 3]; 3];

pub fn v(a: &nalgebra::Vector3<f64>) -> V {
    [DD::from(a.x), DD::from(a.y), DD::from(a.z)]
}

pub fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub fn scale(a: V, k: DD) -> V {
    [a[0] * k, a[1] * k, a[2] * k]
}

pub fn dot(a: V, b: V) -> DD {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub fn mat(m: &nalgebra::Matrix3<f64>) -> M {
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| DD::from(m[(r, c)])))
}

pub fn mul_v(m: M, x: V) -> V {
    [0, 1, 2].map(|r| m[r][0] * x[0] + m[r][1] * x[1] + m[r][2] * x[2])
}

pub fn mul_m(a: M, b: M) -> M {
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| a[r][0] * b[0][c] + a[r][1] * b[1][c] + a[r][2] * b[2][c]))
}

pub fn transpose(a: M) -> M {
    [0, 1, 2].map(|r| [0, 1, 2].map(|c| a[c][r]))
}

/// Inverse by the adjugate.
pub fn inverse(m: M) -> M {
    let c =
        |r0: usize, r1: usize, c0: usize, c1: usize| m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
    let adj = [
        [c(1, 2, 1, 2), -c(0, 2, 1, 2), c(0, 1, 1, 2)],
        [-c(1, 2, 0, 2), c(0, 2, 0, 2), -c(0, 1, 0, 2)],
        [c(1, 2, 0, 1), -c(0, 2, 0, 1), c(0, 1, 0, 1)],
    ];
    let det = m[0][0] * adj[0][0] + m[0][1] * adj[1][0] + m[0][2] * adj[2][0];
    adj.map(|row| row.map(|x| x / det))
}

/// Rotation matrix of the quaternion `[w, x, y, z]`, normalised in DD.
pub fn rotation(q: &nalgebra::Quaternion<f64>) -> M {
    let (w, x, y, z) = (DD::from(q.w), DD::from(q.i), DD::from(q.j), DD::from(q.k));
    let n = (w * w + x * x + y * y + z * z).sqrt();
    let (w, x, y, z) = (w / n, x / n, y / n, z / n);
    let one = DD::ONE;
    let two = DD::from(2.0);
    [
        [
            one - two * (y * y + z * z),
            two * (x * y - w * z),
            two * (x * z + w * y),
        ],
        [
            two * (x * y + w * z),
            one - two * (x * x + z * z),
            two * (y * z - w * x),
        ],
        [
            two * (x * z - w * y),
            two * (y * z + w * x),
            one - two * (x * x + y * y),
        ],
    ]
}

pub fn norm(a: V) -> DD {
    dot(a, a).sqrt()
}
