//! Lessons compiled into the binary, so the app works from any directory.

macro_rules! embed {
    ($($file:literal),* $(,)?) => {
        &[$(($file, include_str!(concat!("../../lessons/", $file)))),*]
    };
}

/// `(file name, text)` of every lesson under `lessons/` (a test checks the list is complete).
#[rustfmt::skip]
pub const LESSONS: &[(&str, &str)] = embed![
    "lecture-1.toml",
    "lecture-2.toml",
    "lecture-3.toml",
    "friction-cube.toml",
    "spinning-ball.toml",
    "excessive-rotation.toml",
    "two-boxes.toml",
    "kane-energy-gain.toml",
    "rod-reverses.toml",
    "box-four-corners.toml",
    "sphere-row.toml",
    "newtons-cradle.toml",
    "box-stack.toml",
    "third-example-floor.toml",
    "impact-row-3.toml",
    "impact-row-5.toml",
    "impact-row-poisson.toml",
    "impact-stack-r01.toml",
    "impact-stack-r05.toml",
    "extremes/extreme-mass-ratio.toml",
    "extremes/extreme-far-from-origin.toml",
    "extremes/extreme-velocities.toml",
    "extremes/extreme-penetrations.toml",
    "extremes/extreme-normals.toml",
    "extremes/extreme-inertia.toml",
];

/// Scenes (`lessons/scenes/`): lessons that `simulate` steps in time. They
/// load by id like any lesson but are listed apart, since their contacts are
/// generated at every step rather than written in the file.
#[rustfmt::skip]
pub const SCENES: &[(&str, &str)] = embed![
    "scenes/ball-drop.toml",
    "scenes/resting-box.toml",
    "scenes/sliding-box.toml",
    "scenes/ramp-stick.toml",
    "scenes/ramp-slide.toml",
    "scenes/stack-5.toml",
    "scenes/cradle-over-time.toml",
    "scenes/cradle-gaps.toml",
    "scenes/sleep-and-wake.toml",
    "scenes/sleep-modes.toml",
    "scenes/kane-rod-bounce.toml",
    "scenes/sphere-row-20.toml",
    "scenes/mass-ratio-stack.toml",
    "scenes/overlap-recovery.toml",
    "scenes/hull-stack.toml",
    "scenes/gjk-separated.toml",
    "scenes/gjk-touching.toml",
    "scenes/epa-edge-edge.toml",
    "scenes/cylinder-on-box.toml",
    "scenes/bullet-wall.toml",
    "scenes/spinning-edge.toml",
    "scenes/plate-drop.toml",
    "scenes/tetra-on-floor.toml",
    "scenes/capsule-on-slope.toml",
    "scenes/ball-floor-fast.toml",
    "scenes/mesh-floor-slide.toml",
    "scenes/mesh-bowl-ball.toml",
    "scenes/mesh-ramp-ball.toml",
];

/// Ids of the embedded scenes, in list order.
pub fn scene_ids() -> Vec<&'static str> {
    SCENES.iter().map(|(file, _)| id_of(file)).collect()
}

/// The id of an embedded lesson file: its base name without `.toml`.
fn id_of(file: &str) -> &str {
    file.rsplit('/')
        .next()
        .unwrap_or(file)
        .trim_end_matches(".toml")
}

/// Ids of the embedded lessons, in list order.
pub fn ids() -> Vec<&'static str> {
    LESSONS.iter().map(|(file, _)| id_of(file)).collect()
}

pub fn find(id: &str) -> Option<&'static str> {
    LESSONS
        .iter()
        .chain(SCENES)
        .find(|(file, _)| id_of(file) == id)
        .map(|(_, text)| *text)
}

pub fn origin(id: &str) -> String {
    let file = LESSONS
        .iter()
        .chain(SCENES)
        .map(|(f, _)| *f)
        .find(|f| id_of(f) == id)
        .unwrap_or(id);
    format!("lessons/{file} (embedded)")
}
