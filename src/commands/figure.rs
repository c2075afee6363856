//! `contact-lab figure`: one contact as an SVG, to stdout or a file.

use std::io::Write;

use super::{io, load, warn, write_atomic};
use crate::cli::{FigureArgs, PlaneArg};
use crate::error::AppError;
use crate::render::svg::{self, Plane};

pub fn plane(p: PlaneArg) -> Plane {
    match p {
        PlaneArg::Xy => Plane::Xy,
        PlaneArg::Yz => Plane::Yz,
        PlaneArg::Zx => Plane::Zx,
    }
}

pub fn figure(args: &FigureArgs, out: &mut dyn Write, err: &mut dyn Write) -> Result<(), AppError> {
    let lesson = load(
        &args.lesson,
        &super::overrides(&args.model)?,
        Some(args.contact),
    )?;
    warn(&lesson, err);
    let trace = crate::worked_solution(&lesson, args.contact);
    let text = svg::render_at(&trace, plane(args.plane), args.stage);
    match &args.output {
        Some(path) => write_atomic(path, text.as_bytes()),
        None => out.write_all(text.as_bytes()).map_err(io),
    }
}
