//! Application errors and their exit codes (documented in `docs/exit-codes.md`).

use crate::lesson::LessonError;

#[derive(Debug, thiserror::Error)]
pub enum AppError {
    #[error(transparent)]
    Lesson(#[from] LessonError),
    /// Bad command-line use that clap cannot see (exit 2).
    #[error("{0}")]
    Usage(String),
    /// Anything else that went wrong at run time (exit 1).
    #[error("{0}")]
    Runtime(String),
    /// The output could not be written (exit 1).
    #[error("cannot write output: {0}")]
    Output(#[source] std::io::Error),
}

impl AppError {
    pub fn exit_code(&self) -> u8 {
        match self {
            AppError::Lesson(LessonError::Missing { .. }) => 66,
            AppError::Lesson(LessonError::Invalid { .. }) => 65,
            AppError::Lesson(LessonError::Unreadable { .. }) => 1,
            AppError::Usage(_) => 2,
            AppError::Runtime(_) | AppError::Output(_) => 1,
        }
    }

    /// The reader of the output went away (`contact-lab … | head`): not a
    /// failure to report, as for any Unix filter.
    pub fn is_broken_pipe(&self) -> bool {
        matches!(self, AppError::Output(e) if e.kind() == std::io::ErrorKind::BrokenPipe)
    }

    /// The message for stderr: invalid lessons get a snippet per error.
    pub fn report(&self, color: bool) -> String {
        match self {
            AppError::Lesson(LessonError::Invalid {
                path,
                diagnostics,
                omitted,
            }) => {
                let theme = if color {
                    miette::GraphicalTheme::unicode()
                } else {
                    miette::GraphicalTheme::unicode_nocolor()
                };
                let handler = miette::GraphicalReportHandler::new_themed(theme).with_width(100);
                let mut out = String::new();
                for d in diagnostics {
                    out.push_str(&format!("error: {d}\n"));
                    let mut report = String::new();
                    let _ = handler.render_report(&mut report, d);
                    out.push_str(&without_header(&report));
                }
                if *omitted > 0 {
                    out.push_str(&format!(
                        "error: {path}: {omitted} more error(s) not shown; fix the ones above first\n"
                    ));
                }
                out
            }
            other => format!("error: {other}\n"),
        }
    }
}

/// A miette report without its `× message` header (and the header's
/// wrapped lines): the `error:` line above already says it, once.
fn without_header(report: &str) -> String {
    let mut lines = report.lines().peekable();
    let mut out = String::new();
    if lines
        .peek()
        .is_some_and(|l| l.trim_start().starts_with('×'))
    {
        lines.next();
        while lines
            .peek()
            .is_some_and(|l| l.trim_start().starts_with('│'))
        {
            lines.next();
        }
    }
    for l in lines {
        out.push_str(l);
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_report_header_is_dropped_once() {
        let r =
            "  × a.toml:8:9: bad\n  │ (more)\n   ╭─[a.toml:8:9]\n 8 │ x\n   ╰────\n  help: fix\n";
        assert_eq!(
            super::without_header(r),
            "   ╭─[a.toml:8:9]\n 8 │ x\n   ╰────\n  help: fix\n"
        );
    }
}
