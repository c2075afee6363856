//! Placing the SVG figure's labels: each label's box must stay inside the
//! drawing area, clear of the labels placed before it and of every stroke
//! drawn (outlines, arrows and their heads, spins, surfaces, dots). A label
//! that finds no free place goes to the legend, with a numbered marker (①,
//! ②, …) beside its mark where the marker itself finds room.

use super::page::{Page, Pending, Stroke, AREA};
use crate::render::figure::P;

/// The box a label of `size` px takes when written at `at` with `anchor`
/// (an estimate: 0.55 em a character, combining accents take no room).
pub fn label_box(at: P, size: f64, anchor: &str, s: &str) -> [f64; 4] {
    let chars = s
        .chars()
        .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
        .count() as f64;
    let w = 0.55 * size * chars;
    let x0 = match anchor {
        "middle" => at[0] - w / 2.0,
        "end" => at[0] - w,
        _ => at[0],
    };
    [x0, at[1] - 0.75 * size, x0 + w, at[1] + 0.2 * size]
}

/// Whether two boxes overlap by more than 2 px each way.
pub fn overlap(a: &[f64; 4], b: &[f64; 4]) -> bool {
    a[2].min(b[2]) - a[0].max(b[0]) > 2.0 && a[3].min(b[3]) - a[1].max(b[1]) > 2.0
}

/// Whether the segment `a`–`b` passes through the box (Liang–Barsky clipping).
pub fn crosses(bx: &[f64; 4], a: P, b: P) -> bool {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-d[0], a[0] - bx[0]),
        (d[0], bx[2] - a[0]),
        (-d[1], a[1] - bx[1]),
        (d[1], bx[3] - a[1]),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    t0 <= t1
}

/// Whether a stroke touches the box (the box grown by half the stroke's width).
pub fn touches(bx: &[f64; 4], s: &Stroke) -> bool {
    let h = s.half_width;
    let grown = [bx[0] - h, bx[1] - h, bx[2] + h, bx[3] + h];
    crosses(&grown, s.from, s.to)
}

/// Circled numbers for the markers of labels moved to the legend.
fn marker(n: usize) -> String {
    match n {
        1..=20 => char::from_u32(0x2460 + n as u32 - 1).map_or(format!("({n})"), String::from),
        _ => format!("({n})"),
    }
}

impl Page {
    /// A label in the drawing, placed by [`Page::place_labels`].
    pub fn label(&mut self, at: P, size: f64, anchor: &str, weight: &str, fill: &str, s: &str) {
        self.pending.push(Pending {
            at,
            size,
            anchor: anchor.to_string(),
            weight: weight.to_string(),
            fill: fill.to_string(),
            text: s.to_string(),
            elsewhere: vec![],
        });
    }

    /// A label with other anchors to try where `at` and its nudges are taken.
    pub fn label_or(&mut self, at: P, elsewhere: Vec<P>, size: f64, fill: &str, s: &str) {
        self.label(at, size, "middle", "normal", fill, s);
        if let Some(l) = self.pending.last_mut() {
            l.elsewhere = elsewhere;
        }
    }

    /// A straight stroke of `width` px from `a` to `b` (page coordinates).
    pub fn stroke(&mut self, a: P, b: P, width: f64) {
        self.strokes.push(Stroke {
            from: a,
            to: b,
            half_width: width / 2.0,
        });
    }

    /// A closed polyline (page coordinates).
    pub fn stroke_ring(&mut self, points: &[P], width: f64) {
        for (i, a) in points.iter().enumerate() {
            self.stroke(*a, points[(i + 1) % points.len()], width);
        }
    }

    /// A circle of `r` px about `centre` (page), as 32 pieces.
    pub fn stroke_circle(&mut self, centre: P, r: f64, width: f64) {
        let ring: Vec<P> = (0..32)
            .map(|i| {
                let a = std::f64::consts::TAU * f64::from(i) / 32.0;
                [centre[0] + r * a.cos(), centre[1] + r * a.sin()]
            })
            .collect();
        self.stroke_ring(&ring, width);
    }

    /// The head (`marker-end`, 4.5 stroke widths square, its tip 0.9 widths
    /// past the end) of a stroke of `width` px going from `p` to `q`.
    pub fn stroke_head(&mut self, p: P, q: P, width: f64) {
        let len = (q[0] - p[0]).hypot(q[1] - p[1]);
        if len <= 0.0 {
            return;
        }
        let (u, n) = ([(q[0] - p[0]) / len, (q[1] - p[1]) / len], 2.25 * width);
        let at = |a: f64, s: f64| [q[0] + a * u[0] - s * u[1], q[1] + a * u[1] + s * u[0]];
        let head = [
            at(0.9 * width, 0.0),
            at(-3.6 * width, n),
            at(-3.6 * width, -n),
        ];
        self.stroke_ring(&head, 1.0);
    }

    /// Whether a label box at `b` is inside the area, clear of the labels
    /// placed and of every stroke.
    fn free(&self, b: &[f64; 4]) -> bool {
        let inside = b[0] >= AREA.0 && b[2] <= AREA.2 && b[1] >= AREA.1 && b[3] <= AREA.3;
        inside
            && !self.placed.iter().any(|o| overlap(o, b))
            && !self.strokes.iter().any(|s| touches(b, s))
    }

    /// The first free place for a label of `size` with `anchor` near one of
    /// the anchors `at` (in order): there, else nudged 22, 44 or 66 px in
    /// one of eight directions.
    fn place(&self, at: &[P], size: f64, anchor: &str, text: &str) -> Option<(P, [f64; 4])> {
        at.iter()
            .find_map(|at| self.place_near(*at, size, anchor, text))
    }

    fn place_near(&self, at: P, size: f64, anchor: &str, text: &str) -> Option<(P, [f64; 4])> {
        let mut candidates = vec![at];
        for r in [22.0, 44.0, 66.0] {
            for (dx, dy) in [
                (0.0, -1.0),
                (0.0, 1.0),
                (1.0, 0.0),
                (-1.0, 0.0),
                (1.0, -1.0),
                (-1.0, -1.0),
                (1.0, 1.0),
                (-1.0, 1.0),
            ] {
                candidates.push([at[0] + r * dx, at[1] + r * dy]);
            }
        }
        candidates.into_iter().find_map(|p| {
            let b = label_box(p, size, anchor, text);
            self.free(&b).then_some((p, b))
        })
    }

    /// Writes the pending labels, the contact point's and the centres' first,
    /// then the normal, the impulse, velocities, arms, names: each at the
    /// first free place near it ([`Page::place`]). A label with no free
    /// place goes to the legend ([`Page::moved`]), and a numbered marker
    /// takes its place where one fits.
    pub fn place_labels(&mut self) {
        let rank = |t: &str| match t.chars().next() {
            Some('q') => 0,
            Some('p') => 1,
            Some('d') => 2,
            Some('g') | Some('−') | Some('-') => 3,
            Some('v') | Some('ω') => 4,
            Some('r') => 5,
            _ => 6,
        };
        let mut pending = std::mem::take(&mut self.pending);
        pending.sort_by_key(|l| rank(&l.text));
        for l in pending {
            let anchors: Vec<P> = std::iter::once(l.at).chain(l.elsewhere).collect();
            if let Some((p, b)) = self.place(&anchors, l.size, &l.anchor, &l.text) {
                self.placed.push(b);
                self.text(p, l.size, &l.anchor, &l.weight, &l.fill, &l.text);
                continue;
            }
            let mark = marker(self.moved.len() + 1);
            let spot = self.place(&anchors, 16.0, "middle", &mark);
            if let Some((p, b)) = spot {
                self.placed.push(b);
                self.text(p, 16.0, "middle", "bold", &l.fill, &mark);
            }
            self.moved
                .push((spot.map(|_| mark), l.text.clone(), l.fill.clone()));
        }
    }
}
