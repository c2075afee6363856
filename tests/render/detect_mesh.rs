//! `detect` on a pair with a mesh (the mesh contract in docs/detect.md): the JSON's mid phase (the
//! tree's nodes from the root, the candidates, how many were tested), the
//! pair's least distance, each triangle's raw and corrected normal, each
//! contact's triangle; the text shows the same traversal. The candidates
//! are the triangles whose boxes the query box overlaps, found here by
//! brute force.

use contact_lab::format::Fmt;
use contact_lab::lesson::Lesson;
use contact_lab::physics::step::Simulation;
use contact_lab::physics::Shape;
use contact_lab::render::detect::{json, text};
use contact_lab::session::detect_trace;
use contact_lab::trace::Plane;

fn trace(id: &str) -> (contact_lab::trace::detect::DetectTrace, Simulation<f64>) {
    let lesson = Lesson::load(id).unwrap();
    let params = lesson.sim_params().unwrap();
    let mut world = lesson.world::<f64>();
    world.contacts.clear();
    let materials = lesson.simulation.clone().unwrap().materials;
    let sim = Simulation::new(world, params, materials);
    (detect_trace(&sim, &lesson, 0, Plane::Xy, None), sim)
}

#[test]
fn a_mesh_pair_prints_its_tree_its_candidates_and_each_triangles_normal() {
    let (t, sim) = trace("mesh-floor-slide");
    let v: serde_json::Value = serde_json::from_str(&json(&t)).unwrap();
    let pair = &v["pairs"][0];
    assert_eq!(pair["method"], "mesh");
    let mid = &pair["mid_phase"];
    let nodes = mid["nodes"].as_array().unwrap();
    assert_eq!(nodes[0]["node"], 0, "the walk starts at the root");
    assert_eq!(nodes[0]["overlap"], true);
    // Every candidate is a leaf the walk reached and found overlapping.
    let candidates: Vec<u64> = (mid["candidates"].as_array().unwrap().iter())
        .map(|c| c.as_u64().unwrap())
        .collect();
    assert_eq!(mid["tested"], candidates.len());
    for c in &candidates {
        assert!(
            nodes
                .iter()
                .any(|n| n["triangle"] == *c && n["overlap"] == true),
            "{c}"
        );
    }
    // Brute force: the triangles whose boxes meet the query box.
    let Some(Shape::Mesh(mesh)) = &sim.world.bodies[1].shape else {
        panic!()
    };
    let q = &mid["query"];
    let at = |k: usize, i: usize| q[k][i].as_f64().unwrap();
    let mut expected: Vec<u64> = (0..mesh.triangles().len())
        .filter(|&t| {
            let c = mesh.corners(t);
            (0..3).all(|i| {
                let lo = c.iter().map(|p| p[i]).fold(f64::INFINITY, f64::min);
                let hi = c.iter().map(|p| p[i]).fold(f64::NEG_INFINITY, f64::max);
                lo <= at(1, i) && at(0, i) <= hi
            })
        })
        .map(|t| t as u64)
        .collect();
    let mut found = candidates.clone();
    expected.sort();
    found.sort();
    assert_eq!(found, expected);
    // The box rests on the floor: touching, every contact on a candidate.
    assert_eq!(pair["distance"], 0.0);
    let triangles = pair["triangles"].as_array().unwrap();
    assert_eq!(triangles.len(), candidates.len());
    for tr in triangles {
        assert!(tr["raw_normal"].is_array() && tr["normal"].is_array());
        assert_eq!(tr["corrected"], tr["rule"].is_string());
    }
    let contacts = pair["contacts"].as_array().unwrap();
    assert!(!contacts.is_empty());
    for c in contacts {
        assert!(candidates.contains(&c["triangle"].as_u64().unwrap()), "{c}");
    }
    let page = text(&t, &Fmt::new(6), 0);
    assert!(
        page.contains("Mid phase: the mesh's tree (body 2's frame)"),
        "{page}"
    );
    assert!(
        page.contains("Each candidate triangle's narrow phase"),
        "{page}"
    );
}
