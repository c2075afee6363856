//! The figure model that the SVG figure and the TUI picture both draw: the
//! bodies as outlines, contact points, arrows (arms, normals, impulses,
//! velocities), spins, surfaces and a legend, in view coordinates of a
//! chosen [`Plane`], with semantic inks. Built from the trace's scene; it
//! holds any number of bodies and contacts. Renderers only map it to their
//! primitives and fit it to pixels or cells (and choose arrow scales).

mod build;
mod model;
mod outline;
mod stage;
#[cfg(test)]
mod surface_tests;
#[cfg(test)]
mod tests;
mod view;

pub use model::{
    Arrow, ArrowKind, BodyMarks, Bounds, ContactMarks, Figure, Ink, LegendItem, Point, PointKind,
    Section, Span, Spin, Surface, FACE_ON, ROUND_OFF_MOVE,
};
pub use outline::{hull, outline, spin_arc_radius, surface_distance, Outline, Silhouette};
pub use view::{flat, P, V};

pub use crate::trace::Plane;
use crate::trace::{BodyView, ContactView, SceneView};

impl Figure {
    /// The figure of the trace's one contact: its body or bodies (numbered
    /// 1 and 2 as in the lecture), the contact point, normal, arms, impulse.
    pub fn of_contact(scene: &SceneView, plane: Plane) -> Figure {
        let shown: Vec<usize> = (0..scene.bodies.len())
            .filter(|i| scene.bodies[*i].slot > 0)
            .collect();
        let bodies: Vec<&BodyView> = shown.iter().map(|i| &scene.bodies[*i]).collect();
        let mut contact = scene.contact_view();
        contact.bodies = contact
            .bodies
            .map(|b| b.and_then(|b| shown.iter().position(|i| *i == b)));
        let mut f = build::build(&bodies, &[contact], plane);
        f.corrected.clone_from(&scene.corrected);
        f.prune_legend();
        f
    }

    /// A figure of a whole scene: every body given and every contact between
    /// them (bodies by index into `bodies`), each contact's marks labelled
    /// with its number (q₃, d̂₃, g₃). With a single contact it is drawn as
    /// [`Figure::of_contact`] draws one: q, and bodies 1 and 2.
    pub fn of_scene(bodies: &[BodyView], contacts: &[ContactView], plane: Plane) -> Figure {
        let bodies: Vec<&BodyView> = bodies.iter().collect();
        let mut f = build::build(&bodies, contacts, plane);
        f.prune_legend();
        f
    }
}
