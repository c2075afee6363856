//! Manifold clipping for box–box: the incident face clipped against the
//! reference face's side planes (Sutherland–Hodgman), the points below the
//! reference face kept, at most 4 of them.
//!
//! Everything runs in the reference box's frame, where the reference face is
//! `x_i = s·h_i` and its side planes are `x_k = ±h_k` for the other two axes.

use nalgebra::Vector3;

use super::{c, ContactPoint, Feature, Pose, Real, Side};

/// A convex polygon of at most 8 points: 4 clipped by 4 planes (each clip
/// adds at most one point to a convex polygon).
#[derive(Debug, Clone, Copy)]
pub(super) struct Polygon<T: Real> {
    pub points: [Vector3<T>; 8],
    pub len: usize,
}

impl<T: Real> Polygon<T> {
    pub fn new() -> Self {
        Polygon {
            points: [Vector3::zeros(); 8],
            len: 0,
        }
    }

    fn push(&mut self, p: Vector3<T>) {
        // A convex polygon never overflows; a rounding-degenerate one drops points.
        if self.len < self.points.len() {
            self.points[self.len] = p;
            self.len += 1;
        }
    }

    pub fn iter(&self) -> impl Iterator<Item = &Vector3<T>> {
        self.points[..self.len].iter()
    }
}

/// The reference face: face `axis` of the box at `pose` with half sides `h`,
/// on the side `sign` (±1) of its centre; `side` says which body it is.
#[derive(Debug, Clone, Copy)]
pub(super) struct Reference<'a, T: Real> {
    pub pose: &'a Pose<T>,
    pub h: &'a Vector3<T>,
    pub axis: usize,
    pub sign: T,
    pub side: Side,
}

impl<T: Real> Reference<'_, T> {
    /// Depth of a reference-frame point below the face: `h_i - s·x_i`.
    pub fn depth(&self, local: &Vector3<T>) -> T {
        self.h[self.axis] - self.sign * local[self.axis]
    }

    /// True for a clipped point (already between the side planes) below the
    /// face by at most `tol` and not beyond the opposite face: in the box.
    pub fn holds(&self, local: &Vector3<T>, tol: T) -> bool {
        let depth = self.depth(local);
        depth >= -tol && depth <= self.h[self.axis] + self.h[self.axis]
    }

    /// The contact at a reference-frame point of the incident face (the
    /// point itself: on the incident box, `depth` inside the reference box).
    pub fn contact(
        &self,
        local: &Vector3<T>,
        normal: &Vector3<T>,
        penetration: T,
    ) -> ContactPoint<T> {
        ContactPoint {
            point: self.pose.to_world(local),
            normal: *normal,
            penetration,
            feature: Feature::FaceFace {
                reference: self.side,
                axis: self.axis as u8,
            },
        }
    }
}

/// The incident box's face most anti-parallel to the reference face, in the
/// reference frame, clipped against the reference face's four side planes,
/// into `polygon`.
pub(super) fn clip_incident<T: Real>(
    reference: &Reference<'_, T>,
    incident: &Pose<T>,
    hi: &Vector3<T>,
    polygon: &mut Polygon<T>,
) {
    // The incident box in the reference frame: its axes are the columns of
    // C = R_refᵀ R_inc, its centre o = R_refᵀ (x_inc - x_ref).
    let rel = reference.pose.rotation.tr_mul(&incident.rotation);
    let origin = reference.pose.to_local(&incident.position);
    // The incident axis most along the reference face's outward normal
    // s·e_i: incident axis k · outward = s·C_ik.
    let dots = rel.row(reference.axis).transpose() * reference.sign;
    let j = dots.iamax();
    // The incident face facing the reference box: its normal against `outward`.
    let face_sign = if dots[j] > T::zero() {
        -T::one()
    } else {
        T::one()
    };
    let (u, v) = ((j + 1) % 3, (j + 2) % 3);
    polygon.len = 0;
    for (su, sv) in [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)] {
        let mut corner = Vector3::zeros();
        corner[j] = face_sign * hi[j];
        corner[u] = c::<T>(su) * hi[u];
        corner[v] = c::<T>(sv) * hi[v];
        polygon.push(origin + rel * corner);
    }
    // The four side planes, the lower axis first, + before -; the polygon
    // and a spare take turns (nothing copied between the clips).
    let (k1, k2) = ((reference.axis + 1) % 3, (reference.axis + 2) % 3);
    let (k1, k2) = (k1.min(k2), k1.max(k2));
    let mut spare = Polygon::new();
    let (mut input, mut output) = (polygon, &mut spare);
    let mut clipped = 0;
    let (plus, minus) = (T::one(), -T::one());
    for (k, s) in [(k1, plus), (k1, minus), (k2, plus), (k2, minus)] {
        let limit = reference.h[k];
        // Every point on the kept side: the clip would copy the polygon as
        // it is (no edge crosses, every point kept in order).
        if input.iter().all(|p| s * p[k] - limit <= T::zero()) {
            continue;
        }
        clip_plane(input, k, s, limit, output);
        std::mem::swap(&mut input, &mut output);
        clipped += 1;
    }
    // An odd number of clips left the result in the spare.
    if clipped % 2 == 1 {
        *output = *input;
    }
}

/// Sutherland–Hodgman against one plane: `output` is the part of `input`
/// where `s·x_k ≤ limit`.
fn clip_plane<T: Real>(input: &Polygon<T>, k: usize, s: T, limit: T, output: &mut Polygon<T>) {
    output.len = 0;
    let points = &input.points[..input.len.min(input.points.len())];
    let Some(&last) = points.last() else {
        return;
    };
    // Each edge p → q, starting with the closing edge last → first; each
    // point's signed distance once.
    let (mut p, mut dp) = (last, s * last[k] - limit);
    for &q in points {
        let dq = s * q[k] - limit;
        if (dp < T::zero() && dq > T::zero()) || (dp > T::zero() && dq < T::zero()) {
            output.push(p + (q - p) * (dp / (dp - dq)));
        }
        if dq <= T::zero() {
            output.push(q);
        }
        (p, dp) = (q, dq);
    }
}

/// Appends the clipped points at most `tol` above the reference face (and not
/// through the box), at most 4 (the deepest, the one farthest from it, then
/// those spanning the largest area), each with its own depth. Returns how
/// many were added.
pub(super) fn manifold<T: Real>(
    reference: &Reference<'_, T>,
    polygon: &Polygon<T>,
    normal: &Vector3<T>,
    tol: T,
    out: &mut Vec<ContactPoint<T>>,
) -> usize {
    // At most 4 points, all held (a face resting on a face): all of them,
    // in order, as the reduction would keep them.
    if polygon.len <= 4 && polygon.iter().all(|p| reference.holds(p, tol)) {
        for p in polygon.iter() {
            out.push(reference.contact(p, normal, reference.depth(p)));
        }
        return polygon.len;
    }
    let mut kept = Polygon::new();
    for p in polygon.iter().filter(|p| reference.holds(p, tol)) {
        kept.push(*p);
    }
    let (u, v) = ((reference.axis + 1) % 3, (reference.axis + 2) % 3);
    let chosen = reduce(&kept, |p| reference.depth(p), u, v);
    for &idx in &chosen.0[..chosen.1] {
        let p = kept.points[idx];
        out.push(reference.contact(&p, normal, reference.depth(&p)));
    }
    chosen.1
}

/// Indices (ascending) of at most 4 of the polygon's points.
fn reduce<T: Real>(
    polygon: &Polygon<T>,
    depth: impl Fn(&Vector3<T>) -> T,
    u: usize,
    v: usize,
) -> ([usize; 4], usize) {
    let n = polygon.len;
    if n <= 4 {
        return ([0, 1, 2, 3], n);
    }
    let pts = &polygon.points[..n];
    // Twice the signed area of the triangle (a, b, p) in the face plane.
    let cross = |a: usize, b: usize, p: usize| {
        let (ab, ap) = (pts[b] - pts[a], pts[p] - pts[a]);
        ab[u] * ap[v] - ab[v] * ap[u]
    };
    // Index of the largest score, first on ties (deterministic).
    let argmax = |score: &dyn Fn(usize) -> T| {
        (1..n).fold(0, |best, k| if score(k) > score(best) { k } else { best })
    };
    let first = argmax(&|k| depth(&pts[k]));
    let second = argmax(&|k| {
        let d = pts[k] - pts[first];
        d[u] * d[u] + d[v] * d[v]
    });
    let third = argmax(&|k| cross(first, second, k).abs());
    // The fourth adds the most area: the triangle areas it sees from outside.
    let turn = cross(first, second, third);
    let added = |k: usize| {
        let edges = [(first, second), (second, third), (third, first)];
        edges.iter().fold(T::zero(), |sum, &(a, b)| {
            let outside = if turn < T::zero() {
                cross(a, b, k)
            } else {
                -cross(a, b, k)
            };
            sum + outside.max(T::zero())
        })
    };
    let fourth = argmax(&added);
    let mut keep = [first, second, third, fourth];
    let count = if added(fourth) > T::zero() { 4 } else { 3 };
    keep[..count].sort_unstable();
    (keep, count)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn polygon(points: &[[f64; 3]]) -> Polygon<f64> {
        let mut p = Polygon::new();
        for q in points {
            p.push(Vector3::from(*q));
        }
        p
    }

    #[test]
    fn sutherland_hodgman_cuts_a_square_corner() {
        let square = polygon(&[
            [1.0, 0.0, 1.0],
            [-1.0, 0.0, 1.0],
            [-1.0, 0.0, -1.0],
            [1.0, 0.0, -1.0],
        ]);
        // Keep x ≤ 0.5: the square loses a strip, 4 points remain.
        let mut cut = Polygon::new();
        clip_plane(&square, 0, 1.0, 0.5, &mut cut);
        assert_eq!(cut.len, 4);
        assert!(cut.iter().all(|p| p.x <= 0.5));
        assert_eq!(cut.iter().filter(|p| p.x == 0.5).count(), 2);
        // Keep -x ≤ 2: untouched, in order.
        clip_plane(&square, 0, -1.0, 2.0, &mut cut);
        assert_eq!(cut.points[..4], square.points[..4]);
        // Keep x ≤ -3: nothing.
        clip_plane(&square, 0, 1.0, -3.0, &mut cut);
        assert_eq!(cut.len, 0);
    }

    #[test]
    fn reduction_keeps_the_deepest_and_the_widest_spread() {
        // An octagon in the xz plane (u = z, v = x for axis y), depths by y.
        let mut pts = Vec::new();
        for k in 0..8 {
            let a = k as f64 * std::f64::consts::FRAC_PI_4;
            pts.push([a.cos(), if k == 5 { 0.1 } else { 0.0 }, a.sin()]);
        }
        let poly = polygon(&pts);
        // Depth = y here: the deepest is point 5.
        let (keep, n) = reduce(&poly, |p| p.y, 2, 0);
        assert_eq!(n, 4);
        assert!(keep[..4].contains(&5));
        // Opposite of 5 is 1; the other two span the most area: 3 and 7.
        assert_eq!(keep, [1, 3, 5, 7]);
    }
}
