//! One narrow-phase query: GJK on the cores; separated shapes end there;
//! shapes whose cores are apart but margins overlap (spheres, capsules) get
//! their penetration from the cores, δ = m_A + m_B − |v| along v̂ (exact);
//! shapes whose cores overlap run GJK again on the whole shapes and EPA
//! from its terminal simplex.

use nalgebra::Vector3;

use super::epa::{epa, EpaObserver, EpaOptions, EpaResult};
use super::features::{feature_of, FeaturePair};
use super::gjk::{gjk, GjkObserver, GjkOptions, GjkResult, GjkVerdict};
use super::support::Support;
use crate::physics::collide::Pose;
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
    /// EPA on the whole shapes.
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
    let whole = if options.gjk.use_margins
        && (first.margins[0] > T::zero() || first.margins[1] > T::zero())
    {
        let options = GjkOptions {
            use_margins: false,
            ..options.gjk
        };
        gjk(a, pose_a, b, pose_b, &options, gjk_observer)
    } else {
        first
    };
    let found = epa(
        a,
        pose_a,
        b,
        pose_b,
        &whole.simplex,
        &options.epa,
        epa_observer,
    );
    Query {
        gjk: whole,
        epa: Some(found),
        penetration: Some(Penetration {
            depth: found.depth,
            normal: found.normal,
            point_a: found.point_a,
            point_b: found.point_b,
            point: found.point,
            feature: found.feature,
            source: PenetrationSource::Epa,
        }),
    }
}
