//! Every identifier name of this folder in one place: the JSON and trace
//! names of the feature kinds and pairs, GJK's ends and verdicts, EPA's ends.

use super::epa::EpaEnd;
use super::features::{FeatureKind, FeaturePair};
use super::gjk::{GjkEnd, GjkVerdict};

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
