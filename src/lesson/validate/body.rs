//! Validation of one `[[body]]`: mass, shape, inertia tensor (given or from
//! the shape, invertible and well conditioned), pose and velocities.

#[allow(unused_imports)]
use super::*;

impl Validator {
    pub(super) fn body(&mut self, raw: &RawBody) -> BodyDef {
        let name = raw.name.get_ref().clone();
        if let Err(e) = rules::name(&name) {
            self.err(raw.name.span(), format!("body name {e}"));
        }
        let mass = self.rule(&format!("body '{name}'"), &raw.mass, super::rules::mass);
        let movable = mass.is_finite() && rules::mass(mass).is_ok();
        let errors_before = self.errors.len();
        let (mut shape, centre_of_mass) =
            self.shape(&format!("body '{name}'"), &raw.shape, movable);
        self.half_space_normal(&name, raw, &mut shape);
        if let (Some(s), Some(span)) = (&shape, raw.shape.as_ref().map(|s| s.span())) {
            if s.dimensions()
                .iter()
                .any(|x| !rules::in_range(*x) || !rules::in_range(1.0 / x) || *x <= 0.0)
            {
                self.err(
                    span.clone(),
                    format!(
                        "body '{name}': shape sizes must be finite and > 0 (within 1e-60 to 1e60)"
                    ),
                );
            } else if !s.is_finite() && movable {
                self.err(
                    span,
                    format!("body '{name}': a half-space must be immovable (mass = inf)"),
                );
            }
        }
        let shape_inertia = shape
            .as_ref()
            .filter(|_| movable)
            .and_then(|s| s.inertia(mass));
        let explicit = raw
            .inertia
            .as_ref()
            .map(|t| (mat(self.finite_tensor(&name, t)), t.span()));
        if let Some((tensor, span)) = &explicit {
            if movable {
                self.check_tensor(&name, tensor, span.clone());
            }
        }
        let inertia = match (&explicit, shape_inertia) {
            (Some((t, span)), Some(s)) => {
                if (t - s).norm() > 1e-9 * s.norm() {
                    self.warnings.push(
                        Note::new(
                            format!(
                                "body '{name}': the inertia tensor given differs from the {}: given {}, the shape gives {}; the given tensor is used",
                                shape.as_ref().map(crate::lesson::shape::describe).unwrap_or_default(),
                                tensor(t),
                                tensor(&s)
                            ),
                            span.clone(),
                        )
                        .help("either the tensor or the shape's size is off; `contact-lab check` compares them"),
                    );
                }
                Some(*t)
            }
            (Some((t, _)), None) => Some(*t),
            (None, Some(s)) => Some(s),
            (None, None) => {
                if movable
                    && shape
                        .as_ref()
                        .map_or(raw.shape.is_none(), |s| s.is_finite())
                {
                    self.err(
                        raw.name.span(),
                        format!("body '{name}' needs an `inertia` tensor or a `shape`"),
                    );
                }
                None
            }
        };
        // The stages use I⁻¹: a tensor whose inverse is out of range, has no
        // correct digit or cannot be found must not become a silent zero (a
        // body that cannot turn), inf or NaN (see `lesson::ranges`).
        if let Some(t) = inertia.filter(|_| movable && self.errors.len() == errors_before) {
            if let Err(e) = rules::inertia(&t) {
                let span = raw.inertia.as_ref().map(|t| t.span());
                let from = if span.is_some() {
                    ""
                } else {
                    " (from the shape)"
                };
                let span = span.or(raw.shape.as_ref().map(|s| s.span()));
                self.err(
                    span.unwrap_or(raw.name.span()),
                    format!(
                        "body '{name}': the inertia tensor {}{from}: {e}",
                        tensor(&t)
                    ),
                );
            }
        }
        let position = v3(self.finite(&format!("body '{name}' position"), &raw.position));
        let orientation = match &raw.orientation {
            None => Quaternion::identity(),
            Some(o) => {
                let q = Quaternion::from(nalgebra::Vector4::new(
                    o.get_ref()[1],
                    o.get_ref()[2],
                    o.get_ref()[3],
                    o.get_ref()[0],
                ));
                self.finite_direction(&format!("body '{name}' orientation"), o);
                let n = crate::physics::scale::stable_norm_quaternion(&q);
                if !n.is_finite() {
                    Quaternion::identity()
                } else if n == 0.0 {
                    self.err(
                        o.span(),
                        format!(
                            "body '{name}': orientation must be a non-zero quaternion [w, x, y, z]"
                        ),
                    );
                    Quaternion::identity()
                } else {
                    if (n - 1.0).abs() > 1e-6 {
                        self.warnings.push(Note::new(
                            format!(
                                "body '{name}': orientation has length {}; it was normalised",
                                crate::format::exact(n)
                            ),
                            o.span(),
                        ));
                    }
                    let unit = q / n;
                    let [w, x, y, z] = [unit.w, unit.i, unit.j, unit.k].map(|c| {
                        if c.abs() < rules::MIN_MAGNITUDE {
                            0.0
                        } else {
                            c
                        }
                    });
                    Quaternion::new(w, x, y, z)
                }
            }
        };
        // A hull's centre of mass is its centroid: the body's position moves
        // there (x + R c) and the hull's points were moved by −c.
        let position = if centre_of_mass == Vector3::zeros() {
            position
        } else {
            position + nalgebra::UnitQuaternion::from_quaternion(orientation) * centre_of_mass
        };
        let velocity = self.opt_vec(&format!("body '{name}' velocity"), &raw.velocity);
        let angular_velocity = self.opt_vec(
            &format!("body '{name}' angular_velocity"),
            &raw.angular_velocity,
        );
        let acceleration = self.opt_vec(&format!("body '{name}' acceleration"), &raw.acceleration);
        if mass.is_infinite() {
            // An immovable body neither moves nor turns: whatever would make
            // it do so is refused, not silently ignored.
            if let Some(t) = &raw.inertia {
                self.err(
                    t.span(),
                    format!("body '{name}' is immovable (mass = inf): it takes no `inertia` tensor (remove it, or give a finite mass)"),
                );
            }
            for (field, value) in [
                ("velocity", &raw.velocity),
                ("angular_velocity", &raw.angular_velocity),
                ("acceleration", &raw.acceleration),
            ] {
                if let Some(v) = value {
                    if v.get_ref().iter().any(|x| *x != 0.0) {
                        self.err(
                            v.span(),
                            format!("body '{name}' is immovable (mass = inf): its {field} must be zero or absent"),
                        );
                    }
                }
            }
        }
        BodyDef {
            name,
            mass,
            shape,
            inertia: inertia.filter(|_| movable),
            shape_inertia,
            position,
            orientation,
            velocity,
            angular_velocity,
            acceleration,
        }
    }

    /// A shape table as a physics shape and the centre of mass's offset
    /// from the file's frame (a hull's centroid); a degenerate hull is an
    /// error at the shape's span.
    pub(super) fn shape(
        &mut self,
        what: &str,
        raw: &Option<S<raw::RawShape>>,
        movable: bool,
    ) -> (Option<Shape>, Vector3<f64>) {
        let Some(raw) = raw else {
            return (None, Vector3::zeros());
        };
        if let raw::RawShape::Mesh(mesh) = raw.get_ref() {
            return match crate::lesson::mesh::from_raw(mesh, &self.origin.clone(), movable) {
                Ok((shape, offset, note)) => {
                    if let Some(note) = note {
                        self.warnings
                            .push(Note::new(format!("{what}: {note}"), raw.span()));
                    }
                    (Some(shape), offset)
                }
                Err(e) => {
                    self.err(raw.span(), format!("{what}: {e}"));
                    (None, Vector3::zeros())
                }
            };
        }
        match crate::lesson::shape::from_raw(raw.get_ref()) {
            Ok((shape, offset)) => {
                if let (raw::RawShape::Convex(points), Shape::Hull(hull)) = (raw.get_ref(), &shape)
                {
                    if let Some(tolerance) = hull.widened_tolerance() {
                        self.warnings.push(Note::new(
                            format!(
                                "{what}: the points are nearly coplanar: the convex hull was built at tolerance {tolerance:.3e} m (points within it of a face are on the face)"
                            ),
                            raw.span(),
                        ));
                    }
                    let dropped = crate::lesson::shape::dropped_points(points.len(), hull);
                    if dropped > 0 {
                        self.warnings.push(Note::new(
                            format!(
                                "{what}: the convex hull of {} points has {} vertices; the {dropped} points inside it or on its faces were dropped",
                                points.len(),
                                hull.vertices().len()
                            ),
                            raw.span(),
                        ));
                    }
                }
                (Some(shape), offset)
            }
            Err(e) => {
                self.err(
                    raw.span(),
                    format!("{what}: the convex hull is degenerate: {e}"),
                );
                (None, Vector3::zeros())
            }
        }
    }

    /// A scene whose step would meet two meshes, one of them movable, is
    /// refused: mesh against mesh (triangle against triangle) makes no
    /// contacts yet, and a body falling through another is no lesson.
    /// Continuous detection and the previous frame's normal work on convex
    /// shapes only: with a mesh in the scene, a warning says so.
    pub(super) fn mesh_pairs(
        &mut self,
        raw: &RawLesson,
        bodies: &[BodyDef],
        scene: &crate::physics::params::SceneSettings,
    ) {
        let is_mesh = |b: &BodyDef| matches!(b.shape, Some(Shape::Mesh(_)));
        let meshes: Vec<usize> = (0..bodies.len()).filter(|&i| is_mesh(&bodies[i])).collect();
        let convex_only = [
            (
                scene.ccd != crate::physics::params::Ccd::None,
                "continuous detection (ccd)",
            ),
            (
                scene.normal_from == crate::physics::params::NormalFrom::Previous,
                "normal_from = \"previous\"",
            ),
        ];
        if let (Some(&i), Some((_, what))) = (meshes.first(), convex_only.iter().find(|c| c.0)) {
            let span = raw.bodies[i]
                .shape
                .as_ref()
                .map_or(raw.bodies[i].name.span(), |s| s.span());
            self.warnings.push(Note::new(
                format!(
                    "body '{}' is a mesh: {what} works on convex shapes only, so a pair with a mesh is detected at each step's poses as without it",
                    bodies[i].name
                ),
                span,
            ));
        }
        for &i in &meshes {
            let other = meshes
                .iter()
                .find(|&&j| j != i && (bodies[i].mass.is_finite() || bodies[j].mass.is_finite()));
            if let (Some(&j), true) = (other, bodies[i].mass.is_finite()) {
                let span = raw.bodies[i]
                    .shape
                    .as_ref()
                    .map_or(raw.bodies[i].name.span(), |s| s.span());
                self.err(
                    span,
                    format!(
                        "body '{}': a movable mesh beside another mesh ('{}'): contacts between two meshes (triangle against triangle) are not made, so one would pass through the other; make one of them a convex shape",
                        bodies[i].name, bodies[j].name
                    ),
                );
            }
        }
    }

    fn finite_tensor(&mut self, name: &str, t: &S<[[f64; 3]; 3]>) -> [[f64; 3]; 3] {
        let cells = t
            .get_ref()
            .iter()
            .enumerate()
            .flat_map(|(r, row)| row.iter().enumerate().map(move |(c, x)| (r + 1, c + 1, *x)));
        if let Some((r, c, x)) = cells.into_iter().find(|(_, _, x)| !rules::in_range(*x)) {
            let message = if x.is_finite() && x.abs() < rules::MIN_MAGNITUDE {
                format!(
                    "body '{name}': inertia component in row {r}, column {c}: {}",
                    crate::lesson::ranges::too_small(x)
                )
            } else {
                let x = if x.is_finite() {
                    format!("{x:e}")
                } else {
                    format!("{x}")
                };
                format!("body '{name}': every inertia component must be a finite number within ±1e60, got {x} in row {r}, column {c}")
            };
            self.err(t.span(), message);
        }
        *t.get_ref()
    }

    fn check_tensor(&mut self, name: &str, t: &Matrix3<f64>, span: std::ops::Range<usize>) {
        if !t.iter().all(|x| x.is_finite()) {
            return;
        }
        let norm = crate::physics::scale::stable_norm_matrix;
        let asym = norm(&(t - t.transpose()));
        if asym > 1e-9 * norm(t) {
            self.err(
                span,
                format!(
                    "body '{name}': inertia tensor must be symmetric (|I - Iᵀ| = {})",
                    crate::format::Fmt::new(3).num(asym)
                ),
            );
            return;
        }
        let eig = crate::lesson::ranges::principal_moments(t);
        let scaled = t / crate::physics::scale::pow2_below(t.amax().max(f64::MIN_POSITIVE));
        if eig[0] <= 0.0 || scaled.cholesky().is_none() {
            self.err(
                span,
                format!("body '{name}': inertia tensor must be positive-definite (eigenvalues {:.6e}, {:.6e}, {:.6e})", eig[0], eig[1], eig[2]),
            );
            return;
        }
        let condition = eig[2] / eig[0];
        if condition > 1e8 {
            self.warnings.push(Note::new(
                format!(
                    "body '{name}': the inertia tensor's condition number is {}: its inverse keeps only about {:.0} significant digits in f64",
                    crate::format::Fmt::new(2).num(condition),
                    (1.0 / (condition * f64::EPSILON)).log10().max(0.0)
                ),
                span.clone(),
            ));
        }
        let e = eig;
        if e[0] + e[1] < e[2] * (1.0 - 1e-9) {
            let f = crate::format::Fmt::new(6);
            self.warnings.push(Note::new(
                format!("body '{name}': principal moments {}, {}, {} break the triangle inequality: no real body has this tensor", f.num(e[0]), f.num(e[1]), f.num(e[2])),
                span,
            ));
        }
    }
}
