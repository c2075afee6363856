//! The broad phase's search in words and numbers (`detect`'s "Broad
//! phase: search"): which method found the pairs, how many cells, tree
//! nodes or boxes it visited, the box tests it made and the pairs it kept.

use crate::format::Fmt;
use crate::knobs::Choice;
use crate::physics::collide::{BroadCounts, BroadPhaseMethod};

/// One broad-phase call, as `detect` shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct BroadSearch {
    /// The `broad_phase` choice's spelling ("sweep", "grid", "bvh").
    pub method: &'static str,
    /// What `visited` counts: "boxes" (swept), "cells", "tree nodes".
    pub visited_what: &'static str,
    pub visited: usize,
    /// Box-against-box tests made.
    pub tests: usize,
    /// Pairs kept (boxes that overlap or touch, and the half-space pairs).
    pub kept: usize,
    /// Bodies with a box.
    pub boxes: usize,
    /// Boxes tested against every other (too large for the cells, or not finite).
    pub loose: usize,
    /// The grid's cell side (m), when the method is the grid.
    pub cell: Option<f64>,
    /// The tree's height, when the method is the tree.
    pub height: Option<u32>,
}

impl BroadSearch {
    pub fn of(c: &BroadCounts) -> Self {
        let (visited_what, cell, height) = match c.method {
            BroadPhaseMethod::Sweep => ("boxes", None, None),
            BroadPhaseMethod::Grid => ("cells", Some(c.cell), None),
            BroadPhaseMethod::Bvh => ("tree nodes", None, Some(c.height)),
        };
        BroadSearch {
            method: c.method.name(),
            visited_what,
            visited: c.visited,
            tests: c.tests,
            kept: c.kept,
            boxes: c.boxes,
            loose: c.loose,
            cell,
            height,
        }
    }

    /// The search in one paragraph.
    pub fn words(&self, f: &Fmt) -> String {
        let how = match (self.cell, self.height) {
            (Some(cell), _) => format!("a uniform grid of {} m cells", f.num(cell)),
            (_, Some(h)) => format!("a bounding-volume tree of height {h}"),
            _ => "sort and sweep".to_string(),
        };
        let all = self.boxes * self.boxes.saturating_sub(1) / 2;
        let mut s = format!(
            "Search (broad_phase = {}): {how} over {}; {} {} visited, {} made (all against all: {all}), {} kept by the search (boxes that overlap or touch, and each body with a half-space).",
            self.method,
            count(self.boxes, "box", "boxes"),
            self.visited,
            self.visited_what,
            count(self.tests, "box test", "box tests"),
            count(self.kept, "pair", "pairs"),
        );
        if self.cell.is_none() && self.height.is_none() {
            s.push_str(" The sweep's tests: the boxes grown by 5 % swept, then each pair it found tested on the boxes themselves (a later step whose boxes stay inside the grown ones makes only the second).");
        }
        if self.loose > 0 {
            s.push_str(&format!(
                " {} tested against every other box (too large for the {} or not finite).",
                count(self.loose, "box", "boxes"),
                if self.cell.is_some() { "cells" } else { "tree" }
            ));
        }
        s
    }
}

/// `n` and the noun, singular or plural.
fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}
