//! What EPA reports: one record per split, an observer whose methods do
//! nothing by default, and a recorder that keeps every split with its faces.

use nalgebra::Vector3;

use super::simplex::Vertex;
use crate::physics::Real;

/// One split.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EpaIteration<T: Real> {
    pub index: usize,
    /// The face closest to the origin (its three w), its unit outward
    /// normal n_k and distance δ_k = n_k·w.
    pub face: [Vector3<T>; 3],
    pub normal: Vector3<T>,
    pub distance: T,
    /// w_k = s_A(n_k) − s_B(−n_k) with its two shape points (world).
    pub support: Vertex<T>,
    /// n_k·w_k − δ_k = |v_k − w_k| along n_k, where v_k = δ_k n_k.
    pub gap: T,
    /// How many faces the split removed (those w_k sees) and added (one per horizon edge).
    pub removed: usize,
    pub added: usize,
}

/// Observer of a run; every method does nothing by default.
pub trait EpaObserver<T: Real> {
    /// True to be given the faces removed and added (they are built only then).
    fn wants_faces(&self) -> bool {
        false
    }
    fn iteration(
        &mut self,
        _it: &EpaIteration<T>,
        _removed: &[[Vector3<T>; 3]],
        _added: &[[Vector3<T>; 3]],
    ) {
    }
}

impl<T: Real> EpaObserver<T> for () {}

/// One recorded split with its faces.
#[derive(Debug, Clone, PartialEq)]
pub struct EpaRecord<T: Real> {
    pub iteration: EpaIteration<T>,
    pub removed: Vec<[Vector3<T>; 3]>,
    pub added: Vec<[Vector3<T>; 3]>,
}

/// Keeps every split with its faces.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct EpaRecorder<T: Real> {
    pub iterations: Vec<EpaRecord<T>>,
}

impl<T: Real> EpaObserver<T> for EpaRecorder<T> {
    fn wants_faces(&self) -> bool {
        true
    }
    fn iteration(
        &mut self,
        it: &EpaIteration<T>,
        removed: &[[Vector3<T>; 3]],
        added: &[[Vector3<T>; 3]],
    ) {
        self.iterations.push(EpaRecord {
            iteration: *it,
            removed: removed.to_vec(),
            added: added.to_vec(),
        });
    }
}
