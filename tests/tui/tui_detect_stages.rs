//! The detection screen's pictures and its way down (issue 24 item 7):
//! A - B drawn beside the shapes at the iteration on show, Enter on the
//! pair's contact goes to its stages as the resolver gets it and Esc comes
//! back, and `t` starts with the search the scene's continuous detection runs.

use crate::common;
use crate::common::tui::{app, draw, key, keys, screen, snapshot, term};

use contact_lab::tui::app::Mode;
use contact_lab::tui::screens::{Screen, Shown};
use ratatui::crossterm::event::KeyCode;

fn joined(rows: &[String]) -> String {
    rows.join("\n")
}

#[test]
fn the_minkowski_picture_at_80_by_24() {
    // EPA's first split of the two crossed boxes: the face closest to the
    // origin, w_k and d_k = n_k drawn in A - B under the shapes.
    let mut a = app("epa-edge-edge", false);
    key(&mut a, KeyCode::Char('d'));
    keys(&mut a, KeyCode::Right, 2);
    let mut t = term(80, 24);
    draw(&mut t, &a);
    snapshot("tui_detect_epa_edge_edge_80x24", &t);
}

#[test]
fn the_minkowski_picture_follows_the_iteration_and_x_cycles_the_pictures() {
    let mut a = app("gjk-separated", false);
    key(&mut a, KeyCode::Char('d'));
    let first = joined(&screen(&a, 100, 30));
    assert!(
        first.contains("A - B · GJK iteration 1 · xy plane"),
        "{first}"
    );
    assert!(
        first.contains("• simplex ✗ dropped w=w_k v=v_k d=d_k"),
        "{first}"
    );
    key(&mut a, KeyCode::End);
    let result = joined(&screen(&a, 100, 30));
    assert!(result.contains("A - B · result ·"), "{result}");
    key(&mut a, KeyCode::Char('x'));
    assert_eq!(a.detect.as_ref().unwrap().shown, Shown::Shapes);
    let shapes = joined(&screen(&a, 100, 30));
    assert!(!shapes.contains("A - B ·"), "{shapes}");
    assert!(
        shapes.contains("turned – cube · • closest points"),
        "{shapes}"
    );
    key(&mut a, KeyCode::Char('x'));
    let alone = joined(&screen(&a, 100, 30));
    assert!(alone.contains("A - B · result"), "{alone}");
    assert!(!alone.contains("turned – cube · •"), "{alone}");
    key(&mut a, KeyCode::Char('x'));
    assert_eq!(a.detect.as_ref().unwrap().shown, Shown::Both);
}

#[test]
fn v_traces_a_minus_b_again_in_the_next_plane() {
    let mut a = app("epa-edge-edge", false);
    key(&mut a, KeyCode::Char('d'));
    keys(&mut a, KeyCode::Right, 3);
    let before = a.detect.as_ref().unwrap().trace.pairs[0].minkowski.clone();
    key(&mut a, KeyCode::Char('v'));
    let d = a.detect.as_ref().unwrap();
    assert_eq!(d.stop, 3, "the iteration on show is kept");
    assert_ne!(d.trace.pairs[0].minkowski, before);
    assert!(joined(&screen(&a, 100, 30)).contains("A - B · EPA iteration 2 · yz plane"));
}

#[test]
fn enter_on_the_result_opens_the_contacts_stages_and_esc_comes_back() {
    let mut a = app("epa-edge-edge", false);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::End);
    let stop = a.detect.as_ref().unwrap().stop;
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.screen, Screen::Contact);
    let stages = joined(&screen(&a, 120, 40));
    assert!(
        stages.contains("step 0 › detection › step 1's resolver › contact 0 › overview"),
        "{stages}"
    );
    assert!(stages.contains("Contact 0: upper ↔ lower"), "{stages}");
    key(&mut a, KeyCode::Right);
    assert!(joined(&screen(&a, 120, 40)).contains("› contact 0 › "));
    key(&mut a, KeyCode::Esc);
    assert_eq!(a.screen, Screen::Detect);
    assert!(a.resolver.is_none() && a.opened.is_none());
    let d = a.detect.as_ref().unwrap();
    assert_eq!((d.pair, d.stop), (0, stop), "back where Enter was pressed");
    assert!(joined(&screen(&a, 120, 40)).contains("step 0 › detection"));
    key(&mut a, KeyCode::Esc);
    assert_eq!(a.screen, Screen::Run);
    assert_eq!(a.run.as_ref().unwrap().frame, 0);
}

#[test]
fn enter_opens_the_contact_the_run_screen_opens_in_the_next_step() {
    // The bodies after step 0 are what step 1 detects and resolves.
    let mut a = app("cylinder-on-box", false);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::End);
    // The can's manifold: Tab picks its second contact.
    let n = a.detect.as_ref().unwrap().trace.pairs[0].contacts.len();
    assert!(n >= 2, "a manifold of {n}");
    key(&mut a, KeyCode::Tab);
    let detected = a.detect.as_ref().unwrap().trace.pairs[0].contacts[1];
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.screen, Screen::Contact);
    let k = a.contact;
    let from_detection = a.opened.as_ref().unwrap().lesson.contacts[k].clone();
    // It is the contact the detection found: its point and depth.
    for i in 0..3 {
        let (q, p) = (detected.point[i], from_detection.point[i]);
        assert!((q - p).abs() < 1e-9, "{q} vs {p}: {from_detection:?}");
    }
    assert!((detected.penetration - from_detection.penetration).abs() < 1e-12);
    key(&mut a, KeyCode::Esc);
    key(&mut a, KeyCode::Esc);
    // The run screen's way: step 1, its resolver, that contact selected.
    key(&mut a, KeyCode::Right);
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.screen, Screen::Resolver);
    for _ in 0..8 {
        if a.resolver.as_ref().unwrap().selected == k {
            break;
        }
        key(&mut a, KeyCode::Tab);
    }
    key(&mut a, KeyCode::Enter);
    assert_eq!((a.screen, a.contact), (Screen::Contact, k));
    let from_run = a.opened.as_ref().unwrap().lesson.contacts[k].clone();
    assert_eq!(format!("{from_detection:?}"), format!("{from_run:?}"));
}

#[test]
fn the_picture_is_the_svgs_geometry_at_the_iteration_on_show() {
    use contact_lab::render::detect::minkowski::minkowski;
    let mut a = app("gjk-separated", false);
    key(&mut a, KeyCode::Char('d'));
    let d = a.detect.as_ref().unwrap();
    let p = &d.trace.pairs[0];
    // GJK iteration 2 (as the screen prints it): w_k = (0.5, -0.207107, 0),
    // the simplex of three with the second point dropped.
    let m = minkowski(d.trace.plane, p, 1);
    let w = m.support.unwrap();
    assert!(
        (w[0] - 0.5).abs() < 1e-6 && (w[1] + 0.207107).abs() < 1e-6,
        "{w:?}"
    );
    assert_eq!((m.simplex.len(), m.dropped.clone()), (3, vec![1]));
    // d_k = (-0.146447, -0.353553): drawn from the origin along it.
    let tip = m.direction.unwrap();
    let cross = tip[0] * -0.353553 - tip[1] * -0.146447;
    assert!(cross.abs() < 1e-6 && tip[0] < 0.0, "{tip:?}");
    // The result: v, the distance (√2 - 1)/2 from the origin.
    let end = minkowski(d.trace.plane, p, usize::MAX);
    let (v, label) = end.arrow.unwrap();
    assert_eq!(label, "v");
    assert!(
        (v[0].hypot(v[1]) - (2f64.sqrt() - 1.0) / 2.0).abs() < 1e-9,
        "{v:?}"
    );
    assert!(end.direction.is_none() && end.support.is_none());
}

#[test]
fn a_pair_without_a_contact_says_so_on_enter() {
    let mut a = app("gjk-separated", false);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::End);
    key(&mut a, KeyCode::Enter);
    assert_eq!(a.screen, Screen::Detect);
    let rows = joined(&screen(&a, 100, 30));
    assert!(
        rows.contains("turned – cube gives the resolver no contact at this step"),
        "{rows}"
    );
}

#[test]
fn t_starts_with_the_scenes_continuous_detection() {
    let text = include_str!("../../lessons/scenes/bullet-wall.toml")
        .replace("steps = 30\n", "steps = 30\nccd = \"conservative\"\n");
    assert!(text.contains("ccd = \"conservative\""));
    let file = common::scratch("tui-detect-ccd").join("bullet-wall-ccd.toml");
    std::fs::write(&file, text).unwrap();
    let mut a = app(file.to_str().unwrap(), false);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('t'));
    let rows = joined(&screen(&a, 300, 40));
    assert!(rows.contains("by conservative"), "{rows}");
    assert!(
        rows.contains(
            "The scene's continuous detection (its ccd knob) searches by conservative advancement;"
        ),
        "{rows}"
    );
    key(&mut a, KeyCode::Char('m'));
    let rows = joined(&screen(&a, 300, 40));
    assert!(rows.contains("by bisection"), "{rows}");
    assert!(
        rows.contains(
            "m switched from the scene's search (conservative advancement, its ccd knob)."
        ),
        "{rows}"
    );
    // Without the knob: bisection, and it says why.
    let mut a = app("bullet-wall", false);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::Char('t'));
    let rows = joined(&screen(&a, 300, 40));
    assert!(
        rows.contains(
            "The scene runs no continuous detection (ccd none): bisection, the lecture's;"
        ),
        "{rows}"
    );
}

#[test]
fn w_on_a_contact_from_the_detection_names_the_step_that_resolves_it() {
    let mut a = app("epa-edge-edge", false);
    key(&mut a, KeyCode::Char('d'));
    key(&mut a, KeyCode::End);
    key(&mut a, KeyCode::Enter);
    key(&mut a, KeyCode::Char('w'));
    let Mode::Write { input, .. } = &a.mode else {
        panic!("w asks for a file name")
    };
    // Step 1 (t = 1/60 s) resolves what the detection after step 0 found.
    assert_eq!(
        input,
        "epa-edge-edge-t0.017-step1-position-it0-contact-0.md"
    );
}
