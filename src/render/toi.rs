//! `detect --toi` as text and JSON (docs/ccd.md, `detect SCENE --toi`: each pair's
//! `toi` with `method`, `time` and `iterations` of `t0`, `t1`, `hit`).

use serde_json::{json, Value};

use crate::format::Fmt;
use crate::physics::detect::ToiMethod;
use crate::trace::toi::{end_name, end_text, method_words, DetectToi, PairToi, Test, Trial};

fn vec3(f: &Fmt, v: &[f64; 3]) -> String {
    format!("({}, {}, {})", f.num(v[0]), f.num(v[1]), f.num(v[2]))
}

fn yes(b: bool) -> &'static str {
    if b {
        "yes"
    } else {
        "no"
    }
}

/// The run in words: one block per pair.
pub fn text(d: &DetectToi, f: &Fmt) -> String {
    let mut s = format!(
        "{}: step {} (t = {} s to {} s), time of collision by {}\n",
        d.lesson,
        d.step,
        f.num(d.time),
        f.num(d.time + d.dt),
        method_words(d.method)
    );
    if d.pairs.is_empty() {
        s.push_str("no pair's movement bounds meet over the step: nothing to search\n");
    }
    for p in &d.pairs {
        s.push('\n');
        pair_text(&mut s, p, f);
        if p.method != d.method {
            s.push_str(&format!(
                "  ({}'s scan would need more than {} pieces to certify the step: {} instead)\n",
                crate::knobs::toi_method_name(d.method),
                crate::physics::detect::toi_sweep::MAX_PIECES,
                crate::knobs::toi_method_name(p.method)
            ));
        }
    }
    s
}

fn pair_text(s: &mut String, p: &PairToi, f: &Fmt) {
    s.push_str(&format!("{} ↔ {}\n", p.a, p.b));
    s.push_str(&format!(
        "  movement bounds: swept AABBs overlap: {}; swept spheres meet: {}\n",
        yes(p.aabbs_overlap),
        yes(p.spheres_meet)
    ));
    if !p.record.scan.is_empty() {
        let hit = p.record.scan.iter().find(|x| x.hit);
        s.push_str(&format!(
            "  scan: {} piece{} tested, each {} s long; {}\n",
            p.record.scan.len(),
            if p.record.scan.len() == 1 { "" } else { "s" },
            f.num(p.record.scan[0].t1 - p.record.scan[0].t0),
            match hit {
                Some(x) => format!(
                    "[{}, {}] ends intersecting: bisected",
                    f.num(x.t0),
                    f.num(x.t1)
                ),
                None => "none ends intersecting".into(),
            }
        ));
    }
    for t in &p.record.tests() {
        s.push_str(&format!("  {}\n", test_line(p, t, f)));
    }
    s.push_str(&format!("  {}\n", outcome_line(p, f)));
    // What gave the normals: EPA and the closest points, or the plane.
    let (end_by, start_by) = if p.half_space {
        (
            "the half-space's normal, the depth in closed form",
            "the half-space's normal",
        )
    } else {
        ("EPA", "closest points at the step's start")
    };
    s.push_str(&format!(
        "  normal at the step's end ({end_by}): {}\n",
        p.at_end
            .map_or("none: apart at the step's end".into(), |o| format!(
                "{}, depth {} m",
                vec3(f, &o.normal),
                f.num(o.depth)
            ))
    ));
    s.push_str(&format!(
        "  normal one frame earlier ({start_by}): {}\n",
        p.previous_frame
            .map_or("none: overlapping at the step's start".into(), |n| vec3(
                f, &n
            ))
    ));
}

/// One test of the pair's search (a scan piece or a trial), as the text's
/// line says it.
pub fn test_line(p: &PairToi, t: &Test, f: &Fmt) -> String {
    match t {
        Test::Scan { index, piece } => format!(
            "scan piece {}: [{}, {}] {}",
            index + 1,
            f.num(piece.t0),
            f.num(piece.t1),
            if piece.hit {
                "intersects at its end → bisect it"
            } else {
                "apart at its end"
            }
        ),
        Test::Trial(x) => trial_line(p, x, f),
    }
}

/// `n` tests, singular or plural.
pub fn tests_count(n: usize) -> String {
    format!("{n} {}", if n == 1 { "test" } else { "tests" })
}

/// One trial of the pair's search, as the text's line says it.
pub fn trial_line(p: &PairToi, t: &Trial, f: &Fmt) -> String {
    match p.method {
        ToiMethod::Bisection => format!(
            "[t₀, t₁] = [{}, {}]: midpoint {} {} → keep [{}, {}]",
            f.num(t.t0),
            f.num(t.t1),
            f.num(t.trial),
            if t.hit { "intersects" } else { "apart" },
            f.num(if t.hit { t.t0 } else { t.trial }),
            f.num(if t.hit { t.trial } else { t.t1 })
        ),
        ToiMethod::Conservative => format!(
            "t = {}: distance {} m{}",
            f.num(t.t0),
            f.num(t.distance),
            if t.hit {
                " within the tolerance: stop".to_string()
            } else {
                format!(
                    " → advance to t = {} (distance / closing bound)",
                    f.num(t.t1)
                )
            }
        ),
    }
}

/// The search's outcome line: the time of collision and why it ended.
pub fn outcome_line(p: &PairToi, f: &Fmt) -> String {
    format!(
        "time of collision: {} ({}, {})",
        p.time.map_or("none".into(), |t| format!(
            "t = {} s into the step",
            f.num(t)
        )),
        end_text(p.end),
        tests_count(p.tests)
    )
}

/// The run as JSON.
pub fn json(d: &DetectToi) -> String {
    let pairs: Vec<Value> = d.pairs.iter().map(pair_json).collect();
    let doc = json!({
        "lesson": d.lesson,
        "step": d.step,
        "time": d.time,
        "dt": d.dt,
        "pairs": pairs,
    });
    serde_json::to_string_pretty(&doc).expect("JSON") + "\n"
}

fn pair_json(p: &PairToi) -> Value {
    let iterations: Vec<Value> = p
        .record
        .trials
        .iter()
        .map(|t| json!({ "t0": t.t0, "t1": t.t1, "trial": t.trial, "hit": t.hit, "distance": t.distance }))
        .collect();
    let scan: Vec<Value> = p
        .record
        .scan
        .iter()
        .map(|x| json!({ "t0": x.t0, "t1": x.t1, "hit": x.hit }))
        .collect();
    json!({
        "a": p.a,
        "b": p.b,
        "movement_bounds": { "aabbs_overlap": p.aabbs_overlap, "spheres_meet": p.spheres_meet },
        "toi": {
            "method": crate::knobs::toi_method_name(p.method),
            "time": p.time,
            "end": end_name(p.end),
            "tests": p.tests,
            "scan": scan,
            "iterations": iterations,
        },
        "normals": {
            "epa_at_end": p.at_end.map(|o| json!({ "normal": o.normal, "depth": o.depth })),
            "previous_frame": p.previous_frame,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::detect::ToiEnd;
    use crate::trace::toi::{Piece, SearchRecord};

    #[test]
    fn one_scan_piece_is_one_test_in_the_text_and_the_outcome() {
        let p = PairToi {
            a: "a".into(),
            b: "b".into(),
            aabbs_overlap: true,
            spheres_meet: true,
            method: ToiMethod::Bisection,
            time: None,
            end: ToiEnd::NoHitInStep,
            tests: 1,
            record: SearchRecord {
                scan: vec![Piece {
                    t0: 0.0,
                    t1: 0.01,
                    hit: false,
                }],
                trials: vec![],
            },
            at_end: None,
            previous_frame: None,
            half_space: false,
        };
        let f = Fmt::new(6);
        assert_eq!(p.record.tests().len(), p.tests);
        assert_eq!(
            outcome_line(&p, &f),
            "time of collision: none (no collision in the step, 1 test)"
        );
        let mut s = String::new();
        pair_text(&mut s, &p, &f);
        assert!(
            s.contains("  scan piece 1: [0, 0.01] apart at its end\n"),
            "{s}"
        );
    }
}
