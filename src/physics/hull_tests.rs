//! The conflict build against its twin, the build it replaced (every point
//! tested against every triangle, the horizon by a search of the visible
//! edges): the same triangles in the same order on random clouds and on
//! spheres. (On grids on a box's faces with noise about ε the old build did
//! not end in a minute in debug; no comparison there.)

use nalgebra::Vector3;

use super::{build, extent_eps, start, tri, HullError, Tri};

/// The old build: O(n·F).
fn build_twin(pts: &[Vector3<f64>], eps: f64) -> Result<(Vec<Tri>, usize), HullError> {
    let (mut tris, order) = start(pts, eps)?;
    let mut tests = 0;
    let mut edges: Vec<[usize; 2]> = Vec::new();
    for i in order {
        let p = pts[i];
        tests += tris.len();
        if tris.iter().all(|t| t.n.dot(&p) - t.d <= eps) {
            continue;
        }
        edges.clear();
        tris.retain(|t| {
            let visible = t.n.dot(&p) - t.d > eps;
            if visible {
                edges.extend([[t.v[0], t.v[1]], [t.v[1], t.v[2]], [t.v[2], t.v[0]]]);
            }
            !visible
        });
        for &[a, b] in &edges {
            if !edges.contains(&[b, a]) {
                tris.push(tri(pts, [a, b, i]));
            }
        }
    }
    Ok((tris, tests))
}

/// A small deterministic generator (xorshift), values in [-1, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

fn same(pts: &[Vector3<f64>]) {
    let eps = extent_eps(pts);
    let (new, _) = build(pts, eps).unwrap();
    let (old, _) = build_twin(pts, eps).unwrap();
    let v = |t: &[Tri]| t.iter().map(|t| t.v).collect::<Vec<_>>();
    assert_eq!(v(&new), v(&old));
}

#[test]
fn random_clouds_give_the_old_hull() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for n in [4, 5, 8, 20, 100, 500] {
        for _ in 0..20 {
            let pts: Vec<_> = (0..n)
                .map(|_| Vector3::new(rng.next(), rng.next(), rng.next()))
                .collect();
            same(&pts);
        }
    }
}

#[test]
fn spheres_give_the_old_hull() {
    let mut rng = Rng(12345);
    for n in [50, 300, 1000] {
        let pts: Vec<_> = (0..n)
            .map(|_| Vector3::new(rng.next(), rng.next(), rng.next()).normalize())
            .collect();
        same(&pts);
    }
}

#[test]
fn the_work_is_far_below_the_old_builds_on_a_sphere() {
    let mut rng = Rng(4242);
    let pts: Vec<_> = (0..2000)
        .map(|_| Vector3::new(rng.next(), rng.next(), rng.next()).normalize())
        .collect();
    let eps = extent_eps(&pts);
    let (_, new) = build(&pts, eps).unwrap();
    let (_, old) = build_twin(&pts, eps).unwrap();
    assert!(new * 5 < old, "{new} plane tests against the old {old}");
}
