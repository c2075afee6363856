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
];

/// Id of an embedded lesson file: its `id = "…"` line (file names match ids).
pub fn ids() -> Vec<&'static str> {
    LESSONS
        .iter()
        .map(|(file, _)| file.trim_end_matches(".toml"))
        .collect()
}

pub fn find(id: &str) -> Option<&'static str> {
    LESSONS
        .iter()
        .find(|(file, _)| file.trim_end_matches(".toml") == id)
        .map(|(_, text)| *text)
}

pub fn origin(id: &str) -> String {
    format!("lessons/{id}.toml (embedded)")
}
