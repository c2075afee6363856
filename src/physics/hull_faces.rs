//! Polygon faces of a hull: neighbouring triangles in one plane (normals
//! within 1e-9, every vertex within ε of the plane) merged, their boundary
//! chained counter-clockwise, vertices on a straight stretch of it dropped.

use nalgebra::Vector3;

/// A polygon face: vertex indices counter-clockwise seen from outside, the
/// unit outward normal, and the plane offset (n·x = offset on the face).
#[derive(Debug, Clone, PartialEq)]
pub struct HullFace {
    pub vertices: Vec<usize>,
    pub normal: Vector3<f64>,
    pub offset: f64,
}

/// Groups `triangles` (counter-clockwise from outside, unit `normals`) into
/// polygon faces.
pub(super) fn merge(
    vertices: &[Vector3<f64>],
    triangles: &[[usize; 3]],
    normals: &[Vector3<f64>],
    eps: f64,
) -> Vec<HullFace> {
    let edges_of = |t: &[usize; 3]| [[t[0], t[1]], [t[1], t[2]], [t[2], t[0]]];
    let mut group = vec![usize::MAX; triangles.len()];
    let mut faces = Vec::new();
    for seed in 0..triangles.len() {
        if group[seed] != usize::MAX {
            continue;
        }
        let id = faces.len();
        let n = normals[seed];
        let offset = n.dot(&vertices[triangles[seed][0]]);
        let coplanar = |t: usize| {
            normals[t].dot(&n) > 1.0 - 1e-9
                && triangles[t]
                    .iter()
                    .all(|&i| (n.dot(&vertices[i]) - offset).abs() <= eps)
        };
        // Flood fill over shared edges.
        let mut members = vec![seed];
        group[seed] = id;
        let mut k = 0;
        while k < members.len() {
            let t = members[k];
            k += 1;
            for [a, b] in edges_of(&triangles[t]) {
                for (u, other) in triangles.iter().enumerate() {
                    if group[u] == usize::MAX && edges_of(other).contains(&[b, a]) && coplanar(u) {
                        group[u] = id;
                        members.push(u);
                    }
                }
            }
        }
        let boundary: Vec<[usize; 2]> = {
            let all: Vec<[usize; 2]> = members
                .iter()
                .flat_map(|&t| edges_of(&triangles[t]))
                .collect();
            all.iter()
                .copied()
                .filter(|&[a, b]| !all.contains(&[b, a]))
                .collect()
        };
        let ring = chain(&boundary);
        let ring = drop_straight(vertices, &ring, eps);
        // The normal of the whole polygon (Newell), more accurate than one triangle's.
        let normal = newell(vertices, &ring).unwrap_or(n);
        let offset =
            ring.iter().map(|&i| normal.dot(&vertices[i])).sum::<f64>() / ring.len() as f64;
        faces.push(HullFace {
            vertices: ring,
            normal,
            offset,
        });
    }
    faces
}

/// The boundary edges `a → b` followed from one to the next into a loop.
fn chain(boundary: &[[usize; 2]]) -> Vec<usize> {
    let mut ring = vec![boundary[0][0]];
    let mut at = boundary[0][1];
    while at != ring[0] && ring.len() <= boundary.len() {
        ring.push(at);
        match boundary.iter().find(|e| e[0] == at) {
            Some(e) => at = e[1],
            None => break,
        }
    }
    ring
}

/// Drops vertices within `eps` of the line through their neighbours.
fn drop_straight(vertices: &[Vector3<f64>], ring: &[usize], eps: f64) -> Vec<usize> {
    let mut out: Vec<usize> = ring.to_vec();
    let mut k = 0;
    while out.len() > 3 && k < out.len() {
        let n = out.len();
        let (p, q, r) = (
            vertices[out[(k + n - 1) % n]],
            vertices[out[k]],
            vertices[out[(k + 1) % n]],
        );
        let line = r - p;
        let off = (q - p).cross(&line).norm() / line.norm();
        if off <= eps {
            out.remove(k);
        } else {
            k += 1;
        }
    }
    out
}

/// Newell's polygon normal: Σ (p_i × p_{i+1}), normalised.
fn newell(vertices: &[Vector3<f64>], ring: &[usize]) -> Option<Vector3<f64>> {
    let n = ring.len();
    let sum: Vector3<f64> = (0..n)
        .map(|k| vertices[ring[k]].cross(&vertices[ring[(k + 1) % n]]))
        .sum();
    sum.try_normalize(0.0)
}
