//! A huge step's recording kept within a budget. Recording keeps, per
//! iteration, the contact taken, its value before → after and its moves or
//! impulse, always; the *rows* (every other contact the iteration changed,
//! and the resolver's bodies at the stop, one row per body) are kept while
//! they fit in [`ROW_BUDGET`]. Past it, only every K-th iteration (K a power
//! of two) keeps its rows, the others say how many they changed and that
//! their rows were elided. A step under the budget is recorded whole (K = 1),
//! exactly as before; past it the cost is the resolver's own (iterations ×
//! the contacts each one changes, counted, not kept) and memory is bounded by
//! the iterations plus the budget.
//!
//! The budget, measured (release, `simulate --trace-step 1` of a pile of
//! coincident spheres, text): 20 spheres record 0.06 M rows (2.4 MB of
//! text), 50 spheres 1 M rows (40 MB of text, 4 s, 0.8 GB before this
//! budget), 150 spheres 27 M rows (not recorded in 300 s before it; 6 s and
//! 143 MB with it). Every embedded lesson and scene records far fewer rows
//! (the largest step of the embedded scenes: 512 iterations over 32 contacts,
//! under 20,000 rows), so their output is unchanged. docs/resolve.md has the
//! table.

use super::Recorder;
use crate::physics::resolver::ResolverBody;

/// The most rows a recording keeps (see the module's comment).
pub const ROW_BUDGET: usize = 200_000;

/// How a recording past the budget was thinned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Elision {
    /// Iterations whose index is a multiple of `every` kept their rows.
    pub every: usize,
    /// The row budget it was kept within.
    pub budget: usize,
}

/// The recorder's bookkeeping of kept rows.
#[derive(Debug, Clone)]
pub(crate) struct Thinning {
    pub every: usize,
    pub kept: usize,
    pub budget: usize,
}

impl Default for Thinning {
    fn default() -> Self {
        Thinning::new(ROW_BUDGET)
    }
}

impl Thinning {
    pub fn new(budget: usize) -> Self {
        Thinning {
            every: 1,
            kept: 0,
            budget,
        }
    }

    /// Does iteration `i` (of either phase) keep its rows?
    pub fn keeps(&self, i: usize) -> bool {
        i.is_multiple_of(self.every)
    }

    /// How the recording was thinned, if it was.
    pub fn elision(&self) -> Option<Elision> {
        (self.every > 1).then_some(Elision {
            every: self.every,
            budget: self.budget,
        })
    }
}

impl Recorder {
    /// Past the row budget: keep the rows of every other kept iteration
    /// only, until they fit (iteration 0 of each phase is always kept).
    pub(super) fn thin(&mut self) {
        while self.thinning.kept > self.thinning.budget {
            let most = self.position.len().max(self.velocity.len());
            if self.thinning.every >= most {
                return;
            }
            self.thinning.every *= 2;
            let every = self.thinning.every;
            let mut dropped = 0;
            for log in [&mut self.position, &mut self.velocity] {
                for it in log
                    .iter_mut()
                    .filter(|it| !it.elided && !it.iteration.is_multiple_of(every))
                {
                    dropped += it.updated.len();
                    it.updated = Vec::new();
                    it.elided = true;
                }
            }
            for phase in &mut self.bodies {
                for (i, b) in phase.iter_mut().enumerate() {
                    if !i.is_multiple_of(every) && !b.is_empty() {
                        dropped += b.len();
                        *b = Vec::new();
                    }
                }
            }
            self.thinning.kept -= dropped;
        }
    }

    /// The bodies before iteration `i` of a phase, when its rows are kept.
    pub(super) fn keep_bodies_at(&mut self, phase: usize, i: usize, bodies: &[ResolverBody<f64>]) {
        if !self.keep_bodies {
            return;
        }
        if self.thinning.keeps(i) {
            self.bodies[phase].push(bodies.to_vec());
            self.thinning.kept += bodies.len();
            self.thin();
        } else {
            self.bodies[phase].push(Vec::new());
        }
    }
}
