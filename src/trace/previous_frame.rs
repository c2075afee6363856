//! The normals from the previous frame, as rows: for each penetrating
//! contact of a step whose pair was apart one frame earlier, the normal at
//! t beside the one from the closest points at t − Δt ("Lecture IV
//! Collisions", the time issue; docs/ccd.md).

use super::resolver::Names;
use crate::physics::World;

/// A penetrating contact's normal at t beside the one from the closest
/// points one frame earlier (t − Δt), when its pair was apart then.
#[derive(Debug, Clone, PartialEq)]
pub struct PreviousNormal {
    /// The contact's number in the step and its label.
    pub contact: usize,
    pub label: String,
    pub normal: [f64; 3],
    pub previous: [f64; 3],
}

/// The contacts of `world` that have a previous-frame normal.
pub(super) fn rows(
    world: &World<f64>,
    names: &Names,
    previous: &[Option<[f64; 3]>],
) -> Vec<PreviousNormal> {
    (world.contacts.iter().enumerate())
        .zip(previous)
        .filter_map(|((k, c), previous)| {
            let n = c.input.normal;
            Some(PreviousNormal {
                contact: k,
                label: names
                    .contacts
                    .get(k)
                    .cloned()
                    .unwrap_or_else(|| k.to_string()),
                normal: [n.x, n.y, n.z],
                previous: (*previous)?,
            })
        })
        .collect()
}
