//! The lectures' picture of one pair's narrow phase, in the view plane: the
//! Minkowski difference A − B projected on the plane through the origin
//! (its outline w(d) = s_A(d) − s_B(−d) for d in the plane), and at a stop
//! of GJK or EPA the simplex (or EPA's closest face), the support point
//! w_k, the closest point v_k, the search direction d_k and the origin.
//! Geometry only, in plane coordinates: the `detect --figure` SVG and the
//! TUI's detection screen both draw it.

use super::steps::{stops, Stop};
use crate::render::figure::{hull, P};
use crate::trace::detect::{PairTrace, V3};
use crate::trace::Plane;

/// What the picture holds at one stop (or at the result).
#[derive(Debug, Clone, PartialEq)]
pub struct Minkowski {
    /// A − B's outline, counter-clockwise (empty: a half-space has none).
    pub hull: Vec<P>,
    /// GJK's simplex with w_k added, or EPA's face closest to the origin.
    pub simplex: Vec<P>,
    /// Which of `simplex` GJK's sub-algorithm dropped (✗).
    pub dropped: Vec<usize>,
    /// w_k, the support point of the stop.
    pub support: Option<P>,
    /// v_k: the point GJK's iteration starts from (d_k = −v_k); EPA's
    /// δ_k n_k, the closest face's point nearest the origin.
    pub closest: Option<P>,
    /// GJK's v_{k+1}: the closest point of the simplex with w_k added and
    /// reduced (`None` at EPA's stops and where GJK stopped at the bound).
    pub next: Option<P>,
    /// The tip of d_k drawn from the origin (a third of the picture's size;
    /// `None` when d_k is seen end-on).
    pub direction: Option<P>,
    /// At the result: −δn (EPA: the penetration vector) or v (GJK: the
    /// distance), from the origin, and its label.
    pub arrow: Option<(P, &'static str)>,
}

impl Minkowski {
    /// The simplex's edges (every pair of its points, as the lectures draw
    /// a segment, triangle or tetrahedron).
    pub fn edges(&self) -> Vec<[P; 2]> {
        let s = &self.simplex;
        (0..s.len())
            .flat_map(|i| (i + 1..s.len()).map(move |j| [s[i], s[j]]))
            .collect()
    }

    /// Every point the picture shows, with the origin: what a view fits.
    pub fn points(&self) -> Vec<P> {
        let mut out: Vec<P> = self.hull.iter().chain(&self.simplex).copied().collect();
        out.extend(self.support);
        out.extend(self.closest);
        out.extend(self.next);
        out.extend(self.direction);
        out.extend(self.arrow.map(|(p, _)| p));
        out.push([0.0, 0.0]);
        out
    }
}

/// Pair `p`'s picture in `plane` at stop `stop` (an index into
/// [`stops`]); past the stops, the result: the last simplex or face and
/// the penetration vector or the distance.
pub fn minkowski(plane: Plane, p: &PairTrace, stop: usize) -> Minkowski {
    let (u, w, _) = plane.axes();
    let flat = |x: &V3| -> P { [x[u], x[w]] };
    let outline = if p.minkowski.is_empty() {
        vec![]
    } else {
        hull(p.minkowski.iter().map(flat).collect())
    };
    let mut m = Minkowski {
        hull: outline,
        simplex: vec![],
        dropped: vec![],
        support: None,
        closest: None,
        next: None,
        direction: None,
        arrow: None,
    };
    match stops(p).get(stop) {
        // A mesh's tree and triangles: no single A - B to mark.
        Some(Stop::Node(_) | Stop::Triangle(_)) => {}
        Some(Stop::Gjk(k)) => {
            let Some(it) = p.gjk.as_ref().and_then(|g| g.iterations.get(*k)) else {
                return m;
            };
            m.simplex = it.simplex.iter().map(flat).collect();
            m.dropped = (0..it.simplex.len())
                .filter(|i| !it.kept.contains(i))
                .collect();
            m.support = Some(flat(&it.support));
            m.closest = Some(flat(&it.v));
            m.next = it.next.as_ref().map(flat);
            m.direction = tip(&m, flat(&it.direction), norm(&it.direction));
        }
        Some(Stop::Epa(k)) => {
            let Some(it) = p.epa.as_ref().and_then(|e| e.iterations.get(*k)) else {
                return m;
            };
            m.simplex = it.face.iter().map(flat).collect();
            m.support = Some(flat(&it.support));
            let n = flat(&it.normal);
            m.closest = Some([n[0] * it.distance, n[1] * it.distance]);
            // EPA searches along the closest face's normal: d_k = n_k.
            m.direction = tip(&m, n, norm(&it.normal));
        }
        None => {
            // As the figure has always drawn the result: EPA's last face
            // (GJK's last simplex when EPA did not run), and −δn or v.
            m.simplex = match (&p.epa, &p.gjk) {
                (Some(e), _) if !e.iterations.is_empty() => e
                    .iterations
                    .last()
                    .map(|it| it.face.iter().map(flat).collect())
                    .unwrap_or_default(),
                (_, Some(g)) => g
                    .iterations
                    .last()
                    .map(|it| it.simplex.iter().map(flat).collect())
                    .unwrap_or_default(),
                _ => vec![],
            };
            m.arrow = if let Some(e) = &p.epa {
                let n = flat(&e.normal);
                Some(([-n[0] * e.depth, -n[1] * e.depth], "-δn"))
            } else {
                p.gjk
                    .as_ref()
                    .and_then(|g| g.iterations.last())
                    .map(|it| (flat(&it.next.unwrap_or(it.v)), "v"))
            };
        }
    }
    m
}

fn norm(v: &V3) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// The tip of direction `d` (seen in the plane; `full`: its length in
/// space) drawn from the origin, a third of the size of what the picture
/// already holds; `None` for a direction seen end-on.
fn tip(m: &Minkowski, d: P, full: f64) -> Option<P> {
    let pts = m.points();
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in pts.iter().filter(|p| p[0].is_finite() && p[1].is_finite()) {
        lo = [lo[0].min(p[0]), lo[1].min(p[1])];
        hi = [hi[0].max(p[0]), hi[1].max(p[1])];
    }
    let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let len = d[0].hypot(d[1]);
    // End-on: what is left in the plane is round-off of the direction.
    if !(size > 0.0 && size.is_finite() && len.is_finite()) || len <= 1e-9 * full {
        return None;
    }
    Some([d[0] / len * size / 3.0, d[1] / len * size / 3.0])
}
