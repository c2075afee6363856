//! A scene file of `n` spheres all at the same place on a floor: the
//! coincident pile of the huge-step and responsiveness tests.

use std::path::PathBuf;

/// Writes the pile of `n` coincident spheres under the test target's temp
/// dir as `{tag}-pile-{n}.toml` and returns its path.
pub fn coincident(tag: &str, n: usize) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let path = dir.join(format!("{tag}-pile-{n}.toml"));
    let mut s = format!(
        "id = \"pile-{n}\"\ntitle = \"{n} coincident spheres\"\nsource = \"test\"\nsummary = \"test\"\n\n[world]\ngravity = [0, -9.81, 0]\n\n[step]\ndt = 0.016666666666666666\nsteps = 10\n\n[sleep]\nenabled = false\n\n[[body]]\nname = \"floor\"\nmass = inf\nshape = \"half_space\"\nnormal = [0, 1, 0]\nposition = [0, 0, 0]\n"
    );
    for i in 0..n {
        s.push_str(&format!(
            "\n[[body]]\nname = \"s{i}\"\nmass = 1.0\nshape = {{ sphere = 0.5 }}\nposition = [0, 0.5, 0]\n"
        ));
    }
    std::fs::write(&path, s).unwrap();
    path
}
