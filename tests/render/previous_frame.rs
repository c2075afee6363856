//! The normal from the previous frame in a contact's stages (issue 25,
//! item 5): the spinning blade's second step generates contacts whose
//! normal at t is sideways (1, 0, 0) while the closest points one frame
//! earlier give (0, 1, 0), the way it came; `simulate --trace-step`, the
//! worked solution of a recorded step's contact (what the TUI's contact
//! stages show) and its JSON carry both and the angle between them.

use assert_cmd::Command;
use contact_lab::lesson::Lesson;
use contact_lab::session::Player;

fn trace_step(n: &str) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args([
            "simulate",
            "spinning-edge",
            "--trace-step",
            n,
            "--width",
            "0",
        ])
        .output()
        .expect("contact-lab runs");
    assert_eq!(out.status.code(), Some(0));
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn trace_step_lists_both_normals_of_the_blades_penetrating_contacts() {
    let text = trace_step("2");
    let block = &text[text.find("Normals from the previous frame").expect(&text)..];
    let rows: Vec<&str> = block
        .lines()
        .filter(|l| l.contains("blade ↔ block"))
        .collect();
    assert_eq!(rows.len(), 4, "{block}");
    for r in rows {
        assert!(r.contains("(1, 0, 0)    (0, 1, 0)         90"), "{r}");
    }
    // The first step has no frame before it.
    assert!(!trace_step("1").contains("Normals from the previous frame"));
    // JSON: one entry per such contact, beside resolve's keys.
    let out = Command::new(env!("CARGO_BIN_EXE_contact-lab"))
        .args([
            "simulate",
            "spinning-edge",
            "--trace-step",
            "2",
            "--format",
            "json",
        ])
        .output()
        .expect("contact-lab runs");
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let rows = j["previous_frame_normals"].as_array().expect("an array");
    assert_eq!(rows.len(), 4);
    assert_eq!(rows[0]["contact"], 0);
    assert!((rows[0]["previous_frame"][1].as_f64().unwrap() - 1.0).abs() < 1e-9);
    assert!((rows[0]["angle_degrees"].as_f64().unwrap() - 90.0).abs() < 1e-6);
    assert!(j.get("position").is_some() && j.get("velocity").is_some());
}

#[test]
fn a_recorded_contacts_first_stage_shows_the_previous_frame_normal_and_the_angle() {
    let lesson = Lesson::load("spinning-edge").unwrap();
    let mut p = Player::new(&lesson).unwrap();
    assert!(p.reach(2));
    let step = p.record(2).expect("step 2 records");
    assert_eq!(step.previous_normals.len(), step.world.contacts.len());
    let previous = step.previous_normals[0].expect("the blade was apart at t − Δt");
    assert!((previous[1] - 1.0).abs() < 1e-9, "{previous:?}");
    // Step 1's contacts (none penetrate) have no previous frame.
    let first = p.record(1).unwrap();
    assert!(first.previous_normals.iter().all(Option::is_none));
    // The contact stages the TUI opens at the first stop.
    let at = step.lesson_at(&lesson, 0);
    let solution = contact_lab::physics::solve(&at.problem::<f64>(0));
    let trace = contact_lab::trace::build(&at, 0, &solution);
    let frame = &trace.stages[0];
    let value = |name: &str| {
        frame
            .values
            .iter()
            .find(|(n, _)| n == name)
            .unwrap_or_else(|| panic!("no {name}: {:?}", frame.values))
            .1
            .clone()
    };
    assert_eq!(
        value("previous_frame_normal"),
        contact_lab::trace::Value::Vector(previous)
    );
    let contact_lab::trace::Value::Scalar(angle) = value("normal_angle_degrees") else {
        panic!("a scalar angle")
    };
    assert!((angle - 90.0).abs() < 1e-6, "{angle}");
    assert!(frame.notes.iter().any(|n| n.contains("one frame earlier")));
    let text =
        contact_lab::render::contact::text::render(&trace, &contact_lab::format::Fmt::new(6));
    assert!(text.contains("θ = acos(d̂ · d̂₋)"), "{text}");
    let json = contact_lab::render::contact::json::render(&trace);
    assert!(json.contains("\"previous_frame_normal\""), "{json}");
    assert!(json.contains("\"normal_angle_degrees\""), "{json}");
}
