//! Issue 39's huge hull: 100,000 points on a sphere took 168 s to build
//! (every point tested against every face, O(n·F)). The build now keeps one
//! face each waiting point sees; its work, counted in plane tests, on 20,000
//! points on a sphere (all of them vertices) stays below 100·n·log₂ n (the
//! order, farthest from the first tetrahedron's centre first, sweeps the
//! sphere rather than visiting it at random, so the work grows faster than
//! n log n). The old build's was about n·F/2 ≈ 4·10⁸ there, 14 times the bound.

use contact_lab::physics::hull::ConvexHull;

/// 20,000 points on the unit sphere (a deterministic xorshift).
fn sphere(n: usize) -> Vec<[f64; 3]> {
    let mut s = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    };
    (0..n)
        .map(|_| {
            let p = [next(), next(), next()];
            let r = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
            p.map(|x| x / r)
        })
        .collect()
}

#[test]
fn a_sphere_of_20000_points_builds_in_a_bounded_number_of_plane_tests() {
    let n = 20_000;
    let points = sphere(n);
    let tests = ConvexHull::plane_tests(&points).unwrap();
    let bound = 100.0 * n as f64 * (n as f64).log2();
    assert!(
        (tests as f64) < bound,
        "{tests} plane tests, above 100·n·log2 n = {bound:.0}"
    );
    assert!(ConvexHull::new(&points).unwrap().vertices().len() > 19_900);
}
