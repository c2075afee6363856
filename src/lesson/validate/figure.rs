//! Validation of `[figure]`: the note, and each `[[figure.body]]`'s name
//! (a body of the lesson), shape (finite sizes > 0, not a half-space) and
//! orientation (a non-zero quaternion, normalised).

use std::collections::HashMap;

use super::rules;
use super::Validator;
use crate::lesson::raw::RawFigure;
use crate::lesson::{DrawnBody, FigureDef};

impl Validator {
    pub(super) fn figure(&mut self, raw: &RawFigure, index: &HashMap<&str, usize>) -> FigureDef {
        if let Err(e) = rules::text(raw.note.get_ref()) {
            self.err(raw.note.span(), format!("[figure] note {e}"));
        }
        let mut bodies = vec![];
        for b in &raw.bodies {
            let name = b.name.get_ref();
            let Some(&body) = index.get(name.as_str()) else {
                self.err(
                    b.name.span(),
                    format!("[[figure.body]] names '{name}', which is not a body of the lesson"),
                );
                continue;
            };
            let (shape, _) = self.shape(&format!("[[figure.body]] '{name}'"), &b.shape, false);
            if let (Some(s), Some(raw)) = (&shape, &b.shape) {
                let sizes_ok = s
                    .dimensions()
                    .iter()
                    .all(|x| rules::in_range(*x) && rules::in_range(1.0 / x) && *x > 0.0);
                if !s.is_finite() || !sizes_ok {
                    self.err(
                        raw.span(),
                        format!("[[figure.body]] '{name}': the shape drawn must be finite, its sizes finite and > 0"),
                    );
                }
            }
            let orientation = b.orientation.as_ref().and_then(|o| {
                let q = self.finite_direction(&format!("[[figure.body]] '{name}' orientation"), o);
                let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
                if n > 0.0 && n.is_finite() {
                    Some(q.map(|x| x / n))
                } else {
                    self.err(
                        o.span(),
                        format!("[[figure.body]] '{name}': orientation must be a non-zero quaternion [w, x, y, z]"),
                    );
                    None
                }
            });
            bodies.push(DrawnBody {
                body,
                shape,
                orientation,
            });
        }
        FigureDef {
            note: crate::lesson::ascii_minus(raw.note.get_ref().trim()),
            bodies,
        }
    }
}
