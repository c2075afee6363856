//! `detect`'s broad-phase search (method, visits, box tests, pairs kept):
//! for each method on scenes of every size, the numbers the JSON and the
//! Markdown print are the trace's, and the trace's are what the step's own
//! broad phase (`ContactGenerator`) counts on the same bodies.

use contact_lab::format::Fmt;
use contact_lab::knobs::Choice;
use contact_lab::lesson::Lesson;
use contact_lab::physics::collide::{BroadPhaseMethod, ContactGenerator, Options};
use contact_lab::physics::step::Simulation;
use contact_lab::render::detect::{json, markdown};
use contact_lab::session::detect_trace;
use contact_lab::trace::Plane;

#[test]
fn the_printed_search_counts_are_the_steps_broad_phase_counts() {
    for id in ["stack-5", "hull-stack", "sphere-row-20", "sleep-and-wake"] {
        let lesson = Lesson::load(id).unwrap();
        for method in [
            BroadPhaseMethod::Sweep,
            BroadPhaseMethod::Grid,
            BroadPhaseMethod::Bvh,
        ] {
            let mut params = lesson.sim_params().unwrap();
            params.broad_phase = method;
            let mut world = lesson.world::<f64>();
            world.contacts.clear();
            let materials = lesson.simulation.clone().unwrap().materials;
            let sim = Simulation::new(world, params, materials);
            let t = detect_trace(&sim, &lesson, 0, Plane::Xy, None);
            // The step's broad phase on the same bodies, called afresh.
            let mut generator = ContactGenerator::<f64>::new();
            let options = Options {
                box_box: params.box_box,
                tolerance: params.contact_margin,
                narrow_phase: params.narrow_phase,
                broad_phase: method,
                internal_edges: params.internal_edges,
            };
            generator.generate_world(&sim.world.bodies, &options, &mut vec![]);
            let c = generator.broad_counts();
            let s = &t.search;
            assert_eq!(s.method, method.name());
            let at = format!("{id} under {}", method.name());
            assert_eq!(
                (s.visited, s.tests, s.kept, s.boxes, s.loose),
                (c.visited, c.tests, c.kept, c.boxes, c.loose),
                "{at}"
            );
            assert_eq!(s.kept, generator.pairs().len(), "{at}");
            assert!(s.tests > 0 && s.visited > 0, "{at}");
            // The JSON.
            let doc: serde_json::Value = serde_json::from_str(&json(&t)).unwrap();
            let b = &doc["broad_phase"];
            assert_eq!(b["method"], method.name(), "{at}");
            for (key, value) in [
                ("tests", s.tests),
                ("visited", s.visited),
                ("kept", s.kept),
                ("loose", s.loose),
            ] {
                assert_eq!(b[key].as_u64(), Some(value as u64), "{at}: {key}");
            }
            assert_eq!(b["visited_what"], s.visited_what, "{at}");
            // The Markdown (never folded) says the same numbers.
            let all = s.boxes * (s.boxes - 1) / 2;
            let said = format!(
                "(broad_phase = {}): {}",
                method.name(),
                match method {
                    BroadPhaseMethod::Sweep => "sort and sweep".to_string(),
                    BroadPhaseMethod::Grid =>
                        format!("a uniform grid of {} m cells", Fmt::default().num(c.cell)),
                    BroadPhaseMethod::Bvh =>
                        format!("a bounding-volume tree of height {}", c.height),
                }
            );
            let counted = format!(
                "over {}; {} {} visited, {} made (all against all: {all}), {} kept",
                count(s.boxes, "box", "boxes"),
                s.visited,
                s.visited_what,
                count(s.tests, "box test", "box tests"),
                count(s.kept, "pair", "pairs"),
            );
            let page = markdown(&t, &Fmt::default());
            assert!(
                page.contains(&said) && page.contains(&counted),
                "{at}:\n{page}"
            );
        }
    }
}

fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}
