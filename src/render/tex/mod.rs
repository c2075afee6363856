//! Unicode formula text to LaTeX (the formulas are written once, in
//! Unicode); [`prose()`] does the same for text with maths in it.

mod prose;

pub use prose::{escape_text, prose};

/// Converts the Unicode maths used in formulas to LaTeX math. `{name}`
/// placeholders pass through untouched; `_word` becomes a braced subscript
/// (merged with a following subscript run: `Δq̇_d₁` → `\Delta \dot{q}_{d,1}`);
/// runs of sub- or superscript characters become one group (`M₀₁` →
/// `M_{01}`, `10⁻³` → `10^{-3}`); `^(…)` and `√(…)` take their parentheses
/// as the group.
pub fn to_latex(s: &str) -> String {
    let chars: Vec<char> = s.chars().collect();
    let mut out = String::new();
    let mut square = 0usize;
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        let next = chars.get(i + 1).copied();
        // Accents are combining marks that follow their letter.
        if let Some(accent) = next.and_then(accent) {
            out.push_str(&format!(
                "{accent}{{{}}}",
                symbol(ch).unwrap_or_else(|| ch.to_string())
            ));
            i += 2;
            space_before_letter(&mut out, chars.get(i));
            continue;
        }
        if ch == '{' {
            // Placeholder: copy through to the closing brace.
            while i < chars.len() {
                out.push(chars[i]);
                if chars[i] == '}' {
                    break;
                }
                i += 1;
            }
            i += 1;
            continue;
        }
        if ch == '_' {
            let mut j = i + 1;
            // A comma joins two indices (M_0,1), not a subscript to the next item.
            let joins = |j: usize| {
                chars[j] == ',' && chars.get(j + 1).is_some_and(char::is_ascii_alphanumeric)
            };
            while j < chars.len() && (chars[j].is_ascii_alphanumeric() || joins(j)) {
                j += 1;
            }
            let word: String = chars[i + 1..j].iter().collect();
            let word = if word.chars().count() > 1 {
                format!("\\mathrm{{{word}}}")
            } else {
                word
            };
            // An arrow between two indices is one subscript: M_C→W is
            // M_{C\to W}, not M_C\to W.
            let (word, j) = match (chars.get(j), chars.get(j + 1)) {
                (Some('→'), Some(c)) if !word.is_empty() && c.is_ascii_alphanumeric() => {
                    let mut k = j + 1;
                    while k < chars.len() && chars[k].is_ascii_alphanumeric() {
                        k += 1;
                    }
                    let to: String = chars[j + 1..k].iter().collect();
                    (format!("{word}\\to {to}"), k)
                }
                _ => (word, j),
            };
            let (run, end) = script_run(&chars, j, subscript);
            let group = match (word.is_empty(), run.is_empty()) {
                (false, true) => word,
                (true, false) => run,
                (false, false) => format!("{word},{run}"),
                (true, true) => String::new(),
            };
            out.push_str(&script('_', &group));
            i = end;
            continue;
        }
        // A word of two or more letters is a name, set upright; a name
        // joined by `_` to another long word is one identifier.
        if ch.is_ascii_alphabetic() && !out.ends_with('\\') && !prev_is_letter(&chars, i) {
            let mut j = i;
            while j < chars.len() && chars[j].is_ascii_alphanumeric() {
                j += 1;
            }
            let head_len = chars[i..j]
                .iter()
                .take_while(|c| c.is_ascii_alphabetic())
                .count();
            if head_len >= 2 && chars.get(i + head_len).and_then(|c| accent(*c)).is_none() {
                let mut name: String = chars[i..j].iter().collect();
                while chars.get(j) == Some(&'_')
                    && chars[j + 1..]
                        .iter()
                        .take_while(|c| c.is_ascii_alphanumeric())
                        .count()
                        >= 2
                {
                    let mut k = j + 1;
                    while k < chars.len() && chars[k].is_ascii_alphanumeric() {
                        k += 1;
                    }
                    name.push_str("\\_");
                    name.extend(&chars[j + 1..k]);
                    j = k;
                }
                out.push_str(&format!("\\mathrm{{{name}}}"));
                i = j;
                continue;
            }
        }
        if subscript(ch).is_some() {
            let (run, end) = script_run(&chars, i, subscript);
            out.push_str(&script('_', &run));
            i = end;
            continue;
        }
        if superscript(ch).is_some() {
            let (run, end) = script_run(&chars, i, superscript);
            out.push_str(&script('^', &run));
            i = end;
            continue;
        }
        if (ch == '^' || ch == '√') && next == Some('(') {
            if let Some(close) = matching_paren(&chars, i + 1) {
                let inner: String = chars[i + 2..close].iter().collect();
                let head = if ch == '^' { "^" } else { "\\sqrt" };
                out.push_str(&format!("{head}{{{}}}", to_latex(&inner)));
                i = close + 1;
                continue;
            }
        }
        // Inside square brackets a space separates columns ([d̂ t₀ t₁]):
        // math mode would swallow it.
        if ch == ' ' && square > 0 {
            out.push_str("\\;");
            i += 1;
            continue;
        }
        match ch {
            '[' => square += 1,
            ']' => square = square.saturating_sub(1),
            _ => {}
        }
        match symbol(ch) {
            Some(t) => {
                out.push_str(&t);
                space_before_letter(&mut out, chars.get(i + 1));
            }
            None => out.push(ch),
        }
        i += 1;
    }
    out
}

fn prev_is_letter(chars: &[char], i: usize) -> bool {
    i > 0 && chars[i - 1].is_ascii_alphanumeric()
}

/// Keeps a command from swallowing the next letter.
fn space_before_letter(out: &mut String, next: Option<&char>) {
    let ends_in_command = {
        let word: String = out
            .chars()
            .rev()
            .take_while(|c| c.is_ascii_alphabetic())
            .collect();
        !word.is_empty() && out[..out.len() - word.len()].ends_with('\\')
    };
    let letter =
        |c: &char| c.is_alphanumeric() && subscript(*c).is_none() && superscript(*c).is_none();
    if ends_in_command && next.is_some_and(letter) {
        out.push(' ');
    }
}

fn accent(c: char) -> Option<&'static str> {
    match c {
        '\u{302}' => Some("\\hat"),
        '\u{307}' => Some("\\dot"),
        _ => None,
    }
}

fn script(mark: char, group: &str) -> String {
    match group.chars().count() {
        0 => String::new(),
        1 => format!("{mark}{group}"),
        _ => format!("{mark}{{{group}}}"),
    }
}

/// The LaTeX of a run of script characters starting at `from`, and where it ends.
fn script_run(
    chars: &[char],
    from: usize,
    map: fn(char) -> Option<&'static str>,
) -> (String, usize) {
    let mut run = String::new();
    let mut j = from;
    while let Some(t) = chars.get(j).and_then(|c| map(*c)) {
        run.push_str(t);
        j += 1;
    }
    (run, j)
}

fn matching_paren(chars: &[char], open: usize) -> Option<usize> {
    let mut depth = 0;
    for (j, c) in chars.iter().enumerate().skip(open) {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(j);
                }
            }
            _ => {}
        }
    }
    None
}

fn subscript(c: char) -> Option<&'static str> {
    Some(match c {
        '₀' => "0",
        '₁' => "1",
        '₂' => "2",
        '₃' => "3",
        '₄' => "4",
        '₅' => "5",
        '₆' => "6",
        '₇' => "7",
        '₈' => "8",
        '₉' => "9",
        'ᵢ' => "i",
        _ => return None,
    })
}

fn superscript(c: char) -> Option<&'static str> {
    Some(match c {
        '⁰' => "0",
        '¹' => "1",
        '²' => "2",
        '³' => "3",
        '⁴' => "4",
        '⁵' => "5",
        '⁶' => "6",
        '⁷' => "7",
        '⁸' => "8",
        '⁹' => "9",
        '⁻' => "-",
        'ᵀ' => "\\mathsf{T}",
        _ => return None,
    })
}

fn symbol(c: char) -> Option<String> {
    let s = match c {
        'Δ' => "\\Delta",
        'Σ' => "\\sum",
        'θ' => "\\theta",
        'τ' => "\\tau",
        'ω' => "\\omega",
        'μ' => "\\mu",
        'κ' => "\\kappa",
        'λ' => "\\lambda",
        'ε' => "\\varepsilon",
        'π' => "\\pi",
        'φ' => "\\varphi",
        'δ' => "\\delta",
        'ṗ' => "\\dot{p}",
        '∞' => "\\infty",
        '×' => "\\times",
        '·' => "\\cdot",
        '−' | '–' => "-",
        '±' => "\\pm",
        '≤' => "\\le",
        '≥' => "\\ge",
        '≈' => "\\approx",
        '≠' => "\\neq",
        '→' => "\\to",
        '↔' => "\\leftrightarrow",
        '∥' => "\\parallel",
        '½' => "\\tfrac{1}{2}",
        '𝟙' => "\\mathbf{1}",
        '′' => "'",
        '″' => "''",
        // `{}` keeps 10⁻⁵° from being a double superscript.
        '°' => "{}^{\\circ}",
        '⊥' => "_{\\perp}",
        '√' => "\\sqrt",
        '∫' => "\\int",
        '‖' => "\\|",
        '⟨' => "\\langle",
        '⟩' => "\\rangle",
        '…' => "\\ldots",
        '§' => "\\S",
        '%' => "\\%",
        '&' => "\\&",
        '#' => "\\#",
        _ => return None,
    };
    Some(s.to_string())
}

#[cfg(test)]
mod tests {
    use super::to_latex;

    #[test]
    fn converts_the_symbols_formulas_use() {
        assert_eq!(
            to_latex("Δv = −(1 + c)·v_s"),
            "\\Delta v = -(1 + c)\\cdot v_s"
        );
        assert_eq!(to_latex("u₁ = r₁ × d̂"), "u_1 = r_1 \\times \\hat{d}");
        assert_eq!(
            to_latex("Δθ̇₁ = I₁⁻¹ u₁"),
            "\\Delta \\dot{\\theta}_1 = I_1^{-1} u_1"
        );
        assert_eq!(to_latex("v_acc"), "v_{\\mathrm{acc}}");
        // A comma after a subscript ends it; between indices it joins them.
        assert_eq!(to_latex("(Δv, −v_y, −v_z)"), "(\\Delta v, -v_y, -v_z)");
        assert_eq!(to_latex("M_0,1"), "M_{\\mathrm{0,1}}");
        assert_eq!(to_latex("{r1} × {d}"), "{r1} \\times {d}");
    }

    #[test]
    fn script_runs_are_one_group() {
        assert_eq!(to_latex("M₀₁ u_y"), "M_{01} u_y");
        assert_eq!(to_latex("Δq̇_d₁"), "\\Delta \\dot{q}_{d,1}");
        assert_eq!(to_latex("I_l₂"), "I_{l,2}");
        assert_eq!(to_latex("10⁻³"), "10^{-3}");
        assert_eq!(to_latex("Cᵀ"), "C^{\\mathsf{T}}");
        assert_eq!(to_latex("√(g_y² + g_z²)"), "\\sqrt{g_y^2 + g_z^2}");
        assert_eq!(to_latex("(−1)^(2+1) d_pen"), "(-1)^{2+1} d_{\\mathrm{pen}}");
        assert_eq!(to_latex("Δṗ_d"), "\\Delta \\dot{p}_d");
        assert_eq!(to_latex("Δṗ₁"), "\\Delta \\dot{p}_1");
        assert_eq!(
            to_latex("limit₁ = angular_limit · 2"),
            "\\mathrm{limit}_1 = \\mathrm{angular\\_limit} \\cdot 2"
        );
        assert_eq!(
            to_latex("2 atan2(|v|, w) of θ′"),
            "2 \\mathrm{atan2}(|v|, w) \\mathrm{of} \\theta'"
        );
        assert_eq!(to_latex("x̂ ab̂"), "\\hat{x} a\\hat{b}");
    }
}

/// LaTeX of a formula's `lhs = rhs`, made on demand (only the LaTeX and
/// Markdown renderers need it, so building a trace does not pay for it).
pub fn formula(f: &crate::trace::Formula) -> String {
    format!("{} = {}", to_latex(&f.lhs), to_latex(&f.rhs))
}

/// LaTeX of a formula's substituted form, placeholders kept.
pub fn substituted(f: &crate::trace::Formula) -> Option<String> {
    f.substituted.as_deref().map(to_latex)
}

#[cfg(test)]
mod formula_tests {
    use super::*;
    use crate::lesson::Lesson;

    #[test]
    fn latex_is_made_on_demand_from_the_unicode() {
        let lesson = Lesson::load("lecture-2").unwrap();
        let t = crate::worked_solution(&lesson, 0);
        let f = &t
            .stages
            .iter()
            .find(|s| s.id == crate::physics::StageId::DesiredDeltaVelocity)
            .unwrap()
            .formulas[0];
        assert_eq!(
            formula(f),
            format!("{} = {}", to_latex(&f.lhs), to_latex(&f.rhs))
        );
        assert_eq!(substituted(f), f.substituted.as_deref().map(to_latex));
        assert!(formula(f).contains("\\omega"), "{}", formula(f));
    }
}
