//! Where a chart's legend goes: a corner (or the middle of the top or
//! bottom edge) of the plot whose box no curve crosses.

/// A rectangle on the page: left, top, width, height.
pub type Rect = (f64, f64, f64, f64);

/// The gap between the legend box and the plot's frame.
const PAD: f64 = 6.0;

/// The legend box's size for `names` (one line of 15 px each; a 24 px
/// swatch, then the name at about 7 px a character).
pub fn size(names: &[&str]) -> (f64, f64) {
    let longest = names.iter().map(|n| n.chars().count()).max().unwrap_or(0);
    (
        24.0 + 7.0 * longest as f64 + 12.0,
        15.0 * names.len() as f64 + 6.0,
    )
}

/// The first of the plot's corners, then the middles of its top and bottom
/// edges, where a box of `size` crosses none of `curves` (polylines in page
/// coordinates; a single point stands for a marker, a box of its own).
pub fn place(plot: Rect, size: (f64, f64), curves: &[Vec<(f64, f64)>]) -> Option<Rect> {
    let (left, top, w, h) = plot;
    let (bw, bh) = size;
    let (right, bottom) = (left + w, top + h);
    let xs = [right - PAD - bw, left + PAD, left + (w - bw) / 2.0];
    let ys = [top + PAD, bottom - PAD - bh];
    let candidates = [
        (xs[0], ys[0]),
        (xs[1], ys[0]),
        (xs[0], ys[1]),
        (xs[1], ys[1]),
        (xs[2], ys[0]),
        (xs[2], ys[1]),
    ];
    candidates
        .into_iter()
        .map(|(x, y)| (x, y, bw, bh))
        .find(|b| curves.iter().all(|c| !crosses(*b, c)))
}

/// Whether polyline `c` (or, when it is one point, a 4 px marker around
/// it) enters box `b`.
pub fn crosses(b: Rect, c: &[(f64, f64)]) -> bool {
    match c {
        [] => false,
        [p] => {
            let m = 4.0;
            p.0 + m >= b.0 && p.0 - m <= b.0 + b.2 && p.1 + m >= b.1 && p.1 - m <= b.1 + b.3
        }
        _ => c.windows(2).any(|s| segment_meets_box(s[0], s[1], b)),
    }
}

/// Whether segment `p`–`q` meets box `b` (Liang–Barsky clipping).
pub fn segment_meets_box(p: (f64, f64), q: (f64, f64), b: Rect) -> bool {
    let (dx, dy) = (q.0 - p.0, q.1 - p.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (edge_p, edge_q) in [
        (-dx, p.0 - b.0),
        (dx, b.0 + b.2 - p.0),
        (-dy, p.1 - b.1),
        (dy, b.1 + b.3 - p.1),
    ] {
        if edge_p == 0.0 {
            if edge_q < 0.0 {
                return false;
            }
        } else {
            let r = edge_q / edge_p;
            if edge_p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_through_the_box_meets_it_and_one_beside_it_does_not() {
        let b = (10.0, 10.0, 20.0, 10.0);
        assert!(segment_meets_box((0.0, 15.0), (40.0, 15.0), b));
        assert!(segment_meets_box((15.0, 12.0), (16.0, 13.0), b));
        assert!(!segment_meets_box((0.0, 25.0), (40.0, 25.0), b));
        assert!(!segment_meets_box((0.0, 0.0), (9.0, 40.0), b));
    }

    #[test]
    fn the_legend_leaves_the_top_right_for_a_curve_that_runs_through_it() {
        let plot = (0.0, 0.0, 400.0, 200.0);
        // A falling line from the top left to the bottom right, and a flat
        // one along the top: the top corners are taken, the bottom left is free.
        let curves = vec![
            vec![(0.0, 10.0), (400.0, 10.0)],
            vec![(200.0, 100.0), (400.0, 190.0)],
        ];
        let b = place(plot, (100.0, 36.0), &curves).unwrap();
        assert_eq!((b.0, b.1), (6.0, 200.0 - 6.0 - 36.0));
    }
}
