//! Unit tests of where a surface meets each view plane (issue 16, item 7):
//! a half-space turned so its normal is (0, 0.6, 0.8), through (0, 8, 0),
//! touched at q = (3, 8, 5); and the world of a one-body contact.

use super::*;
use crate::physics::Shape;

fn ball() -> BodyView {
    BodyView {
        name: "ball".into(),
        movable: true,
        slot: 1,
        shape: Some(Shape::Sphere { radius: 1.0 }),
        position: [3.0, 9.0, 5.0],
        orientation: [1.0, 0.0, 0.0, 0.0],
        position_after: [3.0, 9.0, 5.0],
        orientation_after: [1.0, 0.0, 0.0, 0.0],
        velocity: [0.0; 3],
        velocity_after: [0.0; 3],
        angular_velocity: [0.0; 3],
        angular_velocity_after: [0.0; 3],
    }
}

/// The ball on a slope: a half-space with body normal y, turned about x
/// until its normal is (0, cos θ, sin θ) = (0, 0.6, 0.8).
fn on_slope() -> SceneView {
    let slope = BodyView {
        name: "slope".into(),
        movable: false,
        slot: 2,
        shape: Some(Shape::HalfSpace {
            normal: [0.0, 1.0, 0.0],
        }),
        position: [0.0, 8.0, 0.0],
        orientation: [0.8f64.sqrt(), 0.2f64.sqrt(), 0.0, 0.0],
        ..ball()
    };
    SceneView {
        bodies: vec![ball(), slope],
        contact: 0,
        point: [3.0, 8.0, 5.0],
        normal: [0.0, 0.6, 0.8],
        penetration: 0.0,
        impulse: None,
        corrected: None,
    }
}

fn section(scene: &SceneView, plane: Plane) -> Option<Section> {
    let fig = Figure::of_contact(scene, plane);
    assert_eq!(fig.surfaces.len(), 1);
    fig.surfaces[0].section
}

fn close(a: P, b: P) -> bool {
    (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12
}

#[track_caller]
fn assert_section(s: Option<Section>, at: P, along: P, solid_side: P) {
    let s = s.expect("the surface is seen edge on");
    assert!(close(s.at, at), "at {:?}, expected {at:?}", s.at);
    assert!(close(s.along, along), "along {:?}", s.along);
    assert!(close(s.solid_side, solid_side), "solid {:?}", s.solid_side);
}

#[test]
fn in_xy_the_slope_meets_the_view_plane_z_5_at_y_four_thirds() {
    // 0.6 y + 0.8 · 5 = 0.6 · 8: y = 4/3, a horizontal line, solid below.
    let s = section(&on_slope(), Plane::Xy);
    assert_section(s, [3.0, 4.0 / 3.0], [-1.0, 0.0], [0.0, -1.0]);
}

#[test]
fn in_yz_the_slope_is_the_line_0_6_y_plus_0_8_z_equals_4_8() {
    // Right y, up z: the line through (5.6, 1.8), nearest q's (8, 5); the
    // solid side is -(0.6, 0.8).
    let s = section(&on_slope(), Plane::Yz);
    assert_section(s, [5.6, 1.8], [-0.8, 0.6], [-0.6, -0.8]);
}

#[test]
fn in_zx_the_slope_meets_the_view_plane_y_8_at_z_0() {
    // Right z, up x: 0.6 · 8 + 0.8 z = 4.8 gives z = 0, a vertical line,
    // solid toward -z (left).
    let s = section(&on_slope(), Plane::Zx);
    assert_section(s, [0.0, 3.0], [0.0, 1.0], [-1.0, 0.0]);
}

#[test]
fn a_floor_seen_from_above_is_not_drawn_and_the_world_follows_q() {
    // The world of a one-body contact: the plane through q across d̂ = y.
    let mut scene = on_slope();
    scene.bodies.truncate(1);
    scene.normal = [0.0, 1.0, 0.0];
    assert_section(
        section(&scene, Plane::Xy),
        [3.0, 8.0],
        [-1.0, 0.0],
        [0.0, -1.0],
    );
    // yz: right y, up z: a vertical line at y = 8, solid on the left.
    assert_section(
        section(&scene, Plane::Yz),
        [8.0, 5.0],
        [0.0, 1.0],
        [-1.0, 0.0],
    );
    // zx: y toward the viewer, who sees the floor face on.
    assert_eq!(section(&scene, Plane::Zx), None);
    // A normal with less than FACE_ON of its length in the view plane
    // counts as facing the viewer; just above it, it is drawn.
    let tilt = |s: f64| [0.0, (1.0 - s * s).sqrt(), s];
    scene.normal = tilt(0.19);
    assert_eq!(section(&scene, Plane::Zx), None);
    scene.normal = tilt(0.21);
    assert!(section(&scene, Plane::Zx).is_some());
}
