//! The iteration the detection figure draws on its Minkowski panel: by
//! default the last (EPA's last closest face and the penetration vector
//! -δn, or GJK's last simplex and v), or a chosen GJK or EPA iteration k
//! with its simplex (GJK, dropped points hollow) or closest face (EPA), the
//! support point w_k = s_A(d_k) - s_B(-d_k), the closest point v_k and the
//! search direction d_k (EPA: the face's normal n_k, v_k = δ_k n_k).

use std::fmt::Write;

use super::{arrow, Fit};
use crate::render::figure::P;
use crate::trace::detect::{PairTrace, V3};

/// Which iteration the figure draws (0-based).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shown {
    /// EPA's last iteration when EPA ran, else GJK's last.
    Last,
    Gjk(usize),
    Epa(usize),
}

/// What one iteration puts on the panel.
struct Marks {
    /// The simplex or face, and whether each point was dropped.
    points: Vec<(V3, bool)>,
    w: Option<V3>,
    v: Option<V3>,
    d: Option<V3>,
    caption: Option<String>,
}

fn gjk(p: &PairTrace, k: usize) -> Option<Marks> {
    let g = p.gjk.as_ref()?;
    let it = g.iterations.get(k)?;
    Some(Marks {
        points: it
            .simplex
            .iter()
            .enumerate()
            .map(|(i, x)| (*x, !it.kept.contains(&i)))
            .collect(),
        w: Some(it.support),
        v: Some(it.closest),
        d: Some(it.direction),
        caption: Some(format!(
            "GJK iteration {} of {}: simplex (hollow: dropped), v_k, w_k, d_k",
            k + 1,
            g.iterations.len()
        )),
    })
}

fn epa(p: &PairTrace, k: usize) -> Option<Marks> {
    let e = p.epa.as_ref()?;
    let it = e.iterations.get(k)?;
    let v = it.normal.map(|x| x * it.distance);
    Some(Marks {
        points: it.face.iter().map(|x| (*x, false)).collect(),
        w: Some(it.support),
        v: Some(v),
        d: Some(it.normal),
        caption: Some(format!(
            "EPA iteration {} of {}: closest face, v_k = δ_k n_k, w_k, d_k = n_k",
            k + 1,
            e.iterations.len()
        )),
    })
}

fn marks(p: &PairTrace, shown: Shown) -> Option<Marks> {
    match shown {
        Shown::Gjk(k) => gjk(p, k),
        Shown::Epa(k) => epa(p, k),
        Shown::Last => None,
    }
}

/// How long d_k is drawn: a quarter of the span of `pts` (the panel's
/// points before the marks).
pub(super) fn d_length(pts: &[P]) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in pts.iter().filter(|p| p[0].is_finite() && p[1].is_finite()) {
        lo = [lo[0].min(p[0]), lo[1].min(p[1])];
        hi = [hi[0].max(p[0]), hi[1].max(p[1])];
    }
    let span = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    if span.is_finite() && span > 0.0 {
        0.25 * span
    } else {
        1.0
    }
}

/// d_k's tip, `length` from the origin (`None` for a zero direction).
fn d_tip(d: P, length: f64) -> Option<P> {
    let len = d[0].hypot(d[1]);
    (len > 1e-12).then(|| [d[0] * length / len, d[1] * length / len])
}

/// The points the shown iteration's marks reach, for the panel's fit.
pub(super) fn reach(p: &PairTrace, shown: Shown, flat: &dyn Fn(&V3) -> P, d_length: f64) -> Vec<P> {
    let Some(m) = marks(p, shown) else {
        return vec![];
    };
    let d = m.d.and_then(|d| d_tip(flat(&d), d_length));
    m.points
        .iter()
        .map(|(x, _)| flat(x))
        .chain(m.w.map(|w| flat(&w)))
        .chain(m.v.map(|v| flat(&v)))
        .chain(d)
        .collect()
}

/// Draws the shown iteration on the right panel `f`; `None` when the pair
/// has no such iteration.
pub(super) fn draw(
    out: &mut String,
    f: &Fit,
    p: &PairTrace,
    shown: Shown,
    flat: &dyn Fn(&V3) -> P,
    d_length: f64,
) -> Option<()> {
    if shown == Shown::Last {
        last(out, f, p, flat);
        return Some(());
    }
    let marks = marks(p, shown)?;
    let pts: Vec<(P, bool)> = marks
        .points
        .iter()
        .map(|(x, gone)| (flat(x), *gone))
        .collect();
    simplex(out, f, &pts);
    origin(out, f);
    if let Some(c) = &marks.caption {
        let _ = writeln!(
            out,
            r#"  <text x="{:.1}" y="50" font-size="14">{}</text>"#,
            f.left + 20.0,
            super::xml(c)
        );
    }
    // d_k drawn from the origin, its direction only.
    if let Some(tip) = marks.d.and_then(|d| d_tip(flat(&d), d_length)) {
        arrow(out, f, [0.0, 0.0], tip, "#17becf", "d_k");
    }
    if let Some(v) = marks.v.map(|v| flat(&v)) {
        let (o, tip) = (f.at([0.0, 0.0]), f.at(v));
        if (tip[0] - o[0]).hypot(tip[1] - o[1]) > 8.0 {
            arrow(out, f, [0.0, 0.0], v, "#2ca02c", "v_k");
        } else {
            // v_k at the origin (in this plane): said below O, not over it.
            let _ = writeln!(
                out,
                r##"  <text x="{:.1}" y="{:.1}" font-size="15" fill="#2ca02c">v_k ≈ 0</text>"##,
                o[0] + 8.0,
                o[1] + 20.0
            );
        }
    }
    if let Some(w) = marks.w {
        let c = f.at(flat(&w));
        let _ = writeln!(
            out,
            r##"  <rect x="{:.1}" y="{:.1}" width="10" height="10" fill="#8c564b"/>
  <text x="{:.1}" y="{:.1}" font-size="15" fill="#8c564b">w_k</text>"##,
            c[0] - 5.0,
            c[1] - 5.0,
            c[0] + 8.0,
            c[1] + 16.0
        );
    }
    Some(())
}

/// The simplex's edges and points (hollow: dropped).
fn simplex(out: &mut String, f: &Fit, pts: &[(P, bool)]) {
    for (i, (a, _)) in pts.iter().enumerate() {
        for (b, _) in &pts[i + 1..] {
            let (a, b) = (f.at(*a), f.at(*b));
            let _ = writeln!(
                out,
                r##"  <line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="#ff7f0e" stroke-width="2"/>"##,
                a[0], a[1], b[0], b[1]
            );
        }
    }
    for (a, gone) in pts {
        let c = f.at(*a);
        let fill = if *gone {
            r##"fill="white" stroke="#ff7f0e" stroke-width="2""##
        } else {
            r##"fill="#ff7f0e""##
        };
        let _ = writeln!(
            out,
            r#"  <circle cx="{:.1}" cy="{:.1}" r="4" {fill}/>"#,
            c[0], c[1]
        );
    }
}

/// The last iteration, as the figure drew it before an iteration could be
/// chosen: EPA's last face and -δn, or GJK's last simplex and v.
fn last(out: &mut String, f: &Fit, p: &PairTrace, flat: &dyn Fn(&V3) -> P) {
    let face: Vec<(P, bool)> = match (&p.epa, &p.gjk) {
        (Some(e), _) if !e.iterations.is_empty() => e
            .iterations
            .last()
            .map(|it| it.face.iter().map(|x| (flat(x), false)).collect())
            .unwrap_or_default(),
        (_, Some(g)) => g
            .iterations
            .last()
            .map(|it| it.simplex.iter().map(|x| (flat(x), false)).collect())
            .unwrap_or_default(),
        _ => vec![],
    };
    simplex(out, f, &face);
    origin(out, f);
    if let Some(e) = &p.epa {
        let n = flat(&e.normal);
        // -depth·n: the penetration vector from the origin to the boundary.
        arrow(
            out,
            f,
            [0.0, 0.0],
            [-n[0] * e.depth, -n[1] * e.depth],
            "#2ca02c",
            "-δn",
        );
    } else if let Some(g) = p.gjk.as_ref().and_then(|g| g.iterations.last()) {
        arrow(out, f, [0.0, 0.0], flat(&g.closest), "#2ca02c", "v");
    }
}

/// The origin O.
fn origin(out: &mut String, f: &Fit) {
    let o = f.at([0.0, 0.0]);
    let _ = writeln!(
        out,
        r#"  <circle cx="{:.1}" cy="{:.1}" r="5" fill="black"/>
  <text x="{:.1}" y="{:.1}" font-size="14">O</text>"#,
        o[0],
        o[1],
        o[0] + 8.0,
        o[1] - 8.0
    );
}
