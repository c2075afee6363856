//! One rule for a GJK row (docs/detect.md): over every embedded lesson and
//! scene `detect` accepts, with the scene's narrow phase and with GJK for
//! every pair, each row's bound is |v_k|² − v_k·w_k of the v_k and w_k that
//! same row shows — in the JSON, in the table the text, Markdown and LaTeX
//! lay out (read here from the Markdown), and in the TUI's lines — and its
//! d_k is −v_k, its v_k+1 the next row's v_k.

use crate::common;

use contact_lab::format::Fmt;
use contact_lab::lesson::Lesson;
use contact_lab::physics::collide::NarrowPhase;
use contact_lab::physics::step::Simulation;
use contact_lab::render::detect::steps::{stop_lines, stops, Stop};
use contact_lab::render::detect::{json, markdown};
use contact_lab::session::detect_trace;
use contact_lab::trace::detect::DetectTrace;
use contact_lab::trace::Plane;

/// The detection `detect ID` shows (step 0), the narrow phase as given.
fn trace(lesson: &Lesson, narrow: Option<NarrowPhase>) -> DetectTrace {
    let mut params = lesson.sim_params().unwrap_or_default();
    if let Some(n) = narrow {
        params.narrow_phase = n;
    }
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson
        .simulation
        .as_ref()
        .map(|s| s.materials.clone())
        .unwrap_or_else(|| vec![Default::default(); world.bodies.len()]);
    let sim = Simulation::new(world, params, materials);
    detect_trace(&sim, lesson, 0, Plane::Xy, None)
}

fn v3(x: &serde_json::Value) -> [f64; 3] {
    let a = x.as_array().expect("a vector");
    [0, 1, 2].map(|k| a[k].as_f64().unwrap())
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The numbers of a printed vector `(x, y, z)` (the first one in `s`).
fn printed_vector(s: &str) -> [f64; 3] {
    let open = s.find('(').unwrap_or_else(|| panic!("no vector in {s:?}"));
    let close = open + s[open..].find(')').unwrap();
    let parts: Vec<f64> = s[open + 1..close]
        .split(", ")
        .map(|x| x.parse().unwrap_or_else(|_| panic!("{x:?} in {s:?}")))
        .collect();
    [parts[0], parts[1], parts[2]]
}

/// The bound a row prints: the number before ` (ε …)`.
fn printed_bound(s: &str) -> f64 {
    let n = s.split(" (ε").next().unwrap().trim();
    n.parse().unwrap_or_else(|_| panic!("bound {s:?}"))
}

/// |v|² − v·w of printed v and w agrees with the printed bound, to the
/// digits printed (6 significant: each printed number is off by 5e-6 of
/// itself at most).
fn agrees(bound: f64, v: [f64; 3], w: [f64; 3], what: &str) {
    let expect = dot(v, v) - dot(v, w);
    let scale = dot(v, v) + dot(v, v).sqrt() * dot(w, w).sqrt();
    assert!(
        (bound - expect).abs() <= 2e-5 * scale + 1e-9,
        "{what}: prints |v|² - v·w = {bound} beside v = {v:?}, w = {w:?} (|v|² - v·w = {expect})"
    );
}

/// The GJK tables of a Markdown page: for each pair, its rows' cells.
fn markdown_gjk_rows(md: &str) -> Vec<Vec<Vec<String>>> {
    let mut out = vec![];
    let mut lines = md.lines();
    while let Some(l) = lines.next() {
        if l != "### GJK" {
            continue;
        }
        let rows: Vec<Vec<String>> = lines
            .by_ref()
            .skip_while(|l| l.is_empty())
            .take_while(|l| l.starts_with('|'))
            .skip(2)
            .map(|l| {
                l.trim_start_matches("| ")
                    .trim_end_matches(" |")
                    .split(" | ")
                    .map(String::from)
                    .collect()
            })
            .collect();
        out.push(rows);
    }
    out
}

#[test]
fn every_gjk_row_shows_the_v_w_and_bound_of_one_iteration() {
    let f = Fmt::new(6);
    let mut rows_checked = 0;
    for lesson in common::all_lessons() {
        for narrow in [None, Some(NarrowPhase::Gjk)] {
            let t = trace(&lesson, narrow);
            let what = format!("{} ({narrow:?})", lesson.id);
            let doc: serde_json::Value = serde_json::from_str(&json(&t)).unwrap();
            let tables = markdown_gjk_rows(&markdown(&t, &f));
            let with_gjk: Vec<_> = doc["pairs"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|p| !p["gjk"].is_null())
                .collect();
            assert_eq!(tables.len(), with_gjk.len(), "{what}");
            for ((p, table), trace_pair) in with_gjk
                .iter()
                .zip(&tables)
                .zip(t.pairs.iter().filter(|p| p.gjk.is_some()))
            {
                let its = p["gjk"]["iterations"].as_array().unwrap();
                assert_eq!(table.len(), its.len(), "{what}");
                for (k, (it, row)) in its.iter().zip(table).enumerate() {
                    let at = format!("{what}, {} – {}, row {}", p["a"], p["b"], k + 1);
                    let (v, w, d) = (v3(&it["v"]), v3(&it["support"]), v3(&it["direction"]));
                    // JSON: full f64.
                    let bound = it["bound"].as_f64().unwrap();
                    let expect = dot(v, v) - dot(v, w);
                    let scale = dot(v, v) + dot(v, v).sqrt() * dot(w, w).sqrt();
                    assert!((bound - expect).abs() <= 1e-12 * scale, "{at}: JSON");
                    assert_eq!(d, v.map(|x| -x), "{at}: d_k = -v_k");
                    if let Some(next) = its.get(k + 1) {
                        assert_eq!(it["next"], next["v"], "{at}: v_k+1");
                    }
                    // The table's row: k, v_k, d_k, w_k = …, bound, simplex, v_k+1.
                    assert_eq!(row[0], (k + 1).to_string(), "{at}");
                    agrees(
                        printed_bound(&row[4]),
                        printed_vector(&row[1]),
                        printed_vector(&row[3]),
                        &format!("{at}: table"),
                    );
                    // The TUI's lines of the same stop.
                    let stop = stops(trace_pair)
                        .into_iter()
                        .position(|s| s == Stop::Gjk(k))
                        .unwrap();
                    let (_, lines) = stop_lines(trace_pair, stops(trace_pair)[stop], &f);
                    let line = |head: &str| {
                        lines
                            .iter()
                            .find_map(|l| l.strip_prefix(&format!("{head}: ")))
                            .unwrap_or_else(|| panic!("{at}: no {head} in {lines:?}"))
                            .to_string()
                    };
                    agrees(
                        printed_bound(&line("|v_k|² - v_k·w_k")),
                        printed_vector(&line("v_k")),
                        printed_vector(&line("w_k = s_A(d_k) - s_B(-d_k)")),
                        &format!("{at}: TUI"),
                    );
                    rows_checked += 1;
                }
            }
        }
    }
    assert!(rows_checked > 50, "only {rows_checked} rows");
}
