//! The plane a picture of the scene shows (SVG figures and the TUI canvas).

/// The view plane: which world axes run right and up; the third points at
/// the viewer (each view is right-handed).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Plane {
    Xy,
    Yz,
    Zx,
}

impl Plane {
    /// Indices of the (right, up, toward the viewer) world axes.
    pub fn axes(self) -> (usize, usize, usize) {
        match self {
            Plane::Xy => (0, 1, 2),
            Plane::Yz => (1, 2, 0),
            Plane::Zx => (2, 0, 1),
        }
    }

    /// The next plane, cycling xy → yz → zx.
    pub fn next(self) -> Self {
        match self {
            Plane::Xy => Plane::Yz,
            Plane::Yz => Plane::Zx,
            Plane::Zx => Plane::Xy,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Plane::Xy => "xy",
            Plane::Yz => "yz",
            Plane::Zx => "zx",
        }
    }

    pub fn project(self, p: [f64; 3]) -> (f64, f64) {
        let (u, v, _) = self.axes();
        (p[u], p[v])
    }

    /// The component along the axis that points at the viewer.
    pub fn depth(self, p: [f64; 3]) -> f64 {
        p[self.axes().2]
    }
}
