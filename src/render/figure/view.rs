//! The figure's coordinates: a view vector and a point in the view plane,
//! which the figure model and the outlines share.

/// View coordinates: right and up in the view plane, then toward the viewer.
pub type V = [f64; 3];
/// A point in the view plane (right, up).
pub type P = [f64; 2];

/// The view-plane part of a view vector.
pub fn flat(v: V) -> P {
    [v[0], v[1]]
}
