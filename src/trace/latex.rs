//! Unicode formula text to LaTeX (the formulas are written once, in Unicode).

/// Converts the Unicode maths used in formulas to LaTeX. `{name}` placeholders
/// pass through untouched; `_word` becomes a braced subscript.
pub fn to_latex(s: &str) -> String {
    let chars: Vec<char> = s.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        let next = chars.get(i + 1).copied();
        // Accents are combining marks that follow their letter.
        if next == Some('\u{302}') || next == Some('\u{307}') {
            let accent = if next == Some('\u{302}') {
                "\\hat"
            } else {
                "\\dot"
            };
            out.push_str(&format!(
                "{accent}{{{}}}",
                symbol(ch).unwrap_or_else(|| ch.to_string())
            ));
            i += 2;
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
            while j < chars.len()
                && (chars[j].is_alphanumeric() || chars[j] == ',')
                && !is_subscript(chars[j])
            {
                j += 1;
            }
            let word: String = chars[i + 1..j].iter().collect();
            if word.chars().count() > 1 {
                out.push_str(&format!("_{{\\mathrm{{{word}}}}}"));
            } else {
                out.push('_');
                out.push_str(&word);
            }
            i = j;
            continue;
        }
        match symbol(ch) {
            Some(t) => {
                out.push_str(&t);
                // Keep a command from swallowing the next letter.
                if t.starts_with('\\')
                    && t.chars().last().is_some_and(|c| c.is_alphabetic())
                    && next.is_some_and(|c| c.is_alphanumeric())
                {
                    out.push(' ');
                }
            }
            None => out.push(ch),
        }
        i += 1;
    }
    out
}

fn is_subscript(c: char) -> bool {
    matches!(c, '₀'..='₉' | 'ᵢ')
}

fn symbol(c: char) -> Option<String> {
    let s = match c {
        'Δ' => "\\Delta",
        'θ' => "\\theta",
        'ω' => "\\omega",
        'μ' => "\\mu",
        'κ' => "\\kappa",
        'λ' => "\\lambda",
        'ε' => "\\varepsilon",
        'Σ' => "\\sum",
        '∞' => "\\infty",
        '×' => "\\times",
        '·' => "\\cdot",
        '−' => "-",
        '≤' => "\\le",
        '≥' => "\\ge",
        '≈' => "\\approx",
        '→' => "\\to",
        '½' => "\\tfrac{1}{2}",
        '𝟙' => "\\mathbb{1}",
        '⁻' => "^{-",
        '¹' => "1}",
        'ᵀ' => "^{\\mathsf{T}}",
        '′' => "'",
        '°' => "^{\\circ}",
        '₀' => "_0",
        '₁' => "_1",
        '₂' => "_2",
        'ᵢ' => "_i",
        '⊥' => "_{\\perp}",
        '√' => "\\sqrt",
        '‖' => "\\|",
        '⟨' => "\\langle",
        '⟩' => "\\rangle",
        '%' => "\\%",
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
        assert_eq!(to_latex("{r1} × {d}"), "{r1} \\times {d}");
    }
}
