//! Every quantity in the narrative of every embedded lesson and scene (its
//! `summary`, which the TUI's overview and the LaTeX sheet print) carries its
//! unit (issue 40): "sunk 0.1 into" and "radius 0.5, mass 1" are refused,
//! "sunk 0.1 m into" and "radius 0.5 m, mass 1 kg" pass. A number needs no
//! unit where it is a count or a ratio (a count noun, `of`, `×` or `per`
//! follows it), an index (`step 3`, `contact 0`), or the value of a
//! quantity without one named in its clause (restitution, friction, a
//! normal or a direction, an orientation, a factor).

use contact_lab::lesson::{embedded, Lesson};

/// Units a narrative writes after a number (longest first).
const UNITS: [&str; 26] = [
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
    "seconds",
    "degrees",
    "%",
    "J",
    "m",
    "s",
    "g",
];

/// Words after a number that make it a count or a ratio.
const COUNTS: [&str; 22] = [
    "contact",
    "triangle",
    "iteration",
    "ball",
    "box",
    "times",
    "test",
    "point",
    "corner",
    "step",
    "digit",
    "wake",
    "layer",
    "of",
    "per",
    "in",
    "for",
    "with",
    "between",
    "million",
    "×",
    "significant",
];

/// Words just before a number that make it an index.
const INDEXES: [&str; 5] = ["step", "contact", "ball", "body", "bodies"];

/// Quantities without a unit: named in the clause before the number.
const DIMENSIONLESS: [&str; 16] = [
    "restitution",
    "friction",
    "μ",
    "e =",
    "e² =",
    "e ×",
    "tan",
    "factor",
    "relative",
    "condition number",
    "κ",
    "|τ|",
    "rounds",
    "normal",
    "along",
    "orientation",
];

const SUPERSCRIPTS: &str = "⁰¹²³⁴⁵⁶⁷⁸⁹";

/// A number as narratives write it: `0.25`, `-2.6`, `+42`, `1e-12`,
/// `10⁸`, `7.5·10⁻⁹`, `200 000` (the last as two words, each a number).
fn is_number(core: &str) -> bool {
    let core = core.trim_start_matches(['±', '~']);
    if core.parse::<f64>().is_ok() && core.contains(|c: char| c.is_ascii_digit()) {
        return !core.eq_ignore_ascii_case("inf") && !core.eq_ignore_ascii_case("nan");
    }
    let power = |p: &str| {
        p.strip_prefix("10").is_some_and(|e| {
            let e = e.strip_prefix('⁻').unwrap_or(e);
            !e.is_empty() && e.chars().all(|c| SUPERSCRIPTS.contains(c))
        })
    };
    match core.split_once(['·', '×']) {
        Some((m, p)) => m.parse::<f64>().is_ok() && power(p),
        None => power(core),
    }
}

/// A word without the brackets, quotes and punctuation around it.
fn core(word: &str) -> &str {
    word.trim_start_matches(['(', '[', '"'])
        .trim_end_matches([',', '.', ';', ':', ')', ']', '"', '\''])
}

fn starts_with_unit(word: &str) -> bool {
    let word = word.trim_start_matches('(');
    UNITS.iter().any(|u| {
        word.strip_prefix(u)
            .is_some_and(|rest| !rest.starts_with(|c: char| c.is_alphabetic()))
    }) || word.starts_with("(m/s)")
}

/// The narrative's words: code spans dropped (a command's `--step 3` is no
/// quantity) unless one word (an identifier such as `static_friction`).
fn words(summary: &str) -> Vec<String> {
    let mut text = String::new();
    for (i, part) in summary.split('`').enumerate() {
        if i % 2 == 0 || !part.contains(char::is_whitespace) {
            text.push_str(part);
        }
        text.push(' ');
    }
    text.split_whitespace().map(str::to_string).collect()
}

/// The numbers of `summary` that lack a unit, each with its context.
fn bare_numbers(summary: &str) -> Vec<String> {
    let w = words(summary);
    let mut bare = vec![];
    for k in 0..w.len() {
        if !is_number(core(&w[k])) {
            continue;
        }
        // The clause before the list the number is in: back to the last
        // comma, colon or stop, or to an opening bracket.
        let mut start = k;
        while start > 0 && w[start - 1].ends_with(',') && is_number(core(&w[start - 1])) {
            start -= 1;
        }
        let mut clause = vec![];
        for j in (0..start).rev() {
            if w[j].ends_with([',', ';', ':', '.']) {
                break;
            }
            clause.push(w[j].to_lowercase());
            if w[j].starts_with('(') {
                break;
            }
        }
        clause.reverse();
        let clause = clause.join(" ");
        let previous = k.checked_sub(1).map(|j| core(&w[j]).to_lowercase());
        if DIMENSIONLESS.iter().any(|d| clause.contains(d))
            || previous.is_some_and(|p| INDEXES.contains(&p.as_str()))
        {
            continue;
        }
        // Along a list or an expression to the word after it.
        let mut j = k + 1;
        while j < w.len() {
            let c = core(&w[j]);
            let joiner = ["and", "to", "or", "=", "-", "+", "≈", "/", "<", ">"].contains(&c);
            let symbol = c.chars().count() == 1 && c.starts_with(|c: char| c.is_alphabetic());
            let chained = is_number(c)
                || (joiner && w.get(j + 1).is_some_and(|n| is_number(core(n))))
                || (symbol && w[j - 1].ends_with(','));
            if !chained || (starts_with_unit(&w[j]) && !is_number(c)) {
                break;
            }
            j += 1;
        }
        let next = w.get(j).map_or("", String::as_str);
        let noun = core(next);
        let counted = COUNTS.iter().any(|c| {
            [c.to_string(), format!("{c}s"), format!("{c}es")].contains(&noun.to_string())
        });
        if !(starts_with_unit(next) || counted) {
            let from = k.saturating_sub(4);
            let to = (j + 2).min(w.len());
            bare.push(w[from..to].join(" "));
        }
    }
    bare
}

#[test]
fn the_rule_refuses_a_bare_quantity_and_passes_counts_indexes_and_ratios() {
    let bare = bare_numbers("A box has sunk 0.1 into the floor (radius 0.5, mass 1).");
    assert_eq!(bare.len(), 3, "{bare:?}");
    let fine = "A box has sunk 0.1 m into the floor (radius 0.5 m, mass 1 kg) \
                at (0.5, -2) m/s: step 3 of 12 contacts, 8 × contacts, e = 0.5, \
                the normal (0, 1, 0), 10⁻¹² of it, 4 - 6.6 = -2.6 m/s, 47°, \
                `--velocity-iterations 200`, 7.5·10⁻⁹ m, (0.6464, 0.6464, z) m.";
    assert_eq!(bare_numbers(fine), Vec::<String>::new());
}

#[test]
fn every_quantity_in_every_narrative_has_its_unit() {
    let ids: Vec<&str> = embedded::ids()
        .into_iter()
        .chain(embedded::scene_ids())
        .collect();
    assert!(ids.len() > 40, "{}", ids.len());
    let mut bare = vec![];
    for id in ids {
        let lesson = Lesson::load(id).unwrap();
        for context in bare_numbers(&lesson.summary) {
            bare.push(format!("{id}: …{context}…"));
        }
    }
    assert!(
        bare.is_empty(),
        "numbers without a unit:\n{}",
        bare.join("\n")
    );
}
