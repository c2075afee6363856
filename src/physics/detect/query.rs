//! One narrow-phase query: GJK on the cores; separated shapes end there;
//! shapes whose cores are apart but margins overlap (spheres, capsules) get
//! their penetration from the cores, δ = m_A + m_B − |v| along v̂ (exact);
//! shapes whose cores overlap run EPA on the cores and add the margins
//! (exact too); where both cores are flat (points, segments: spheres and
//! capsules crossing at their cores) the depth is m_A + m_B along a normal
//! of the flat set. Shapes without margins run EPA from GJK's simplex.

use nalgebra::Vector3;

use super::epa::{self, epa, EpaEnd, EpaObserver, EpaOptions, EpaResult};
use super::features::{feature_of, FeaturePair};
use super::gjk::{gjk, GjkObserver, GjkOptions, GjkResult, GjkVerdict, Pair};
use super::support::Support;
use crate::physics::pose::Pose;
use crate::physics::{c, Real};

/// Options of a query.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct QueryOptions<T: Real> {
    pub gjk: GjkOptions<T>,
    pub epa: EpaOptions<T>,
}

/// Where the penetration came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PenetrationSource {
    /// EPA (on the cores, plus the margins, where the shapes have them).
    Epa,
    /// The cores' distance and the margins (sphere, capsule).
    Margins,
}

impl PenetrationSource {
    pub fn json_name(self) -> &'static str {
        match self {
            PenetrationSource::Epa => "epa",
            PenetrationSource::Margins => "margins",
        }
    }
}

/// An overlap: depth ≥ 0 along `normal` (unit, from B toward A), A's
/// deepest point in B, B's in A (point_a = point_b − depth·normal), midway point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Penetration<T: Real> {
    pub depth: T,
    pub normal: Vector3<T>,
    pub point_a: Vector3<T>,
    pub point_b: Vector3<T>,
    pub point: Vector3<T>,
    pub feature: FeaturePair,
    pub source: PenetrationSource,
}

/// The records of a query: GJK's result (of the run EPA started from when
/// the cores overlapped), EPA's when it ran, and the penetration if any.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Query<T: Real> {
    pub gjk: GjkResult<T>,
    pub epa: Option<EpaResult<T>>,
    pub penetration: Option<Penetration<T>>,
}

impl<T: Real> Query<T> {
    pub fn intersecting(&self) -> bool {
        self.gjk.verdict == GjkVerdict::Intersecting
    }
}

/// GJK, then EPA or the margins when the shapes overlap.
pub fn query<T, A, B, G, E>(
    a: &A,
    pose_a: &Pose<T>,
    b: &B,
    pose_b: &Pose<T>,
    options: &QueryOptions<T>,
    gjk_observer: &mut G,
    epa_observer: &mut E,
) -> Query<T>
where
    T: Real,
    A: Support<T> + ?Sized,
    B: Support<T> + ?Sized,
    G: GjkObserver<T> + ?Sized,
    E: EpaObserver<T> + ?Sized,
{
    let first = gjk(a, pose_a, b, pose_b, &options.gjk, gjk_observer);
    if first.verdict == GjkVerdict::Separated {
        return Query {
            gjk: first,
            epa: None,
            penetration: None,
        };
    }
    if first.core_distance > T::zero() {
        let [ma, mb] = first.margins;
        let n = first.v / first.core_distance;
        let (ca, cb) = (first.closest_a, first.closest_b);
        let s = first.simplex.points();
        let pts = |f: &dyn Fn(&super::simplex::Vertex<T>) -> Vector3<T>| {
            [f(&s[0]), f(&s[s.len().min(2) - 1]), f(&s[s.len() - 1])]
        };
        let eps = c::<T>(1e-12) * (first.core_distance + ma + mb);
        let penetration = Penetration {
            depth: ma + mb - first.core_distance,
            normal: n,
            point_a: ca,
            point_b: cb,
            point: (ca + cb) * c::<T>(0.5),
            feature: FeaturePair {
                a: feature_of(&pts(&|p| p.a), eps),
                b: feature_of(&pts(&|p| p.b), eps),
            },
            source: PenetrationSource::Margins,
        };
        return Query {
            gjk: first,
            epa: None,
            penetration: Some(penetration),
        };
    }
    // Cores overlap: EPA on the cores, then the margins on top, exact since
    // A − B = (core_A − core_B) ⊕ ball(m_A + m_B): δ = δ_core + m_A + m_B
    // along the same normal. Two flat cores (points, segments) give EPA no
    // solid: see below.
    let [ma, mb] = first.margins;
    if ma + mb > T::zero() {
        let pair = Pair::new(a, pose_a, b, pose_b, true);
        let found = epa::run(&pair, &first.simplex, &options.epa, epa_observer);
        if found.end != EpaEnd::Degenerate {
            let n = found.normal;
            let point_a = found.point_a - n * ma;
            let point_b = found.point_b + n * mb;
            let depth = found.depth + ma + mb;
            let found = EpaResult {
                depth,
                point_a,
                point_b,
                point: (point_a + point_b) * c::<T>(0.5),
                ..found
            };
            return Query {
                gjk: first,
                epa: Some(found),
                penetration: Some(penetration(&found)),
            };
        }
        // Two flat cores crossing: the origin lies in the flat set F of
        // core_A − core_B, and the depth min_d (h_F(d) + m_A + m_B) is
        // m_A + m_B exactly, along a normal of F's span.
        let n = flat_normal(&pair, &(pose_a.position - pose_b.position));
        let (ca, cb) = (first.closest_a, first.closest_b);
        let point_a = ca - n * ma;
        let point_b = cb + n * mb;
        let flat = EpaResult {
            depth: ma + mb,
            normal: n,
            point_a,
            point_b,
            point: (point_a + point_b) * c::<T>(0.5),
            ..found
        };
        return Query {
            gjk: first,
            epa: Some(flat),
            penetration: Some(penetration(&flat)),
        };
    }
    let found = epa(
        a,
        pose_a,
        b,
        pose_b,
        &first.simplex,
        &options.epa,
        epa_observer,
    );
    Query {
        gjk: first,
        epa: Some(found),
        penetration: Some(penetration(&found)),
    }
}

/// A unit normal of the span of core_A − core_B (a point, a segment or a
/// parallelogram), from its supports along ±x, ±y, ±z, turned toward A.
fn flat_normal<T, A, B>(pair: &Pair<'_, T, A, B>, towards_a: &Vector3<T>) -> Vector3<T>
where
    T: Real,
    A: Support<T> + ?Sized,
    B: Support<T> + ?Sized,
{
    let axes = [Vector3::x(), Vector3::y(), Vector3::z()];
    let pts: Vec<Vector3<T>> = axes
        .iter()
        .flat_map(|d| [pair.vertex(d).w, pair.vertex(&-d).w])
        .collect();
    let size = pts.iter().map(|p| p.norm()).fold(T::zero(), T::max);
    let eps = c::<T>(1e-9) * size;
    let mut e1 = Vector3::zeros();
    for p in &pts {
        for q in &pts {
            if (q - p).norm() > e1.norm() {
                e1 = q - p;
            }
        }
    }
    let n = if e1.norm() <= eps {
        *towards_a
    } else {
        let u = e1.normalize();
        let off = pts
            .iter()
            .map(|p| {
                let r = p - pts[0];
                r - u * u.dot(&r)
            })
            .fold(
                Vector3::zeros(),
                |m, r| if r.norm() > m.norm() { r } else { m },
            );
        if off.norm() > eps {
            u.cross(&off)
        } else {
            u.cross(&axes[u.iamin()])
        }
    };
    let n = n.try_normalize(T::zero()).unwrap_or_else(Vector3::y);
    if n.dot(towards_a) < T::zero() {
        -n
    } else {
        n
    }
}

fn penetration<T: Real>(found: &EpaResult<T>) -> Penetration<T> {
    Penetration {
        depth: found.depth,
        normal: found.normal,
        point_a: found.point_a,
        point_b: found.point_b,
        point: found.point,
        feature: found.feature,
        source: PenetrationSource::Epa,
    }
}
