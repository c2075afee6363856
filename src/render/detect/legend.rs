//! The `detect --figure` SVG's legends: under each panel, one line per
//! kind of mark the panel draws (every arrow among them), with a swatch of
//! the mark and what it is.

use std::fmt::Write;

/// How a legend line's swatch is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Swatch {
    /// An arrow of this colour.
    Arrow(&'static str),
    /// A filled dot; `true`: also a hollow one beside it.
    Dot(&'static str, bool),
    /// A filled square (w_k).
    Square(&'static str),
    /// A hollow diamond (v_k+1).
    Diamond(&'static str),
    /// A line of this colour, dashed with this pattern (`""`: solid).
    Line(&'static str, &'static str),
}

/// The legend's first line's baseline and the distance between lines.
pub const TOP: f64 = 502.0;
pub const STEP: f64 = 16.0;

/// Writes `entries` one under the other from (`x`, [`TOP`]).
pub fn legend(out: &mut String, x: f64, entries: &[(Swatch, String)]) {
    for (i, (swatch, text)) in entries.iter().enumerate() {
        let y = TOP + STEP * i as f64;
        let mid = y - 4.0;
        match *swatch {
            Swatch::Arrow(c) => {
                let _ = writeln!(
                    out,
                    r#"  <line x1="{x:.1}" y1="{mid:.1}" x2="{:.1}" y2="{mid:.1}" stroke="{c}" stroke-width="3"/>
  <polygon points="{:.1},{mid:.1} {:.1},{:.1} {:.1},{:.1}" fill="{c}"/>"#,
                    x + 18.0,
                    x + 26.0,
                    x + 17.0,
                    mid - 4.0,
                    x + 17.0,
                    mid + 4.0
                );
            }
            Swatch::Dot(c, hollow) => {
                let _ = writeln!(
                    out,
                    r#"  <circle cx="{:.1}" cy="{mid:.1}" r="3.5" fill="{c}"/>"#,
                    x + 6.0
                );
                if hollow {
                    let _ = writeln!(
                        out,
                        r#"  <circle cx="{:.1}" cy="{mid:.1}" r="3.5" fill="white" stroke="{c}" stroke-width="2"/>"#,
                        x + 19.0
                    );
                }
            }
            Swatch::Square(c) => {
                let _ = writeln!(
                    out,
                    r#"  <rect x="{:.1}" y="{:.1}" width="10" height="10" fill="{c}"/>"#,
                    x + 8.0,
                    mid - 5.0
                );
            }
            Swatch::Diamond(c) => {
                let _ = writeln!(out, "{}", diamond(x + 13.0, mid, c));
            }
            Swatch::Line(c, dash) => {
                let dash = if dash.is_empty() {
                    String::new()
                } else {
                    format!(r#" stroke-dasharray="{dash}""#)
                };
                let _ = writeln!(
                    out,
                    r#"  <line x1="{x:.1}" y1="{mid:.1}" x2="{:.1}" y2="{mid:.1}" stroke="{c}" stroke-width="2"{dash}/>"#,
                    x + 26.0
                );
            }
        }
        let _ = writeln!(
            out,
            r#"  <text x="{:.1}" y="{y:.1}" font-size="12">{}</text>"#,
            x + 34.0,
            xml(text)
        );
    }
}

/// A hollow diamond centred on (`x`, `y`) (unfilled: the origin shows
/// through it when v_k+1 is 0).
pub fn diamond(x: f64, y: f64, colour: &str) -> String {
    format!(
        r#"  <polygon points="{:.1},{y:.1} {x:.1},{:.1} {:.1},{y:.1} {x:.1},{:.1}" fill="none" stroke="{colour}" stroke-width="2"/>"#,
        x - 6.0,
        y - 6.0,
        x + 6.0,
        y + 6.0
    )
}

/// Text escaped for an SVG element's content (`&`, `<`, `>`; the detect
/// and time-of-collision figures' labels).
pub(crate) fn xml(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
