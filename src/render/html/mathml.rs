//! The LaTeX the worked solutions are written in (`render::tex`, the
//! numbers of `Fill::value_latex`, the units of the glossary) as MathML
//! Core, for the web page. Only the subset those emit: letters, numbers and
//! operators; `_`/`^` scripts and `{…}` groups; `\mathrm`, `\mathsf`,
//! `\mathbf`, `\text`; `\dot`, `\hat`, `\sqrt`, `\tfrac`; `pmatrix`;
//! `\,` and `\;`; the symbols of `render::tex`. Anything else comes out as
//! `<merror>` (a test runs every lesson through it and finds none).

use super::esc;

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Cmd(String),
    Char(char),
    Open,
    Close,
    Sub,
    Sup,
    Amp,
}

fn tokens(tex: &str) -> Vec<Tok> {
    let chars: Vec<char> = tex.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        i += 1;
        match c {
            '\\' => {
                let start = i;
                while i < chars.len() && chars[i].is_ascii_alphabetic() {
                    i += 1;
                }
                if i == start && i < chars.len() {
                    i += 1;
                }
                out.push(Tok::Cmd(chars[start..i].iter().collect()));
            }
            '{' => out.push(Tok::Open),
            '}' => out.push(Tok::Close),
            '_' => out.push(Tok::Sub),
            '^' => out.push(Tok::Sup),
            '&' => out.push(Tok::Amp),
            c if c.is_whitespace() => {}
            c => out.push(Tok::Char(c)),
        }
    }
    out
}

/// What ends a run of atoms.
#[derive(Clone, Copy, PartialEq)]
enum Stop {
    /// The end of the input or a `&` (a cell of an aligned row).
    Cell,
    /// A closing brace.
    Group,
    /// `&`, `\\` or `\end` (a cell of a matrix).
    Matrix,
}

struct Parser {
    toks: Vec<Tok>,
    i: usize,
}

impl Parser {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.i)
    }

    fn stops(&self, stop: Stop) -> bool {
        match (self.peek(), stop) {
            (None, _) => true,
            (Some(Tok::Close), _) => true,
            (Some(Tok::Amp), Stop::Cell | Stop::Matrix) => true,
            (Some(Tok::Cmd(c)), Stop::Matrix) => c == "\\" || c == "end",
            _ => false,
        }
    }

    /// Atoms (with their scripts) up to `stop`, not consuming it.
    fn run(&mut self, stop: Stop, upright: bool) -> String {
        let mut out = String::new();
        while !self.stops(stop) {
            out.push_str(&self.scripted(upright));
        }
        out
    }

    /// A `{…}` group's MathML (one atom when it is not braced).
    fn group(&mut self, upright: bool) -> String {
        if self.peek() == Some(&Tok::Open) {
            self.i += 1;
            let inner = self.run(Stop::Group, upright);
            if self.peek() == Some(&Tok::Close) {
                self.i += 1;
            }
            format!("<mrow>{inner}</mrow>")
        } else if self.peek().is_none() {
            "<mrow></mrow>".into()
        } else {
            self.atom(upright)
        }
    }

    /// A group's raw text (for `\text` and environment names).
    fn raw_group(&mut self) -> String {
        let mut s = String::new();
        if self.peek() != Some(&Tok::Open) {
            return s;
        }
        self.i += 1;
        while let Some(t) = self.peek().cloned() {
            self.i += 1;
            match t {
                Tok::Close => break,
                Tok::Char(c) => s.push(c),
                Tok::Cmd(c) if c.len() == 1 => s.push_str(&c),
                Tok::Cmd(c) => s.push_str(&c),
                Tok::Sub => s.push('_'),
                Tok::Sup => s.push('^'),
                Tok::Amp => s.push('&'),
                Tok::Open => {}
            }
        }
        s
    }

    /// `{}^{\circ}`: the degree sign, not a script on nothing.
    fn degree_next(&self) -> bool {
        self.toks.get(self.i..self.i + 4)
            == Some(&[Tok::Sup, Tok::Open, Tok::Cmd("circ".into()), Tok::Close])
    }

    /// An atom and its sub- and superscripts.
    fn scripted(&mut self, upright: bool) -> String {
        let base = if matches!(self.peek(), Some(Tok::Sub | Tok::Sup)) {
            String::new()
        } else {
            self.atom(upright)
        };
        if self.degree_next() {
            self.i += 4;
            let base = if base == "<mrow></mrow>" { "" } else { &base };
            return format!("{base}<mo>°</mo>");
        }
        let (mut sub, mut sup) = (None, None);
        loop {
            match self.peek() {
                Some(Tok::Sub) if sub.is_none() => {
                    self.i += 1;
                    sub = Some(self.group(upright));
                }
                Some(Tok::Sup) if sup.is_none() => {
                    self.i += 1;
                    sup = Some(self.group(upright));
                }
                _ => break,
            }
        }
        let base = if base.is_empty() {
            "<mrow></mrow>".to_string()
        } else {
            base
        };
        match (sub, sup) {
            (None, None) => base,
            (Some(b), None) => format!("<msub>{base}{b}</msub>"),
            (None, Some(p)) => format!("<msup>{base}{p}</msup>"),
            (Some(b), Some(p)) => format!("<msubsup>{base}{b}{p}</msubsup>"),
        }
    }

    fn atom(&mut self, upright: bool) -> String {
        let Some(t) = self.peek().cloned() else {
            return String::new();
        };
        match t {
            Tok::Open => self.group(upright),
            Tok::Char(c) if c.is_ascii_digit() || c == '.' => self.number(),
            Tok::Char(c) if upright && c.is_alphanumeric() => self.name(),
            Tok::Char(c) => {
                self.i += 1;
                char_atom(c)
            }
            Tok::Cmd(name) => {
                self.i += 1;
                self.command(&name, upright)
            }
            // A stray close, `&`, or script: shown, never looped on.
            Tok::Close | Tok::Amp | Tok::Sub | Tok::Sup => {
                self.i += 1;
                format!("<merror><mtext>{}</mtext></merror>", esc(&format!("{t:?}")))
            }
        }
    }

    /// Digits with at most one decimal point.
    fn number(&mut self) -> String {
        let mut s = String::new();
        while let Some(Tok::Char(c)) = self.peek() {
            if c.is_ascii_digit() || (*c == '.' && !s.contains('.')) {
                s.push(*c);
                self.i += 1;
            } else {
                break;
            }
        }
        format!("<mn>{s}</mn>")
    }

    /// An upright name: letters, digits and `\_`, one identifier.
    fn name(&mut self) -> String {
        let mut s = String::new();
        loop {
            match self.peek() {
                Some(Tok::Char(c)) if c.is_alphanumeric() => s.push(*c),
                Some(Tok::Cmd(c)) if c == "_" => s.push('_'),
                _ => break,
            }
            self.i += 1;
        }
        if s.chars().all(|c| c.is_ascii_digit()) {
            format!("<mn>{s}</mn>")
        } else if s.chars().count() == 1 {
            format!("<mi mathvariant=\"normal\">{}</mi>", esc(&s))
        } else {
            format!("<mi>{}</mi>", esc(&s))
        }
    }

    fn command(&mut self, name: &str, upright: bool) -> String {
        match name {
            "mathrm" | "mathsf" => self.group(true),
            "mathbf" => format!("<mrow class=\"bold\">{}</mrow>", self.group(true)),
            "text" => format!("<mtext>{}</mtext>", esc(&self.raw_group())),
            "dot" => format!(
                "<mover accent=\"true\">{}<mo>˙</mo></mover>",
                self.group(upright)
            ),
            "hat" => format!(
                "<mover accent=\"true\">{}<mo>^</mo></mover>",
                self.group(upright)
            ),
            "sqrt" => format!("<msqrt>{}</msqrt>", self.group(upright)),
            "tfrac" | "frac" => {
                let num = self.group(upright);
                let den = self.group(upright);
                format!("<mfrac displaystyle=\"false\">{num}{den}</mfrac>")
            }
            "begin" => {
                let _env = self.raw_group();
                self.matrix(upright)
            }
            "," => "<mspace width=\"0.1667em\"></mspace>".into(),
            ";" => "<mspace width=\"0.2778em\"></mspace>".into(),
            "_" | "%" | "&" | "#" | "{" | "}" => format!("<mo>{}</mo>", esc(name)),
            other => match symbol(other) {
                Some(s) => s,
                None => format!("<merror><mtext>\\{}</mtext></merror>", esc(other)),
            },
        }
    }

    /// `pmatrix` after its `\begin{…}`: rows of cells, in parentheses.
    fn matrix(&mut self, upright: bool) -> String {
        let mut rows = Vec::new();
        let mut row = Vec::new();
        loop {
            row.push(format!("<mtd>{}</mtd>", self.run(Stop::Matrix, upright)));
            match self.peek().cloned() {
                Some(Tok::Amp) => self.i += 1,
                Some(Tok::Cmd(c)) if c == "\\" => {
                    self.i += 1;
                    rows.push(format!("<mtr>{}</mtr>", row.concat()));
                    row.clear();
                }
                Some(Tok::Cmd(c)) if c == "end" => {
                    self.i += 1;
                    let _ = self.raw_group();
                    break;
                }
                // A close brace or the end: the matrix was not closed.
                _ => break,
            }
        }
        rows.push(format!("<mtr>{}</mtr>", row.concat()));
        format!(
            "<mrow><mo>(</mo><mtable>{}</mtable><mo>)</mo></mrow>",
            rows.concat()
        )
    }
}

fn char_atom(c: char) -> String {
    match c {
        '-' => "<mo>−</mo>".into(),
        '\'' => "<mo>′</mo>".into(),
        // Absolute value bars: the same size on both sides.
        '|' => "<mo stretchy=\"false\">|</mo>".into(),
        c if c.is_alphabetic() => format!("<mi>{c}</mi>"),
        c => format!("<mo>{}</mo>", esc(&c.to_string())),
    }
}

fn symbol(name: &str) -> Option<String> {
    let letter = |c: &str| Some(format!("<mi>{c}</mi>"));
    let upright = |c: &str| Some(format!("<mi mathvariant=\"normal\">{c}</mi>"));
    let op = |c: &str| Some(format!("<mo>{c}</mo>"));
    match name {
        "Delta" => upright("Δ"),
        "theta" => letter("θ"),
        "tau" => letter("τ"),
        "omega" => letter("ω"),
        "mu" => letter("μ"),
        "kappa" => letter("κ"),
        "lambda" => letter("λ"),
        "varepsilon" => letter("ε"),
        "pi" => letter("π"),
        "varphi" => letter("φ"),
        "delta" => letter("δ"),
        "infty" => upright("∞"),
        "sum" => op("∑"),
        "int" => op("∫"),
        "times" => op("×"),
        "cdot" => op("·"),
        "pm" => op("±"),
        "le" => op("≤"),
        "ge" => op("≥"),
        "approx" => op("≈"),
        "neq" => op("≠"),
        "to" => op("→"),
        "leftrightarrow" => op("↔"),
        "parallel" => op("∥"),
        "circ" => op("∘"),
        "|" => op("‖"),
        "langle" => op("⟨"),
        "rangle" => op("⟩"),
        "ldots" => op("…"),
        "S" => op("§"),
        "checkmark" => op("✓"),
        _ => None,
    }
}

/// A piece of LaTeX maths as the content of a `<math>` element.
pub fn convert(tex: &str) -> String {
    cells(tex).concat()
}

/// A row of an aligned block (`lhs &= rhs`) as its cells, each the MathML
/// of the LaTeX between the `&`s.
pub fn cells(tex: &str) -> Vec<String> {
    let mut p = Parser {
        toks: tokens(tex),
        i: 0,
    };
    let mut out = Vec::new();
    loop {
        let cell = p.run(Stop::Cell, false);
        out.push(cell);
        match p.peek() {
            Some(Tok::Amp) => p.i += 1,
            // A stray close brace: skip it and go on in the same cell.
            Some(Tok::Close) => {
                p.i += 1;
                let more = p.run(Stop::Cell, false);
                if let Some(last) = out.last_mut() {
                    last.push_str(&more);
                }
                if p.peek() == Some(&Tok::Amp) {
                    p.i += 1;
                } else if p.peek().is_none() {
                    break;
                }
            }
            _ => break,
        }
    }
    out
}

/// Inline maths: `<math>…</math>`.
pub fn inline(tex: &str) -> String {
    format!("<math>{}</math>", convert(tex))
}

#[cfg(test)]
#[path = "mathml_tests.rs"]
mod tests;
