//! The knobs on the command line: one flag per knob of the levels a command
//! takes, built from the knob table (`knobs`), so a new knob needs
//! no line here. Values stay text until `commands` checks them with the
//! lesson's rules (`lesson::knob_value`).

use std::marker::PhantomData;

use clap::{Arg, ArgAction, ArgMatches, Args, Command, FromArgMatches};

use crate::knobs::{of_levels, Cli, Kind, Knob, Level};

/// The levels of knobs a command takes.
pub trait Levels: Clone + std::fmt::Debug + Send + Sync + 'static {
    const LEVELS: &'static [Level];
}

/// A contact's knobs (`solve`, `figure`).
#[derive(Debug, Clone)]
pub struct ContactLevel;
impl Levels for ContactLevel {
    const LEVELS: &'static [Level] = &[Level::Contact];
}

/// A contact's and the resolver's knobs (`resolve`).
#[derive(Debug, Clone)]
pub struct ResolveLevel;
impl Levels for ResolveLevel {
    const LEVELS: &'static [Level] = &[Level::Contact, Level::Resolver];
}

/// Every knob (`simulate`).
#[derive(Debug, Clone)]
pub struct RunLevel;
impl Levels for RunLevel {
    const LEVELS: &'static [Level] = &Level::ALL;
}

/// The knobs given on the command line, as typed, in table order.
#[derive(Debug, Clone)]
pub struct KnobArgs<L: Levels> {
    pub given: Vec<(&'static Knob, String)>,
    levels: PhantomData<L>,
}

impl<L: Levels> Default for KnobArgs<L> {
    fn default() -> Self {
        KnobArgs {
            given: Vec::new(),
            levels: PhantomData,
        }
    }
}

/// The flag of a knob: its name with `-` for `_`.
pub fn flag(knob: &Knob) -> &'static str {
    static FLAGS: std::sync::OnceLock<Vec<(&'static str, &'static str)>> =
        std::sync::OnceLock::new();
    let flags = FLAGS.get_or_init(|| {
        crate::knobs::KNOBS
            .iter()
            .map(|k| {
                let f: &'static str = Box::leak(k.name.replace('_', "-").into_boxed_str());
                (k.name, f)
            })
            .collect()
    });
    flags
        .iter()
        .find(|(n, _)| *n == knob.name)
        .map_or(knob.name, |(_, f)| f)
}

fn value_name(knob: &Knob) -> &'static str {
    match knob.kind {
        Kind::Number { .. } => "X",
        Kind::Count { .. } => "N",
        Kind::Flag => "BOOL",
        Kind::Choice { .. } => "CHOICE",
        Kind::Vector => "X,Y,Z",
    }
}

fn help(knob: &Knob) -> String {
    let choices = match knob.kind {
        Kind::Choice { choices, .. } => format!(
            " [{}]",
            choices
                .iter()
                .map(|c| c.name)
                .collect::<Vec<_>>()
                .join(", ")
        ),
        _ => String::new(),
    };
    format!(
        "{} (default: the lesson's, else {}){choices}",
        knob.doc, knob.default
    )
}

/// The id of a negated flag (`--no-sleep`): its own long name.
fn negated_id(knob: &Knob) -> &'static str {
    match knob.cli {
        Cli::Negated(alias) => alias,
        _ => knob.name,
    }
}

impl<L: Levels> Args for KnobArgs<L> {
    fn augment_args(mut cmd: Command) -> Command {
        for knob in of_levels(L::LEVELS) {
            if let Cli::No(_) = knob.cli {
                continue;
            }
            let mut arg = Arg::new(knob.name)
                .long(flag(knob))
                .value_name(value_name(knob))
                .help(help(knob))
                .action(ArgAction::Set)
                .allow_hyphen_values(true);
            if knob.kind == Kind::Flag {
                arg = arg
                    .num_args(0..=1)
                    .require_equals(true)
                    .default_missing_value("true");
            }
            cmd = cmd.arg(arg);
            if let Cli::Negated(alias) = knob.cli {
                cmd = cmd.arg(
                    Arg::new(negated_id(knob))
                        .long(alias)
                        .action(ArgAction::SetTrue)
                        .help(format!("The same as --{}=false", flag(knob)))
                        .conflicts_with(knob.name),
                );
            }
        }
        cmd
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

impl<L: Levels> FromArgMatches for KnobArgs<L> {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        let mut given = Vec::new();
        for knob in of_levels(L::LEVELS) {
            if let Cli::No(_) = knob.cli {
                continue;
            }
            if let Some(text) = m.get_one::<String>(knob.name) {
                given.push((knob, text.clone()));
            }
            if let Cli::Negated(_) = knob.cli {
                if m.get_flag(negated_id(knob)) {
                    given.push((knob, "false".to_string()));
                }
            }
        }
        Ok(KnobArgs {
            given,
            levels: PhantomData,
        })
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(m)?;
        Ok(())
    }
}
