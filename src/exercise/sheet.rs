//! The exercise sheet: per exercise the scene and the questions; with
//! answers, the short answers and the worked solution (Markdown or LaTeX).

mod figure;

use crate::render::fill::Fill;
use figure::md_figure;
pub use figure::{figure_svg, MdFigures};

use std::fmt::Write;

use super::Exercise;
use crate::format::Fmt;
use crate::lesson::{BodyDef, Lesson, Shape};
use crate::render::contact::{latex, markdown};
use crate::render::tex::prose;
use crate::trace::Value;

const INTRO: &str = "Resolve each contact as in the lecture (Millington's impulse-based method). The normal d̂ points from body 2 toward body 1; body 1 receives the impulse g and body 2 receives -g. Inertia tensors are in body coordinates; orientations are quaternions [w, x, y, z]. Work to four decimals.";

/// How to regenerate a sheet.
pub struct Request {
    pub seed: u64,
    pub kind: &'static str,
    pub count: usize,
}

fn questions(e: &Exercise) -> Vec<&'static str> {
    super::asked::questions(e.kind, &e.trace)
        .iter()
        .map(|q| q.text)
        .collect()
}

pub use super::asked::{short_answers, ShortAnswer};

/// The sheet asks for four decimals: the answer key gives exactly that.
pub const DECIMALS: u32 = 4;

/// A value to four decimals (`(0.0000, 18.7337, 0.0000)`), words as they are.
pub fn four_decimals(v: &Value) -> String {
    let f = Fmt::default();
    let list = |xs: &[f64]| {
        xs.iter()
            .map(|x| f.fixed(*x, DECIMALS))
            .collect::<Vec<_>>()
            .join(", ")
    };
    match v {
        Value::Scalar(x) => f.fixed(*x, DECIMALS),
        Value::Vector(a) => format!("({})", list(a)),
        Value::Quaternion(q) => format!("[{}]", list(q)),
        Value::Matrix(m) => format!(
            "[{}]",
            m.iter()
                .map(|r| format!("[{}]", list(r)))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Value::Text(t) => t.clone(),
        Value::List(items) => items.join("; "),
    }
}

/// The short answer with its unit, to four decimals.
fn key_text(a: &ShortAnswer) -> String {
    crate::trace::glossary::with_unit(
        &four_decimals(a.value),
        crate::trace::glossary::unit(a.step, a.name),
    )
}

fn shape(s: &Option<Shape>) -> String {
    match s {
        Some(Shape::Box { sides: [x, y, z] }) if x == y && y == z => format!("cube, sides {x} m"),
        Some(Shape::Box { sides: [x, y, z] }) => format!("box {x} × {y} × {z} m"),
        Some(Shape::Sphere { radius: r }) => format!("solid sphere, r = {r} m"),
        Some(Shape::HollowSphere { radius: r }) => format!("hollow sphere, r = {r} m"),
        Some(Shape::Cylinder { radius, height }) => {
            format!("cylinder, r = {radius} m, h = {height} m")
        }
        Some(Shape::Capsule { radius, height }) => {
            format!("capsule, r = {radius} m, h = {height} m")
        }
        Some(Shape::Hull(hull)) => format!("convex hull of {} vertices", hull.vertices().len()),
        Some(Shape::Mesh(mesh)) => format!(
            "{} triangle mesh of {} triangles",
            if mesh.is_closed() { "closed" } else { "open" },
            mesh.triangles().len()
        ),
        Some(Shape::HalfSpace { .. }) => "half-space".into(),
        None => "–".into(),
    }
}

/// Rows of the scene table: (quantity, one cell per body).
fn rows(lesson: &Lesson, fmt: &Fmt) -> Vec<(&'static str, Vec<String>)> {
    let v = |x: &[f64]| format!("({})", fmt.list(x));
    let cell = |b: &BodyDef, f: &dyn Fn(&BodyDef) -> String| {
        if b.movable() {
            f(b)
        } else {
            "–".into()
        }
    };
    let all = |f: &dyn Fn(&BodyDef) -> String| lesson.bodies.iter().map(|b| cell(b, f)).collect();
    vec![
        (
            "mass m",
            lesson
                .bodies
                .iter()
                .map(|b| {
                    if b.movable() {
                        format!("{} kg", fmt.num(b.mass))
                    } else {
                        "∞ (immovable)".into()
                    }
                })
                .collect(),
        ),
        (
            "shape",
            lesson.bodies.iter().map(|b| shape(&b.shape)).collect(),
        ),
        (
            "inertia tensor I",
            all(&|b| {
                b.inertia.map_or("–".into(), |m| {
                    if (0..3).all(|r| (0..3).all(|c| r == c || m[(r, c)] == 0.0)) {
                        format!(
                            "diag({}) kg·m²",
                            fmt.list(&[m[(0, 0)], m[(1, 1)], m[(2, 2)]])
                        )
                    } else {
                        format!("{} kg·m²", fmt.value(&Value::from(m)))
                    }
                })
            }),
        ),
        (
            "position p",
            lesson
                .bodies
                .iter()
                .map(|b| format!("{} m", v(b.position.as_slice())))
                .collect(),
        ),
        (
            "orientation θ",
            all(&|b| {
                let q = b.orientation;
                format!("[{}]", fmt.list(&[q.w, q.i, q.j, q.k]))
            }),
        ),
        (
            "velocity v",
            all(&|b| format!("{} m/s", v(b.velocity.as_slice()))),
        ),
        (
            "angular velocity ω",
            all(&|b| format!("{} rad/s", v(b.angular_velocity.as_slice()))),
        ),
    ]
}

/// The units a cell of the scene table ends with.
const UNITS: [&str; 5] = ["kg·m²", "m/s", "rad/s", "kg", "m"];

/// A cell of the scene table in LaTeX: its unit upright in maths
/// (`$\,\mathrm{kg\cdot m^2}$`), the rest as prose.
fn latex_cell(cell: &str) -> String {
    for unit in UNITS {
        if let Some(number) = cell.strip_suffix(unit).and_then(|c| c.strip_suffix(' ')) {
            return format!(
                "{}${}$",
                prose(number),
                crate::trace::glossary::unit_latex(unit)
            );
        }
    }
    prose(cell)
}

/// The contact's data in one sentence.
fn contact_line(lesson: &Lesson, fmt: &Fmt) -> String {
    let c = &lesson.contacts[0];
    let names = lesson.contact_body_names(0);
    let v = |x: &[f64]| format!("({})", fmt.list(x));
    let mut s = format!(
        "Contact point q = {} m; normal d̂ = {}, from {} toward {}; restitution c = {}",
        v(c.point.as_slice()),
        v(c.normal.as_slice()),
        names.get(1).map_or("the world", String::as_str),
        names[0],
        fmt.num(c.restitution)
    );
    if c.penetration > 0.0 {
        let _ = write!(s, "; penetration d_pen = {} m", fmt.num(c.penetration));
    }
    if c.static_friction > 0.0 || c.dynamic_friction > 0.0 {
        if c.static_friction == c.dynamic_friction {
            let _ = write!(s, "; friction μ = {}", fmt.num(c.static_friction));
        } else {
            let _ = write!(
                s,
                "; static friction μ_s = {}, dynamic friction μ_d = {}",
                fmt.num(c.static_friction),
                fmt.num(c.dynamic_friction)
            );
        }
    } else {
        s.push_str("; no friction");
    }
    s.push('.');
    s
}

fn command(r: &Request, answers: bool, format: &str) -> String {
    format!(
        "contact-lab exercise --seed {} --kind {} --count {}{} --format {format}",
        r.seed,
        r.kind,
        r.count,
        if answers { " --answers" } else { "" }
    )
}

/// The sheet in Markdown, each exercise with its figure.
pub fn markdown(
    exercises: &[Exercise],
    r: &Request,
    answers: bool,
    fmt: &Fmt,
    figures: &MdFigures,
) -> String {
    let inputs = Fmt::new(10);
    let mut out = String::from("# Contact resolution exercises\n\n");
    let _ = writeln!(
        out,
        "Seed {} · {} exercise(s) · `{}`\n\n{}\n",
        r.seed,
        exercises.len(),
        command(r, answers, "md"),
        markdown::escape(INTRO)
    );
    for (i, e) in exercises.iter().enumerate() {
        let l = &e.lesson;
        let _ = writeln!(
            out,
            "## {} ({})\n",
            markdown::escape(&l.title),
            e.kind.name()
        );
        let mut header = String::from("| |");
        let mut rule = String::from("|---|");
        for b in &l.bodies {
            let _ = write!(header, " {} |", markdown::cell(&b.name));
            rule.push_str("---|");
        }
        let _ = writeln!(out, "{header}\n{rule}");
        for (what, cells) in rows(l, &inputs) {
            let cells: Vec<String> = cells.iter().map(|c| markdown::cell(c)).collect();
            let _ = writeln!(out, "| {what} | {} |", cells.join(" | "));
        }
        let _ = writeln!(out, "\n{}\n", markdown::escape(&contact_line(l, &inputs)));
        md_figure(&mut out, e, i, figures);
        for (i, q) in questions(e).iter().enumerate() {
            let _ = writeln!(out, "{}. {}", i + 1, markdown::escape(q));
        }
        out.push('\n');
    }
    if answers {
        out.push_str("# Answers\n\n");
        for e in exercises {
            let _ = writeln!(out, "## {}\n", markdown::escape(&e.lesson.title));
            for a in short_answers(e.kind, &e.trace) {
                let _ = writeln!(
                    out,
                    "- {} = {}",
                    markdown::escape(a.label),
                    markdown::escape(&key_text(&a))
                );
            }
            out.push('\n');
            out.push_str(&markdown::contact(&e.trace, fmt, 3, None));
        }
    }
    out.truncate(out.trim_end().len());
    out.push('\n');
    out
}

/// The sheet as a standalone LaTeX document.
pub fn latex(exercises: &[Exercise], r: &Request, answers: bool, fmt: &Fmt) -> String {
    let inputs = Fmt::new(10);
    let mut body = String::from("\\section*{Contact resolution exercises}\n");
    let _ = writeln!(
        body,
        "Seed {} $\\cdot$ {} exercise(s) $\\cdot$ \\texttt{{{}}}\n\n{}",
        r.seed,
        exercises.len(),
        crate::render::tex::escape_text(&command(r, answers, "latex")),
        prose(INTRO)
    );
    for e in exercises {
        let l = &e.lesson;
        let _ = writeln!(
            body,
            "\n\\subsection*{{{} ({})}}",
            prose(&l.title),
            e.kind.name()
        );
        let _ = writeln!(
            body,
            "\\begin{{center}}\n\\begin{{tabular}}{{l{}}}\n & {} \\\\\n\\hline",
            "l".repeat(l.bodies.len()),
            l.bodies
                .iter()
                .map(|b| prose(&b.name))
                .collect::<Vec<_>>()
                .join(" & ")
        );
        for (what, cells) in rows(l, &inputs) {
            let cells: Vec<String> = cells.iter().map(|c| latex_cell(c)).collect();
            let _ = writeln!(body, "{} & {} \\\\", prose(what), cells.join(" & "));
        }
        let _ = writeln!(
            body,
            "\\end{{tabular}}\n\\end{{center}}\n{}",
            prose(&contact_line(l, &inputs))
        );
        // The set-up as the question sees it: no impulse, nothing after.
        if let Some(fig) = crate::render::contact::latex_figure::picture(
            &e.trace.scene,
            Some(crate::physics::StageId::ContactFrame),
        ) {
            body.push_str(&fig);
        }
        body.push_str("\\begin{enumerate}\n");
        for q in questions(e) {
            let _ = writeln!(body, "\\item {}", prose(q));
        }
        body.push_str("\\end{enumerate}\n");
    }
    if answers {
        body.push_str("\n\\clearpage\n\\section*{Answers}\n");
        for e in exercises {
            let _ = writeln!(body, "\n\\subsection*{{{}}}", prose(&e.lesson.title));
            body.push_str("\\begin{itemize}\n");
            for a in short_answers(e.kind, &e.trace) {
                let _ = writeln!(
                    body,
                    "\\item {} $=$ {}",
                    prose(a.label),
                    prose(&key_text(&a))
                );
            }
            body.push_str("\\end{itemize}\n\n");
            body.push_str(&latex::contact(&e.trace, fmt, 2));
        }
    }
    latex::standalone(&body)
}
