//! The uniform grid of the broad phase (`broad_phase = "grid"`): space cut
//! into cubic cells of one size (the median box's largest side), each box
//! hashed into every cell it overlaps, the boxes that share a cell tested
//! against each other. A pair that shares several cells is tested once: in
//! the first cell both cover (the largest of their low cells on each axis).
//! A box that spans more than [`MAX_SPAN`] cells along an axis (a floor, a
//! wall) or is not finite is *loose*: tested against every other box, as
//! all-against-all would. The pairs are the boxes that overlap or touch,
//! unsorted (the caller sorts them).

use super::bounds::{loose_pairs, Bounds};

/// Cells along one axis a box may span before it is tested against every
/// other box instead of being hashed (so one floor does not fill the grid).
pub(super) const MAX_SPAN: i64 = 4;

/// Cell coordinates farther than this from the origin are not hashed
/// (the box is loose): far beyond any scene's cells, well inside i64.
const FAR: f64 = (1u64 << 40) as f64;

/// A cell's coordinates.
type Cell = [i64; 3];

/// The grid's buffers and its last call's counts.
#[derive(Debug, Clone, Default)]
pub(super) struct Grid {
    /// (cell, body) for every cell each hashed box overlaps, sorted.
    entries: Vec<(Cell, usize)>,
    /// Each body's low and high cell (`None`: loose or no box).
    ranges: Vec<Option<(Cell, Cell)>>,
    loose: Vec<usize>,
    is_loose: Vec<bool>,
    sides: Vec<f64>,
    /// The last call's cell side (m).
    pub(super) cell: f64,
    /// Cells that held at least one box in the last call.
    pub(super) visited: usize,
    /// Box-against-box tests the last call made.
    pub(super) tests: usize,
}

impl Grid {
    /// Appends to `out` every pair (i, j), i < j, of `boxes` that overlap or
    /// touch, each once, unsorted.
    pub(super) fn pairs(&mut self, boxes: &[Option<Bounds>], out: &mut Vec<(usize, usize)>) {
        self.visited = 0;
        self.tests = 0;
        self.cell = self.cell_side(boxes);
        let origin = origin(boxes);
        self.entries.clear();
        self.loose.clear();
        self.ranges.clear();
        self.is_loose.clear();
        self.is_loose.resize(boxes.len(), false);
        for (i, b) in boxes.iter().enumerate() {
            let range = b.as_ref().and_then(|b| cells_of(b, &origin, self.cell));
            self.ranges.push(range);
            match (b, range) {
                (None, _) => {}
                (Some(_), None) => {
                    self.loose.push(i);
                    self.is_loose[i] = true;
                }
                (Some(_), Some((lo, hi))) => {
                    for x in lo[0]..=hi[0] {
                        for y in lo[1]..=hi[1] {
                            for z in lo[2]..=hi[2] {
                                self.entries.push(([x, y, z], i));
                            }
                        }
                    }
                }
            }
        }
        self.entries.sort_unstable();
        let mut start = 0;
        while start < self.entries.len() {
            let cell = self.entries[start].0;
            let end = start
                + self.entries[start..]
                    .iter()
                    .take_while(|e| e.0 == cell)
                    .count();
            self.visited += 1;
            for a in start..end {
                let i = self.entries[a].1;
                let (lo_i, _) = self.ranges[i].expect("hashed");
                for &(_, j) in &self.entries[a + 1..end] {
                    let (lo_j, _) = self.ranges[j].expect("hashed");
                    // Tested in the first cell both cover only.
                    if [0, 1, 2].map(|k| lo_i[k].max(lo_j[k])) != cell {
                        continue;
                    }
                    self.tests += 1;
                    if let (Some(p), Some(q)) = (&boxes[i], &boxes[j]) {
                        if p.overlaps(q) {
                            out.push((i, j));
                        }
                    }
                }
            }
            start = end;
        }
        self.tests += loose_pairs(&self.loose, &self.is_loose, boxes, out);
    }

    /// The median of the boxes' largest sides (the positive, finite ones);
    /// 1 when there is none.
    fn cell_side(&mut self, boxes: &[Option<Bounds>]) -> f64 {
        self.sides.clear();
        self.sides.extend(boxes.iter().flatten().filter_map(|b| {
            let side = (0..3).fold(0.0f64, |m, k| m.max(b.max[k] - b.min[k]));
            (side.is_finite() && side > 0.0).then_some(side)
        }));
        if self.sides.is_empty() {
            return 1.0;
        }
        let mid = self.sides.len() / 2;
        *self.sides.select_nth_unstable_by(mid, f64::total_cmp).1
    }

    /// The last call's loose bodies (tested against every other box).
    pub(super) fn loose(&self) -> usize {
        self.loose.len()
    }
}

/// The least low corner over the finite boxes (zeros when there is none).
fn origin(boxes: &[Option<Bounds>]) -> [f64; 3] {
    let mut low = [f64::INFINITY; 3];
    for b in boxes.iter().flatten() {
        for (l, x) in low.iter_mut().zip(b.min) {
            if x.is_finite() {
                *l = l.min(x);
            }
        }
    }
    low.map(|x| if x.is_finite() { x } else { 0.0 })
}

/// The low and high cells a box overlaps; `None` (loose) when it is not
/// finite, lies too far out, or spans more than [`MAX_SPAN`] cells on an
/// axis. A box's high side on a cell boundary is in the cell above: two
/// boxes that touch share that cell.
fn cells_of(b: &Bounds, origin: &[f64; 3], side: f64) -> Option<(Cell, Cell)> {
    let mut lo = [0; 3];
    let mut hi = [0; 3];
    for k in 0..3 {
        let (l, h) = (
            ((b.min[k] - origin[k]) / side).floor(),
            ((b.max[k] - origin[k]) / side).floor(),
        );
        if !(l.abs() < FAR && h.abs() < FAR && l <= h) {
            return None;
        }
        (lo[k], hi[k]) = (l as i64, h as i64);
        if hi[k] - lo[k] >= MAX_SPAN {
            return None;
        }
    }
    Some((lo, hi))
}
