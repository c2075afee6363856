//! What touched: the feature of each shape spanning EPA's closest face
//! (one distinct support point: a point; two, or three on a line: an edge;
//! three: a face). Their names are in `names.rs`.

use nalgebra::Vector3;

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
