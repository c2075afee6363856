//! `detect --figure --iteration K [--phase gjk|epa]`: the figure draws the
//! chosen GJK or EPA iteration (its simplex or closest face, v_k, w_k, d_k),
//! a K outside the pair's iterations is a usage error naming their count.

use crate::common;
use crate::common::cli::run;

/// The figure `detect ARGS --figure F` writes.
fn figure(name: &str, args: &[&str]) -> String {
    let svg = common::scratch(name).join("pair.svg");
    let out = run(&[&["detect"], args, &["--figure", svg.to_str().unwrap()]].concat());
    assert_eq!(out.code, Some(0), "{args:?}: {}", out.stderr);
    std::fs::read_to_string(&svg).unwrap()
}

/// The orange simplex or face points (`<circle … r="4" …>`), filled and hollow.
fn simplex_points(svg: &str) -> (usize, usize) {
    let dots = svg.lines().filter(|l| l.contains(r#"r="4""#));
    let (hollow, filled): (Vec<&str>, Vec<&str>) = dots.partition(|l| l.contains("white"));
    (filled.len(), hollow.len())
}

#[test]
fn the_chosen_gjk_iteration_is_drawn_and_k_changes_the_picture() {
    let first = figure("iteration-1", &["epa-edge-edge", "--iteration", "1"]);
    let second = figure("iteration-2", &["epa-edge-edge", "--iteration", "2"]);
    assert!(first.contains(">GJK iteration 1 of 2: "), "{first}");
    assert!(second.contains(">GJK iteration 2 of 2: "), "{second}");
    for svg in [&first, &second] {
        for label in [">v_k", ">w_k<", ">d_k<", ">O<"] {
            assert!(svg.contains(label), "no {label}");
        }
    }
    // Iteration 1's simplex is a segment, iteration 2's a triangle (the
    // text's simplex column: 2 points, then 3).
    assert_eq!(simplex_points(&first), (2, 0));
    assert_eq!(simplex_points(&second), (3, 0));
    assert_ne!(first, second);
    // Without --iteration: the last EPA face and -δn, as before.
    let last = figure("iteration-last", &["epa-edge-edge"]);
    assert!(last.contains(">-δn<") && !last.contains(">v_k<"));
}

#[test]
fn the_chosen_epa_iteration_is_its_closest_face() {
    let third = figure(
        "epa-3",
        &["epa-edge-edge", "--phase", "epa", "--iteration", "3"],
    );
    assert!(third.contains(">EPA iteration 3 of 4: "), "{third}");
    assert_eq!(simplex_points(&third), (3, 0));
    // --phase alone: that phase's last iteration.
    let last = figure("epa-last", &["epa-edge-edge", "--phase", "epa"]);
    assert!(last.contains(">EPA iteration 4 of 4: "), "{last}");
    assert_ne!(third, last);
}

#[test]
fn a_dropped_point_is_drawn_hollow() {
    // gjk-separated's GJK drops a point on its way (the text's ✗).
    let text = run(&["detect", "gjk-separated", "--width", "0"]).stdout;
    let dropping = text
        .lines()
        .skip_while(|l| !l.starts_with("k  v_k"))
        .skip(1)
        .take_while(|l| !l.is_empty())
        .position(|l| l.contains('✗'))
        .expect("an iteration that drops a point")
        + 1;
    let svg = figure(
        "dropped",
        &["gjk-separated", "--iteration", &dropping.to_string()],
    );
    let (_, hollow) = simplex_points(&svg);
    assert!(hollow >= 1, "{svg}");
}

#[test]
fn an_iteration_outside_the_pair_is_a_usage_error_naming_the_count() {
    let svg = common::scratch("iteration-bad").join("pair.svg");
    let path = svg.to_str().unwrap();
    for (args, message) in [
        (
            &["epa-edge-edge", "--iteration", "3"][..],
            "--iteration 3: pair upper – lower has 2 GJK iteration(s), 1 to 2",
        ),
        (
            &["epa-edge-edge", "--phase", "epa", "--iteration", "5"][..],
            "--iteration 5: pair upper – lower has 4 EPA iteration(s), 1 to 4",
        ),
        (
            &["gjk-separated", "--phase", "epa"][..],
            "has no EPA iterations",
        ),
        (&["epa-edge-edge", "--iteration", "0"][..], "--iteration"),
    ] {
        let out = run(&[&["detect"], args, &["--figure", path]].concat());
        assert_eq!(out.code, Some(2), "{args:?}: {}", out.stderr);
        assert!(out.stderr.contains(message), "{args:?}: {}", out.stderr);
        assert!(!svg.exists(), "{args:?} wrote a figure");
    }
    // --iteration draws a figure, so it needs --figure.
    let out = run(&["detect", "epa-edge-edge", "--iteration", "1"]);
    assert_eq!(out.code, Some(2));
    assert!(out.stderr.contains("--figure"), "{}", out.stderr);
}

#[test]
fn the_figure_of_gjk_iteration_2_is_held_as_a_snapshot() {
    let svg = figure("iteration-snapshot", &["epa-edge-edge", "--iteration", "2"]);
    common::snapshot_settings().bind(|| {
        insta::assert_snapshot!("detect_svg@epa-edge-edge-gjk-2", svg);
    });
}

/// The result's figure never prints the origin's "O" over another label:
/// on `hull-stack`'s resting pair the penetration vector −δn is shorter
/// than a pixel and its label sat on O's (issue 40); it is now said below
/// O, and a drawn arrow puts O's label on the side away from it.
#[test]
fn the_origin_label_overlaps_no_other_label() {
    let cases: [&[&str]; 7] = [
        &["hull-stack", "--pair", "hexagon,octagon"],
        &["epa-edge-edge"],
        &["gjk-separated"],
        &["gjk-touching"],
        &["cylinder-on-box"],
        &["tetra-on-floor"],
        &["capsule-on-slope"],
    ];
    for (i, args) in cases.into_iter().enumerate() {
        let svg = figure(&format!("origin-label-{i}"), args);
        let labels = common::svg::label_boxes(&svg);
        let (o, _) = labels
            .iter()
            .find(|(_, t)| t == "O")
            .unwrap_or_else(|| panic!("{args:?}: no O"));
        for (b, text) in labels.iter().filter(|(_, t)| t != "O") {
            let apart = b[2] <= o[0] || o[2] <= b[0] || b[3] <= o[1] || o[3] <= b[1];
            assert!(apart, "{args:?}: O at {o:?} overlaps {text:?} at {b:?}");
        }
    }
    let resting = figure("origin-label-resting", cases[0]);
    assert!(resting.contains(">-δn ≈ 0<"), "{resting}");
}
