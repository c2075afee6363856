//! Prose with Unicode maths in it (notes, titles, summaries) as LaTeX
//! text: maths runs in `$…$`, identifiers in `\texttt`, the rest escaped.

use super::{accent, subscript, superscript, symbol, to_latex};

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
            // `--exact` is a flag, not an en dash: LaTeX joins `--` and `---`.
            '-' if chars.get(i + 1) == Some(&'-') => out.push_str("-{}"),
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

/// A minus sign in prose (ASCII, as every output writes it): alone between
/// spaces (`q - p`), or before a symbol or bracket (`-g`, `-(1 + c)`); not
/// a number's sign (`-1.25` stays text) nor a hyphen (`non-zero`).
fn minus(core: &str) -> bool {
    let mut c = core.trim_start_matches('(').chars();
    match (c.next(), c.next()) {
        (Some('-'), None) => true,
        (Some('-'), Some(n)) => n.is_ascii_alphabetic() || n == '(' || is_math_char(n),
        _ => false,
    }
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
    if core.chars().any(is_math_char) || core.contains('_') || minus(core) {
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
        with_upright_units(core),
        escape_text(tail)
    )
}

/// Units prose writes after a number, longest first (so `m/s` is not `m`).
const UNITS: [&str; 23] = [
    "(m/s)/(N·s)",
    "kg·m²",
    "kg·m/s",
    "N·m·s",
    "rad/s²",
    "rad/s",
    "kg⁻¹",
    "mm/s",
    "m/s²",
    "m/s",
    "N·s",
    "µJ",
    "rad",
    "kg",
    "Hz",
    "mm",
    "cm",
    "ms",
    "°/s",
    "J",
    "N",
    "m",
    "s",
];

/// A maths run with each unit after a number set upright
/// (`22.5 N·s` → `22.5\,\mathrm{N\cdot s}`), as the worked values are. A
/// one-letter unit is one only where it ends a clause or stands before an
/// operator (`2/5 m r²`: m is the mass).
fn with_upright_units(core: &str) -> String {
    let words: Vec<&str> = core.split(' ').collect();
    let numeric_end = |w: &str| {
        let w = w.trim_end_matches([',', ';']);
        w.ends_with(|c: char| c.is_ascii_digit() || "⁰¹²³⁴⁵⁶⁷⁸⁹".contains(c))
            || (w.ends_with([')', ']']) && w.contains(|c: char| c.is_ascii_digit()))
    };
    // A one-letter unit ends a clause or stands before an operator.
    let ends = |k: usize| {
        words[k].len() > 1
            || words
                .get(k + 1)
                .is_none_or(|w| w.starts_with(|c: char| "=/≈×+-<>≤≥·".contains(c)))
    };
    // The words between units go to `to_latex` whole (it reads brackets
    // across words: `[0, Δθ]`); a unit's `\,` takes the space before it.
    let mut out = String::new();
    let mut run: Vec<&str> = Vec::new();
    for (k, w) in words.iter().enumerate() {
        let unit = UNITS.iter().find(|u| {
            w.strip_prefix(**u)
                .is_some_and(|rest| rest.chars().all(|c| "),;:.".contains(c)))
        });
        let unit = unit
            .filter(|u| k > 0 && numeric_end(words[k - 1]) && (u.chars().count() > 1 || ends(k)));
        match unit {
            Some(u) => {
                out.push_str(&to_latex(&run.join(" ")));
                run.clear();
                out.push_str(&crate::trace::glossary::unit_latex(
                    &u.replace('°', "{}^{\\circ}"),
                ));
                run.push(&w[u.len()..]);
            }
            None => run.push(w),
        }
    }
    // The rest of a unit's word (`)`, `,`) joins the next word without a space.
    let rest = run.join(" ");
    out.push_str(&to_latex(&rest));
    out
}

#[cfg(test)]
mod tests {
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
            // An ASCII minus before a symbol or between spaces is maths; a
            // number's sign and a hyphen stay text.
            ("body 2 gets -g.", r"body 2 gets $-g$."),
            ("only r = q - p, so", r"only $r = q - p$, so"),
            ("printed -1.25, non-zero", "printed -1.25, non-zero"),
            (
                "run `contact-lab check` \"now\"",
                r"run \texttt{contact-lab check} ``now''",
            ),
            // Units in maths are upright, after a number only (m r²: the mass).
            (
                "|q - p| = 6.005 m, m·Δv = 22.5 N·s. (I = 2/5 m r²)",
                r"$|q - p| = 6.005\,\mathrm{m}, m\cdot \Delta v = 22.5\,\mathrm{N\cdot s}$. $(I = 2/5 m r^2)$",
            ),
            (
                "(Δq̇_t = 0.15 (m/s)/(N·s)), Δθ̇ = (0, 0, 0.1715) rad/s, turned 5.9×10⁻⁵°",
                r"$(\Delta \dot{q}_t = 0.15\,\mathrm{(m/s)/(N\cdot s)}), \Delta \dot{\theta} = (0, 0, 0.1715)$ rad/s, turned $5.9\times 10^{-5}{}^{\circ}$",
            ),
            // A flag stays two hyphens, in text and in code.
            (
                "(solve --exact newton) or `solve --exact`",
                r"(solve -{}-exact newton) or \texttt{solve -{}-exact}",
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
