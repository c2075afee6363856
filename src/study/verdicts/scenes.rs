//! The verdict matrix's scenes, built in code as lesson text (so they go
//! through the same reading and checking as any lesson): Solver2D's test
//! scenes in 3-D, and the slender box of `docs/simulate.md` ("Gap
//! contacts"). Each takes a [`Size`]: the full scene, or a reduced one for
//! the debug tests. Every scene steps at 1/60 s with sleep off (the solver
//! is what is judged, not sleep).

use super::Size;

/// The ramp's angle (rad).
pub const RAMP_ANGLE: f64 = 0.25;
/// The ramp's own μ: a box's μ with it is √(μ_box · μ_ramp).
pub const RAMP_FRICTION: f64 = 1.0;
/// The five boxes' μ on the ramp: effective √(μ · 1) = 0.387, 0.316,
/// 0.265, 0.141 and 0 against tan 0.25 = 0.2553.
pub const RAMP_BOX_FRICTION: [f64; 5] = [0.15, 0.1, 0.07, 0.02, 0.0];
/// Where the ramp's boxes start, up the slope from its centre (m).
const RAMP_START: f64 = 11.0;

/// The crowd's spheres: radius, and the spacing of their grid (they start
/// overlapped by 2r − spacing).
pub const CROWD_RADIUS: f64 = 0.5;
const CROWD_SPACING: f64 = 0.9;
/// How far the walls stand inside the outer spheres' surfaces (m).
const CROWD_SQUEEZE: f64 = 0.05;

/// The pyramid's horizontal spacing: 1 m boxes 5 cm apart.
const PYRAMID_SPACING: f64 = 1.05;

fn head(id: &str, title: &str, world: &str, seconds: f64) -> String {
    let steps = (seconds * 60.0).round() as usize;
    format!(
        "id = \"{id}\"\ntitle = \"{title}\"\nsource = \"Solver2D's test scenes (Erin Catto), in 3-D\"\n\n\
         [world]\n{world}\n\n[step]\ndt = 0.016666666666666666\nsteps = {steps}\n\n[sleep]\nsleep = false\n"
    )
}

fn body(name: &str, mass: &str, shape: &str, p: [f64; 3], more: &str) -> String {
    format!(
        "\n[[body]]\nname = \"{name}\"\nmass = {mass}\nshape = {shape}\nposition = [{:?}, {:?}, {:?}]\n{more}",
        p[0], p[1], p[2]
    )
}

const FLOOR: &str =
    "\n[[body]]\nname = \"floor\"\nmass = inf\nshape = \"half_space\"\nposition = [0, 0, 0]\n";
const UNIT_BOX: &str = "{ box = [1, 1, 1] }";

/// Boxes in the stack of [`stack`].
pub fn stack_height(size: Size) -> usize {
    match size {
        Size::Full => 15,
        Size::Reduced => 4,
    }
}

/// A vertical stack of 1 m boxes of 1 kg on the floor, μ 0.6, no bounce.
pub fn stack(size: Size, seconds: f64) -> String {
    let n = stack_height(size);
    let mut t = head(
        "verdict-stack",
        &format!("A vertical stack of {n} boxes"),
        "restitution = 0.0\nfriction = 0.6\nbox_box = \"manifold\"",
        seconds,
    );
    for i in 0..n {
        t += &body(
            &format!("box{}", i + 1),
            "1.0",
            UNIT_BOX,
            [0.0, i as f64 + 0.5, 0.0],
            "",
        );
    }
    t + FLOOR
}

/// The pyramid's base (boxes in its bottom row).
pub fn pyramid_base(size: Size) -> usize {
    match size {
        Size::Full => 20,
        Size::Reduced => 3,
    }
}

/// A pyramid of 1 m boxes, 5 cm apart in each row, each row centred on
/// the one below.
pub fn pyramid(size: Size, seconds: f64) -> String {
    let n = pyramid_base(size);
    let mut t = head(
        "verdict-pyramid",
        &format!("A pyramid with a base of {n} boxes"),
        "restitution = 0.0\nfriction = 0.6\nbox_box = \"manifold\"",
        seconds,
    );
    for row in 0..n {
        let count = n - row;
        for i in 0..count {
            let x = (i as f64 - (count - 1) as f64 / 2.0) * PYRAMID_SPACING;
            let name = format!("box-r{}-{}", row + 1, i + 1);
            t += &body(&name, "1.0", UNIT_BOX, [x, row as f64 + 0.5, 0.0], "");
        }
    }
    t + FLOOR
}

/// A 20 × 1 × 20 m plate of 400 kg on two 1 m boxes of 1 kg under its
/// ends (the plate is body 3, its bottom face at y = 1).
pub fn mass_ratio(_size: Size, seconds: f64) -> String {
    let mut t = head(
        "verdict-mass-ratio",
        "A 400 kg plate on two 1 kg boxes",
        "restitution = 0.0\nfriction = 0.6\nbox_box = \"manifold\"",
        seconds,
    );
    t += &body("left", "1.0", UNIT_BOX, [-9.5, 0.5, 0.0], "");
    t += &body("right", "1.0", UNIT_BOX, [9.5, 0.5, 0.0], "");
    t += &body(
        "plate",
        "400.0",
        "{ box = [20, 1, 20] }",
        [0.0, 1.5, 0.0],
        "",
    );
    t + FLOOR
}

/// The unit vector up the ramp, (cos θ, sin θ, 0).
pub fn ramp_uphill() -> [f64; 3] {
    [RAMP_ANGLE.cos(), RAMP_ANGLE.sin(), 0.0]
}

/// Five 1 m boxes of 1 kg resting on a 30 × 1 × 12 m ramp turned 0.25 rad
/// about z, 2.5 m apart across it, each with its own μ
/// ([`RAMP_BOX_FRICTION`]); the ramp's μ is [`RAMP_FRICTION`].
pub fn ramp(_size: Size, seconds: f64) -> String {
    let (s, c) = RAMP_ANGLE.sin_cos();
    let q = format!(
        "orientation = [{:?}, 0, 0, {:?}]\n",
        (RAMP_ANGLE / 2.0).cos(),
        (RAMP_ANGLE / 2.0).sin()
    );
    let mut t = head(
        "verdict-ramp",
        "Five boxes on a 0.25 rad ramp",
        "restitution = 0.0\nfriction = 0.0\nbox_box = \"manifold\"",
        seconds,
    );
    let normal = [-s, c, 0.0];
    for (k, mu) in RAMP_BOX_FRICTION.iter().enumerate() {
        let z = (k as f64 - 2.0) * 2.5;
        let p = [normal[0] + RAMP_START * c, normal[1] + RAMP_START * s, z];
        t += &body(
            &format!("mu-{mu}"),
            "1.0",
            UNIT_BOX,
            p,
            &format!("{q}friction = {mu:?}\n"),
        );
    }
    t += &body(
        "ramp",
        "inf",
        "{ box = [30, 1, 12] }",
        [0.0, 0.0, 0.0],
        &format!("{q}friction = {RAMP_FRICTION:?}\n"),
    );
    t
}

/// Boxes in the overlapped stack.
pub fn overlap_height(size: Size) -> usize {
    match size {
        Size::Full => 3,
        Size::Reduced => 2,
    }
}

/// A stack of 1 m boxes started 25 % overlapped: the bottom one 0.25 m
/// into the floor, each other 0.25 m into the one below.
pub fn overlap(size: Size, seconds: f64) -> String {
    let n = overlap_height(size);
    let mut t = head(
        "verdict-overlap",
        &format!("A stack of {n} boxes started 25 % overlapped"),
        "restitution = 0.0\nfriction = 0.6\nbox_box = \"manifold\"",
        seconds,
    );
    for i in 0..n {
        t += &body(
            &format!("box{}", i + 1),
            "1.0",
            UNIT_BOX,
            [0.0, 0.25 + 0.75 * i as f64, 0.0],
            "",
        );
    }
    t + FLOOR
}

/// Spheres along each side of the crowd's cube.
pub fn crowd_side(size: Size) -> usize {
    match size {
        Size::Full => 4,
        Size::Reduced => 2,
    }
}

/// A cube of spheres (r = 0.5 m, 1 kg) on a 0.9 m grid, each 10 cm into
/// its neighbours, no gravity, boxed in by six immovable walls that stand
/// 5 cm inside the outer spheres.
pub fn crowd(size: Size, seconds: f64) -> String {
    let k = crowd_side(size);
    let mut t = head(
        "verdict-crowd",
        &format!("{} spheres squeezed by walls", k * k * k),
        "gravity = [0, 0, 0]\nrestitution = 0.0\nfriction = 0.0",
        seconds,
    );
    let half = (k - 1) as f64 * CROWD_SPACING / 2.0;
    let sphere = format!("{{ sphere = {CROWD_RADIUS:?} }}");
    for i in 0..k {
        for j in 0..k {
            for l in 0..k {
                let at = |n: usize| n as f64 * CROWD_SPACING - half;
                let name = format!("ball-{}-{}-{}", i + 1, j + 1, l + 1);
                t += &body(&name, "1.0", &sphere, [at(i), at(j), at(l)], "");
            }
        }
    }
    let inner = half + CROWD_RADIUS - CROWD_SQUEEZE;
    let long = 2.0 * inner + 2.0;
    for axis in 0..3 {
        for sign in [-1.0, 1.0] {
            let mut p = [0.0; 3];
            p[axis] = sign * (inner + 0.5);
            let mut dims = [long; 3];
            dims[axis] = 1.0;
            let shape = format!("{{ box = [{:?}, {:?}, {:?}] }}", dims[0], dims[1], dims[2]);
            let name = format!(
                "wall-{}{}",
                if sign < 0.0 { "-" } else { "+" },
                ["x", "y", "z"][axis]
            );
            t += &body(&name, "inf", &shape, p, "");
        }
    }
    t
}

/// The slender box of docs/simulate.md: 0.42 × 0.8 × 0.42 m, 1 kg,
/// standing on an immovable 2 × 1 × 2 m box, μ 0.5, restitution 0.2. The
/// lecture's deepest-first order rocks it (tests/physics/resting_slender.rs).
pub fn slender(_size: Size, seconds: f64) -> String {
    let mut t = head(
        "verdict-slender",
        "A slender box standing on a box",
        "restitution = 0.2\nfriction = 0.5",
        seconds,
    );
    t += &body(
        "post",
        "1.0",
        "{ box = [0.42, 0.8, 0.42] }",
        [0.0, 0.9, 0.0],
        "",
    );
    t += &body("box", "inf", "{ box = [2, 1, 2] }", [0.0, 0.0, 0.0], "");
    t
}
