//! Writing an output file without destroying or hijacking anything: the one
//! way contact-lab writes files (`figure -o`, `solve --figures`, `exercise
//! --dir`, the TUI's `w`).
//!
//! The bytes go to a temporary file created exclusively (`O_EXCL`, so a
//! planted file or symbolic link at that name makes the creation fail rather
//! than be followed) under an unpredictable name (64 bits from the operating
//! system's random source plus tempfile's own) in the target's directory,
//! are synced, and the file is renamed over the target. A reader never sees
//! half a file, and a failure leaves no file behind.
//!
//! The target itself is looked at without following links: if it exists and
//! is not a regular file (a directory, a symbolic link, a FIFO, a device, a
//! socket) the write is refused, so `-o /dev/null` never replaces the device
//! and a link never redirects the write to another file.

use std::fmt;
use std::io::Write;
use std::path::{Path, PathBuf};

/// What to do when the target already exists as a regular file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Existing {
    /// Replace it (keeping its permission bits).
    Replace,
    /// Leave it alone and report [`Error::Exists`] (the TUI asks first).
    Keep,
}

/// Why a file was not written.
#[derive(Debug)]
pub enum Error {
    /// The target exists and [`Existing::Keep`] was asked for.
    Exists(PathBuf),
    /// The target exists and is not a regular file.
    NotRegular { path: PathBuf, what: &'static str },
    /// The path names no file (`/`, `..`).
    NoFileName(PathBuf),
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Exists(p) => write!(f, "{}: already exists", shown(p)),
            Error::NotRegular { path, what } => write!(
                f,
                "{}: it is {what}, not a regular file; contact-lab writes only regular files",
                shown(path)
            ),
            Error::NoFileName(p) => write!(f, "{}: not a file name", shown(p)),
            Error::Io { path, source } => write!(f, "{}: {source}", shown(path)),
        }
    }
}

impl std::error::Error for Error {}

impl Error {
    /// The message without the path, for a prompt that already shows it.
    pub fn reason(&self) -> String {
        match self {
            Error::Exists(_) => "already exists".into(),
            Error::NotRegular { what, .. } => {
                format!("it is {what}, not a regular file; contact-lab writes only regular files")
            }
            Error::NoFileName(_) => "not a file name".into(),
            Error::Io { source, .. } => source.to_string(),
        }
    }
}

/// A path for a message: lossy UTF-8, control characters escaped, so a file
/// name cannot move the cursor or recolour the terminal.
pub fn shown(path: &Path) -> String {
    crate::printable::printable(path.to_string_lossy().into_owned()).replace('\n', "\\n")
}

/// What a non-regular file is, for a refusal (of an output target here, of a
/// lesson path in `lesson::read`).
pub(crate) fn kind(t: std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_symlink() {
        "a symbolic link"
    } else if t.is_dir() {
        "a directory"
    } else {
        "not a regular file"
    }
}

/// Whether [`write`] would accept `path` as its target (a file name; absent,
/// or a regular file that may be replaced), without writing anything: a
/// command that writes several files checks its main one first.
pub fn check(path: &Path, existing: Existing) -> Result<(), Error> {
    target(path, existing).map(|_| ())
}

/// The checks of the target: the permissions of the file it replaces, if any.
fn target(path: &Path, existing: Existing) -> Result<Option<std::fs::Permissions>, Error> {
    let io = |source: std::io::Error| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    if path.file_name().is_none() {
        return Err(Error::NoFileName(path.to_path_buf()));
    }
    let permissions = match std::fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_file() => match existing {
            Existing::Keep => return Err(Error::Exists(path.to_path_buf())),
            Existing::Replace => Some(m.permissions()),
        },
        Ok(m) => {
            return Err(Error::NotRegular {
                path: path.to_path_buf(),
                what: kind(m.file_type()),
            })
        }
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
        Err(e) => return Err(io(e)),
    };
    Ok(permissions)
}

/// Writes `bytes` to `path` as described in the module documentation.
pub fn write(path: &Path, bytes: &[u8], existing: Existing) -> Result<(), Error> {
    let io = |source: std::io::Error| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    let permissions = target(path, existing)?;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    // 64 bits from the OS in the name; tempfile adds its own random letters
    // and retries (re-seeding from the OS) if a name is taken.
    let nonce = getrandom::u64().map_err(|e| io(std::io::Error::other(e)))?;
    let prefix = format!(".contact-lab-{nonce:016x}-");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    // A new file gets what `File::create` gives it, 0o666 less the umask
    // (tempfile's own 0o600 would hide a figure from a web server).
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    let mut temp = builder.tempfile_in(dir).map_err(|e| {
        // tempfile's message ends "at path …/.contact-lab-….tmp"; the
        // directory is what the user can act on.
        let text = e.to_string();
        let cause = text.split(" at path \"").next().unwrap_or(&text);
        io(std::io::Error::new(
            e.kind(),
            format!("cannot create a file in {}: {cause}", shown(dir)),
        ))
    })?;
    if let Some(p) = permissions {
        temp.as_file().set_permissions(p).map_err(io)?;
    }
    temp.write_all(bytes).map_err(io)?;
    temp.as_file().sync_all().map_err(io)?;
    // On failure the temporary file is removed when `PersistError` drops.
    match existing {
        Existing::Replace => temp.persist(path).map(drop).map_err(|e| io(e.error)),
        Existing::Keep => temp.persist_noclobber(path).map(drop).map_err(|e| {
            if e.error.kind() == std::io::ErrorKind::AlreadyExists {
                Error::Exists(path.to_path_buf())
            } else {
                io(e.error)
            }
        }),
    }
}

/// A lesson id made safe for a file name.
pub fn file_stem(id: &str) -> String {
    id.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '-'
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::fs::Permissions;

    fn dir(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("contact-lab-out-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    fn entries(d: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn writes_replaces_and_keeps_as_asked() {
        let d = dir("basic");
        let p = d.join("a.svg");
        write(&p, b"one", Existing::Keep).unwrap();
        assert!(matches!(
            write(&p, b"two", Existing::Keep),
            Err(Error::Exists(_))
        ));
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "one");
        write(&p, b"three", Existing::Replace).unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "three");
        assert_eq!(entries(&d), ["a.svg"], "no temporary file left behind");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn a_replaced_file_keeps_its_permissions_and_a_new_one_is_readable() {
        use std::os::unix::fs::PermissionsExt;
        let d = dir("mode");
        let p = d.join("a.svg");
        std::fs::write(&p, "old").unwrap();
        std::fs::set_permissions(&p, Permissions::from_mode(0o640)).unwrap();
        write(&p, b"new", Existing::Replace).unwrap();
        let mode = std::fs::metadata(&p).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o640);
        let q = d.join("b.svg");
        write(&q, b"new", Existing::Replace).unwrap();
        let mode = std::fs::metadata(&q).unwrap().permissions().mode() & 0o777;
        assert_ne!(mode & 0o600, 0, "owner can read and write");
        assert_ne!(
            mode, 0o600,
            "not tempfile's private 0o600 (umask permitting)"
        );
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn a_symbolic_link_target_is_refused_and_what_it_points_to_untouched() {
        let d = dir("link");
        let victim = d.join("victim.txt");
        std::fs::write(&victim, "precious").unwrap();
        let p = d.join("figure.svg");
        std::os::unix::fs::symlink(&victim, &p).unwrap();
        for existing in [Existing::Replace, Existing::Keep] {
            let e = write(&p, b"svg", existing).unwrap_err();
            assert!(
                e.to_string()
                    .contains("it is a symbolic link, not a regular file"),
                "{e}"
            );
        }
        assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious");
        assert!(std::fs::symlink_metadata(&p)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(entries(&d), ["figure.svg", "victim.txt"]);
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn the_old_predictable_temporary_name_is_not_followed() {
        // The writer used `.NAME.PID.tmp`: a link planted there redirected the write.
        let d = dir("planted");
        let victim = d.join("victim.txt");
        std::fs::write(&victim, "precious").unwrap();
        let p = d.join("figure.svg");
        let planted = d.join(format!(".figure.svg.{}.tmp", std::process::id()));
        std::os::unix::fs::symlink(&victim, &planted).unwrap();
        write(&p, b"svg", Existing::Replace).unwrap();
        assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious");
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "svg");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_directory_target_is_refused() {
        let d = dir("isdir");
        let e = write(&d, b"x", Existing::Replace).unwrap_err();
        assert!(e.to_string().contains("it is a directory"), "{e}");
        let e = write(Path::new("/"), b"x", Existing::Replace).unwrap_err();
        assert!(matches!(e, Error::NoFileName(_)), "{e}");
        std::fs::remove_dir_all(&d).unwrap();
    }

    #[test]
    fn a_missing_directory_is_an_io_error() {
        let p = std::env::temp_dir().join("contact-lab-no-such-dir-xyz/a.md");
        let e = write(&p, b"x", Existing::Keep).unwrap_err();
        assert!(matches!(e, Error::Io { .. }));
        let text = e.to_string();
        assert!(text.contains("cannot create a file in"), "{text}");
        assert!(!text.contains(".contact-lab-"), "no temporary name: {text}");
    }

    #[test]
    fn names_in_messages_are_escaped() {
        let e = Error::Exists(PathBuf::from("a\u{1b}[31m\rb.svg"));
        assert_eq!(e.to_string(), "a\\u{1b}[31m\\u{d}b.svg: already exists");
    }
}
