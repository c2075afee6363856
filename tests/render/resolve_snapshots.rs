//! `resolve` (with the log) for each scene lesson, held as snapshots: the
//! text for the lecture's third example on the floor, rounded JSON (every
//! value, `common::json`) for the others. JSON `seconds` are wall-clock
//! times, so they are zero here (the command fills them in). A change is
//! reviewed line by line.

use crate::common;

use contact_lab::format::Fmt;
use contact_lab::lesson::Lesson;
use contact_lab::physics::resolver::Implementation;
use contact_lab::render::resolve::{self, Seconds};
use contact_lab::trace::resolver::describe;

/// The lesson whose resolution is held as text: the lecture's example.
const LECTURE: &str = "third-example-floor";

/// The lessons that teach sets of contacts.
const SCENES: [&str; 5] = [
    "box-four-corners",
    "sphere-row",
    "newtons-cradle",
    "box-stack",
    "third-example-floor",
];

#[test]
fn resolve_text_of_the_lecture_and_json_of_every_other_scene_lesson() {
    common::snapshot_settings().bind(|| {
        for id in SCENES {
            let lesson = Lesson::load(id).unwrap();
            let trace = describe(&lesson, &lesson.resolver, Implementation::Indexed, true);
            if id == LECTURE {
                insta::assert_snapshot!(
                    format!("resolve_text@{id}"),
                    resolve::text::render(&trace, &Fmt::default())
                );
            } else {
                let json = resolve::json::render(&trace, &Seconds::default(), true);
                insta::assert_snapshot!(
                    format!("resolve_json@{id}"),
                    common::json::rounded(&json, None)
                );
            }
        }
    });
}

/// The scan describes every scene exactly as the indexed resolver does.
#[test]
fn both_implementations_describe_the_same_resolution() {
    for id in SCENES {
        let lesson = Lesson::load(id).unwrap();
        let mut scan = describe(&lesson, &lesson.resolver, Implementation::Scan, true);
        let indexed = describe(&lesson, &lesson.resolver, Implementation::Indexed, true);
        scan.implementation = Implementation::Indexed;
        assert_eq!(scan, indexed, "{id}");
    }
}
