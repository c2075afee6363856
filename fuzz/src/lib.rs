//! Scenes for the fuzz targets: an `arbitrary` description turned into lesson
//! TOML, so every generated scene goes through the same validator a user's
//! file does. Numbers are drawn mostly from ordinary ranges (so most scenes
//! validate and reach the physics), sometimes from the edges of the accepted
//! range (1e-60 … 1e60), sometimes raw (NaN, inf, subnormals: the validator
//! must refuse them).

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;

use arbitrary::{Result, Unstructured};
use clap::Parser;

/// One number, biased toward values a scene uses.
pub fn number(u: &mut Unstructured) -> Result<f64> {
    Ok(match u.int_in_range(0u8..=19)? {
        0 => f64::from_bits(u.arbitrary()?),
        1 => {
            let k: i32 = u.int_in_range(-60..=60)?;
            let sign = if u.arbitrary()? { -1.0 } else { 1.0 };
            sign * 10f64.powi(k)
        }
        2 => 0.0,
        _ => f64::from(u.arbitrary::<i16>()?) / 2048.0,
    })
}

fn positive(u: &mut Unstructured) -> Result<f64> {
    Ok(match u.int_in_range(0u8..=9)? {
        0 => number(u)?,
        1 => 10f64.powi(u.int_in_range(-8..=8)?),
        _ => 0.05 + f64::from(u.arbitrary::<u8>()?) / 64.0,
    })
}

fn unit(u: &mut Unstructured) -> Result<f64> {
    Ok(match u.int_in_range(0u8..=9)? {
        0 => number(u)?,
        _ => f64::from(u.arbitrary::<u8>()?) / 255.0,
    })
}

/// TOML for a float: `nan` and `inf` are TOML's spellings.
pub fn toml_float(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.into()
    } else {
        format!("{x:?}")
    }
}

fn vector(u: &mut Unstructured) -> Result<String> {
    Ok(format!(
        "[{}, {}, {}]",
        toml_float(number(u)?),
        toml_float(number(u)?),
        toml_float(number(u)?)
    ))
}

fn shape(u: &mut Unstructured) -> Result<String> {
    Ok(match u.int_in_range(0u8..=4)? {
        0 => format!("{{ sphere = {} }}", toml_float(positive(u)?)),
        1 => format!(
            "{{ box = [{}, {}, {}] }}",
            toml_float(positive(u)?),
            toml_float(positive(u)?),
            toml_float(positive(u)?)
        ),
        2 => format!(
            "{{ cylinder = {{ radius = {}, height = {} }} }}",
            toml_float(positive(u)?),
            toml_float(positive(u)?)
        ),
        3 => format!("{{ hollow_sphere = {} }}", toml_float(positive(u)?)),
        _ => "\"half_space\"".into(),
    })
}

/// A body: movable with a shape most of the time, sometimes immovable.
fn body(u: &mut Unstructured, i: usize, out: &mut String) -> Result<()> {
    let immovable = u.ratio(1u8, 4u8)?;
    let _ = writeln!(out, "\n[[body]]\nname = \"b{i}\"");
    if immovable {
        let _ = writeln!(out, "mass = inf");
        let half_space = u.ratio(2u8, 3u8)?;
        let s = if half_space { "\"half_space\"".into() } else { shape(u)? };
        let _ = writeln!(out, "shape = {s}");
        if half_space && u.ratio(1u8, 3u8)? {
            let _ = writeln!(out, "normal = {}", vector(u)?);
        }
    } else {
        let _ = writeln!(out, "mass = {}", toml_float(positive(u)?));
        if u.ratio(9u8, 10u8)? {
            let _ = writeln!(out, "shape = {}", shape(u)?);
        }
        if u.ratio(1u8, 2u8)? {
            let _ = writeln!(out, "velocity = {}", vector(u)?);
        }
        if u.ratio(1u8, 2u8)? {
            let _ = writeln!(out, "angular_velocity = {}", vector(u)?);
        }
        if u.ratio(1u8, 4u8)? {
            let _ = writeln!(out, "acceleration = {}", vector(u)?);
        }
        if u.ratio(1u8, 3u8)? {
            let _ = writeln!(out, "orientation = [{}, {}]", toml_float(number(u)?), {
                let v = vector(u)?;
                v[1..v.len() - 1].to_string()
            });
        }
        for key in ["restitution", "friction"] {
            if u.ratio(1u8, 5u8)? {
                let _ = writeln!(out, "{key} = {}", toml_float(unit(u)?));
            }
        }
    }
    let _ = writeln!(out, "position = {}", vector(u)?);
    Ok(())
}

/// Settings every contact shares, and the resolver's.
fn settings(u: &mut Unstructured, out: &mut String) -> Result<()> {
    let _ = writeln!(out, "\n[settings]");
    if u.ratio(1u8, 3u8)? {
        let model = *u.choose(&["millington", "kinetic-direction", "isotropic"])?;
        let _ = writeln!(out, "friction_model = \"{model}\"");
    }
    if u.ratio(1u8, 3u8)? {
        let p = *u.choose(&["nonlinear", "linear"])?;
        let _ = writeln!(out, "projection = \"{p}\"");
    }
    for key in ["position_iterations", "velocity_iterations"] {
        if u.ratio(1u8, 3u8)? {
            let _ = writeln!(out, "{key} = {}", u.int_in_range(0u32..=64)?);
        }
    }
    for key in ["position_epsilon", "velocity_epsilon", "relaxation"] {
        if u.ratio(1u8, 5u8)? {
            let _ = writeln!(out, "{key} = {}", toml_float(unit(u)?));
        }
    }
    Ok(())
}

/// A scene for `resolve`: bodies and hand-placed contacts between them.
pub fn resolve_scene(u: &mut Unstructured) -> Result<String> {
    let mut out = String::from("id = \"fuzz\"\ntitle = \"fuzz\"\n");
    let n = u.int_in_range(1usize..=5)?;
    for i in 0..n {
        body(u, i, &mut out)?;
    }
    let contacts = u.int_in_range(1usize..=8)?;
    for k in 0..contacts {
        let a = u.int_in_range(0..=n - 1)?;
        let _ = writeln!(out, "\n[[contact]]\nname = \"c{k}\"");
        if n > 1 && u.ratio(1u8, 2u8)? {
            let b = u.int_in_range(0..=n - 1)?;
            let _ = writeln!(out, "bodies = [\"b{a}\", \"b{b}\"]");
        } else {
            let _ = writeln!(out, "bodies = [\"b{a}\"]");
        }
        let _ = writeln!(out, "point = {}", vector(u)?);
        let _ = writeln!(out, "normal = {}", vector(u)?);
        let _ = writeln!(out, "penetration = {}", toml_float(number(u)?));
        for key in ["restitution", "friction"] {
            if u.ratio(1u8, 2u8)? {
                let _ = writeln!(out, "{key} = {}", toml_float(unit(u)?));
            }
        }
    }
    settings(u, &mut out)?;
    Ok(out)
}

/// A scene for `simulate`: shaped bodies, world, step and sleep settings.
pub fn simulate_scene(u: &mut Unstructured) -> Result<String> {
    let mut out = String::from("id = \"fuzz\"\ntitle = \"fuzz\"\n");
    let _ = writeln!(out, "\n[world]");
    if u.ratio(1u8, 2u8)? {
        let _ = writeln!(out, "gravity = {}", vector(u)?);
    }
    for key in ["restitution", "friction"] {
        if u.ratio(1u8, 2u8)? {
            let _ = writeln!(out, "{key} = {}", toml_float(unit(u)?));
        }
    }
    if u.ratio(1u8, 3u8)? {
        let _ = writeln!(out, "damping = {}", toml_float(unit(u)?));
    }
    if u.ratio(1u8, 2u8)? {
        let mode = *u.choose(&["single", "manifold"])?;
        let _ = writeln!(out, "box_box = \"{mode}\"");
    }
    if u.ratio(1u8, 4u8)? {
        let _ = writeln!(out, "acceleration_compensation = {}", u.arbitrary::<bool>()?);
    }
    let _ = writeln!(out, "\n[step]");
    let dt = match u.int_in_range(0u8..=7)? {
        0 => number(u)?,
        k => 1.0 / f64::from(30 * u32::from(k)),
    };
    let _ = writeln!(out, "dt = {}\nsteps = {}", toml_float(dt), u.int_in_range(1u32..=120)?);
    if u.ratio(1u8, 2u8)? {
        let _ = writeln!(out, "\n[sleep]\nenabled = {}", u.arbitrary::<bool>()?);
        if u.ratio(1u8, 2u8)? {
            let mode = *u.choose(&["body", "island"])?;
            let _ = writeln!(out, "mode = \"{mode}\"");
        }
        if u.ratio(1u8, 3u8)? {
            let _ = writeln!(out, "epsilon = {}", toml_float(unit(u)?));
        }
    }
    let n = u.int_in_range(1usize..=7)?;
    for i in 0..n {
        body(u, i, &mut out)?;
    }
    if u.ratio(1u8, 2u8)? {
        settings(u, &mut out)?;
    }
    Ok(out)
}

/// Writes `text` to this process's scratch lesson file and returns its path.
pub fn scratch(text: &str) -> PathBuf {
    let path = std::env::temp_dir().join(format!("contact-lab-fuzz-{}.toml", std::process::id()));
    let mut f = std::fs::File::create(&path).expect("scratch file");
    f.write_all(text.as_bytes()).expect("scratch write");
    path
}

/// Runs `contact-lab ARGS…` in-process; the exit code and what it printed.
pub fn run(args: &[&str]) -> (i32, String) {
    let cli = contact_lab::cli::Cli::try_parse_from(
        std::iter::once("contact-lab").chain(args.iter().copied()),
    )
    .expect("the fuzz targets pass valid arguments");
    let (mut out, mut err) = (Vec::new(), Vec::new());
    let code = match contact_lab::commands::run(cli, &mut out, &mut err) {
        Ok(()) => 0,
        Err(e) => i32::from(e.exit_code()),
    };
    (code, String::from_utf8(out).expect("output is UTF-8"))
}

/// The property every target checks: a run either succeeds and prints only
/// finite numbers, or fails with a documented code (65 refused lesson, 1 a
/// scene that blew up) — never 70-like internal errors or a panic.
pub fn check(code: i32, out: &str, scene: &str) {
    match code {
        0 => {
            for word in out.split(|c: char| !c.is_alphanumeric()) {
                assert!(
                    !matches!(word, "NaN" | "nan" | "inf" | "Infinity"),
                    "non-finite number printed for scene:\n{scene}\n--- output ---\n{out}"
                );
            }
            assert!(!out.contains(": null"), "null in JSON for scene:\n{scene}");
        }
        65 => assert!(out.is_empty(), "a refused lesson printed output:\n{scene}"),
        1 => {}
        other => panic!("unexpected exit code {other} for scene:\n{scene}"),
    }
}
