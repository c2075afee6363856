//! The detection screen (issues 24 and 25): `d` on the run opens the step's
//! detection, → steps through the pair's GJK and EPA iterations, `t` shows
//! its time of collision, Esc goes back to the run at the same step.

use crate::common::tui::{app, draw, key, keys, screen, snapshot, term};

use contact_lab::tui::app::Mode;
use contact_lab::tui::screens::{Screen, DETECT_KEYS};
use ratatui::crossterm::event::KeyCode;

fn joined(rows: &[String]) -> String {
    rows.join("\n")
}

#[test]
fn d_opens_the_detection_and_right_steps_through_the_gjk_iterations() {
    let mut a = app("gjk-separated", false);
    assert_eq!(a.screen, Screen::Run);
    key(&mut a, KeyCode::Char('d'));
    assert_eq!(a.screen, Screen::Detect);
    let first = joined(&screen(&a, 200, 40));
    assert!(first.contains("turned – cube"), "{first}");
    assert!(first.contains("GJK iteration 1 of 3"), "{first}");
    // The result: the distance GJK finds, 0.207107 (√2 - 1)/2 ≈ 0.2071.
    assert!(first.contains("separated at distance 0.207107"), "{first}");
    // Iteration 1's support point, as `detect` prints it.
    assert!(
        first.contains("(1.5, -0.207107, 0) = (1, 0.292893, 0.5) - (-0.5, 0.5, 0.5)"),
        "{first}"
    );
    key(&mut a, KeyCode::Right);
    let second = joined(&screen(&a, 200, 40));
    assert!(second.contains("GJK iteration 2 of 3"), "{second}");
    assert!(
        second.contains("(0.5, -0.207107, 0) = (1, 0.292893, 0.5) - (0.5, 0.5, 0.5)"),
        "{second}"
    );
    keys(&mut a, KeyCode::Right, 5);
    let last = joined(&screen(&a, 200, 40));
    assert!(last.contains("result ·"), "{last}");
    assert!(!last.contains("GJK iteration"), "{last}");
}

#[test]
fn esc_goes_back_to_the_run_at_the_same_step() {
    let mut a = app("gjk-separated", false);
    keys(&mut a, KeyCode::Right, 2);
    key(&mut a, KeyCode::Char('d'));
    assert_eq!(a.screen, Screen::Detect);
    assert!(joined(&screen(&a, 200, 40)).contains("step 2 › detection"));
    key(&mut a, KeyCode::Esc);
    assert_eq!(a.screen, Screen::Run);
    assert!(a.detect.is_none());
    assert_eq!(a.run.as_ref().unwrap().frame, 2);
    assert!(!a.quit);
}

#[test]
fn t_shows_the_bullets_time_of_collision_test_by_test_scan_first() {
    let mut a = app("bullet-wall", false);
    key(&mut a, KeyCode::Char('d'));
    assert_eq!(a.screen, Screen::Detect);
    key(&mut a, KeyCode::Char('t'));
    let rows = joined(&screen(&a, 200, 40));
    // The scan's 25 pieces are the first tests, then bisection's 15: the
    // 40 the outcome counts, as `detect --toi` prints them.
    assert!(rows.contains("test 1 of 40"), "{rows}");
    assert!(
        rows.contains("Test 1 of 40: scan piece 1: [0, 0.000198413] apart at its end"),
        "{rows}"
    );
    assert!(
        rows.contains("time of collision: t = 0.0048008 s into the step (converged, 40 tests)"),
        "{rows}"
    );
    assert!(rows.contains("←→ test  t Esc iterations"), "{rows}");
    keys(&mut a, KeyCode::Right, 24);
    let rows = joined(&screen(&a, 200, 40));
    assert!(
        rows.contains("Test 25 of 40: scan piece 25: [0.0047619, 0.00496032] intersects at its end → bisect it"),
        "{rows}"
    );
    key(&mut a, KeyCode::Right);
    let rows = joined(&screen(&a, 200, 40));
    assert!(rows.contains("test 26 of 40"), "{rows}");
    assert!(rows.contains("midpoint 0.00486111 intersects"), "{rows}");
    // Esc leaves the time of collision for the pair's iterations, then the run.
    key(&mut a, KeyCode::Esc);
    assert!(a.detect.as_ref().is_some_and(|d| d.toi.is_none()));
    key(&mut a, KeyCode::Esc);
    assert_eq!(a.screen, Screen::Run);
}

#[test]
fn the_help_lists_the_detection_keys() {
    let mut a = app("gjk-separated", false);
    key(&mut a, KeyCode::Char('?'));
    let run_help = joined(&screen(&a, 120, 50));
    assert!(run_help.contains("this step's detection"), "{run_help}");
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('?'));
    assert_eq!(a.mode, Mode::Help);
    let help = joined(&screen(&a, 120, 50));
    assert!(help.contains("Keys · detection"), "{help}");
    let keys_page = include_str!("../../docs/tui.md");
    for (k, what) in contact_lab::tui::keys::help(DETECT_KEYS) {
        assert!(help.contains(what), "{what} is not in the help:\n{help}");
        assert!(
            keys_page.contains(&format!("| {k} | {what} |")),
            "docs/tui.md lacks {k}"
        );
    }
}

#[test]
fn the_detection_table_binds_each_key_once() {
    use contact_lab::tui::keys::find;
    let mut seen = Vec::new();
    for row in DETECT_KEYS {
        for (code, bound) in row.keys {
            assert!(!seen.contains(code), "{code:?} bound twice");
            seen.push(*code);
            assert_eq!(find(DETECT_KEYS, *code), Some(*bound), "{}", row.label);
        }
    }
}

#[test]
fn the_detection_screen_at_100_by_30() {
    let mut a = app("gjk-separated", false);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Right);
    let mut t = term(100, 30);
    draw(&mut t, &a);
    snapshot("tui_detect_gjk_separated_100x30", &t);
}

#[test]
fn the_time_of_collision_picture_moves_the_bullet_to_the_trial_time() {
    let mut a = app("bullet-wall", false);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('t'));
    let first = joined(&screen(&a, 100, 30));
    // The first test: the scan's first piece, tested at its end.
    assert!(
        first.contains("bullet – wall · t = 0.000198413 s ·"),
        "{first}"
    );
    key(&mut a, KeyCode::End);
    let last = joined(&screen(&a, 100, 30));
    // After the tests: the pair at the time of collision.
    assert!(last.contains("bullet – wall · t = 0.0048008 s ·"), "{last}");
    assert!(last.contains("All 40 tests done."), "{last}");
}

#[test]
fn after_gjk_come_the_epa_iterations_then_the_depth() {
    let mut a = app("epa-edge-edge", false);
    key(&mut a, KeyCode::Char('d'));
    keys(&mut a, KeyCode::Right, 2);
    let epa = joined(&screen(&a, 200, 40));
    assert!(epa.contains("EPA iteration 1 of 4"), "{epa}");
    assert!(epa.contains("faces: -2 +4"), "{epa}");
    key(&mut a, KeyCode::End);
    let end = joined(&screen(&a, 200, 40));
    assert!(end.contains("depth 0.05 m along normal (0, 1, 0)"), "{end}");
    assert!(end.contains("• contacts"), "{end}");
    key(&mut a, KeyCode::Home);
    assert!(joined(&screen(&a, 200, 40)).contains("GJK iteration 1 of 2"));
}

#[test]
fn m_switches_the_search_to_conservative_advancement() {
    let mut a = app("bullet-wall", false);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('t'));
    key(&mut a, KeyCode::Char('m'));
    let rows = joined(&screen(&a, 200, 40));
    assert!(rows.contains("by conservative advancement."), "{rows}");
    // Advancement's first test: the distance at the step's start.
    assert!(rows.contains("Test 1 of 2:"), "{rows}");
    assert!(rows.contains("t = 0: distance"), "{rows}");
    assert!(rows.contains("time of collision: t = 0.0048"), "{rows}");
    key(&mut a, KeyCode::Char('m'));
    assert!(joined(&screen(&a, 200, 40)).contains("by bisection"));
}

#[test]
fn a_ruled_out_pair_has_its_narrow_phase_run_anyway() {
    // bullet-wall at step 0: the boxes are apart along x, so the broad phase
    // rules the pair out; its GJK still runs, as `detect --pair` runs it.
    let mut a = app("bullet-wall", false);
    key(&mut a, KeyCode::Char('d'));
    let rows = joined(&screen(&a, 200, 40));
    assert!(
        rows.contains("bullet – wall: ruled out, their bounding boxes are apart along x"),
        "{rows}"
    );
    assert!(
        rows.contains("the broad phase rules this pair out"),
        "{rows}"
    );
    assert!(rows.contains("GJK iteration 1 of 2"), "{rows}");
    assert!(rows.contains("separated at distance 0.48"), "{rows}");
}

#[test]
fn a_mesh_pair_says_why_it_has_no_single_minkowski_difference() {
    // The bowl is a mesh: its pair is decided triangle by triangle, and the
    // A - B panel names that, not a half-space (which it is not).
    let mut a = app("mesh-bowl-ball", false);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Char('d'));
    assert_eq!(a.screen, Screen::Detect);
    let shown = joined(&screen(&a, 200, 40));
    assert!(shown.contains("ball – bowl: mesh"), "{shown}");
    assert!(
        shown.contains("a mesh is not convex: no single A - B"),
        "{shown}"
    );
    assert!(!shown.contains("half-space"), "{shown}");
}

#[test]
fn a_mesh_pair_walks_its_tree_node_by_node_then_each_candidate_triangle() {
    // The stops: each node the traversal visited, then each candidate
    // triangle's narrow phase, then the result; each shows the trace's values.
    let mut a = app("mesh-bowl-ball", false);
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Char('d'));
    let m = a.detect.as_ref().unwrap().trace.pairs[0]
        .mid_phase
        .clone()
        .expect("the bowl pair has a mid phase");
    let (nodes, tris) = (m.nodes.len(), m.triangles.len());
    assert!(nodes > 1 && tris > 1, "{nodes} nodes, {tris} triangles");
    let first = joined(&screen(&a, 200, 40));
    assert!(
        first.contains(&format!("tree node 1 of {nodes} visited")),
        "{first}"
    );
    assert!(
        first.contains(&format!("node: {}", m.nodes[0].node)),
        "{first}"
    );
    let pushed = m.nodes[0]
        .children
        .iter()
        .map(|c| c.to_string())
        .collect::<Vec<_>>()
        .join(", ");
    assert!(first.contains(&format!("then: push {pushed}")), "{first}");
    key(&mut a, KeyCode::Right);
    let second = joined(&screen(&a, 200, 40));
    assert!(
        second.contains(&format!("tree node 2 of {nodes} visited")),
        "{second}"
    );
    assert!(
        second.contains(&format!("node: {}", m.nodes[1].node)),
        "{second}"
    );
    // Past the nodes: the first candidate triangle, its id and normal rule.
    keys(&mut a, KeyCode::Right, nodes - 1);
    let tri = joined(&screen(&a, 200, 40));
    assert!(
        tri.contains(&format!("candidate triangle 1 of {tris}")),
        "{tri}"
    );
    assert!(
        tri.contains(&format!("triangle: {}", m.triangles[0].triangle)),
        "{tri}"
    );
    assert!(tri.contains("internal edge: "), "{tri}");
    // End: the result, with the tree's summary.
    key(&mut a, KeyCode::End);
    let last = joined(&screen(&a, 200, 40));
    assert!(last.contains("result ·"), "{last}");
    assert!(
        last.contains(&format!(
            "Mesh tree: {nodes} node(s) visited, {tris} candidate triangle(s) tested"
        )),
        "{last}"
    );
}
