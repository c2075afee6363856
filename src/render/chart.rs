//! Line and scatter charts as SVG panels: series against a shared x axis,
//! linear or logarithmic axes with round ticks, a legend, an optional cursor.
//! Used for a simulation's energy and penetration over time and for the
//! study's error against cost. Numbers go through the one formatter.

use std::fmt::Write;

use crate::format::Fmt;

mod legend;
mod ticks;
mod xmap;

use ticks::integer_range;
pub use ticks::{integer_ticks, ticks};
pub use xmap::XMap;
use xmap::{back, tick_range};

/// A scale of one axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Scale {
    #[default]
    Linear,
    /// Base-10 logarithmic; values ≤ 0 are left out.
    Log,
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mark {
    #[default]
    Line,
    /// Dots, for a scatter plot.
    Dots,
    /// Squares, triangles and diamonds: scatter marks told apart without colour.
    Squares,
    Triangles,
    Diamonds,
    /// Crosses (×) and pluses (+), stroked.
    Crosses,
    Pluses,
    /// A step line (the value holds until the next point), for counts.
    Steps,
}

/// One series.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    pub colour: &'static str,
    pub mark: Mark,
    /// Dashed line: told apart without colour.
    pub dashed: bool,
}

/// One chart panel.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Chart {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub x_scale: Scale,
    pub y_scale: Scale,
    pub series: Vec<Series>,
    /// A vertical line at this x (the current time, say).
    pub cursor: Option<f64>,
    /// Joined points drawn over the series (a Pareto front).
    pub front: Option<Vec<(f64, f64)>>,
    /// Labelled vertical lines at these x (events: where a phase changes).
    pub marks: Vec<(f64, String)>,
    /// The y values are counts: whole-number ticks from 0 (or below).
    pub integer_y: bool,
    /// Hover details of scatter marks: `tips[series][point]`, drawn as the
    /// mark's `<title>` (a web page shows it on hover); none where empty.
    pub tips: Vec<Vec<String>>,
}

/// Colours told apart by colour-blind readers (Okabe–Ito).
pub const PALETTE: [&str; 8] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#F0E442", "#000000",
];

const FONT: &str = "DejaVu Sans, Helvetica, Arial, sans-serif";

fn transform(x: f64, scale: Scale) -> Option<f64> {
    match scale {
        Scale::Linear => x.is_finite().then_some(x),
        Scale::Log => (x > 0.0 && x.is_finite()).then(|| x.log10()),
    }
}

/// The range of the finite values (after the scale), widened when flat.
fn range(values: impl Iterator<Item = f64>, scale: Scale) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter_map(|v| transform(v, scale)) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    if hi - lo < 1e-12 * lo.abs().max(1.0) {
        let pad = if scale == Scale::Log {
            0.5
        } else {
            lo.abs().max(1.0) * 0.1
        };
        return (lo - pad, hi + pad);
    }
    (lo, hi)
}

impl Chart {
    /// The x axis and the plot's edges [`Chart::draw`] uses in the box
    /// `(x, y, width, height)`: a cursor drawn by a page's script lands
    /// where the chart's own would.
    pub fn x_map(&self, (x0, y0, w, h): (f64, f64, f64, f64)) -> XMap {
        let all = || self.series.iter().flat_map(|s| s.points.iter());
        let (xl, xh) = range(all().map(|p| p.0), self.x_scale);
        let xt = ticks(back(xl, self.x_scale), back(xh, self.x_scale), self.x_scale);
        // The axis range widened to the outer ticks.
        let (lo, hi) = tick_range(&xt, self.x_scale, xl, xh);
        XMap {
            left: x0 + 64.0,
            right: x0 + w - 12.0,
            lo,
            hi,
            top: y0 + 28.0,
            bottom: y0 + h - 40.0,
        }
    }

    /// Draws the chart into `out` as an SVG group within the box
    /// `(x, y, width, height)` of the page.
    pub fn draw(&self, out: &mut String, (x0, y0, w, h): (f64, f64, f64, f64)) {
        let fmt = Fmt::new(3);
        let all = || self.series.iter().flat_map(|s| s.points.iter());
        let (yl0, yh0) = if self.integer_y && self.y_scale == Scale::Linear {
            integer_range(all().map(|p| p.1))
        } else {
            range(all().map(|p| p.1), self.y_scale)
        };
        let map = self.x_map((x0, y0, w, h));
        let (xl, xh) = range(all().map(|p| p.0), self.x_scale);
        let xt = ticks(back(xl, self.x_scale), back(xh, self.x_scale), self.x_scale);
        let (left, top, right, bottom) = (map.left, map.top, map.right, map.bottom);
        let px = |v: f64| map.px(v);
        let y_axis = |yh: f64| {
            let yt = if self.integer_y && self.y_scale == Scale::Linear {
                integer_ticks(yl0, yh)
            } else {
                ticks(
                    back(yl0, self.y_scale),
                    back(yh, self.y_scale),
                    self.y_scale,
                )
            };
            let (yl, yh) = tick_range(&yt, self.y_scale, yl0, yh);
            (yt, yl, yh)
        };
        // The legend: in a corner no curve crosses; where every corner is
        // crossed, the y axis grows at the top until the top right is clear.
        let names: Vec<&str> = self
            .series
            .iter()
            .filter(|s| !s.name.is_empty())
            .map(|s| s.name.as_str())
            .collect();
        let size = legend::size(&names);
        let plot = (left, top, right - left, bottom - top);
        let mut y_top = yh0;
        let (mut yt, mut yl, mut yh) = y_axis(y_top);
        let mut legend_box = None;
        for _ in 0..6 {
            let py = |v: f64| bottom - (v - yl) / (yh - yl).max(1e-300) * (bottom - top);
            let curves = self.page_curves(&px, &py);
            legend_box = if names.is_empty() {
                None
            } else {
                legend::place(plot, size, &curves)
            };
            if names.is_empty() || legend_box.is_some() {
                break;
            }
            // Room above the highest value for the legend's height.
            let high = all()
                .filter_map(|p| transform(p.1, self.y_scale))
                .fold(yl, f64::max);
            let r = ((size.1 + 12.0) / (bottom - top)).min(0.8);
            y_top = y_top.max((high - r * yl) / (1.0 - r)) + (yh - yl) * 0.02;
            (yt, yl, yh) = y_axis(y_top);
        }
        let py = |v: f64| bottom - (v - yl) / (yh - yl).max(1e-300) * (bottom - top);
        let _ = writeln!(
            out,
            r##"<g font-family="{FONT}" font-size="12"><text x="{:.1}" y="{:.1}" font-size="14" font-weight="bold">{}</text>"##,
            x0 + 8.0,
            y0 + 16.0,
            escape(&self.title)
        );
        let _ = writeln!(
            out,
            r##"<rect x="{left:.1}" y="{top:.1}" width="{:.1}" height="{:.1}" fill="none" stroke="#888888"/>"##,
            right - left,
            bottom - top
        );
        for t in &xt {
            let Some(v) = transform(*t, self.x_scale) else {
                continue;
            };
            let x = px(v);
            let _ = writeln!(
                out,
                r##"<line x1="{x:.1}" y1="{top:.1}" x2="{x:.1}" y2="{bottom:.1}" stroke="#E4E4E4"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
                bottom + 16.0,
                fmt.num(*t)
            );
        }
        for t in &yt {
            let Some(v) = transform(*t, self.y_scale) else {
                continue;
            };
            let y = py(v);
            let _ = writeln!(
                out,
                r##"<line x1="{left:.1}" y1="{y:.1}" x2="{right:.1}" y2="{y:.1}" stroke="#E4E4E4"/><text x="{:.1}" y="{:.1}" text-anchor="end">{}</text>"##,
                left - 6.0,
                y + 4.0,
                fmt.num(*t)
            );
        }
        let _ = writeln!(
            out,
            r##"<text x="{:.1}" y="{:.1}" text-anchor="middle">{}</text>"##,
            (left + right) / 2.0,
            bottom + 34.0,
            escape(&self.x_label)
        );
        let _ = writeln!(
            out,
            r##"<text x="{:.1}" y="{:.1}" text-anchor="middle" transform="rotate(-90 {:.1} {:.1})">{}</text>"##,
            x0 + 14.0,
            (top + bottom) / 2.0,
            x0 + 14.0,
            (top + bottom) / 2.0,
            escape(&self.y_label)
        );
        for (k, s) in self.series.iter().enumerate() {
            let placed: Vec<(usize, (f64, f64))> = (s.points.iter().enumerate())
                .filter_map(|(i, p)| {
                    Some((
                        i,
                        (
                            px(transform(p.0, self.x_scale)?),
                            py(transform(p.1, self.y_scale)?),
                        ),
                    ))
                })
                .collect();
            let pts: Vec<(f64, f64)> = placed.iter().map(|(_, p)| *p).collect();
            let dash = if s.dashed {
                r#" stroke-dasharray="6 4""#
            } else {
                ""
            };
            match s.mark {
                Mark::Dots
                | Mark::Squares
                | Mark::Triangles
                | Mark::Diamonds
                | Mark::Crosses
                | Mark::Pluses => {
                    for (i, (x, y)) in &placed {
                        let tip = self.tips.get(k).and_then(|t| t.get(*i));
                        if let Some(tip) = tip.filter(|t| !t.is_empty()) {
                            let _ = write!(out, "<g class=\"tip\"><title>{}</title>", escape(tip));
                            marker(out, s.mark, *x, *y, s.colour);
                            out.push_str("</g>\n");
                        } else {
                            marker(out, s.mark, *x, *y, s.colour);
                        }
                    }
                }
                Mark::Line | Mark::Steps => {
                    let mut d = String::new();
                    for (i, (x, y)) in pts.iter().enumerate() {
                        if i == 0 {
                            let _ = write!(d, "M{x:.1},{y:.1}");
                        } else if s.mark == Mark::Steps {
                            let _ = write!(d, " H{x:.1} V{y:.1}");
                        } else {
                            let _ = write!(d, " L{x:.1},{y:.1}");
                        }
                    }
                    if !d.is_empty() {
                        let _ = writeln!(
                            out,
                            r##"<path d="{d}" fill="none" stroke="{}" stroke-width="1.8"{dash}/>"##,
                            s.colour
                        );
                    }
                }
            }
        }
        if let Some(front) = &self.front {
            let pts: Vec<String> = front
                .iter()
                .filter_map(|p| {
                    Some(format!(
                        "{:.1},{:.1}",
                        px(transform(p.0, self.x_scale)?),
                        py(transform(p.1, self.y_scale)?)
                    ))
                })
                .collect();
            if pts.len() > 1 {
                let _ = writeln!(
                    out,
                    r##"<polyline points="{}" fill="none" stroke="#000000" stroke-width="1.2" stroke-dasharray="2 3"/>"##,
                    pts.join(" ")
                );
            }
        }
        if let Some(c) = self.cursor.and_then(|c| transform(c, self.x_scale)) {
            let x = px(c);
            let _ = writeln!(
                out,
                r##"<line x1="{x:.1}" y1="{top:.1}" x2="{x:.1}" y2="{bottom:.1}" stroke="#000000" stroke-dasharray="3 3"/>"##
            );
        }
        for (at, label) in &self.marks {
            let Some(v) = transform(*at, self.x_scale) else {
                continue;
            };
            let x = px(v);
            let _ = writeln!(
                out,
                r##"<line x1="{x:.1}" y1="{top:.1}" x2="{x:.1}" y2="{bottom:.1}" stroke="#444444" stroke-dasharray="2 3"/><text x="{:.1}" y="{:.1}" font-size="11" fill="#444444" text-anchor="end" transform="rotate(-90 {:.1} {:.1})">{}</text>"##,
                x + 12.0,
                top + 4.0,
                x + 12.0,
                top + 4.0,
                escape(label)
            );
        }
        // Legend (series without a name have none: the caller draws its
        // own), on a white box where no curve runs.
        if let Some((bx, by, bw, bh)) = legend_box {
            let _ = writeln!(
                out,
                r##"<rect class="legend-box" x="{bx:.1}" y="{by:.1}" width="{bw:.1}" height="{bh:.1}" fill="#FFFFFF" fill-opacity="0.9" stroke="#CCCCCC"/>"##
            );
            for (i, s) in self
                .series
                .iter()
                .filter(|s| !s.name.is_empty())
                .enumerate()
            {
                let y = by + 15.0 + 15.0 * i as f64;
                let x = bx + 6.0;
                let dash = if s.dashed {
                    r#" stroke-dasharray="6 4""#
                } else {
                    ""
                };
                let _ = writeln!(
                    out,
                    r##"<line x1="{x:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{}" stroke-width="2"{dash}/><text x="{:.1}" y="{y:.1}">{}</text>"##,
                    y - 4.0,
                    x + 18.0,
                    y - 4.0,
                    s.colour,
                    x + 24.0,
                    escape(&s.name)
                );
            }
        }
        out.push_str("</g>\n");
    }

    /// Every series as drawn on the page (a step line with its corners; a
    /// scatter series one point per mark), and the front: what the legend
    /// must stay clear of.
    fn page_curves(
        &self,
        px: &dyn Fn(f64) -> f64,
        py: &dyn Fn(f64) -> f64,
    ) -> Vec<Vec<(f64, f64)>> {
        let page = |p: &(f64, f64)| {
            Some((
                px(transform(p.0, self.x_scale)?),
                py(transform(p.1, self.y_scale)?),
            ))
        };
        let mut out = vec![];
        for s in &self.series {
            let pts: Vec<(f64, f64)> = s.points.iter().filter_map(page).collect();
            match s.mark {
                Mark::Line => out.push(pts),
                Mark::Steps => {
                    let mut line = vec![];
                    for (i, p) in pts.iter().enumerate() {
                        if i > 0 {
                            line.push((p.0, pts[i - 1].1));
                        }
                        line.push(*p);
                    }
                    out.push(line);
                }
                _ => out.extend(pts.into_iter().map(|p| vec![p])),
            }
        }
        if let Some(front) = &self.front {
            out.push(front.iter().filter_map(page).collect());
        }
        out
    }
}

/// One scatter mark centred at (x, y).
pub fn marker(out: &mut String, mark: Mark, x: f64, y: f64, colour: &str) {
    let r = 3.8;
    let _ = match mark {
        Mark::Squares => writeln!(
            out,
            r##"<rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="{colour}"/>"##,
            x - r,
            y - r,
            2.0 * r,
            2.0 * r
        ),
        Mark::Triangles => writeln!(
            out,
            r##"<polygon points="{x:.1},{:.1} {:.1},{:.1} {:.1},{:.1}" fill="{colour}"/>"##,
            y - r * 1.2,
            x - r * 1.1,
            y + r * 0.8,
            x + r * 1.1,
            y + r * 0.8
        ),
        Mark::Diamonds => writeln!(
            out,
            r##"<polygon points="{x:.1},{:.1} {:.1},{y:.1} {x:.1},{:.1} {:.1},{y:.1}" fill="{colour}"/>"##,
            y - r * 1.3,
            x + r * 1.3,
            y + r * 1.3,
            x - r * 1.3
        ),
        Mark::Crosses => writeln!(
            out,
            r##"<path d="M{:.1},{:.1} L{:.1},{:.1} M{:.1},{:.1} L{:.1},{:.1}" stroke="{colour}" stroke-width="2" fill="none"/>"##,
            x - r,
            y - r,
            x + r,
            y + r,
            x - r,
            y + r,
            x + r,
            y - r
        ),
        Mark::Pluses => writeln!(
            out,
            r##"<path d="M{:.1},{y:.1} L{:.1},{y:.1} M{x:.1},{:.1} L{x:.1},{:.1}" stroke="{colour}" stroke-width="2" fill="none"/>"##,
            x - r * 1.2,
            x + r * 1.2,
            y - r * 1.2,
            y + r * 1.2
        ),
        _ => writeln!(
            out,
            r##"<circle cx="{x:.1}" cy="{y:.1}" r="3.5" fill="{colour}"/>"##
        ),
    };
}

/// Text escaped for SVG.
pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_chart_draws_every_series_and_skips_non_positive_values_on_a_log_axis() {
        let chart = Chart {
            title: "energy".into(),
            x_label: "t (s)".into(),
            y_label: "J".into(),
            y_scale: Scale::Log,
            series: vec![
                Series {
                    name: "kinetic".into(),
                    points: vec![(0.0, 1.0), (1.0, 0.0), (2.0, 0.5)],
                    colour: PALETTE[0],
                    mark: Mark::Line,
                    dashed: false,
                },
                Series {
                    name: "a < b".into(),
                    points: vec![(0.0, 2.0)],
                    colour: PALETTE[1],
                    mark: Mark::Dots,
                    dashed: true,
                },
            ],
            cursor: Some(1.0),
            ..Chart::default()
        };
        let mut out = String::new();
        chart.draw(&mut out, (0.0, 0.0, 400.0, 300.0));
        assert_eq!(out.matches("<path").count(), 1);
        // The zero is left out: the path has two points.
        let path = out.lines().find(|l| l.starts_with("<path")).unwrap();
        assert_eq!(path.matches('L').count(), 1);
        assert_eq!(out.matches("<circle").count(), 1);
        assert!(out.contains("a &lt; b"));
        assert!(!out.contains("NaN"));
    }
}
