//! Unicode formula text to LaTeX (the formulas are written once, in Unicode).

/// Converts the Unicode maths used in formulas to LaTeX math. `{name}`
/// placeholders pass through untouched; `_word` becomes a braced subscript
/// (merged with a following subscript run: `Δq̇_d₁` → `\Delta \dot{q}_{d,1}`);
/// runs of sub- or superscript characters become one group (`M₀₁` →
/// `M_{01}`, `10⁻³` → `10^{-3}`); `^(…)` and `√(…)` take their parentheses
/// as the group.
pub fn to_latex(s: &str) -> String {
    let chars: Vec<char> = s.chars().collect();
    let mut out = String::new();
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
            while j < chars.len() && (chars[j].is_ascii_alphanumeric() || chars[j] == ',') {
                j += 1;
            }
            let word: String = chars[i + 1..j].iter().collect();
            let (run, end) = script_run(&chars, j, subscript);
            let word = if word.chars().count() > 1 {
                format!("\\mathrm{{{word}}}")
            } else {
                word
            };
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
        'ω' => "\\omega",
        'μ' => "\\mu",
        'κ' => "\\kappa",
        'λ' => "\\lambda",
        'ε' => "\\varepsilon",
        'π' => "\\pi",
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
        '°' => "^{\\circ}",
        '⊥' => "_{\\perp}",
        '√' => "\\sqrt",
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

/// Escapes text for LaTeX's text mode: the special characters, typographic
/// punctuation, and any maths symbol as `\ensuremath{…}`.
pub fn escape_text(s: &str) -> String {
    let chars: Vec<char> = s.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if chars.get(i + 1).copied().and_then(accent).is_some() {
            let pair: String = chars[i..i + 2].iter().collect();
            out.push_str(&format!("\\ensuremath{{{}}}", to_latex(&pair)));
            i += 2;
            continue;
        }
        match c {
            '\\' => out.push_str("\\textbackslash{}"),
            '{' | '}' | '$' | '&' | '%' | '#' | '_' => {
                out.push('\\');
                out.push(c);
            }
            '~' => out.push_str("\\~{}"),
            '^' => out.push_str("\\^{}"),
            // The default (OT1) fonts have no <, > or | in text.
            '<' => out.push_str("\\textless{}"),
            '>' => out.push_str("\\textgreater{}"),
            '|' => out.push_str("\\textbar{}"),
            '—' => out.push_str("---"),
            '–' => out.push_str("--"),
            '…' => out.push_str("\\ldots{}"),
            '‘' => out.push('`'),
            '’' => out.push('\''),
            '“' => out.push_str("``"),
            '”' => out.push_str("\'\'"),
            '§' => out.push_str("\\S{}"),
            '°' => out.push_str("\\ensuremath{^{\\circ}}"),
            c if is_math_char(c) => {
                out.push_str(&format!("\\ensuremath{{{}}}", to_latex(&c.to_string())))
            }
            c => out.push(c),
        }
        i += 1;
    }
    out
}

/// A character that only exists in maths (Greek, operators, scripts, accents).
fn is_math_char(c: char) -> bool {
    !c.is_ascii()
        && !matches!(c, '—' | '–' | '…' | '‘' | '’' | '“' | '”' | '§' | '°')
        && (symbol(c).is_some()
            || subscript(c).is_some()
            || superscript(c).is_some()
            || accent(c).is_some())
}

/// Prose with Unicode maths in it (notes, summaries, titles) as LaTeX text.
/// A run of words that carries maths (`Δθ̇₁`, `μ_s`, `r²`) together with the
/// operands and operators around it (`(r × n)ᵀ I⁻¹ = 0`) becomes one inline
/// `$…$`; identifiers such as `velocity_limit` and `code` spans become
/// `\texttt`; the rest is escaped text.
pub fn prose(s: &str) -> String {
    // `code` spans (when the backticks pair up) are typewriter text.
    let ticks = s.matches('`').count();
    if ticks >= 2 && ticks.is_multiple_of(2) {
        return s
            .split('`')
            .enumerate()
            .map(|(i, part)| {
                if i % 2 == 1 {
                    format!("\\texttt{{{}}}", escape_text(part))
                } else {
                    prose(part)
                }
            })
            .collect();
    }
    // Words and the whitespace before each.
    let mut words: Vec<(String, String)> = Vec::new();
    let mut space = String::new();
    let mut word = String::new();
    for c in s.chars() {
        if c.is_whitespace() {
            if !word.is_empty() {
                words.push((std::mem::take(&mut space), std::mem::take(&mut word)));
            }
            space.push(c);
        } else {
            word.push(c);
        }
    }
    if !word.is_empty() {
        words.push((std::mem::take(&mut space), word));
    }
    let mut out = String::new();
    let mut i = 0;
    while i < words.len() {
        let class = classify(&words[i].1);
        if class == Class::Text {
            out.push_str(&words[i].0);
            out.push_str(&text_word(&words[i].1));
            i += 1;
            continue;
        }
        // A run of maths and operands, ended by text or a sentence stop.
        let mut j = i;
        while j < words.len() && classify(&words[j].1) != Class::Text {
            j += 1;
            if words[j - 1].1.ends_with(['.', ';', ':', '!', '?']) {
                break;
            }
        }
        let run = &words[i..j];
        out.push_str(&run[0].0);
        if run.iter().all(|(_, w)| classify(w) == Class::Operand) {
            for (k, (sp, w)) in run.iter().enumerate() {
                if k > 0 {
                    out.push_str(sp);
                }
                out.push_str(&text_word(w));
            }
        } else {
            let mut text = run[0].1.clone();
            for (sp, w) in &run[1..] {
                text.push_str(sp);
                text.push_str(w);
            }
            out.push_str(&math_span(&text));
        }
        i = j;
    }
    out.push_str(&space);
    // Straight double quotes become opening and closing quotes, in turn.
    let mut open = true;
    out.chars()
        .map(|c| match c {
            '"' => {
                open = !open;
                if open { "''" } else { "``" }.to_string()
            }
            c => c.to_string(),
        })
        .collect()
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Class {
    /// Carries maths: a maths symbol, or a subscript such as `v_s`.
    Math,
    /// Could sit in a formula: single letters, numbers, operators, brackets.
    Operand,
    Text,
}

/// An identifier such as `velocity_limit` (every part two characters or more).
fn identifier(core: &str) -> bool {
    let parts: Vec<&str> = core.split('_').collect();
    parts.len() > 1
        && parts.iter().all(|p| p.len() > 1)
        && core.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && core.starts_with(|c: char| c.is_ascii_alphabetic())
}

fn trim_punctuation(w: &str) -> &str {
    w.trim_matches(|c: char| ".,;:!?\"'‘’“”".contains(c))
}

fn classify(w: &str) -> Class {
    let core = trim_punctuation(w);
    if core.is_empty() || core.chars().any(|c| "\\{}$&#~^%`".contains(c)) {
        return Class::Text;
    }
    let bare = core.trim_matches(['(', ')']);
    if identifier(bare) {
        return Class::Text;
    }
    if core.chars().any(is_math_char) || core.contains('_') {
        return Class::Math;
    }
    let mut letters = 0;
    for c in core.chars() {
        if c.is_ascii_alphabetic() {
            letters += 1;
            if letters > 1 {
                return Class::Text;
            }
        } else {
            letters = 0;
        }
    }
    if core
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || "+-*/=<>|()[].,".contains(c))
    {
        Class::Operand
    } else {
        Class::Text
    }
}

/// One word of plain text: escaped, or `\texttt` for an identifier.
fn text_word(w: &str) -> String {
    let lead = w.len() - w.trim_start_matches(['(', '"', '\'']).len();
    let core = trim_punctuation(&w[lead..]).trim_end_matches(')');
    let start = w.find(core).filter(|_| !core.is_empty()).unwrap_or(0);
    if identifier(core) {
        format!(
            "{}\\texttt{{{}}}{}",
            escape_text(&w[..start]),
            escape_text(core),
            escape_text(&w[start + core.len()..])
        )
    } else {
        escape_text(w)
    }
}

/// A run of words with maths as `$…$`; surrounding punctuation and
/// unbalanced brackets stay outside.
fn math_span(text: &str) -> String {
    let opens = text.matches('(').count();
    let closes = text.matches(')').count();
    let lead_end = text
        .char_indices()
        .find(|&(i, c)| !("\"'‘“".contains(c) || (c == '(' && opens > closes && i == 0)))
        .map_or(text.len(), |(i, _)| i);
    let (lead, rest) = text.split_at(lead_end);
    let core =
        rest.trim_end_matches(|c: char| ".,;:!?\"'’”".contains(c) || (c == ')' && closes > opens));
    let tail = &rest[core.len()..];
    format!(
        "{}${}${}",
        escape_text(lead),
        to_latex(core),
        escape_text(tail)
    )
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

    #[test]
    fn prose_puts_maths_in_dollars_and_escapes_the_rest() {
        use super::{escape_text, prose};
        let cases = [
            (
                "50% of μ_s g_n, #1 & co.",
                r"50\% of $\mu_s g_n$, \#1 \& co.",
            ),
            (
                "the velocity_limit (0.25) is 9.8 °/s — fine…",
                r"the \texttt{velocity\_limit} (0.25) is 9.8 \ensuremath{^{\circ}}/s --- fine\ldots{}",
            ),
            (
                "|Δθ̇₁| = 2, (r × d̂ ≈ 0).",
                r"$|\Delta \dot{\theta}_1| = 2, (r \times \hat{d} \approx 0)$.",
            ),
            (
                "right-handed (t₁ = d̂ × t₀).",
                r"right-handed $(t_1 = \hat{d} \times t_0)$.",
            ),
            (
                "route ((r × n)ᵀ I⁻¹ (r × n) = ((I⁻¹(r × n)) × r) · n).",
                r"route $((r \times n)^{\mathsf{T}} I^{-1} (r \times n) = ((I^{-1}(r \times n)) \times r) \cdot n)$.",
            ),
            (
                "the closing speed is 1.25 m/s",
                "the closing speed is 1.25 m/s",
            ),
            ("v_s < 0: the points", r"$v_s < 0$: the points"),
            (
                "run `contact-lab check` \"now\"",
                r"run \texttt{contact-lab check} ``now''",
            ),
        ];
        for (text, latex) in cases {
            assert_eq!(prose(text), latex, "{text}");
        }
        assert_eq!(
            escape_text("a_b {x} ↔ y"),
            r"a\_b \{x\} \ensuremath{\leftrightarrow} y"
        );
    }
}
