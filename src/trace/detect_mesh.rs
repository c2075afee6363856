//! A pair with a mesh in the detection's description: the mid phase (the
//! query box, each tree node visited with its box, whether the query box
//! overlaps it and the children pushed; the candidate triangles), each
//! candidate triangle's narrow phase (distance, depth, raw and corrected
//! normal, the rule that changed it), and the least distance. Boxes are in
//! the mesh's body frame (its tree is built there); normals are world
//! vectors from body 2 toward body 1, as every contact's.

use nalgebra::Vector3;

use crate::physics::collide::record::MeshRecord;

pub type V3 = [f64; 3];

/// One node the traversal visited.
#[derive(Debug, Clone, PartialEq)]
pub struct NodeLine {
    pub node: usize,
    pub bounds: [V3; 2],
    pub overlap: bool,
    pub children: Vec<usize>,
    /// The leaf's triangle.
    pub triangle: Option<usize>,
}

/// One candidate triangle's narrow phase.
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleLine {
    pub triangle: usize,
    pub distance: f64,
    pub penetration: f64,
    pub normal: V3,
    pub raw_normal: V3,
    /// The rule that changed the normal (`None`: kept).
    pub rule: Option<&'static str>,
}

/// The mid phase of a pair with a mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct MidPhase {
    /// Which body is the mesh: 1 or 2.
    pub mesh_body: u8,
    /// The other body's box in the mesh's frame (`None` against a
    /// half-space, where the mesh's vertices are tested instead).
    pub query: Option<[V3; 2]>,
    pub nodes: Vec<NodeLine>,
    pub candidates: Vec<usize>,
    pub triangles: Vec<TriangleLine>,
    /// The least distance over the candidates (`None`: no candidate).
    pub distance: Option<f64>,
}

/// The trace of a mesh record.
pub fn mid_phase(m: &MeshRecord) -> MidPhase {
    // Normals from body 2 toward body 1: the record's point from the mesh.
    let sign = if m.mesh_is_body1 { -1.0 } else { 1.0 };
    let w = |x: &Vector3<f64>| v(&(x * sign));
    let Some(q) = &m.query else {
        return MidPhase {
            mesh_body: if m.mesh_is_body1 { 1 } else { 2 },
            query: None,
            nodes: vec![],
            candidates: vec![],
            triangles: vec![],
            distance: None,
        };
    };
    MidPhase {
        mesh_body: if m.mesh_is_body1 { 1 } else { 2 },
        query: Some([v(&q.bounds[0]), v(&q.bounds[1])]),
        nodes: (q.nodes.iter())
            .map(|n| NodeLine {
                node: n.node,
                bounds: [v(&n.bounds[0]), v(&n.bounds[1])],
                overlap: n.overlap,
                children: n.children.clone(),
                triangle: n.triangle,
            })
            .collect(),
        candidates: q.candidates.clone(),
        triangles: (q.triangles.iter())
            .map(|t| TriangleLine {
                triangle: t.triangle,
                distance: t.distance,
                penetration: t.penetration,
                normal: w(&t.normal),
                raw_normal: w(&t.raw_normal),
                rule: t.rule.map(|r| r.json_name()),
            })
            .collect(),
        distance: q.distance.is_finite().then_some(q.distance),
    }
}

fn v(x: &Vector3<f64>) -> V3 {
    [x.x, x.y, x.z]
}
