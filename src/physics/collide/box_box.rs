//! Box–box contact by the separating axis test on 15 axes (3 face axes of
//! each box, 9 edge cross products), as the reference engine's `boxAndBox`;
//! one contact (single mode) or the clipped face manifold.

use nalgebra::Vector3;

use super::clip::{clip_incident, manifold, Polygon, Reference};
use super::{c, vertex, BoxBoxMode, ContactPoint, Feature, Pose, Real, Side};

/// The axis of least overlap.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Axis {
    FaceA(usize),
    FaceB(usize),
    /// Edge of A along axis i crossed with an edge of B along axis j.
    Edge(usize, usize),
}

/// Result of the separating axis test for overlapping boxes.
#[derive(Debug, Clone, Copy)]
pub(super) struct Overlap<T: Real> {
    pub axis: Axis,
    /// Unit axis oriented from B toward A.
    pub normal: Vector3<T>,
    /// Overlap of the two projections on the axis: r_A + r_B - |d·L|.
    pub depth: T,
}

/// Edge pairs with |a_i × b_j|² below this are (nearly) parallel: their cross
/// product is no reliable axis, and the face axes already cover them.
const PARALLEL_SQUARED: f64 = 1e-6;
/// An edge axis replaces the best face axis only when shallower by 5 % (plus
/// a round-off margin), so that resting faces keep face contacts.
const EDGE_BIAS: f64 = 0.95;

/// Separating axis test: `None` when an axis separates the boxes by more than
/// `tol`, else the axis of least overlap (face axes preferred, A's first).
///
/// On a unit axis L the boxes overlap by r_A + r_B - |d·L|, with
/// r = Σ h_k |axis_k·L| and d = x_A - x_B. Everything is taken in A's frame,
/// where A's axes are e_i, B's axes the columns of C = AᵀB and d is t = Aᵀd
/// (Gottschalk's OBB test; Ericson, Real-Time Collision Detection, 4.4.1).
pub(super) fn separating_axis<T: Real>(
    ha: &Vector3<T>,
    pa: &Pose<T>,
    hb: &Vector3<T>,
    pb: &Pose<T>,
    tol: T,
) -> Option<Overlap<T>> {
    let d = pa.position - pb.position;
    let rot = pa.rotation.tr_mul(&pb.rotation);
    let abs = rot.abs();
    let t = pa.rotation.tr_mul(&d);
    let mut best: Option<(Axis, T)> = None;
    let mut keep = |axis: Axis, depth: T| {
        if best.is_none_or(|(_, least)| depth < least) {
            best = Some((axis, depth));
        }
        depth >= -tol
    };
    for i in 0..3 {
        // L = A's axis i: r_A = h_A,i, r_B = Σ_k h_B,k |C_ik|, d·L = t_i.
        let rb = hb.dot(&abs.row(i).transpose());
        if !keep(Axis::FaceA(i), ha[i] + rb - t[i].abs()) {
            return None;
        }
    }
    for j in 0..3 {
        // L = B's axis j: r_A = Σ_k h_A,k |C_kj|, r_B = h_B,j, d·L = t·C_j.
        let ra = ha.dot(&abs.column(j));
        if !keep(Axis::FaceB(j), ra + hb[j] - t.dot(&rot.column(j)).abs()) {
            return None;
        }
    }
    let face = best?;
    best = None;
    let mut keep = |axis: Axis, depth: T| {
        if best.is_none_or(|(_, least)| depth < least) {
            best = Some((axis, depth));
        }
        depth >= -tol
    };
    for i in 0..3 {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        for j in 0..3 {
            let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
            // L = e_i × C_j, |L|² = C_i1j² + C_i2j²: skip (nearly) parallel edges.
            let length_squared = rot[(i1, j)] * rot[(i1, j)] + rot[(i2, j)] * rot[(i2, j)];
            if length_squared < c::<T>(PARALLEL_SQUARED) {
                continue;
            }
            // Unnormalised: r_A = h_A,i1 |C_i2j| + h_A,i2 |C_i1j|,
            // r_B = h_B,j1 |C_ij2| + h_B,j2 |C_ij1|, d·L = t_i2 C_i1j - t_i1 C_i2j.
            let ra = ha[i1] * abs[(i2, j)] + ha[i2] * abs[(i1, j)];
            let rb = hb[j1] * abs[(i, j2)] + hb[j2] * abs[(i, j1)];
            let dl = t[i2] * rot[(i1, j)] - t[i1] * rot[(i2, j)];
            if !keep(
                Axis::Edge(i, j),
                (ra + rb - dl.abs()) / length_squared.sqrt(),
            ) {
                return None;
            }
        }
    }
    let (mut axis, mut depth) = face;
    if let Some((edge_axis, edge_depth)) = best {
        // Round-off margin: 64 ulps of the boxes' size.
        let size = ha.amax().max(hb.amax());
        let margin = size * T::default_epsilon() * c::<T>(64.0);
        if edge_depth < depth - (T::one() - c::<T>(EDGE_BIAS)) * depth.abs() - margin {
            (axis, depth) = (edge_axis, edge_depth);
        }
    }
    let l = match axis {
        Axis::FaceA(i) => pa.axis(i),
        Axis::FaceB(j) => pb.axis(j),
        Axis::Edge(i, j) => pa.axis(i).cross(&pb.axis(j)).normalize(),
    };
    let normal = if d.dot(&l) < T::zero() { -l } else { l };
    Some(Overlap {
        axis,
        normal,
        depth,
    })
}

/// Box A (half sides `ha`) against box B (`hb`).
pub(super) fn box_box<T: Real>(
    ha: &Vector3<T>,
    pa: &Pose<T>,
    hb: &Vector3<T>,
    pb: &Pose<T>,
    mode: BoxBoxMode,
    tol: T,
    out: &mut Vec<ContactPoint<T>>,
) {
    let Some(overlap) = separating_axis(ha, pa, hb, pb, tol) else {
        return;
    };
    // Reference face: its box, the other (incident) box, and the face's
    // outward normal, which points from the reference box toward the other.
    let (reference, incident, hi) = match overlap.axis {
        Axis::Edge(i, j) => {
            out.push(edge_edge(ha, pa, i, hb, pb, j, &overlap));
            return;
        }
        Axis::FaceA(i) => (face(ha, pa, i, -overlap.normal, Side::A), pb, hb),
        Axis::FaceB(j) => (face(hb, pb, j, overlap.normal, Side::B), pa, ha),
    };
    if mode == BoxBoxMode::Manifold {
        let mut polygon = Polygon::new();
        clip_incident(&reference, incident, hi, &mut polygon);
        if manifold(&reference, &polygon, &overlap.normal, tol, out) > 0 {
            return;
        }
    }
    out.push(point_face(&reference, incident, hi, &overlap));
}

fn face<'a, T: Real>(
    h: &'a Vector3<T>,
    pose: &'a Pose<T>,
    axis: usize,
    outward: Vector3<T>,
    side: Side,
) -> Reference<'a, T> {
    let sign = if pose.axis(axis).dot(&outward) < T::zero() {
        -T::one()
    } else {
        T::one()
    };
    Reference {
        pose,
        h,
        axis,
        sign,
        side,
    }
}

/// Single mode, face axis: the incident box's vertex deepest through the
/// reference face (its support point against the outward normal), midway
/// between it and the face, with the overlap on the axis as penetration.
/// The reference engine takes that vertex even when it lies beside the face
/// (an edge across the face, or a box hanging over the face's edge); then the
/// deepest point of the clipped incident face is taken instead.
fn point_face<T: Real>(
    reference: &Reference<'_, T>,
    incident: &Pose<T>,
    hi: &Vector3<T>,
    overlap: &Overlap<T>,
) -> ContactPoint<T> {
    let outward = reference.pose.axis(reference.axis) * reference.sign;
    // Bit k set (+h_k) unless axis k points along the outward normal.
    let index = (0..3).fold(0u8, |bits, k| {
        let plus = incident.axis(k).dot(&outward) <= T::zero();
        bits | (u8::from(plus) << k)
    });
    let local = reference
        .pose
        .to_local(&incident.to_world(&vertex(hi, index)));
    let slack = reference.h.amax() * T::default_epsilon() * c::<T>(4096.0);
    let beside = (0..3)
        .filter(|&k| k != reference.axis)
        .any(|k| local[k].abs() > reference.h[k] + slack);
    let deepest = if beside {
        let mut polygon = Polygon::new();
        clip_incident(reference, incident, hi, &mut polygon);
        let depth = |p: &&Vector3<T>| reference.depth(p);
        let inside = polygon.iter().filter(|p| reference.holds(p, T::zero()));
        inside
            .reduce(|best, p| if depth(&p) > depth(&best) { p } else { best })
            .copied()
    } else {
        None
    };
    if let Some(p) = deepest {
        return reference.contact(&p, &overlap.normal, overlap.depth);
    }
    // The face is `depth` beyond the vertex along the outward normal.
    let mut mid = local;
    mid[reference.axis] += reference.sign * overlap.depth * c::<T>(0.5);
    ContactPoint {
        point: reference.pose.to_world(&mid),
        normal: overlap.normal,
        penetration: overlap.depth,
        feature: Feature::VertexFace {
            face: reference.side,
            axis: reference.axis as u8,
            vertex: index,
        },
    }
}

/// Edge–edge: A's edge along axis i nearest B and B's edge along axis j
/// nearest A; the contact point is midway between their closest points.
fn edge_edge<T: Real>(
    ha: &Vector3<T>,
    pa: &Pose<T>,
    i: usize,
    hb: &Vector3<T>,
    pb: &Pose<T>,
    j: usize,
    overlap: &Overlap<T>,
) -> ContactPoint<T> {
    let n = overlap.normal;
    // Midpoint of a box's edge along `axis`, on the box's side toward `towards`.
    let edge_middle = |h: &Vector3<T>, pose: &Pose<T>, axis: usize, towards: Vector3<T>| {
        let local = Vector3::from_fn(|k, _| match k {
            k if k == axis => T::zero(),
            k if pose.axis(k).dot(&towards) < T::zero() => -h[k],
            k => h[k],
        });
        pose.to_world(&local)
    };
    let (ma, mb) = (edge_middle(ha, pa, i, -n), edge_middle(hb, pb, j, n));
    let (da, db) = (pa.axis(i), pb.axis(j));
    // Closest points ma + s·da, mb + t·db of the two segments (lines first,
    // then clamped to the edges): s = (e f - a·r)/(1 - e²), t = f + s e with
    // r = ma - mb, e = da·db, f = db·r.
    let r = ma - mb;
    let (e, f, g) = (da.dot(&db), db.dot(&r), da.dot(&r));
    let clamp = |x: T, h: T| x.max(-h).min(h);
    let s = clamp((e * f - g) / (T::one() - e * e), ha[i]);
    let t = clamp(f + s * e, hb[j]);
    let s = clamp(t * e - g, ha[i]);
    let (on_a, on_b) = (ma + da * s, mb + db * t);
    ContactPoint {
        point: (on_a + on_b) * c::<T>(0.5),
        normal: n,
        penetration: overlap.depth,
        feature: Feature::EdgeEdge {
            axis_a: i as u8,
            axis_b: j as u8,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::UnitQuaternion;
    use std::f64::consts::{FRAC_PI_4, SQRT_2};

    /// Unit cubes: A turned 45° about x (bottom edge along x) above B turned
    /// 45° about z (top edge along z), the edges `e` deep.
    fn crossing(e: f64) -> Option<Overlap<f64>> {
        let a = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), FRAC_PI_4);
        let b = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), FRAC_PI_4);
        let h = Vector3::repeat(0.5);
        let pa = Pose::from_unit(Vector3::new(0.0, SQRT_2 - e, 0.0), &a);
        let pb = Pose::from_unit(Vector3::zeros(), &b);
        separating_axis(&h, &pa, &h, &pb, 0.0)
    }

    #[test]
    fn an_edge_axis_wins_only_when_clearly_shallower_than_the_best_face() {
        // Overlap on the best face axis (A's y): √2/4 + e·√2/2; on x × z: e.
        let face = |e: f64| SQRT_2 / 4.0 + e * SQRT_2 / 2.0;
        let deep = crossing(1.0).unwrap();
        assert_eq!(deep.axis, Axis::Edge(0, 2));
        assert!((deep.depth - 1.0).abs() < 1e-12 && 1.0 < 0.95 * face(1.0));
        // At e = 1.1 the edge axis is still the shallower (1.1 < 1.131), but
        // by less than 5 %: the face axis is kept, as for resting faces.
        let deeper = crossing(1.1).unwrap();
        assert_eq!(deeper.axis, Axis::FaceA(1));
        assert!((deeper.depth - face(1.1)).abs() < 1e-12);
        assert!((deeper.normal - Vector3::new(0.0, 1.0, 1.0).normalize()).norm() < 1e-12);
    }

    #[test]
    fn separated_by_an_edge_axis_alone() {
        assert!(crossing(-1e-9).is_none());
        assert_eq!(crossing(1e-9).unwrap().axis, Axis::Edge(0, 2));
    }

    #[test]
    fn parallel_edges_are_skipped_and_aligned_boxes_meet_on_a_face() {
        // Axis-aligned: every cross product is zero or a face axis.
        let h: Vector3<f64> = Vector3::new(1.0, 0.5, 2.0);
        let pa = Pose::at(Vector3::new(0.3, 0.0, 0.0));
        let pb = Pose::at(Vector3::new(0.0, 0.9, 0.1));
        let overlap = separating_axis(&h, &pa, &h, &pb, 0.0).unwrap();
        assert_eq!(overlap.axis, Axis::FaceA(1));
        assert_eq!(overlap.normal, -Vector3::y());
        assert!((overlap.depth - 0.1).abs() < 1e-15);
    }
}
