//! The page around a renderer's body: the document head, the style and the
//! script inline (page.css, page.js: nothing is fetched), the step controls
//! the script turns on, and the footer.

use super::esc;

/// What the page steps through, for the controls' words.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Steps {
    /// A worked solution's stages (with "predict before you look").
    Stages,
    /// A resolve's iterations.
    Iterations,
    /// No step controls: the page's own script (the player, the study's
    /// sorting) does what it does.
    Plain,
}

const STYLE: &str = include_str!("page.css");
const SCRIPT: &str = include_str!("page.js");

/// The previous/next buttons, the position and (for stages) the predict
/// switch: hidden until the script shows them.
fn controls(steps: Steps) -> String {
    let what = match steps {
        Steps::Stages => "stage",
        Steps::Iterations => "step",
        Steps::Plain => return String::new(),
    };
    let predict = match steps {
        Steps::Stages => {
            "\n  <label class=\"predict-toggle\"><input type=\"checkbox\" id=\"predict\" aria-label=\"predict before you look\"> Predict before you look</label>\n  <span class=\"score\" aria-live=\"polite\"></span>"
        }
        Steps::Iterations | Steps::Plain => "",
    };
    format!(
        "<div class=\"controls\" role=\"toolbar\" aria-label=\"{what}s\" hidden>\n  \
         <button type=\"button\" data-go=\"prev\" aria-label=\"previous {what}\" aria-keyshortcuts=\"ArrowLeft\">← Previous</button>\n  \
         <span class=\"where\" aria-live=\"polite\"></span>\n  \
         <button type=\"button\" data-go=\"next\" aria-label=\"next {what}\" aria-keyshortcuts=\"ArrowRight\">Next →</button>{predict}\n</div>\n"
    )
}

/// The predict tolerance the page's script grades with, as data on the
/// page (`<body data-tolerance>`): the app's one rule
/// ([`crate::exercise::answer::tolerance`]), never restated in page.js.
pub fn tolerance_data() -> String {
    use crate::exercise::answer::MIN_DECIMALS;
    use crate::lesson::printed::{LAST_DIGIT_UNITS, RELATIVE};
    esc(&serde_json::json!({
        "last_digit_units": LAST_DIGIT_UNITS,
        "min_decimals": MIN_DECIMALS,
        "relative": RELATIVE,
    })
    .to_string())
}

/// A whole page: `title` in the head, `header` above the controls, `body`
/// below them.
pub fn page(title: &str, steps: Steps, header: &str, body: &str) -> String {
    page_with(title, steps, header, body, "")
}

/// [`page`] with `script` run after the page's own (a player's, a
/// sortable table's).
pub fn page_with(title: &str, steps: Steps, header: &str, body: &str, script: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <meta name=\"generator\" content=\"contact-lab {version}\">\n\
         <title>{title}</title>\n<style>\n{STYLE}</style>\n</head>\n<body data-tolerance=\"{tolerance}\">\n\
         <header class=\"top\">\n{header}</header>\n{controls}{body}\n\
         <footer>Made with contact-lab {version}, a step-by-step calculator for rigid-body contact resolution \
         (the impulse method of Millington's Game Physics Engine Development). This page works offline: \
         everything it shows is in this one file.</footer>\n\
         <script>\n{SCRIPT}{script}</script>\n</body>\n</html>\n",
        title = esc(title),
        version = env!("CARGO_PKG_VERSION"),
        controls = controls(steps),
        tolerance = tolerance_data(),
    )
}
