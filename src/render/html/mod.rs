//! Web pages (`--format html`): one self-contained UTF-8 file per output,
//! read offline — formulas as MathML (mathml.rs, from the LaTeX the worked
//! solutions already have), figures as inline SVG (figure.rs), the style
//! and a small script inline (page.rs, page.css, page.js). Without the
//! script a page reads top to bottom; with it, one stage (or iteration) at
//! a time. docs/html.md says what each page holds and how large it is.

pub mod detect;
pub mod figure;
pub mod mathml;
pub mod page;
pub mod player;
pub mod player_frames;
pub mod resolve;
pub mod solve;
pub mod study;
pub mod toi;

/// Text escaped for HTML content and double-quoted attributes.
pub fn esc(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}
