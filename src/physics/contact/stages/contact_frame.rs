//! Stage 1: contact basis and relative contact positions `r_i = q - p_i`.

use nalgebra::{Matrix3, Vector3};

use crate::physics::frame::{contact_basis, difference_digits, GuessAxis};
use crate::physics::{Problem, Real};

#[derive(Debug, Clone, PartialEq)]
pub struct ContactFrame<T: Real> {
    /// Columns d, t0, t1: converts contact coordinates to world coordinates.
    pub contact_to_world: Matrix3<T>,
    pub guess: GuessAxis,
    /// `r_i = q - p_i` for each movable body.
    pub r: [Option<Vector3<T>>; 2],
}

impl<T: Real> ContactFrame<T> {
    pub fn normal(&self) -> Vector3<T> {
        self.contact_to_world.column(0).into_owned()
    }

    /// World vector into contact coordinates (`Cᵀ v`).
    pub fn to_contact(&self, v: &Vector3<T>) -> Vector3<T> {
        self.contact_to_world.transpose() * v
    }

    /// Contact vector into world coordinates (`C v`).
    pub fn to_world(&self, v: &Vector3<T>) -> Vector3<T> {
        self.contact_to_world * v
    }

    /// Significant digits `r_i` keeps, given how far q and p_i are from the
    /// origin (`None` for an empty slot). Only the trace's note reads it, so
    /// it is computed there, not with the stage.
    pub fn r_digits(&self, problem: &Problem<T>, i: usize) -> Option<T> {
        let p = problem.bodies[i].as_ref()?.position;
        Some(difference_digits(&self.r[i]?, &problem.contact.point, &p))
    }

    /// A frame to be written by [`contact_frame_into`].
    pub fn empty() -> Self {
        ContactFrame {
            contact_to_world: Matrix3::zeros(),
            guess: GuessAxis::X,
            r: [None, None],
        }
    }
}

pub fn contact_frame<T: Real>(problem: &Problem<T>) -> ContactFrame<T> {
    let mut frame = ContactFrame::empty();
    contact_frame_into(problem, &mut frame);
    frame
}

/// [`contact_frame`] written into `out` (the stage path's form: the record
/// is built where it stays).
#[inline]
pub fn contact_frame_into<T: Real>(problem: &Problem<T>, out: &mut ContactFrame<T>) {
    let (contact_to_world, guess) = contact_basis(&problem.contact.normal);
    let q = problem.contact.point;
    out.contact_to_world = contact_to_world;
    out.guess = guess;
    for (r, body) in out.r.iter_mut().zip(&problem.bodies) {
        *r = body.as_ref().map(|b| q - b.position);
    }
}
