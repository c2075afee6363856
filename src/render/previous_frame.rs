//! `simulate --trace-step`'s block of the normals from the previous frame:
//! for each penetrating contact of the step whose pair was apart one frame
//! earlier, the normal at t (the step's, the least penetration) beside the
//! one from the closest points at t − Δt, and the angle between them
//! ("Lecture IV Collisions", the time issue).

use crate::format::Fmt;
use crate::physics::step::previous_frame::angle_between;
use crate::trace::previous_frame::PreviousNormal;

/// The block (empty when no contact has a previous-frame normal).
pub fn text(rows: &[PreviousNormal], f: &Fmt) -> String {
    let rows: Vec<[String; 4]> = rows
        .iter()
        .map(|r| {
            let (n, previous) = (
                nalgebra::Vector3::from(r.normal),
                nalgebra::Vector3::from(r.previous),
            );
            [
                r.label.clone(),
                format!("({})", f.list(&[n.x, n.y, n.z])),
                format!("({})", f.list(&[previous.x, previous.y, previous.z])),
                f.num(angle_between(&n, &previous).to_degrees()),
            ]
        })
        .collect();
    if rows.is_empty() {
        return String::new();
    }
    let head = [
        "contact".to_string(),
        "normal at t".to_string(),
        "normal at t − Δt".to_string(),
        "angle (°)".to_string(),
    ];
    let width = |c: usize| {
        (rows.iter().map(|r| &r[c]).chain([&head[c]]))
            .map(|s| s.chars().count())
            .max()
            .unwrap_or(0)
    };
    let widths = [width(0), width(1), width(2)];
    let line = |r: &[String; 4]| {
        let mut s = String::from("   ");
        for c in 0..3 {
            s += &r[c];
            s += &" ".repeat(widths[c] - r[c].chars().count() + 2);
        }
        s + &r[3] + "\n"
    };
    let mut out = String::from(
        "\nNormals from the previous frame\n   A penetrating contact's normal at t (the least \
         penetration, what the step resolves) beside the one from the closest points one \
         frame earlier (t − Δt), when the pair was still apart (Lecture IV Collisions).\n",
    );
    out += &line(&head);
    for r in &rows {
        out += &line(r);
    }
    out
}

/// The same for JSON: one object per contact with a previous-frame normal
/// (`contact` its number, `normal` at t, `previous_frame` at t − Δt,
/// `angle_degrees`).
pub fn json(rows: &[PreviousNormal]) -> serde_json::Value {
    let rows: Vec<serde_json::Value> = rows
        .iter()
        .map(|r| {
            let angle = angle_between(
                &nalgebra::Vector3::from(r.normal),
                &nalgebra::Vector3::from(r.previous),
            )
            .to_degrees();
            serde_json::json!({
                "contact": r.contact,
                "normal": r.normal,
                "previous_frame": r.previous,
                "angle_degrees": angle,
            })
        })
        .collect();
    serde_json::Value::Array(rows)
}
