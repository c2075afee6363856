//! Reading a lesson file: only a regular file is read, at once refused
//! otherwise (a FIFO would block forever, a device never ends), and at most
//! [`super::validate::MAX_BYTES`] + 1 bytes of it.
//!
//! Exit codes (see `LessonError`): nothing at the path is 66 ("missing");
//! a path that exists but cannot be read as a lesson — permission denied, a
//! directory, a FIFO, a device, an I/O error — is 1, with the reason.

use std::io::Read;
use std::path::Path;

use super::source::LessonError;
use super::validate;

/// Opens without blocking: a FIFO with no writer would otherwise hang `open`.
fn open(path: &Path) -> std::io::Result<std::fs::File> {
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        options.custom_flags(libc::O_NONBLOCK);
    }
    options.open(path)
}

/// Only "nothing is there" is missing (66); anything else is a failure to read (1).
fn open_error(e: &std::io::Error, shown: &str) -> LessonError {
    let path = shown.to_string();
    match e.kind() {
        std::io::ErrorKind::NotFound | std::io::ErrorKind::NotADirectory => LessonError::Missing {
            reason: match nearest_id(&path) {
                Some(id) => format!(
                    "no such file, and no embedded lesson has this id; did you mean {id}? (see `contact-lab list`)"
                ),
                None => {
                    "no such file, and no embedded lesson has this id (see `contact-lab list`)".into()
                }
            },
            path,
        },
        std::io::ErrorKind::PermissionDenied => LessonError::Unreadable {
            path,
            reason: "permission denied (the file exists but may not be read)".into(),
        },
        _ => LessonError::Unreadable {
            path,
            reason: e.to_string(),
        },
    }
}

/// The bytes of the lesson file at `path` (`shown` is the path for messages).
pub fn read(path: &Path, shown: &str) -> Result<Vec<u8>, LessonError> {
    let unreadable = |reason: String| LessonError::Unreadable {
        path: shown.to_string(),
        reason,
    };
    match read_regular(path, validate::MAX_BYTES) {
        Ok(bytes) => Ok(bytes),
        Err(Refused::Open(e)) => Err(open_error(&e, shown)),
        Err(Refused::NotRegular(what)) => Err(unreadable(format!(
            "it is {what}, not a lesson file (a lesson is a TOML file)"
        ))),
        Err(Refused::Read(e)) => Err(unreadable(e.to_string())),
    }
}

/// Why [`read_regular`] read nothing.
#[derive(Debug)]
pub enum Refused {
    /// The path could not be opened (nothing there, permission, …).
    Open(std::io::Error),
    /// It is not a regular file: what it is (`a FIFO (named pipe)`, …).
    NotRegular(&'static str),
    Read(std::io::Error),
}

/// The file at `path` read by the lesson loader's rules: opened without
/// blocking, a regular file only (checked on the open file), and at most
/// `limit` + 1 bytes read, so that a caller sees a file over `limit` as one
/// longer than `limit` without ever holding more.
pub fn read_regular(path: &Path, limit: usize) -> Result<Vec<u8>, Refused> {
    let file = open(path).map_err(Refused::Open)?;
    // fstat on the open file: what was opened is what is checked.
    let meta = file.metadata().map_err(Refused::Read)?;
    if !meta.is_file() {
        return Err(Refused::NotRegular(crate::output_file::kind(
            meta.file_type(),
        )));
    }
    let mut bytes = Vec::new();
    file.take(limit as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(Refused::Read)?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::{Error, ErrorKind};

    #[test]
    fn only_a_missing_file_is_missing() {
        let e = open_error(&Error::from(ErrorKind::PermissionDenied), "a.toml");
        assert_eq!(
            e.to_string(),
            "cannot read lesson file a.toml: permission denied (the file exists but may not be read)"
        );
        assert!(matches!(
            open_error(&Error::from(ErrorKind::NotFound), "a.toml"),
            LessonError::Missing { .. }
        ));
        assert!(matches!(
            open_error(&Error::other("disk on fire"), "a.toml"),
            LessonError::Unreadable { .. }
        ));
    }
}

/// The embedded lesson id nearest to what was typed (`lectur-2` →
/// `lecture-2`), when it is close: at most a third of its letters differ.
pub fn nearest_id(typed: &str) -> Option<&'static str> {
    let typed = typed.trim_end_matches(".toml");
    let typed = typed.rsplit('/').next().unwrap_or(typed);
    super::embedded::ids()
        .into_iter()
        .map(|id| (edit_distance(typed, id), id))
        .filter(|(d, id)| *d > 0 && *d * 3 <= id.chars().count().max(3))
        .min()
        .map(|(_, id)| id)
}

/// Levenshtein distance over characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let here = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb))
                .min(row[j] + 1)
                .min(here + 1);
            prev = here;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod suggestion_tests {
    use super::nearest_id;

    #[test]
    fn a_near_miss_suggests_the_embedded_id() {
        assert_eq!(nearest_id("lectur-2"), Some("lecture-2"));
        assert_eq!(nearest_id("lecture2"), Some("lecture-2"));
        assert_eq!(nearest_id("frictoin-cube"), Some("friction-cube"));
        assert!(nearest_id("lessons/lecture-4.toml").is_some());
        assert_eq!(nearest_id("completely-different-thing"), None);
        assert_eq!(nearest_id("xyz"), None);
    }
}
