//! The binary run as a user runs it: from the repository's root, its exit
//! code and both streams as text.

use assert_cmd::Command;

/// `contact-lab`, started in the repository's root.
pub fn contact_lab() -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_contact-lab"));
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"));
    cmd
}

/// What one run gave.
pub struct Run {
    pub code: Option<i32>,
    pub stdout: String,
    pub stderr: String,
}

/// Runs `contact-lab ARGS`.
pub fn run(args: &[&str]) -> Run {
    let out = contact_lab().args(args).output().expect("contact-lab runs");
    Run {
        code: out.status.code(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}
