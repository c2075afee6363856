//! The broad phase by the method `[world] broad_phase` names: sort and
//! sweep ([`super::broad`]), a uniform grid ([`super::grid`]) or a dynamic
//! bounding-volume tree ([`super::tree`]). Each finds the same pairs — the
//! boxes that overlap or touch, and every body with bounds paired with every
//! half-space — sorted the same way, so the narrow phase meets them in the
//! same order and a run is the same state for state under each; only what
//! finding them costs differs, and [`BroadCounts`] says what it was.

use super::bounds::{push_half_space_pairs, Bounds};
use super::broad::{bounds_of, Aabb, BroadPhase};
use super::grid::Grid;
use super::sweep::sort_pairs;
use super::tree::Tree;
use super::Real;
use crate::physics::params::BroadPhaseMethod;

/// What one broad-phase call did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BroadCounts {
    pub method: BroadPhaseMethod,
    /// Bodies with a box (the ones sorted, hashed or put in the tree).
    pub boxes: usize,
    /// Sweep: boxes swept (0 when the pairs kept from an earlier sweep
    /// served); grid: cells that held a box; bvh: tree nodes the queries visited.
    pub visited: usize,
    /// Box-against-box tests made (each pair at most once).
    pub tests: usize,
    /// Pairs kept: boxes that overlap or touch, and the half-space pairs.
    pub kept: usize,
    /// Boxes tested against every other box instead (grid: spanning more
    /// than 4 cells on an axis, or not finite; bvh: not finite).
    pub loose: usize,
    /// The grid's cell side (m); 0 for the other methods.
    pub cell: f64,
    /// The tree's height after the call; 0 for the other methods.
    pub height: u32,
}

/// The broad phase's state for every method, kept from call to call (only
/// the method asked for is run and kept current).
#[derive(Debug, Clone, Default)]
pub struct PairFinder {
    sweep: BroadPhase,
    grid: Grid,
    tree: Tree,
    exact: Vec<Option<Bounds>>,
    counts: BroadCounts,
    sorting: Vec<usize>,
    scratch: Vec<(usize, usize)>,
}

impl PairFinder {
    pub fn new() -> Self {
        Self::default()
    }

    /// Replaces `out` with the candidate pairs (i, j), i < j, sorted, found
    /// by `method`: the same pairs as [`BroadPhase::candidate_pairs`].
    pub fn candidate_pairs<T: Real>(
        &mut self,
        method: BroadPhaseMethod,
        bounds: &[Option<Aabb<T>>],
        half_spaces: &[usize],
        out: &mut Vec<(usize, usize)>,
    ) {
        let boxes = bounds.iter().flatten().count();
        let mut counts = BroadCounts {
            method,
            boxes,
            ..BroadCounts::default()
        };
        if method == BroadPhaseMethod::Sweep {
            self.sweep.candidate_pairs(bounds, half_spaces, out);
            counts.visited = if self.sweep.swept { boxes } else { 0 };
            counts.tests = self.sweep.tests;
            counts.kept = out.len();
            self.counts = counts;
            return;
        }
        self.exact.clear();
        self.exact
            .extend(bounds.iter().map(|b| b.as_ref().map(bounds_of)));
        out.clear();
        if method == BroadPhaseMethod::Grid {
            self.grid.pairs(&self.exact, out);
            counts.visited = self.grid.visited;
            counts.tests = self.grid.tests;
            counts.loose = self.grid.loose();
            counts.cell = self.grid.cell;
        } else {
            self.tree.pairs(&self.exact, out);
            counts.visited = self.tree.visited;
            counts.tests = self.tree.tests;
            counts.loose = self.tree.loose();
            counts.height = self.tree.height();
        }
        push_half_space_pairs(&self.exact, half_spaces, out);
        sort_pairs(out, bounds.len(), &mut self.sorting, &mut self.scratch);
        counts.kept = out.len();
        self.counts = counts;
    }

    /// What the last call did.
    pub fn counts(&self) -> BroadCounts {
        self.counts
    }

    /// The tree's shape checked (for tests).
    #[cfg(test)]
    pub(super) fn check_tree(&self) {
        self.tree.check();
    }
}

#[cfg(test)]
#[path = "partition_tests.rs"]
mod tests;
