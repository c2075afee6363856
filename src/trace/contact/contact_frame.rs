//! The `contact_frame` stage described: the basis d̂, t₀, t₁ and the arms r.

use nalgebra::Vector3;

use super::builder::{SolvedContact, B, SUB};
use crate::physics::frame::GuessAxis;
use crate::physics::step::previous_frame::angle_between;
use crate::physics::StageId;
use crate::trace::Step;

/// The contact basis (Millington's `makeOrthonormalBasis`) and r_i = q - p_i.
pub fn contact_frame(c: &SolvedContact) -> Step {
    let mut b = B::new(StageId::ContactFrame);
    let f = &c.solution.frame;
    let d = f.normal();
    b.input("q", c.problem.contact.point);
    b.input("d", d);
    let guess = match f.guess {
        GuessAxis::X => (Vector3::x(), "x"),
        GuessAxis::Y => (Vector3::y(), "y"),
    };
    b.input("guess", guess.0);
    b.value("contact_to_world", f.contact_to_world);
    b.value("normal", d);
    b.value("tangent0", f.contact_to_world.column(1).into_owned());
    b.value("tangent1", f.contact_to_world.column(2).into_owned());
    b.f(
        "t₀",
        "â × d̂ / |â × d̂|",
        Some("{guess} × {d} / |{guess} × {d}|"),
        Some("tangent0"),
    );
    b.f("t₁", "d̂ × t₀", Some("{d} × {tangent0}"), Some("tangent1"));
    b.f("C", "[d̂ t₀ t₁]", None::<&str>, Some("contact_to_world"));
    for i in c.movable() {
        b.input(slot!(i => "p" N), c.body(i).position);
        b.value(slot!(i => "r" N), c.r(i));
        b.f(
            slot!(i => "r" S),
            slot!(i => "q - p" S),
            Some(slot!(i => "{q} - {p" N "}")),
            Some(slot!(i => "r" N)),
        );
    }
    b.note(format!(
        "The guess axis â is world {} because |d.x| {} |d.y|; the basis columns d̂, t₀, t₁ are orthonormal and right-handed (t₁ = d̂ × t₀).",
        guess.1,
        if guess.1 == "y" { ">" } else { "≤" }
    ));
    if let Some(previous) = c.names.previous_normal {
        previous_frame(&mut b, &d, &previous.into());
    }
    let length = c.names.written.normal_length;
    if (length - 1.0).abs() > 1e-12 {
        b.input("normal_length_deviation", length - 1.0);
        b.note("The normal as written has length 1 + ({normal_length_deviation}); it was normalised before use.");
    }
    for i in c.movable() {
        let n = i + 1;
        if let Some(digits) = f.r_digits(c.problem, i).filter(|d| *d < 12.0) {
            b.input(slot!(i => "r" N "_digits"), digits.floor());
            b.note(format!(
                "q and p{s} lie far from the origin compared with r{s}: each is stored to about ε·|x|, so r{s} = q - p{s} keeps only about {{r{n}_digits}} significant digits of f64's 16 (the subtraction itself is exact).",
                s = SUB[i]
            ));
        }
    }
    for i in c.immovable_named() {
        b.note(format!(
            "{} is immovable (m = ∞): it has no r and contributes nothing.",
            c.name(i)
        ));
    }
    b.done()
}

/// A scene step's penetrating contact: its normal d̂ at t beside the one
/// from the closest points at t − Δt, and the angle between them.
fn previous_frame(b: &mut B, d: &Vector3<f64>, previous: &Vector3<f64>) {
    b.input("d_prev", *previous);
    b.value("previous_frame_normal", *previous);
    b.value(
        "normal_angle_degrees",
        angle_between(d, previous).to_degrees(),
    );
    b.f(
        "θ",
        "acos(d̂ · d̂₋)",
        Some("acos({d} · {d_prev})"),
        Some("normal_angle_degrees"),
    );
    b.note(
        "Two normals for this penetrating contact: d̂ at t, the least penetration the step's detection found; d̂₋ from the closest points one frame earlier (t − Δt), when the pair was still apart: the direction it came from, which Lecture IV Collisions proposes for fast motion. They differ by θ = {normal_angle_degrees}°; the stages below use d̂.",
    );
}
