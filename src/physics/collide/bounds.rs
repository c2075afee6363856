//! The broad phase's boxes as f64 ([`Bounds`]), read by the broad phase
//! ([`super::broad`]) and its sort and sweep ([`super::sweep`]).

/// A box as f64.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Bounds {
    pub(super) min: [f64; 3],
    pub(super) max: [f64; 3],
}

impl Bounds {
    /// Overlap or touch on every axis.
    #[inline]
    pub(super) fn overlaps(&self, o: &Bounds) -> bool {
        (0..3).all(|k| self.min[k] <= o.max[k] && o.min[k] <= self.max[k])
    }

    /// Whether `inner` lies inside (false for a non-finite one).
    #[inline]
    pub(super) fn holds(&self, inner: &Bounds) -> bool {
        (0..3).all(|k| self.min[k] <= inner.min[k] && inner.max[k] <= self.max[k])
    }

    /// Grown by 5 % of the smallest half extent on every side; `None` when
    /// not finite.
    pub(super) fn grown(&self) -> Option<Bounds> {
        let half = (0..3).fold(f64::INFINITY, |m, k| {
            m.min(0.5 * (self.max[k] - self.min[k]))
        });
        let m = 0.05 * half.max(0.0);
        let g = Bounds {
            min: self.min.map(|x| x - m),
            max: self.max.map(|x| x + m),
        };
        (g.min.iter().chain(&g.max).all(|x| x.is_finite()) && m.is_finite()).then_some(g)
    }
}

/// Adds (body, half-space) for every body with bounds.
pub(super) fn push_half_space_pairs<B>(
    bounds: &[Option<B>],
    half_spaces: &[usize],
    out: &mut Vec<(usize, usize)>,
) {
    for (i, _) in bounds.iter().enumerate().filter(|(_, b)| b.is_some()) {
        for &h in half_spaces.iter().filter(|&&h| h != i) {
            out.push((i.min(h), i.max(h)));
        }
    }
}

/// The grid's and the tree's loose boxes (those they do not hold): each
/// tested against every other box, a pair of loose boxes once (from its
/// lower body); the pairs that overlap go to `out` as (lower, higher).
/// Returns the tests made.
pub(super) fn loose_pairs(
    loose: &[usize],
    is_loose: &[bool],
    boxes: &[Option<Bounds>],
    out: &mut Vec<(usize, usize)>,
) -> usize {
    let mut tests = 0;
    for &i in loose {
        let p = boxes[i].as_ref().expect("loose boxes have bounds");
        for (j, q) in boxes.iter().enumerate() {
            let Some(q) = q else { continue };
            if j == i || (is_loose[j] && j < i) {
                continue;
            }
            tests += 1;
            if p.overlaps(q) {
                out.push((i.min(j), i.max(j)));
            }
        }
    }
    tests
}
