//! Simultaneous impact: the velocity phase of a set of contacts as one
//! linear complementarity problem (find λ ≥ 0 with w = Aλ + b ≥ 0 and
//! λ·w = 0), solved by Lemke's method, under Newton's or Poisson's
//! restitution (`lcp_restitution`).
//!
//! - `hertz.rs`: the compliant reference (Hertz contacts on a line,
//!   integrated by RK4 through the impact) the two rigid answers are
//!   judged against;
//! - `lemke.rs`: complementary pivoting with a covering vector, the
//!   lexicographic ratio test, a pivot cap;
//! - A (the coupled unit-impulse matrix) and b come from the prepared
//!   contacts (`physics/resolver/lcp_matrix.rs`), and the velocity phase
//!   that applies the impulses (`solver = "lcp"`) is the resolver's
//!   (`physics/resolver/simultaneous.rs`): this folder is pure algebra,
//!   below the resolver.
//!
//! Friction: after the normal LCP, a projected Gauss–Seidel pass gives
//! each contact with friction a tangential impulse inside the friction
//! disk of radius μ λ_n, λ_n the LCP's normal impulse
//! (`physics/resolver/lcp_friction.rs`; the record's [`Friction`]).

pub mod hertz;
pub mod lemke;

pub use lemke::{Failure, Pivot, Var};

use crate::physics::{LcpRestitution, Real};

/// Which LCP of a phase: Newton's one, or Poisson's compression and (when
/// applying e·P_c leaves a contact closing) a correcting one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    Newton,
    Compression,
    Correction,
}

impl Stage {
    pub fn name(self) -> &'static str {
        match self {
            Stage::Newton => "newton",
            Stage::Compression => "compression",
            Stage::Correction => "correction",
        }
    }
}

/// One LCP solved: its b, its pivots and its impulses (or why none).
#[derive(Debug, Clone, PartialEq)]
pub struct Problem<T: Real> {
    pub stage: Stage,
    pub b: Vec<T>,
    pub pivots: Vec<Pivot<T>>,
    pub result: Result<Vec<T>, Failure>,
}

impl<T: Real> Problem<T> {
    /// The tableau's basis after pivot `k` of this problem (each row's
    /// basic variable and its value), replayed from the recorded pivots:
    /// the pivot row takes the entering variable at the ratio, every other
    /// row's value drops by its column entry times the ratio.
    pub fn basis_after(&self, k: usize) -> Vec<(Var, T)> {
        let mut basis: Vec<(Var, T)> = self
            .b
            .iter()
            .enumerate()
            .map(|(i, &b)| (Var::W(i), b))
            .collect();
        for p in self.pivots.iter().take(k + 1) {
            for (i, row) in basis.iter_mut().enumerate() {
                row.1 = if i == p.row {
                    p.ratio
                } else {
                    p.rhs[i] - p.column[i] * p.ratio
                };
            }
            basis[p.row].0 = p.entering;
        }
        basis
    }

    /// The impulses λ after pivot `k` (0 where λ_i is not basic).
    pub fn lambda_after(&self, k: usize) -> Vec<T> {
        let mut lambda = vec![T::zero(); self.b.len()];
        for (v, x) in self.basis_after(k) {
            if let Var::Lambda(j) = v {
                lambda[j] = x;
            }
        }
        lambda
    }
}

/// What the simultaneous velocity phase did.
#[derive(Debug, Clone, PartialEq)]
pub struct Record<T: Real> {
    pub restitution: LcpRestitution,
    /// A, contacts in file order.
    pub matrix: Vec<Vec<T>>,
    /// The rank of A: below the contact count the impulses are one choice
    /// of many (the velocities after are still unique).
    pub rank: usize,
    pub problems: Vec<Problem<T>>,
    /// Each contact's restitution as applied.
    pub restitutions: Vec<T>,
    /// Each contact's total normal impulse applied (zeros when unsolvable).
    pub impulses: Vec<T>,
    /// Each contact's normal velocity after (before, when unsolvable).
    pub velocities_after: Vec<T>,
    /// The friction pass, when any contact has friction.
    pub friction: Option<Friction<T>>,
}

/// The friction pass after the normal LCP: projected Gauss–Seidel sweeps
/// over the contacts with friction, each tangential impulse projected onto
/// the disk |λ_t| ≤ μ λ_n with λ_n the LCP's normal impulse (held fixed).
#[derive(Debug, Clone, PartialEq)]
pub struct Friction<T: Real> {
    pub rows: Vec<FrictionRow<T>>,
    /// Sweeps taken (at most [`FRICTION_SWEEP_CAP`]).
    pub sweeps: usize,
    /// Whether the last sweep changed no impulse by more than the tolerance.
    pub converged: bool,
    /// Contacts the tangential impulses left closing (normal velocity
    /// below -1e-9 after): the normal LCP is not solved again.
    pub closing: Vec<usize>,
}

/// The most sweeps of the friction pass.
pub const FRICTION_SWEEP_CAP: usize = 200;

/// One contact's friction: its coefficients, the normal impulse bounding
/// it, the tangential impulse (contact axes y, z) and whether it slides.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionRow<T: Real> {
    pub contact: usize,
    pub static_friction: T,
    pub dynamic_friction: T,
    pub normal: T,
    pub tangential: [T; 2],
    /// On the disk's edge (μ_d λ_n) against the slip; else sticking.
    pub sliding: bool,
    /// The contact point's tangential velocity after (contact axes y, z).
    pub slip_after: [T; 2],
}

impl<T: Real> Record<T> {
    /// Why no impulses were applied, if so.
    pub fn failure(&self) -> Option<Failure> {
        self.problems
            .iter()
            .find_map(|p| p.result.as_ref().err().copied())
    }

    /// Every pivot of every problem, in order.
    pub fn pivots(&self) -> impl Iterator<Item = (Stage, &Pivot<T>)> {
        self.problems
            .iter()
            .flat_map(|p| p.pivots.iter().map(move |v| (p.stage, v)))
    }

    /// A note on degeneracy: A singular (identical or dependent contacts)
    /// or a ratio test that tied.
    pub fn degenerate(&self) -> Option<String> {
        let n = self.matrix.len();
        if self.rank < n {
            return Some(format!(
                "degenerate: A is singular (rank {} of {n}): dependent contacts; the impulses are one solution of many, the velocities after are unique",
                self.rank
            ));
        }
        let ties = self.pivots().filter(|(_, p)| p.tie).count();
        (ties > 0)
            .then(|| format!("degenerate: {ties} ratio test(s) tied; the lexicographic rule chose"))
    }
}
