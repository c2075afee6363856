//! GJK (Gilbert–Johnson–Keerthi, in van den Bergen's distance form): the
//! point v of the Minkowski difference A − B closest to the origin.
//!
//! Iteration k starts from v_k, the simplex's point closest to the origin
//! (v_1: the first support point): search direction d_k = −v_k; support
//! point w_k = s_A(d_k) − s_B(−d_k); stop when |v_k|² − v_k·w_k ≤
//! ε_rel |v_k|² (the lower bound v·w/|v| and the upper bound |v| on the
//! distance agree); otherwise add w_k to the simplex and keep the
//! sub-simplex closest to the origin (signed volumes, [`super::simplex`]),
//! whose closest point is v_{k+1}, where the next iteration starts.
//! The origin inside a tetrahedron, or |v| within ε_touch of the simplex's
//! size, means the shapes intersect. An iteration cap and a no-progress test
//! (v must shrink, w must be new) end every run.
//!
//! The run is on the shapes' cores ([`Support::core_support`]) with their
//! margins added at the end when [`GjkOptions::use_margins`] is set, and in a
//! frame whose origin is B's position (so that two bodies far from the world
//! origin keep their digits); records and results are in world coordinates.

use nalgebra::Vector3;

use super::simplex::{project, Simplex, Vertex};
use super::support::Support;
use crate::physics::pose::Pose;
use crate::physics::{c, Real};

/// Tolerances and caps of a GJK run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GjkOptions<T: Real> {
    /// At most this many support points.
    pub max_iterations: usize,
    /// Stop when |v|² − v·w ≤ this × |v|²: the distance's relative accuracy.
    pub relative_tolerance: T,
    /// |v| at most this × the largest |w| seen counts as touching.
    pub touching_tolerance: T,
    /// Run on the cores (sphere centre, capsule segment) and add the radii.
    pub use_margins: bool,
}

impl<T: Real> Default for GjkOptions<T> {
    fn default() -> Self {
        GjkOptions {
            max_iterations: 128,
            // 1e-12 in f64; a few ulps of the float type where that is coarser (f32).
            relative_tolerance: c::<T>(1e-12).max(T::default_epsilon() * c(8.0)),
            touching_tolerance: c::<T>(1e-12).max(T::default_epsilon() * c(8.0)),
            use_margins: true,
        }
    }
}

/// Why a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GjkEnd {
    /// |v|² − v·w ≤ ε_rel |v|²: v is the closest point to the tolerance.
    Converged,
    /// The support point was already in the simplex, or v did not shrink.
    NoProgress,
    /// The origin lies inside the tetrahedron.
    OriginInside,
    /// |v| within the touching tolerance: the origin is on the simplex.
    Touching,
    /// The iteration cap was reached.
    IterationCap,
}

/// The verdict of a run (margins included).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GjkVerdict {
    Separated,
    Intersecting,
}

impl GjkEnd {
    /// Every reason, in declaration order.
    pub const ALL: [GjkEnd; 5] = [
        GjkEnd::Converged,
        GjkEnd::NoProgress,
        GjkEnd::OriginInside,
        GjkEnd::Touching,
        GjkEnd::IterationCap,
    ];
}

/// One iteration, as the lecture draws it: everything it holds belongs to
/// the same pass of the loop, which starts from `v` (v_k).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GjkIteration<T: Real> {
    pub index: usize,
    /// v_k: the closest point of the simplex the iteration starts from.
    pub v: Vector3<T>,
    /// d_k = −v_k.
    pub direction: Vector3<T>,
    /// w_k with the support points of A (along d_k) and B (along −d_k), world.
    pub support: Vertex<T>,
    /// |v_k|² − v_k·w_k, and the limit ε_rel |v_k|² it is held to.
    pub bound: T,
    pub bound_limit: T,
    /// The simplex w_i with w_k added (1–4 points; unchanged when the run ends here).
    pub simplex: [Vector3<T>; 4],
    pub simplex_len: usize,
    /// Bit i set: point i of `simplex` is kept in the sub-simplex.
    pub kept: u8,
    /// v_{k+1}: the closest point of the kept sub-simplex, where the next
    /// iteration starts; `None` when the run stopped at the bound test
    /// (w_k was not added).
    pub next: Option<Vector3<T>>,
}

/// Observer of a run; every method does nothing by default.
pub trait GjkObserver<T: Real> {
    /// A run starts (a query may run GJK twice: on the cores, then whole).
    fn start(&mut self, _use_margins: bool) {}
    fn iteration(&mut self, _it: &GjkIteration<T>) {}
}

impl<T: Real> GjkObserver<T> for () {}

/// Keeps the iterations of the last run.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct GjkRecorder<T: Real> {
    pub iterations: Vec<GjkIteration<T>>,
    /// How many runs were started (2 when the cores overlapped).
    pub runs: usize,
}

impl<T: Real> GjkObserver<T> for GjkRecorder<T> {
    fn start(&mut self, _use_margins: bool) {
        self.iterations.clear();
        self.runs += 1;
    }
    fn iteration(&mut self, it: &GjkIteration<T>) {
        self.iterations.push(*it);
    }
}

/// The outcome of a run, world coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GjkResult<T: Real> {
    pub verdict: GjkVerdict,
    pub end: GjkEnd,
    /// Distance between the shapes (margins included), 0 when intersecting.
    pub distance: T,
    /// |v| between the cores (the shapes when margins are not used).
    pub core_distance: T,
    /// Closest points on A and B from the barycentric coordinates (and the
    /// margins along v̂); when intersecting, the cores' closest points.
    pub closest_a: Vector3<T>,
    pub closest_b: Vector3<T>,
    /// v = Σ λ_i w_i.
    pub v: Vector3<T>,
    pub margins: [T; 2],
    pub iterations: usize,
    /// The terminal simplex (a, b in world coordinates).
    pub simplex: Simplex<T>,
}

/// A pair in B's frame: A at `a_pose`, B at the origin with `b_pose`'s rotation.
pub(super) struct Pair<'s, T: Real, A: ?Sized, B: ?Sized> {
    pub a: &'s A,
    pub b: &'s B,
    pub a_pose: Pose<T>,
    pub b_pose: Pose<T>,
    pub origin: Vector3<T>,
    pub cores: bool,
}

impl<'s, T: Real, A: Support<T> + ?Sized, B: Support<T> + ?Sized> Pair<'s, T, A, B> {
    pub fn new(a: &'s A, pa: &Pose<T>, b: &'s B, pb: &Pose<T>, cores: bool) -> Self {
        Pair {
            a,
            b,
            a_pose: Pose {
                position: pa.position - pb.position,
                rotation: pa.rotation,
            },
            b_pose: Pose {
                position: Vector3::zeros(),
                rotation: pb.rotation,
            },
            origin: pb.position,
            cores,
        }
    }

    /// w = s_A(d) − s_B(−d), in the pair's frame.
    pub fn vertex(&self, d: &Vector3<T>) -> Vertex<T> {
        let point = |s: &dyn Fn(&Vector3<T>) -> Vector3<T>, pose: &Pose<T>, d: &Vector3<T>| {
            pose.to_world(&s(&pose.rotation.tr_mul(d)))
        };
        let (a, b) = if self.cores {
            (
                point(&|x| self.a.core_support(x), &self.a_pose, d),
                point(&|x| self.b.core_support(x), &self.b_pose, &-d),
            )
        } else {
            (
                point(&|x| self.a.local_support(x), &self.a_pose, d),
                point(&|x| self.b.local_support(x), &self.b_pose, &-d),
            )
        };
        Vertex { w: a - b, a, b }
    }

    /// A vertex moved to world coordinates.
    pub fn world(&self, v: &Vertex<T>) -> Vertex<T> {
        Vertex {
            w: v.w,
            a: v.a + self.origin,
            b: v.b + self.origin,
        }
    }

    pub fn margins(&self) -> [T; 2] {
        if self.cores {
            [self.a.margin(), self.b.margin()]
        } else {
            [T::zero(); 2]
        }
    }
}

/// GJK between `a` at `pose_a` and `b` at `pose_b`.
pub fn gjk<T, A, B, O>(
    a: &A,
    pose_a: &Pose<T>,
    b: &B,
    pose_b: &Pose<T>,
    options: &GjkOptions<T>,
    observer: &mut O,
) -> GjkResult<T>
where
    T: Real,
    A: Support<T> + ?Sized,
    B: Support<T> + ?Sized,
    O: GjkObserver<T> + ?Sized,
{
    let pair = Pair::new(a, pose_a, b, pose_b, options.use_margins);
    observer.start(options.use_margins);
    run(&pair, options, observer)
}

pub(super) fn run<T, A, B, O>(
    pair: &Pair<'_, T, A, B>,
    options: &GjkOptions<T>,
    observer: &mut O,
) -> GjkResult<T>
where
    T: Real,
    A: Support<T> + ?Sized,
    B: Support<T> + ?Sized,
    O: GjkObserver<T> + ?Sized,
{
    // First direction: from A's centre toward B's (toward the origin from A − B's centre).
    let d0 = -pair.a_pose.position;
    let d0 = if d0.norm_squared() > T::zero() {
        d0
    } else {
        Vector3::x()
    };
    let mut simplex = Simplex::point(pair.vertex(&d0));
    let mut v = simplex.vertices[0].w;
    let mut scale = v.norm();
    let mut end = GjkEnd::IterationCap;
    let mut iterations = 0;
    let tol = options.touching_tolerance;
    while iterations < options.max_iterations {
        let vv = v.norm_squared();
        if vv <= tol * tol * scale * scale {
            end = GjkEnd::Touching;
            break;
        }
        iterations += 1;
        let direction = -v;
        let w = pair.vertex(&direction);
        scale = scale.max(w.w.norm());
        let bound = vv - v.dot(&w.w);
        let bound_limit = options.relative_tolerance * vv;
        let mut record = GjkIteration {
            index: iterations - 1,
            direction,
            support: pair.world(&w),
            bound,
            bound_limit,
            simplex: [Vector3::zeros(); 4],
            simplex_len: simplex.len,
            kept: (1u8 << simplex.len) - 1,
            v,
            next: None,
        };
        for (slot, p) in record.simplex.iter_mut().zip(simplex.points()) {
            *slot = p.w;
        }
        let repeated = simplex
            .points()
            .iter()
            .any(|p| (p.w - w.w).norm_squared() <= tol * tol * scale * scale);
        if bound <= bound_limit || repeated {
            observer.iteration(&record);
            end = if repeated && bound > bound_limit {
                GjkEnd::NoProgress
            } else {
                GjkEnd::Converged
            };
            break;
        }
        let before = simplex;
        simplex.push(w);
        let mut ws = [Vector3::zeros(); 4];
        for (slot, p) in ws.iter_mut().zip(simplex.points()) {
            *slot = p.w;
        }
        let projection = project(&ws[..simplex.len]);
        record.simplex = ws;
        record.simplex_len = simplex.len;
        record.kept = projection.kept;
        simplex.reduce(&projection);
        let next = if simplex.len == 4 {
            Vector3::zeros()
        } else {
            simplex.combine(|p| p.w)
        };
        record.next = Some(next);
        observer.iteration(&record);
        if simplex.len == 4 {
            v = next;
            end = GjkEnd::OriginInside;
            break;
        }
        if next.norm_squared() >= vv {
            simplex = before; // no better than before: keep the old simplex
            end = GjkEnd::NoProgress;
            break;
        }
        v = next;
    }
    finish(pair, simplex, v, end, iterations)
}

/// Distance, verdict and closest points from the terminal simplex.
fn finish<T: Real, A: Support<T> + ?Sized, B: Support<T> + ?Sized>(
    pair: &Pair<'_, T, A, B>,
    simplex: Simplex<T>,
    v: Vector3<T>,
    end: GjkEnd,
    iterations: usize,
) -> GjkResult<T> {
    let [ma, mb] = pair.margins();
    let inside = matches!(end, GjkEnd::OriginInside | GjkEnd::Touching);
    let core_distance = if inside { T::zero() } else { v.norm() };
    let mut closest_a = simplex.combine(|p| p.a) + pair.origin;
    let mut closest_b = simplex.combine(|p| p.b) + pair.origin;
    if core_distance > T::zero() {
        let n = v / core_distance;
        closest_a -= n * ma;
        closest_b += n * mb;
    }
    let gap = core_distance - ma - mb;
    let mut world = simplex;
    for p in world.vertices.iter_mut().take(world.len) {
        *p = pair.world(p);
    }
    GjkResult {
        verdict: if inside || gap <= T::zero() {
            GjkVerdict::Intersecting
        } else {
            GjkVerdict::Separated
        },
        end,
        distance: gap.max(T::zero()),
        core_distance,
        closest_a,
        closest_b,
        v,
        margins: [ma, mb],
        iterations,
        simplex: world,
    }
}
