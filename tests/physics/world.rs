//! The world layer: a lesson becomes a world of bodies by id once, and each
//! contact's problem is a view of it.

use crate::common;

use contact_lab::physics::{solve, BodyId, StageId};

#[test]
fn every_lesson_becomes_a_world_with_the_same_bodies_and_contacts() {
    for lesson in common::all_lessons() {
        let world = lesson.world::<f64>();
        assert_eq!(world.bodies.len(), lesson.bodies.len(), "{}", lesson.id);
        assert_eq!(world.contacts.len(), lesson.contacts.len());
        for (body, def) in world.bodies.iter().zip(&lesson.bodies) {
            assert_eq!(body.movable, def.movable(), "{}: {}", lesson.id, def.name);
            assert_eq!(body.state.position, def.position);
            assert_eq!(body.shape, def.shape);
            if !body.movable {
                assert_eq!(body.state.inverse_mass, 0.0);
                assert!(body.dynamic().is_none());
            }
        }
        for (k, def) in lesson.contacts.iter().enumerate() {
            let contact = &world.contacts[k];
            assert_eq!(contact.body1, BodyId(def.bodies.0));
            assert_eq!(contact.body2, def.bodies.1.map(BodyId));
            // The problem view: an immovable body is an empty slot.
            let problem = world.problem(k);
            for (slot, id) in contact.slots().into_iter().enumerate() {
                let movable = id.is_some_and(|id| world.body(id).movable);
                assert_eq!(
                    problem.bodies[slot].is_some(),
                    movable,
                    "{} #{k}",
                    lesson.id
                );
            }
            assert_eq!(problem.duration, def.settings.duration);
            assert_eq!(problem.contact.settings.relaxation, def.settings.relaxation);
        }
    }
}

#[test]
fn the_adjacency_lists_each_contact_under_each_of_its_bodies_once() {
    let lesson = contact_lab::lesson::Lesson::load("friction-cube").unwrap();
    let world = lesson.world::<f64>();
    let adjacency = world.contacts_of_bodies();
    for (k, contact) in world.contacts.iter().enumerate() {
        for id in contact.slots().into_iter().flatten() {
            assert_eq!(adjacency[id.0].iter().filter(|&&j| j == k).count(), 1);
        }
    }
    let listed: usize = adjacency.iter().map(Vec::len).sum();
    let slots: usize = world
        .contacts
        .iter()
        .map(|c| c.slots().iter().flatten().count())
        .collect::<Vec<_>>()
        .iter()
        .sum();
    assert_eq!(listed, slots);
}

#[test]
fn skipped_stages_are_named_by_typed_ids() {
    // lecture-1: frictionless, no penetration.
    let lesson = contact_lab::lesson::Lesson::load("lecture-1").unwrap();
    let s = solve(&lesson.problem::<f64>(0));
    assert!(s.skip(StageId::Impulse).is_none());
    assert!(s.skip(StageId::FrictionClamp).is_some());
    assert!(s.skip(StageId::NonlinearProjection).is_some());
    assert_eq!(
        s.final_impulse_world(),
        s.impulse.as_ref().map(|g| g.impulse_world)
    );
    assert!(s.regime().is_none() && s.closing());
}
