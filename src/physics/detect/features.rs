//! What touched: the feature of each shape spanning EPA's closest face
//! (one distinct support point: a point; two, or three on a line: an edge;
//! three: a face), and every identifier name of this folder in one place.

use nalgebra::Vector3;

use super::epa::EpaEnd;
use super::gjk::{GjkEnd, GjkVerdict};
use crate::physics::Real;

/// A feature of one shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FeatureKind {
    Point,
    Edge,
    Face,
}

/// The features of A and of B that touch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct FeaturePair {
    pub a: FeatureKind,
    pub b: FeatureKind,
}

impl FeatureKind {
    pub fn json_name(self) -> &'static str {
        match self {
            FeatureKind::Point => "point",
            FeatureKind::Edge => "edge",
            FeatureKind::Face => "face",
        }
    }
}

impl FeaturePair {
    /// The pair's name, A's feature first: "point-face", "edge-edge", ….
    pub fn json_name(self) -> &'static str {
        use FeatureKind::*;
        match (self.a, self.b) {
            (Point, Point) => "point-point",
            (Point, Edge) => "point-edge",
            (Point, Face) => "point-face",
            (Edge, Point) => "edge-point",
            (Edge, Edge) => "edge-edge",
            (Edge, Face) => "edge-face",
            (Face, Point) => "face-point",
            (Face, Edge) => "face-edge",
            (Face, Face) => "face-face",
        }
    }
}

impl GjkEnd {
    pub fn json_name(self) -> &'static str {
        match self {
            GjkEnd::Converged => "converged",
            GjkEnd::NoProgress => "no_progress",
            GjkEnd::OriginInside => "origin_inside",
            GjkEnd::Touching => "touching",
            GjkEnd::IterationCap => "iteration_cap",
        }
    }
}

impl GjkVerdict {
    pub fn json_name(self) -> &'static str {
        match self {
            GjkVerdict::Separated => "separated",
            GjkVerdict::Intersecting => "intersecting",
        }
    }
}

impl EpaEnd {
    pub fn json_name(self) -> &'static str {
        match self {
            EpaEnd::Converged => "converged",
            EpaEnd::IterationCap => "iteration_cap",
            EpaEnd::Stalled => "stalled",
            EpaEnd::Degenerate => "degenerate",
        }
    }
}

/// The feature spanned by three support points of one shape: the number of
/// distinct points (within `eps`), three on a line counting as an edge.
pub fn feature_of<T: Real>(p: &[Vector3<T>; 3], eps: T) -> FeatureKind {
    let same = |i: usize, j: usize| (p[i] - p[j]).norm() <= eps;
    let distinct = 1 + usize::from(!same(0, 1)) + usize::from(!same(0, 2) && !same(1, 2));
    match distinct {
        1 => FeatureKind::Point,
        2 => FeatureKind::Edge,
        _ => {
            let area = (p[1] - p[0]).cross(&(p[2] - p[0])).norm();
            let long = (p[1] - p[0])
                .norm()
                .max((p[2] - p[0]).norm())
                .max((p[2] - p[1]).norm());
            if area <= eps * long {
                FeatureKind::Edge
            } else {
                FeatureKind::Face
            }
        }
    }
}

/// The feature pair of a face of A − B whose vertices came from `a` and `b`.
pub fn feature_pair<T: Real>(a: &[Vector3<T>; 3], b: &[Vector3<T>; 3], eps: T) -> FeaturePair {
    FeaturePair {
        a: feature_of(a, eps),
        b: feature_of(b, eps),
    }
}
