//! The study as a Markdown report an instructor can hand out: what was
//! measured and how, then per scene the reference, the table (Pareto rows
//! marked ★) and the trade in one sentence.

use super::{cells, headers, MEASURES};
use crate::format::Fmt;
use crate::study::Study;

fn cell(s: &str) -> String {
    s.replace('|', "\\|")
}

pub fn render(study: &Study, fmt: &Fmt) -> String {
    let mut out = String::from("# Speed against accuracy\n\n");
    out.push_str(
        "Each scene runs under its own settings (the default row), then with one knob \
         turned at a time, and with the iteration budget of each solver: the lecture's \
         deepest-first order and sequential impulses (projected Gauss–Seidel with \
         accumulated, clamped impulses), at equal work counted in contact visits. Every \
         configuration is compared with the most accurate one of the same scene, the \
         reference. ★ marks the Pareto front: no other configuration is both cheaper \
         in work per simulated second and more accurate.\n\n",
    );
    out.push_str("How each number is measured:\n\n");
    for m in MEASURES {
        out.push_str(&format!("- {m}\n"));
    }
    if study.timed {
        out.push_str(&format!(
            "- {} timed runs per configuration\n",
            study.repeats
        ));
    }
    for s in &study.scenes {
        out.push_str(&format!(
            "\n## {} (`{}`, {} s)\n\n**Reference:** {}.\n\n**The trade:** {}\n\n",
            s.title,
            s.scene,
            fmt.num(s.seconds),
            s.reference,
            s.verdict
        ));
        let head = headers(study.timed);
        out.push_str(&format!("| {} |\n", head.join(" | ")));
        out.push_str(&format!("|{}\n", "---|".repeat(head.len())));
        for r in &s.rows {
            let c: Vec<String> = cells(fmt, r, study.timed).iter().map(|c| cell(c)).collect();
            out.push_str(&format!("| {} |\n", c.join(" | ")));
        }
    }
    out
}
