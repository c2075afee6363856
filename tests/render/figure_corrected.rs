//! The lecture's first and third examples drawn with the corrected geometry
//! (issue 16, item 7): the lessons' `[figure]` tables correct what the
//! pictures draw (lecture-1: spheres of r = 6, not overlapping; lecture-3:
//! the cube turned so that q is on it), the SVG, LaTeX and TUI say so, and
//! the numbers of the trace stay the lecture's.

use contact_lab::lesson::Lesson;
use contact_lab::physics::Shape;
use contact_lab::render::figure::{surface_distance, Figure, LegendItem, Plane, Silhouette};

fn trace(id: &str) -> contact_lab::trace::Trace {
    contact_lab::worked_solution(&Lesson::load(id).unwrap(), 0)
}

fn circles(fig: &Figure) -> Vec<([f64; 2], f64)> {
    fig.bodies
        .iter()
        .filter_map(|b| match b.outline.as_ref()?.silhouette {
            Silhouette::Circle { centre, radius } => Some((centre, radius)),
            _ => None,
        })
        .collect()
}

#[test]
fn lecture_1_draws_two_spheres_of_radius_6_that_do_not_overlap() {
    let t = trace("lecture-1");
    for plane in [Plane::Xy, Plane::Yz, Plane::Zx] {
        let fig = Figure::of_contact(&t.scene, plane);
        let c = circles(&fig);
        assert_eq!(c.len(), 2, "{plane:?}");
        assert!(c.iter().all(|(_, r)| *r == 6.0), "{c:?}");
        if plane == Plane::Xy {
            // Centres 12.01 apart: a gap of 0.01, where r = 9 overlapped by 6.
            let gap = (c[0].0[0] - c[1].0[0]).hypot(c[0].0[1] - c[1].0[1]) - c[0].1 - c[1].1;
            assert!(gap > 0.0 && gap < 0.02, "{gap}");
        }
        assert!(fig
            .corrected
            .as_deref()
            .unwrap()
            .starts_with("Drawn with the corrected geometry"));
        assert!(!fig
            .legend
            .iter()
            .any(|i| matches!(i, LegendItem::OffSurface { .. })));
    }
    // The numbers stay the lecture's: the shape's tensor is r = 9's (540).
    let i1 = t.value("unit_impulse", "shape_inertia1").unwrap();
    assert!((i1.numbers()[0] - 540.0).abs() < 1e-9, "{i1:?}");
}

#[test]
fn lecture_3_draws_q_on_the_turned_cube_and_inside_the_sphere() {
    let t = trace("lecture-3");
    let cube = &t.scene.bodies[0];
    let sphere = &t.scene.bodies[1];
    let on_cube = surface_distance(
        cube.shape.as_ref().unwrap(),
        cube.position,
        cube.orientation,
        t.scene.point,
    )
    .unwrap();
    // q is the turned cube's corner (within the lecture's 4 decimals) ...
    assert!(on_cube.abs() < 2e-3, "{on_cube}");
    // ... and lies the penetration deep in the sphere.
    let in_sphere = surface_distance(
        sphere.shape.as_ref().unwrap(),
        sphere.position,
        sphere.orientation,
        t.scene.point,
    )
    .unwrap();
    assert!((in_sphere + 1.4365).abs() < 1e-3, "{in_sphere}");
    assert!(matches!(cube.shape, Some(Shape::Box { .. })));
    let fig = Figure::of_contact(&t.scene, Plane::Xy);
    assert!(!fig
        .legend
        .iter()
        .any(|i| matches!(i, LegendItem::OffSurface { .. })));
    // The projection's turn (7.9° clockwise) is drawn from the drawn pose:
    // the cube after is turned 27.9° in all.
    let w = cube.orientation_after[0];
    let turned = 2.0 * w.acos().to_degrees();
    assert!((turned - 27.88).abs() < 0.05, "{turned}");
    // The numbers stay the lecture's: the cube starts unturned.
    let q = t
        .value("orientation_update", "orientation1_unnormalised")
        .unwrap();
    assert!((q.numbers()[0] - 1.0).abs() < 1e-12 && (q.numbers()[3] + 0.0689).abs() < 1e-3);
}

#[test]
fn every_figure_format_says_the_geometry_is_corrected() {
    for id in ["lecture-1", "lecture-3"] {
        let t = trace(id);
        let svg = contact_lab::render::svg::render(&t, Plane::Xy);
        assert!(
            svg.contains("Drawn with the corrected geometry"),
            "{id} svg"
        );
        let tex = contact_lab::render::contact::latex_figure::picture(&t.scene, None).unwrap();
        assert!(
            tex.contains("Drawn with the corrected geometry"),
            "{id} latex"
        );
    }
    // A lesson without [figure] says nothing of the kind.
    let svg = contact_lab::render::svg::render(&trace("lecture-2"), Plane::Xy);
    assert!(!svg.contains("corrected geometry"));
}

#[test]
fn the_latex_figure_draws_a_sphere_as_a_ring() {
    // 24 rim pieces a sphere; a circle was once drawn as its bounding box's
    // diagonal, there and back.
    let t = trace("lecture-1");
    let tex = contact_lab::render::contact::latex_figure::picture(&t.scene, None).unwrap();
    let pieces: Vec<(String, String)> = tex
        .lines()
        .filter_map(|l| {
            let l = l.strip_prefix("\\qbezier(")?;
            let parts: Vec<&str> = l.trim_end_matches(')').split(")(").collect();
            Some((parts[0].to_string(), parts[2].to_string()))
        })
        .collect();
    assert!(pieces.len() >= 48, "{}", pieces.len());
    for (a, b) in &pieces {
        assert!(
            !pieces.contains(&(b.clone(), a.clone())),
            "{a} – {b} drawn there and back"
        );
    }
}
