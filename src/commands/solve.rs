//! `contact-lab solve`: the worked solution of one contact.

use std::io::Write;

use super::{io, load, warn};
use crate::cli::{Format, SolveArgs};
use crate::error::AppError;
use crate::format::Fmt;
use crate::lesson::Overrides;
use crate::physics::FrictionModel;
use crate::render;

pub fn solve(args: &SolveArgs, out: &mut dyn Write, err: &mut dyn Write) -> Result<(), AppError> {
    let lesson = load(&args.lesson, &args.model, Some(args.contact))?;
    warn(&lesson, err);
    let fmt = Fmt::new(args.digits as usize);
    if args.compare_friction {
        let traces: Vec<_> = FrictionModel::ALL
            .into_iter()
            .map(|m| {
                let mut l = lesson.clone();
                l.apply(&Overrides {
                    friction_model: Some(m),
                    ..Overrides::default()
                });
                (m, crate::worked_solution(&l, args.contact))
            })
            .collect();
        let text = match args.format {
            Format::Json => render::compare::json(&traces),
            Format::Text => render::compare::text(&traces, &fmt),
        };
        return out.write_all(text.as_bytes()).map_err(io);
    }
    let trace = crate::worked_solution(&lesson, args.contact);
    let text = match args.format {
        Format::Text => render::text::render(&trace, &fmt),
        Format::Json => render::json::render(&trace),
    };
    out.write_all(text.as_bytes()).map_err(io)
}
