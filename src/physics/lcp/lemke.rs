//! Lemke's complementary pivoting for the linear complementarity problem
//! (Cottle, Pang & Stone, ch. 4.4): find λ ≥ 0 with w = Aλ + b ≥ 0 and
//! λ·w = 0.
//!
//! The tableau is `w - Aλ - d z0 = b` with the covering vector d = 1 and
//! the artificial variable z0. The first pivot brings z0 in at the row of
//! the most negative b; after that the complement of the variable that
//! just left enters, the ratio test (lexicographic on ties, z0 first)
//! chooses the row, until z0 leaves (solved) or a column has no positive
//! entry (a secondary ray: no solution Lemke can reach) or the pivot cap
//! is reached (cycling on a degenerate system): both are reported, never
//! looped on.

use crate::physics::{c, Real};

/// A variable of the tableau: a contact's separating velocity w_i, its
/// impulse λ_i, or the artificial z0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Var {
    W(usize),
    Lambda(usize),
    Z0,
}

impl Var {
    /// The variable's name as reports print it (`w0`, `lambda1`, `z0`).
    pub fn name(self) -> String {
        match self {
            Var::W(i) => format!("w{i}"),
            Var::Lambda(i) => format!("lambda{i}"),
            Var::Z0 => "z0".to_string(),
        }
    }

    fn complement(self) -> Var {
        match self {
            Var::W(i) => Var::Lambda(i),
            Var::Lambda(i) => Var::W(i),
            Var::Z0 => Var::Z0,
        }
    }

    fn column(self, n: usize) -> usize {
        match self {
            Var::W(i) => i,
            Var::Lambda(i) => n + i,
            Var::Z0 => 2 * n,
        }
    }
}

/// One pivot: who entered, who left (at which row), the tableau's column
/// of the entering variable and the right-hand side before the pivot, and
/// the ratio the test chose (the entering variable's new value).
#[derive(Debug, Clone, PartialEq)]
pub struct Pivot<T: Real> {
    pub entering: Var,
    pub leaving: Var,
    pub row: usize,
    pub ratio: T,
    pub column: Vec<T>,
    pub rhs: Vec<T>,
    /// More than one row met the least ratio (a degenerate pivot): the
    /// lexicographic rule chose.
    pub tie: bool,
}

/// Why Lemke's method stopped without a solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Failure {
    /// The entering variable's column had no positive entry: it can grow
    /// without bound (a secondary ray), so the system is inconsistent.
    Ray(Var),
    /// The pivot cap was reached (a degenerate system cycling).
    PivotCap(usize),
}

impl Failure {
    /// The failure in words.
    pub fn describe(self) -> String {
        match self {
            Failure::Ray(v) => format!(
                "unsolvable: {} can grow without bound (a secondary ray): no impulses >= 0 give every contact a separating velocity >= its target",
                v.name()
            ),
            Failure::PivotCap(cap) => format!(
                "degenerate: stopped at the pivot cap ({cap} pivots) without z0 leaving"
            ),
        }
    }
}

/// What a run of Lemke's method did.
#[derive(Debug, Clone, PartialEq)]
pub struct Run<T: Real> {
    pub pivots: Vec<Pivot<T>>,
    /// The impulses λ, or why there are none.
    pub result: Result<Vec<T>, Failure>,
}

/// The most pivots before a run is called degenerate.
pub fn pivot_cap(n: usize) -> usize {
    50 * (n + 1)
}

/// Solves the LCP (A, b) by Lemke's method.
pub fn solve<T: Real>(a: &[Vec<T>], b: &[T]) -> Run<T> {
    let n = b.len();
    let mut pivots = Vec::new();
    if b.iter().all(|&x| x >= T::zero()) {
        return Run {
            pivots,
            result: Ok(vec![T::zero(); n]),
        };
    }
    let scale = a
        .iter()
        .flatten()
        .chain(b)
        .fold(T::one(), |m, &x| m.max(x.abs()));
    let tol = scale * c::<T>(1e-13);
    // Columns: w (n), λ (n), z0, rhs.
    let width = 2 * n + 2;
    let mut t = vec![vec![T::zero(); width]; n];
    for i in 0..n {
        t[i][i] = T::one();
        for j in 0..n {
            t[i][n + j] = -a[i][j];
        }
        t[i][2 * n] = -T::one();
        t[i][2 * n + 1] = b[i];
    }
    let mut basis: Vec<Var> = (0..n).map(Var::W).collect();
    // First pivot: z0 enters at the most negative b (first on ties).
    let mut row = 0;
    for i in 1..n {
        if b[i] < b[row] {
            row = i;
        }
    }
    let mut entering = Var::Z0;
    let cap = pivot_cap(n);
    loop {
        let col = entering.column(n);
        let column: Vec<T> = t.iter().map(|r| r[col]).collect();
        let rhs: Vec<T> = t.iter().map(|r| r[width - 1]).collect();
        let mut tie = false;
        if entering != Var::Z0 {
            match ratio_test(&t, &basis, col, tol) {
                Some((r, tied)) => {
                    row = r;
                    tie = tied;
                }
                None => {
                    return Run {
                        pivots,
                        result: Err(Failure::Ray(entering)),
                    }
                }
            }
        }
        if pivots.len() == cap {
            return Run {
                pivots,
                result: Err(Failure::PivotCap(cap)),
            };
        }
        let leaving = basis[row];
        let ratio = rhs[row] / column[row];
        pivot(&mut t, row, col);
        basis[row] = entering;
        pivots.push(Pivot {
            entering,
            leaving,
            row,
            ratio,
            column,
            rhs,
            tie,
        });
        if leaving == Var::Z0 {
            break;
        }
        entering = leaving.complement();
    }
    let mut lambda = vec![T::zero(); n];
    for (r, v) in basis.iter().enumerate() {
        if let Var::Lambda(j) = v {
            lambda[*j] = t[r][width - 1].max(T::zero());
        }
    }
    Run {
        pivots,
        result: Ok(lambda),
    }
}

/// The row the entering column `col` pivots on: the least ratio rhs/entry
/// over positive entries; on ties z0's row, else the lexicographically
/// least row of B⁻¹ (the w columns) over the entry. `None`: no positive
/// entry. The flag says whether rows tied.
fn ratio_test<T: Real>(t: &[Vec<T>], basis: &[Var], col: usize, tol: T) -> Option<(usize, bool)> {
    let n = t.len();
    let rhs = 2 * n + 1;
    let rows: Vec<usize> = (0..n).filter(|&i| t[i][col] > tol).collect();
    let least = rows
        .iter()
        .map(|&i| t[i][rhs] / t[i][col])
        .fold(None, |m: Option<T>, x| Some(m.map_or(x, |m| m.min(x))))?;
    let near = tol.max(least.abs() * c::<T>(1e-12));
    let tied: Vec<usize> = rows
        .into_iter()
        .filter(|&i| t[i][rhs] / t[i][col] <= least + near)
        .collect();
    if tied.len() == 1 {
        return Some((tied[0], false));
    }
    if let Some(&z) = tied.iter().find(|&&i| basis[i] == Var::Z0) {
        return Some((z, true));
    }
    let lex = |i: usize, k: usize| t[i][k] / t[i][col];
    let mut best = tied[0];
    for &i in &tied[1..] {
        for k in 0..n {
            let (x, y) = (lex(i, k), lex(best, k));
            if (x - y).abs() > tol {
                if x < y {
                    best = i;
                }
                break;
            }
        }
    }
    Some((best, true))
}

/// Gauss–Jordan pivot of the tableau on (row, col).
fn pivot<T: Real>(t: &mut [Vec<T>], row: usize, col: usize) {
    let p = t[row][col];
    for x in t[row].iter_mut() {
        *x /= p;
    }
    t[row][col] = T::one();
    let pivot_row = t[row].clone();
    for (i, r) in t.iter_mut().enumerate() {
        if i == row {
            continue;
        }
        let f = r[col];
        if f != T::zero() {
            for (x, &p) in r.iter_mut().zip(&pivot_row) {
                *x -= f * p;
            }
            r[col] = T::zero();
        }
    }
}

/// w = Aλ + b.
pub fn residual<T: Real>(a: &[Vec<T>], b: &[T], lambda: &[T]) -> Vec<T> {
    a.iter()
        .zip(b)
        .map(|(row, &bi)| row.iter().zip(lambda).fold(bi, |s, (&x, &l)| s + x * l))
        .collect()
}

/// The rank of A (Gaussian elimination with partial pivoting, entries
/// below `1e-10 ×` the largest taken as zero).
pub fn rank<T: Real>(a: &[Vec<T>]) -> usize {
    let n = a.len();
    let mut m: Vec<Vec<T>> = a.to_vec();
    let scale = m.iter().flatten().fold(T::zero(), |s, &x| s.max(x.abs()));
    let tol = scale * c::<T>(1e-10);
    let mut rank = 0;
    for col in 0..n {
        let Some(p) = (rank..n).max_by(|&i, &j| {
            m[i][col]
                .abs()
                .partial_cmp(&m[j][col].abs())
                .unwrap_or(std::cmp::Ordering::Equal)
        }) else {
            break;
        };
        if m[p][col].abs() <= tol {
            continue;
        }
        m.swap(rank, p);
        let pivot_row = m[rank].clone();
        for row in m.iter_mut().skip(rank + 1) {
            let f = row[col] / pivot_row[col];
            for (x, &v) in row.iter_mut().zip(&pivot_row).skip(col) {
                *x -= f * v;
            }
        }
        rank += 1;
    }
    rank
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trivial_when_b_is_nonnegative() {
        let run = solve(&[vec![1.0f64]], &[0.5]);
        assert!(run.pivots.is_empty());
        assert_eq!(run.result, Ok(vec![0.0]));
    }

    #[test]
    fn two_by_two_newton_row() {
        // N = 3 row, unit masses: A = [[2, -1], [-1, 2]], b = [-2v, 0] (e = 1).
        let a = vec![vec![2.0f64, -1.0], vec![-1.0, 2.0]];
        let run = solve(&a, &[-2.0, 0.0]);
        let l = run.result.unwrap();
        assert!((l[0] - 4.0 / 3.0).abs() < 1e-12 && (l[1] - 2.0 / 3.0).abs() < 1e-12);
        let w = residual(&a, &[-2.0, 0.0], &l);
        assert!(w.iter().all(|x| x.abs() < 1e-12));
    }

    #[test]
    fn inconsistent_system_is_a_ray() {
        // One body between two walls, both contacts asking to separate.
        let a = vec![vec![1.0f64, -1.0], vec![-1.0, 1.0]];
        let run = solve(&a, &[-1.0, -1.0]);
        assert!(matches!(run.result, Err(Failure::Ray(_))));
    }

    #[test]
    fn identical_contacts_terminate() {
        let a = vec![vec![1.0f64, 1.0], vec![1.0, 1.0]];
        let run = solve(&a, &[-2.0, -2.0]);
        let l = run.result.unwrap();
        assert!((l[0] + l[1] - 2.0).abs() < 1e-12);
        assert_eq!(rank(&a), 1);
    }
}
