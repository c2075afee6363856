//! Exercise set-ups drawn from a seed: the lecture's three set-ups (a cube's edge on the
//! floor, two spheres, a cube's edge in a heavy sphere) with numbers of at
//! most four decimals, geometry that fits (the contact point lies on the
//! bodies), and unit normals and quaternions that are exact as written.

use super::rng::SplitMix64;
use super::Kind;
use crate::lesson::Shape;

/// Unit pairs exact in four decimals (Pythagorean triples over 5, 25, 125, 625).
const PAIRS: [(f64, f64); 8] = [
    (0.6, 0.8),
    (0.8, 0.6),
    (0.28, 0.96),
    (0.96, 0.28),
    (0.352, 0.936),
    (0.936, 0.352),
    (0.5376, 0.8432),
    (0.8432, 0.5376),
];

pub fn round4(x: f64) -> f64 {
    let r = (x * 1e4).round() / 1e4;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

fn r3(v: [f64; 3]) -> [f64; 3] {
    v.map(round4)
}

#[derive(Debug, Clone, PartialEq)]
pub struct BodySpec {
    pub name: &'static str,
    /// `f64::INFINITY` for the immovable floor.
    pub mass: f64,
    pub shape: Shape,
    pub position: [f64; 3],
    pub orientation: Option<[f64; 4]>,
    pub velocity: [f64; 3],
    pub angular_velocity: [f64; 3],
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Friction {
    None,
    /// One coefficient for sticking and sliding.
    Same(f64),
    /// `(static, dynamic)`.
    Split(f64, f64),
}

#[derive(Debug, Clone, PartialEq)]
pub struct Setup {
    pub title: &'static str,
    pub bodies: Vec<BodySpec>,
    pub point: [f64; 3],
    pub normal: [f64; 3],
    pub penetration: f64,
    pub restitution: f64,
    pub friction: Friction,
}

/// A turn about z by a quaternion `[w, 0, 0, z]` from [`PAIRS`]: `(quaternion, cos φ, sin φ)`.
fn turn(rng: &mut SplitMix64) -> ([f64; 4], f64, f64) {
    let (w, z) = rng.pick(&PAIRS);
    let z = if rng.coin() { z } else { -z };
    ([w, 0.0, 0.0, z], w * w - z * z, 2.0 * w * z)
}

/// The middle of the cube edge (parallel to z) that reaches furthest along
/// `-d`, relative to the centre.
fn low_edge(half: f64, cos: f64, sin: f64, d: [f64; 2]) -> [f64; 3] {
    let mut best = [0.0; 3];
    let mut lowest = f64::INFINITY;
    for (sx, sy) in [(-1.0, -1.0), (-1.0, 1.0), (1.0, -1.0), (1.0, 1.0)] {
        let (x, y) = (sx * half, sy * half);
        let w = [cos * x - sin * y, sin * x + cos * y, 0.0];
        let along = w[0] * d[0] + w[1] * d[1];
        if along < lowest {
            lowest = along;
            best = w;
        }
    }
    best
}

fn cube(rng: &mut SplitMix64) -> (f64, f64) {
    (
        rng.pick(&[2.0, 4.0, 6.0, 8.0, 10.0, 12.0]),
        rng.pick(&[2.0, 4.0, 5.0, 8.0, 10.0, 12.0, 15.0, 20.0]),
    )
}

fn friction(rng: &mut SplitMix64, kind: Kind) -> Friction {
    match kind {
        Kind::StaticFriction => Friction::Same(rng.pick(&[0.5, 0.6, 0.7, 0.8, 0.9, 1.0])),
        Kind::DynamicFriction => {
            let s = rng.pick(&[0.1, 0.15, 0.2, 0.25, 0.3]);
            Friction::Split(s, round4(s - rng.pick(&[0.0, 0.05])))
        }
        _ => Friction::None,
    }
}

/// Tangential speed: small where friction should hold, large where it should give.
fn sideways(rng: &mut SplitMix64, kind: Kind) -> f64 {
    let s = match kind {
        Kind::StaticFriction => rng.grid(0.1, 1.0, 2),
        Kind::DynamicFriction => rng.grid(2.0, 5.0, 2),
        _ => rng.grid(0.0, 3.0, 2),
    };
    if rng.coin() {
        s
    } else {
        -s
    }
}

fn penetration(rng: &mut SplitMix64, kind: Kind) -> f64 {
    if kind == Kind::Penetration {
        rng.grid(0.05, 1.5, 2)
    } else {
        0.0
    }
}

/// A cube strikes (or has sunk into) the immovable floor with one edge.
pub fn cube_on_floor(rng: &mut SplitMix64, kind: Kind) -> Setup {
    let (side, mass) = cube(rng);
    let (q, cos, sin) = turn(rng);
    let pen = penetration(rng, kind);
    let floor = rng.grid(0.0, 10.0, 0);
    let edge = low_edge(side / 2.0, cos, sin, [0.0, 1.0]);
    let x = rng.grid(0.0, 30.0, 0);
    let position = r3([x, floor - edge[1] - pen, 0.0]);
    let point = r3([position[0] + edge[0], position[1] + edge[1], 0.0]);
    let resting = kind == Kind::Penetration && rng.coin();
    let (velocity, spin) = if resting {
        ([0.0; 3], 0.0)
    } else {
        let spin = if rng.coin() {
            rng.grid(-1.0, 1.0, 2)
        } else {
            0.0
        };
        ([sideways(rng, kind), -rng.grid(0.5, 4.0, 2), 0.0], spin)
    };
    Setup {
        title: if pen > 0.0 {
            "A cube has sunk into the floor"
        } else {
            "A cube strikes the floor"
        },
        bodies: vec![
            BodySpec {
                name: "cube",
                mass,
                shape: Shape::Box { sides: [side; 3] },
                position,
                orientation: Some(q),
                velocity,
                angular_velocity: [0.0, 0.0, spin],
            },
            BodySpec {
                name: "floor",
                mass: f64::INFINITY,
                shape: Shape::HalfSpace {
                    normal: [0.0, 1.0, 0.0],
                },
                position: [point[0], round4(point[1] + pen), 0.0],
                orientation: None,
                velocity: [0.0; 3],
                angular_velocity: [0.0; 3],
            },
        ],
        point,
        normal: [0.0, 1.0, 0.0],
        penetration: pen,
        restitution: rng.pick(&[0.0, 0.2, 0.4, 0.5, 0.6, 0.8]),
        friction: friction(rng, kind),
    }
}

fn direction(rng: &mut SplitMix64, upward: bool) -> [f64; 3] {
    let (a, b) = rng.pick(&PAIRS);
    let x = if rng.coin() { a } else { -a };
    let y = if upward || rng.coin() { b } else { -b };
    [x, y, 0.0]
}

fn sphere_shape(rng: &mut SplitMix64, radius: f64) -> Shape {
    if rng.coin() {
        Shape::Sphere { radius }
    } else {
        Shape::HollowSphere { radius }
    }
}

/// Two spheres collide (or overlap) along the line of their centres.
pub fn two_spheres(rng: &mut SplitMix64, kind: Kind) -> Setup {
    let (r1, r2) = (rng.grid(1.0, 6.0, 0), rng.grid(1.0, 6.0, 0));
    let masses = [1.0, 2.0, 5.0, 10.0, 20.0, 50.0];
    let (m1, m2) = (rng.pick(&masses), rng.pick(&masses));
    let d = direction(rng, false);
    let pen = penetration(rng, kind);
    let p2 = [rng.grid(0.0, 30.0, 0), rng.grid(0.0, 30.0, 0), 0.0];
    let p1 = r3([
        p2[0] + (r1 + r2 - pen) * d[0],
        p2[1] + (r1 + r2 - pen) * d[1],
        0.0,
    ]);
    let point = r3([
        p2[0] + (r2 - pen / 2.0) * d[0],
        p2[1] + (r2 - pen / 2.0) * d[1],
        0.0,
    ]);
    // Closing along d̂ at 0.5 to 4, plus a sideways part in the plane.
    let closing = rng.grid(0.5, 4.0, 2);
    let side = sideways(rng, kind);
    let t = [-d[1], d[0]];
    let v2 = [rng.grid(-1.0, 1.0, 1), rng.grid(-1.0, 1.0, 1), 0.0];
    let v1 = r3([
        v2[0] - closing * d[0] + side * t[0],
        v2[1] - closing * d[1] + side * t[1],
        0.0,
    ]);
    let (v1, v2) = if kind == Kind::Penetration && rng.coin() {
        ([0.0; 3], [0.0; 3])
    } else {
        (v1, v2)
    };
    Setup {
        title: if pen > 0.0 {
            "Two spheres overlap"
        } else {
            "Two spheres collide"
        },
        bodies: vec![
            BodySpec {
                name: "sphere1",
                mass: m1,
                shape: sphere_shape(rng, r1),
                position: p1,
                orientation: None,
                velocity: v1,
                angular_velocity: [0.0; 3],
            },
            BodySpec {
                name: "sphere2",
                mass: m2,
                shape: sphere_shape(rng, r2),
                position: p2,
                orientation: None,
                velocity: v2,
                angular_velocity: [0.0; 3],
            },
        ],
        point,
        normal: d,
        penetration: pen,
        restitution: rng.pick(&[0.0, 0.2, 0.4, 0.5, 0.6, 0.8, 1.0]),
        friction: friction(rng, kind),
    }
}

/// A cube's edge meets (or has sunk into) a heavy sphere below it.
pub fn cube_on_sphere(rng: &mut SplitMix64, kind: Kind) -> Setup {
    let (side, mass) = cube(rng);
    let (q, cos, sin) = turn(rng);
    let d = direction(rng, true);
    let pen = penetration(rng, kind);
    let radius = rng.grid(3.0, 8.0, 0);
    let heavy = rng.pick(&[50.0, 100.0, 200.0]);
    let p1 = [rng.grid(0.0, 30.0, 0), rng.grid(10.0, 30.0, 0), 0.0];
    let edge = low_edge(side / 2.0, cos, sin, [d[0], d[1]]);
    let point = r3([p1[0] + edge[0], p1[1] + edge[1], 0.0]);
    let p2 = r3([
        point[0] - (radius - pen) * d[0],
        point[1] - (radius - pen) * d[1],
        0.0,
    ]);
    let resting = kind == Kind::Penetration && rng.coin();
    let velocity = if resting {
        [0.0; 3]
    } else {
        let closing = rng.grid(0.5, 4.0, 2);
        let side = sideways(rng, kind);
        r3([
            -closing * d[0] - side * d[1],
            -closing * d[1] + side * d[0],
            0.0,
        ])
    };
    Setup {
        title: if pen > 0.0 {
            "A cube has sunk into a heavy sphere"
        } else {
            "A cube strikes a heavy sphere"
        },
        bodies: vec![
            BodySpec {
                name: "cube",
                mass,
                shape: Shape::Box { sides: [side; 3] },
                position: p1,
                orientation: Some(q),
                velocity,
                angular_velocity: [0.0; 3],
            },
            BodySpec {
                name: "sphere",
                mass: heavy,
                shape: Shape::Sphere { radius },
                position: p2,
                orientation: None,
                velocity: [0.0; 3],
                angular_velocity: [0.0; 3],
            },
        ],
        point,
        normal: d,
        penetration: pen,
        restitution: rng.pick(&[0.0, 0.2, 0.4, 0.5, 0.6, 0.8]),
        friction: friction(rng, kind),
    }
}

/// A number as TOML writes a float: shortest round-trip form, always with a
/// decimal point; `inf` for an immovable mass.
fn num(x: f64) -> String {
    if x.is_infinite() {
        return "inf".into();
    }
    let s = format!("{x}");
    if s.contains('.') || s.contains('e') {
        s
    } else {
        format!("{s}.0")
    }
}

fn list(xs: &[f64]) -> String {
    format!(
        "[{}]",
        xs.iter().map(|x| num(*x)).collect::<Vec<_>>().join(", ")
    )
}

fn shape(s: &Shape) -> String {
    match s {
        Shape::Sphere { radius: r } => format!("{{ sphere = {} }}", num(*r)),
        Shape::HollowSphere { radius: r } => format!("{{ hollow_sphere = {} }}", num(*r)),
        Shape::Box { sides: b } => format!("{{ box = {} }}", list(b)),
        Shape::Cylinder { radius, height } => format!(
            "{{ cylinder = {{ radius = {}, height = {} }} }}",
            num(*radius),
            num(*height)
        ),
        Shape::Capsule { radius, height } => format!(
            "{{ capsule = {{ radius = {}, height = {} }} }}",
            num(*radius),
            num(*height)
        ),
        Shape::Hull(hull) => format!(
            "{{ convex = [{}] }}",
            hull.vertices()
                .iter()
                .map(|v| list(v.as_slice()))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Shape::Mesh(mesh) => format!(
            "{{ mesh = {{ vertices = [{}], triangles = [{}] }} }}",
            (mesh.vertices().iter())
                .map(|v| list(v.as_slice()))
                .collect::<Vec<_>>()
                .join(", "),
            (mesh.triangles().iter())
                .map(|t| format!("[{}, {}, {}]", t[0], t[1], t[2]))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Shape::HalfSpace { .. } => "\"half_space\"".into(),
    }
}

impl Setup {
    /// The scene as a lesson file.
    pub fn toml(&self, id: &str, title: &str, source: &str, summary: &str) -> String {
        let mut out = format!(
            "id = \"{id}\"\ntitle = \"{title}\"\nsource = \"{source}\"\nsummary = \"\"\"\n{summary}\n\"\"\"\n"
        );
        for b in &self.bodies {
            out.push_str(&format!(
                "\n[[body]]\nname = \"{}\"\nmass = {}\nshape = {}\nposition = {}\n",
                b.name,
                num(b.mass),
                shape(&b.shape),
                list(&b.position)
            ));
            if let Some(q) = b.orientation {
                out.push_str(&format!("orientation = {}\n", list(&q)));
            }
            if b.velocity != [0.0; 3] {
                out.push_str(&format!("velocity = {}\n", list(&b.velocity)));
            }
            if b.angular_velocity != [0.0; 3] {
                out.push_str(&format!(
                    "angular_velocity = {}\n",
                    list(&b.angular_velocity)
                ));
            }
        }
        out.push_str(&format!(
            "\n[[contact]]\nbodies = [\"{}\", \"{}\"]\npoint = {}\nnormal = {}\n",
            self.bodies[0].name,
            self.bodies[1].name,
            list(&self.point),
            list(&self.normal)
        ));
        if self.penetration > 0.0 {
            out.push_str(&format!("penetration = {}\n", num(self.penetration)));
        }
        out.push_str(&format!("restitution = {}\n", num(self.restitution)));
        match self.friction {
            Friction::None => {}
            Friction::Same(mu) => out.push_str(&format!("friction = {}\n", num(mu))),
            Friction::Split(s, d) => out.push_str(&format!(
                "static_friction = {}\ndynamic_friction = {}\n",
                num(s),
                num(d)
            )),
        }
        out
    }
}
