//! The names a resolution is described with: the lesson's, or a time
//! step's (bodies by world index, contacts labelled by their bodies).

use crate::lesson::Lesson;

/// What a resolution is called and what its bodies and contacts are named.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Names {
    pub lesson: String,
    pub title: String,
    pub source: String,
    pub summary: String,
    /// By world body index.
    pub bodies: Vec<String>,
    /// Contact labels (`0: ball ↔ floor`), by contact number.
    pub contacts: Vec<String>,
    pub warnings: Vec<String>,
}

impl Names {
    /// The names a lesson gives.
    pub fn of_lesson(lesson: &Lesson) -> Self {
        Names {
            lesson: lesson.id.clone(),
            title: lesson.title.clone(),
            source: lesson.source.clone(),
            summary: lesson.summary.clone(),
            bodies: lesson.bodies.iter().map(|b| b.name.clone()).collect(),
            contacts: (0..lesson.contacts.len())
                .map(|k| lesson.contact_label(k))
                .collect(),
            warnings: lesson.warnings.iter().map(|w| w.to_string()).collect(),
        }
    }

    /// The label of contact `k` between world bodies (`3: box-2 ↔ box-1`).
    pub fn pair_label(bodies: &[String], k: usize, a: usize, b: Option<usize>) -> String {
        let name = |i: usize| bodies.get(i).map_or("?", String::as_str);
        match b {
            Some(b) => format!("{k}: {} ↔ {}", name(a), name(b)),
            None => format!("{k}: {} ↔ world", name(a)),
        }
    }
}
