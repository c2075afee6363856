//! Lessons compiled into the binary, so the app works from any directory.

/// `(file name, text)` of every lesson under `lessons/` (a test checks the list is complete).
pub const LESSONS: &[(&str, &str)] = &[
    (
        "lecture-1.toml",
        include_str!("../../lessons/lecture-1.toml"),
    ),
    (
        "lecture-2.toml",
        include_str!("../../lessons/lecture-2.toml"),
    ),
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
