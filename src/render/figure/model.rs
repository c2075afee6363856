//! The figure model's types: bodies, contacts, surfaces, arrows, spins,
//! points and legend items, in view coordinates, with semantic inks.

use super::outline::Outline;
use super::view::{P, V};
use crate::physics::Shape;
use crate::trace::Plane;

/// A change of pose below this (in any position or quaternion component) is
/// round-off, not a move worth drawing.
pub const ROUND_OFF_MOVE: f64 = 1e-9;

/// What a mark stands for; each renderer picks its colour for it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ink {
    /// A body's outline as given.
    Body,
    /// A body's outline after the projection moved it.
    Moved,
    /// A surface that does not move (a half-space, the world).
    Ground,
    /// The contact point.
    Point,
    Normal,
    Arm,
    /// Velocities (and spins) before the impulse.
    Before,
    /// Velocities (and spins) after it.
    After,
    Impulse,
}

/// A figure of a scene seen in one plane: what to draw, before any fitting
/// to pixels or cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    pub plane: Plane,
    pub bodies: Vec<BodyMarks>,
    pub contacts: Vec<ContactMarks>,
    /// Half-space and world surfaces through contact points, in contact order.
    pub surfaces: Vec<Surface>,
    /// Per contact: arms, normal, impulse (and its reaction); then per body:
    /// velocity before and after.
    pub arrows: Vec<Arrow>,
    /// Per movable body that turns about the view axis: before, after.
    pub spins: Vec<Spin>,
    /// Body centres (all but half-spaces), then contact points.
    pub points: Vec<Point>,
    pub legend: Vec<LegendItem>,
    /// The scene before it is resolved: outline edges, centres, contact points.
    pub bounds: Bounds,
    /// A length standing for the scene: the largest bounding radius of a
    /// body, else the longest arm, else 1.
    pub scene_length: f64,
    /// The fastest speed of any body, before or after.
    pub top_speed: f64,
    /// The lesson's note when the bodies are drawn with its `[figure]`
    /// geometry, corrected from the lecture's (the numbers stay the lecture's).
    pub corrected: Option<String>,
}

impl Figure {
    /// Whether a spin is worth drawing: its speed at the scene's length is at
    /// least 2 % of the top speed (round-off leaves tiny spins behind).
    pub fn notable_spin(&self, rate: f64) -> bool {
        if self.top_speed > 0.0 {
            rate.abs() * self.scene_length >= 0.02 * self.top_speed
        } else {
            rate.abs() > 1e-9
        }
    }

    /// Whether a body's spin is worth a legend line, and which phases it
    /// gives (before, after): those the figure draws (a set-up figure shows
    /// no ω′), a spin at rest included (`(0, 0, 0) → …`) when the other
    /// phase is notable at the speeds drawn; `None` when no drawn phase is.
    pub fn spin_line(&self, before: [f64; 3], after: [f64; 3]) -> Option<(bool, bool)> {
        let drawn = |after: bool| {
            let kind = if after {
                ArrowKind::VelocityAfter
            } else {
                ArrowKind::Velocity
            };
            self.spins.iter().any(|s| s.after == after)
                || self.arrows.iter().any(|a| a.kind == kind)
        };
        let (b, a) = (drawn(false), drawn(true));
        let notable = |w: [f64; 3]| self.notable_spin(crate::physics::scale::stable_norm_of(&w));
        ((b && notable(before)) || (a && notable(after))).then_some((b, a))
    }

    /// Whether the projection carries a body further than three scene lengths.
    pub fn beyond(&self, body: &BodyMarks) -> bool {
        body.travel > 3.0 * self.scene_length
    }
}

/// One body as the figure shows it.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyMarks {
    pub name: String,
    pub movable: bool,
    /// 1 or 2 (the lecture's numbering) in a figure of one contact; 0 in a
    /// figure of several.
    pub slot: usize,
    /// Subscript for its symbols: "₁", "₂", or "" in a figure of several contacts.
    pub tag: &'static str,
    /// `None`: no shape given (drawn as a marker).
    pub shape: Option<Shape>,
    pub centre: V,
    pub centre_after: V,
    /// `None` for a half-space (drawn as a surface) or a body without shape.
    pub outline: Option<Outline>,
    /// The outline at the pose after the projection, when the pose changed at all.
    pub outline_after: Option<Outline>,
    /// The largest change of a position or orientation component (0: unmoved).
    pub pose_change: f64,
    /// How far the projection carries the centre, |p′ - p|.
    pub travel: f64,
    /// Radius of the smallest ball about the centre that holds the shape (0
    /// without a finite shape): the body's share of the scene length.
    pub bounding_radius: f64,
    /// Radius of a spin arc drawn well inside the body (`None` without a finite shape).
    pub spin_arc_radius: Option<f64>,
    /// |v| and |v′| (world).
    pub speed: f64,
    pub speed_after: f64,
}

impl BodyMarks {
    /// Whether the projection moves it by more than round-off.
    pub fn moved(&self) -> bool {
        self.pose_change > ROUND_OFF_MOVE
    }
}

/// One contact: its point and normal, and its bodies by index into
/// [`Figure::bodies`].
#[derive(Debug, Clone, PartialEq)]
pub struct ContactMarks {
    /// Its number in the scene (file order, from 0).
    pub number: usize,
    /// Body 1 and body 2 (`None` against the world).
    pub bodies: [Option<usize>; 2],
    pub point: V,
    /// Unit normal d̂, from body 2 toward body 1.
    pub normal: V,
    pub penetration: f64,
    /// The impulse body 1 receives, when one is applied.
    pub impulse: Option<V>,
    /// |g| (world).
    pub impulse_size: f64,
    /// "q", or "q₃" in a figure of several contacts.
    pub label: String,
}

/// A half-space body's own plane (through its position, across its
/// normal), or for the immovable world of a one-body contact the plane
/// through the contact point across d̂: where it meets the other body.
#[derive(Debug, Clone, PartialEq)]
pub struct Surface {
    pub contact: usize,
    /// The half-space body; `None` for the world of a one-body contact.
    pub body: Option<usize>,
    /// +1 when the solid side lies along +d̂ (a half-space as body 1),
    /// -1 along -d̂ (body 2 and the world).
    pub solid: f64,
    /// Where the surface meets the view plane through the contact point;
    /// `None` when the view plane is (nearly) parallel to the surface, which
    /// is then seen face on and not drawn.
    pub section: Option<Section>,
}

/// A surface seen edge on: the line where it meets the view plane through
/// the contact point (depth `q_w`): `n_u u + n_v v = n·p₀ - n_w q_w` for a
/// plane through p₀ with outward normal n.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Section {
    /// The point of the line nearest the contact point.
    pub at: P,
    /// Unit direction of the line.
    pub along: P,
    /// Unit direction, across the line, toward the solid side (for hatching).
    pub solid_side: P,
}

/// A surface whose normal has less than this share in the view plane is
/// taken as facing the viewer (about 11.5° from the view plane or less).
pub const FACE_ON: f64 = 0.2;

/// What an arrow shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArrowKind {
    /// r = q - p, from a body's centre to the contact point.
    Arm,
    /// d̂ at the contact point.
    Normal,
    /// g, the impulse on body 1 at the contact point.
    Impulse,
    /// -g, on a movable body 2.
    Reaction,
    Velocity,
    VelocityAfter,
}

impl ArrowKind {
    pub fn ink(self) -> Ink {
        match self {
            ArrowKind::Arm => Ink::Arm,
            ArrowKind::Normal => Ink::Normal,
            ArrowKind::Impulse | ArrowKind::Reaction => Ink::Impulse,
            ArrowKind::Velocity => Ink::Before,
            ArrowKind::VelocityAfter => Ink::After,
        }
    }
}

/// Where an arrow goes from its anchor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Span {
    /// To a point of the scene (an arm reaches the contact point).
    To(V),
    /// Along a quantity that the renderer scales to a length (velocity,
    /// impulse, the unit normal).
    Along(V),
}

#[derive(Debug, Clone, PartialEq)]
pub struct Arrow {
    pub kind: ArrowKind,
    /// The point it is attached to: a body's centre or a contact point.
    pub at: V,
    pub span: Span,
    pub label: String,
    pub body: Option<usize>,
    pub contact: Option<usize>,
}

impl Arrow {
    /// The other end: the span's point, or `at + scale · vector`.
    pub fn tip(&self, scale: f64) -> V {
        match self.span {
            Span::To(p) => p,
            Span::Along(v) => [0, 1, 2].map(|i| self.at[i] + v[i] * scale),
        }
    }
}

/// A body's turning about the view axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Spin {
    pub body: usize,
    pub at: V,
    /// Rate about the axis toward the viewer; positive turns counter-clockwise.
    pub rate: f64,
    /// After the impulse (else before).
    pub after: bool,
    pub label: String,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointKind {
    Centre { body: usize },
    Contact { contact: usize },
}

#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    pub kind: PointKind,
    pub at: V,
    /// "p₁", "q", …
    pub label: String,
}

/// One entry of the figure's legend, with the world values it quotes.
#[derive(Debug, Clone, PartialEq)]
pub enum LegendItem {
    Body {
        body: usize,
    },
    ContactPoint {
        contact: usize,
        at: [f64; 3],
    },
    Normal {
        contact: usize,
        direction: [f64; 3],
    },
    Impulse {
        contact: usize,
        impulse: [f64; 3],
    },
    /// Both bodies move, so body 2 receives -g.
    Reaction {
        contact: usize,
    },
    Arm {
        contact: usize,
        body: usize,
        arm: [f64; 3],
    },
    /// A body that moves before or after.
    Velocity {
        body: usize,
        before: [f64; 3],
        after: [f64; 3],
    },
    /// A body whose spin is notable before or after.
    Spin {
        body: usize,
        before: [f64; 3],
        after: [f64; 3],
    },
    /// The projection carries the body beyond the figure.
    Travel {
        body: usize,
        distance: f64,
    },
    /// Some body moved: its outline after the projection is drawn.
    Moved,
    /// Velocities and impulses are drawn to scales of their own.
    Scales,
    /// The contact point is not on the body's surface as drawn.
    OffSurface {
        contact: usize,
        body: usize,
        distance: f64,
    },
}

/// An axis-aligned box in the view plane; non-finite points are left out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    pub lo: P,
    pub hi: P,
}

impl Default for Bounds {
    fn default() -> Self {
        Bounds {
            lo: [f64::INFINITY; 2],
            hi: [f64::NEG_INFINITY; 2],
        }
    }
}

impl Bounds {
    pub fn add(&mut self, p: P) {
        if p[0].is_finite() && p[1].is_finite() {
            self.lo = [self.lo[0].min(p[0]), self.lo[1].min(p[1])];
            self.hi = [self.hi[0].max(p[0]), self.hi[1].max(p[1])];
        }
    }

    pub fn is_empty(&self) -> bool {
        self.lo[0] > self.hi[0]
    }

    /// (lo, hi), or the square ±1 when no point was added.
    pub fn or_unit(&self) -> (P, P) {
        if self.is_empty() {
            ([-1.0, -1.0], [1.0, 1.0])
        } else {
            (self.lo, self.hi)
        }
    }
}
