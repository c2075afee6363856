//! The x axis as [`super::Chart::draw`] lays it out, for a page's script
//! that draws over a chart (the player's cursor).

use super::{transform, Scale};

/// The values of `t` after the scale, and the range `(lo, hi)` widened to
/// the first and the last.
pub(super) fn tick_range(t: &[f64], s: Scale, lo: f64, hi: f64) -> (f64, f64) {
    let tt: Vec<f64> = t.iter().filter_map(|v| transform(*v, s)).collect();
    let lo = tt.first().copied().unwrap_or(lo).min(lo);
    let hi = tt.last().copied().unwrap_or(hi).max(hi);
    (lo, hi)
}

pub(super) fn back(v: f64, s: Scale) -> f64 {
    if s == Scale::Log {
        10f64.powf(v)
    } else {
        v
    }
}

/// Where [`Chart::draw`] puts x values in its box: the plot's left and right
/// edges on the page and the (scaled) x values at them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct XMap {
    pub left: f64,
    pub right: f64,
    pub lo: f64,
    pub hi: f64,
    /// The plot's top and bottom on the page.
    pub top: f64,
    pub bottom: f64,
}

impl XMap {
    /// The page x of value `x` (after the chart's scale).
    pub fn px(&self, x: f64) -> f64 {
        self.left + (x - self.lo) / (self.hi - self.lo).max(1e-300) * (self.right - self.left)
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Chart, Mark, Series};

    /// A page's cursor at x lands where the chart's own cursor does.
    #[test]
    fn the_map_puts_x_where_the_chart_draws_its_cursor() {
        for (t, points) in [
            (0.37, vec![(0.0, 1.0), (1.0, 3.0)]),
            (2.5, vec![(0.1, -4.0), (3.3, 2.0), (7.9, 0.5)]),
        ] {
            let chart = Chart {
                series: vec![Series {
                    name: "e".into(),
                    points,
                    colour: "#000000",
                    mark: Mark::Line,
                    dashed: false,
                }],
                cursor: Some(t),
                ..Chart::default()
            };
            let rect = (10.0, 20.0, 700.0, 240.0);
            let mut out = String::new();
            chart.draw(&mut out, rect);
            let line = out
                .lines()
                .find(|l| l.contains("stroke-dasharray=\"3 3\""))
                .expect("the cursor");
            let x1: f64 = line
                .split("x1=\"")
                .nth(1)
                .unwrap()
                .split('"')
                .next()
                .unwrap()
                .parse()
                .unwrap();
            let map = chart.x_map(rect);
            assert!((map.px(t) - x1).abs() <= 0.05, "{} against {x1}", map.px(t));
            assert!(map.left < map.px(t) && map.px(t) < map.right);
        }
    }
}
