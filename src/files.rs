//! Writing files so that a crash or a failure never leaves a truncated one, and nothing
//! is lost or silently replaced: the one writer of the crate, used by the CLI
//! (`run --output`) and the deck save.
//!
//! The rules (issue 14), applied by [`write_atomic`] and [`save_with_backup`]:
//!
//! * a regular file (or a new one) is written as `.<name>.tmp-<pid>` in its directory,
//!   fsynced and renamed over the destination; on any failure the temporary file is
//!   removed and the destination is untouched; the file keeps its permissions;
//! * a symbolic link is written *through*: the rename replaces the file the link
//!   resolves to, and the link stays a link (a dangling link is refused);
//! * a read-only file is refused with a clear message, never replaced;
//! * anything that is not a regular file (a device such as `/dev/null`, a FIFO, a
//!   terminal) is written directly, without a temporary file or a rename;
//! * `-` means standard output ([`write_atomic`] only).
//!
//! [`save_with_backup`] also keeps the previous file as `<name>.bak` and fsyncs the
//! directory after the rename. [`same_file`] lets the CLI refuse to write over the deck
//! it reads.

use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// A failed save: the file concerned, what was being done and the OS error.
#[derive(Debug, thiserror::Error)]
#[error("{}: {action}: {source}", path.display())]
pub struct FileError {
    /// File concerned (the destination, its temporary file or its backup).
    pub path: PathBuf,
    /// What was being done ("cannot write temporary file", ...).
    pub action: &'static str,
    /// The OS error.
    #[source]
    pub source: io::Error,
}

/// How a write reached its destination.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Written {
    /// Standard output (`-`).
    Stdout,
    /// Written in place to something that is not a regular file (device, FIFO).
    Direct(PathBuf),
    /// Replaced atomically; `via` is the symbolic link written through, if any.
    Replaced {
        /// The file actually replaced.
        file: PathBuf,
        /// The link the caller named, when it was one.
        via: Option<PathBuf>,
    },
}

impl std::fmt::Display for Written {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Written::Stdout => write!(f, "standard output"),
            Written::Direct(p) => {
                write!(f, "{} (written in place: not a regular file)", p.display())
            }
            Written::Replaced { file, via: None } => write!(f, "{}", file.display()),
            Written::Replaced {
                file,
                via: Some(link),
            } => write!(
                f,
                "{} (through the link {})",
                file.display(),
                link.display()
            ),
        }
    }
}

/// Where and how `path` is written, by the rules of the module documentation.
#[derive(Debug)]
enum Target {
    Stdout,
    Direct(PathBuf),
    Replace { file: PathBuf, via: Option<PathBuf> },
}

fn refused(msg: String) -> io::Error {
    io::Error::new(io::ErrorKind::PermissionDenied, msg)
}

/// Classifies `path` (`allow_stdout`: `-` is standard output).
fn target(path: &Path, allow_stdout: bool) -> io::Result<Target> {
    if allow_stdout && path.as_os_str() == "-" {
        return Ok(Target::Stdout);
    }
    let link = fs::symlink_metadata(path).ok();
    let is_link = link.as_ref().is_some_and(|m| m.file_type().is_symlink());
    match fs::metadata(path) {
        Ok(m) if !m.is_file() => {
            if m.is_dir() {
                return Err(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    "is a directory, not a file",
                ));
            }
            Ok(Target::Direct(path.to_path_buf()))
        }
        Ok(m) => {
            if m.permissions().readonly() {
                return Err(refused(
                    "the file is read-only; it is not replaced (make it writable or \
                     choose another file)"
                        .into(),
                ));
            }
            if is_link {
                let file = fs::canonicalize(path)?;
                Ok(Target::Replace {
                    file,
                    via: Some(path.to_path_buf()),
                })
            } else {
                Ok(Target::Replace {
                    file: path.to_path_buf(),
                    via: None,
                })
            }
        }
        Err(_) if is_link => Err(io::Error::new(
            io::ErrorKind::NotFound,
            "is a symbolic link to a missing file; not written (create the target or \
             choose another file)",
        )),
        Err(_) => Ok(Target::Replace {
            file: path.to_path_buf(),
            via: None,
        }),
    }
}

/// True when `a` and `b` name the same existing file (after resolving links, or the
/// same inode: hard links). False if either does not exist.
pub fn same_file(a: &Path, b: &Path) -> bool {
    match (fs::canonicalize(a), fs::canonicalize(b)) {
        (Ok(x), Ok(y)) if x == y => return true,
        (Ok(_), Ok(_)) => {}
        _ => return false,
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if let (Ok(x), Ok(y)) = (fs::metadata(a), fs::metadata(b)) {
            return x.dev() == y.dev() && x.ino() == y.ino();
        }
    }
    false
}

/// Writes `bytes` to `path` by the rules of the module documentation (atomic replace of
/// a regular file, through links, refusing read-only files, directly to devices and
/// FIFOs, `-` to standard output). On failure a regular destination is untouched.
pub fn write_atomic(path: impl AsRef<Path>, bytes: impl AsRef<[u8]>) -> io::Result<Written> {
    let path = path.as_ref();
    let bytes = bytes.as_ref();
    match target(path, true)? {
        Target::Stdout => {
            let mut out = io::stdout().lock();
            out.write_all(bytes)?;
            out.flush()?;
            Ok(Written::Stdout)
        }
        Target::Direct(p) => {
            write_direct(&p, bytes)?;
            Ok(Written::Direct(p))
        }
        Target::Replace { file, via } => {
            let tmp = TempFile::write(&file, bytes)?;
            tmp.rename_to(&file)?;
            Ok(Written::Replaced { file, via })
        }
    }
}

/// Writes to a device or FIFO in place (no create, no rename).
fn write_direct(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut f = OpenOptions::new().write(true).open(path)?;
    f.write_all(bytes)?;
    f.flush()
}

/// Saves `text` to `path` by the rules of the module documentation, keeping the previous
/// file: write `.<name>.tmp-<pid>` beside it, fsync, copy the previous file (if any) to
/// `<name>.bak`, rename the temporary file over `path`, then fsync the directory (best
/// effort). A link is saved through (backup beside the file it points to); a read-only
/// deck is refused. On any failure the temporary file is removed and `path` is
/// untouched; the error names the file concerned.
pub fn save_with_backup(path: &Path, text: &str) -> Result<Written, FileError> {
    let err = |path: PathBuf, action: &'static str| {
        move |source: io::Error| FileError {
            path,
            action,
            source,
        }
    };
    let (file, via) = match target(path, false).map_err(err(path.to_path_buf(), "cannot save"))? {
        Target::Direct(p) => {
            write_direct(&p, text.as_bytes()).map_err(err(p.clone(), "cannot save"))?;
            return Ok(Written::Direct(p));
        }
        Target::Replace { file, via } => (file, via),
        Target::Stdout => (path.to_path_buf(), None),
    };
    let path = file.as_path();
    let (dir, file_name) = split(path).map_err(err(path.to_path_buf(), "cannot save"))?;
    let tmp = TempFile::write(path, text.as_bytes()).map_err(err(
        temp_path(&dir, &file_name),
        "cannot write temporary file",
    ))?;
    if path.exists() {
        let bak = dir.join(format!("{file_name}.bak"));
        // An old read-only backup would make the copy fail: it is replaced.
        if fs::symlink_metadata(&bak).is_ok_and(|m| m.is_file() && m.permissions().readonly()) {
            let _ = fs::remove_file(&bak);
        }
        if let Err(e) = fs::copy(path, &bak) {
            return Err(err(bak, "cannot keep the previous deck as backup")(e));
        }
    }
    tmp.rename_to(path)
        .map_err(err(path.to_path_buf(), "cannot replace the deck"))?;
    // Make the rename durable; best effort (not all platforms can fsync a directory).
    if let Ok(d) = File::open(&dir) {
        let _ = d.sync_all();
    }
    Ok(Written::Replaced {
        file: path.to_path_buf(),
        via,
    })
}

/// The directory `path` is in (`.` for a bare name) and its file name.
fn split(path: &Path) -> io::Result<(PathBuf, String)> {
    let file_name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "path has no file name"))?;
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    Ok((dir, file_name))
}

/// `.<name>.tmp-<pid>` in `dir`.
fn temp_path(dir: &Path, file_name: &str) -> PathBuf {
    dir.join(format!(".{file_name}.tmp-{}", std::process::id()))
}

/// A written and fsynced temporary file beside its destination, removed when dropped
/// unless renamed into place.
struct TempFile {
    path: PathBuf,
    renamed: bool,
}

impl TempFile {
    /// Creates (or truncates) the temporary file for `dest`, writes `bytes` and fsyncs.
    fn write(dest: &Path, bytes: &[u8]) -> io::Result<TempFile> {
        let (dir, file_name) = split(dest)?;
        let tmp = TempFile {
            path: temp_path(&dir, &file_name),
            renamed: false,
        };
        let mut f = OpenOptions::new()
            .write(true)
            .create(true)
            .truncate(true)
            .open(&tmp.path)?;
        f.write_all(bytes)?;
        // The replaced file keeps its permissions (a 0600 deck stays private).
        if let Ok(m) = fs::metadata(dest) {
            f.set_permissions(m.permissions())?;
        }
        f.sync_all()?;
        Ok(tmp)
    }

    /// Renames the temporary file over `dest` (removed instead if that fails).
    fn rename_to(mut self, dest: &Path) -> io::Result<()> {
        fs::rename(&self.path, dest)?;
        self.renamed = true;
        Ok(())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.renamed {
            let _ = fs::remove_file(&self.path);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_files(dir: &Path) -> usize {
        fs::read_dir(dir)
            .map(|r| {
                r.filter_map(Result::ok)
                    .filter(|e| e.file_name().to_string_lossy().contains(".tmp"))
                    .count()
            })
            .unwrap_or(99)
    }

    fn read(path: &Path) -> String {
        fs::read_to_string(path).unwrap_or_default()
    }

    /// Writes a new file and replaces an existing one, leaving no temporary file; a
    /// failed write (the temporary file's place is taken by a directory) leaves the
    /// destination as it was; a missing directory is an error.
    #[test]
    fn write_atomic_replaces_or_leaves_untouched() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let path = dir.path().join("r.csv");
        assert!(write_atomic(&path, "one").is_ok());
        assert!(write_atomic(&path, b"two").is_ok());
        assert_eq!(read(&path), "two");
        assert_eq!(temp_files(dir.path()), 0);
        assert!(!dir.path().join("r.csv.bak").exists(), "no backup");

        let blocker = temp_path(dir.path(), "r.csv");
        fs::create_dir(&blocker).unwrap_or_else(|e| panic!("{e}"));
        assert!(write_atomic(&path, "three").is_err());
        assert_eq!(read(&path), "two");
        fs::remove_dir(&blocker).unwrap_or_else(|e| panic!("{e}"));

        assert!(write_atomic(dir.path().join("no/such/dir/r.csv"), "x").is_err());
        assert_eq!(temp_files(dir.path()), 0);
    }

    /// The previous file is kept as `<name>.bak` (none on the first save); a failing
    /// save (the backup cannot be written: a directory is in its way) leaves the file
    /// exactly as it was and no temporary file behind; each failure names its file.
    #[test]
    fn save_with_backup_keeps_previous_file() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let path = dir.path().join("deck.toml");
        let bak = dir.path().join("deck.toml.bak");
        assert!(save_with_backup(&path, "first").is_ok());
        assert!(!bak.exists());
        assert!(save_with_backup(&path, "second").is_ok());
        assert_eq!(
            (read(&path).as_str(), read(&bak).as_str()),
            ("second", "first")
        );

        fs::remove_file(&bak).unwrap_or_else(|e| panic!("{e}"));
        fs::create_dir(&bak).unwrap_or_else(|e| panic!("{e}"));
        fs::write(bak.join("x"), "x").unwrap_or_else(|e| panic!("{e}"));
        let e = save_with_backup(&path, "third").map_err(|e| (e.path, e.action));
        assert_eq!(
            e,
            Err((bak.clone(), "cannot keep the previous deck as backup"))
        );
        assert_eq!(read(&path), "second");
        assert_eq!(temp_files(dir.path()), 0);

        let missing = dir.path().join("no/such/dir/deck.toml");
        let e = save_with_backup(&missing, "x").map_err(|e| e.to_string());
        assert!(
            matches!(&e, Err(m) if m.contains("cannot write temporary file")
                && m.contains(".deck.toml.tmp-")),
            "{e:?}"
        );
        let e = save_with_backup(Path::new(".."), "x").map_err(|e| e.action);
        assert_eq!(e, Err("cannot save"));
    }

    /// A symbolic link is written through: the file it points to gets the new text, the
    /// link stays a link; a dangling link is refused. (Before: the link was replaced by a
    /// regular file and its target never written.)
    #[cfg(unix)]
    #[test]
    fn writes_through_symlinks() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let real = dir.path().join("real.toml");
        let link = dir.path().join("link.toml");
        fs::write(&real, "old").unwrap_or_else(|e| panic!("{e}"));
        std::os::unix::fs::symlink(&real, &link).unwrap_or_else(|e| panic!("{e}"));
        let w = write_atomic(&link, "new").map_err(|e| e.to_string());
        assert!(
            matches!(&w, Ok(Written::Replaced { via: Some(_), .. })),
            "{w:?}"
        );
        assert_eq!(read(&real), "new");
        assert!(fs::symlink_metadata(&link).is_ok_and(|m| m.file_type().is_symlink()));
        let w = save_with_backup(&link, "newer").map_err(|e| e.to_string());
        assert!(w.is_ok(), "{w:?}");
        assert_eq!(read(&real), "newer");
        assert_eq!(read(&dir.path().join("real.toml.bak")), "new");
        assert!(fs::symlink_metadata(&link).is_ok_and(|m| m.file_type().is_symlink()));

        let dangling = dir.path().join("dangling.toml");
        std::os::unix::fs::symlink(dir.path().join("missing"), &dangling)
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(write_atomic(&dangling, "x").is_err());
        assert!(fs::symlink_metadata(&dangling).is_ok_and(|m| m.file_type().is_symlink()));
    }

    /// A read-only file is refused with a clear message and left as it was (content and
    /// mode), by both writers; a writable file keeps its mode. (Before: replaced, 0644.)
    #[cfg(unix)]
    #[test]
    fn refuses_read_only_and_keeps_modes() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let ro = dir.path().join("ro.toml");
        fs::write(&ro, "keep").unwrap_or_else(|e| panic!("{e}"));
        fs::set_permissions(&ro, fs::Permissions::from_mode(0o444))
            .unwrap_or_else(|e| panic!("{e}"));
        let e = write_atomic(&ro, "x").map_err(|e| e.to_string());
        assert!(matches!(&e, Err(m) if m.contains("read-only")), "{e:?}");
        let e = save_with_backup(&ro, "x").map_err(|e| e.to_string());
        assert!(matches!(&e, Err(m) if m.contains("read-only")), "{e:?}");
        assert_eq!(read(&ro), "keep");
        let mode = fs::metadata(&ro).map(|m| m.permissions().mode() & 0o777);
        assert_eq!(mode.ok(), Some(0o444));
        assert!(!dir.path().join("ro.toml.bak").exists());

        let private = dir.path().join("p.toml");
        fs::write(&private, "a").unwrap_or_else(|e| panic!("{e}"));
        fs::set_permissions(&private, fs::Permissions::from_mode(0o600))
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(write_atomic(&private, "b").is_ok());
        let mode = fs::metadata(&private).map(|m| m.permissions().mode() & 0o777);
        assert_eq!(mode.ok(), Some(0o600));
        assert_eq!(temp_files(dir.path()), 0);
    }

    /// Something that is not a regular file (here a FIFO) is written in place, never
    /// replaced by a regular file; `/dev/null` stays a device. (Before: the FIFO was
    /// renamed over and became a regular file.)
    #[cfg(unix)]
    #[test]
    fn writes_devices_and_fifos_in_place() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let fifo = dir.path().join("pipe");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if !made.is_ok_and(|s| s.success()) {
            return; // no mkfifo on this system
        }
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || fs::read_to_string(fifo).unwrap_or_default())
        };
        let w = write_atomic(&fifo, "through the pipe").map_err(|e| e.to_string());
        assert!(matches!(&w, Ok(Written::Direct(_))), "{w:?}");
        assert_eq!(reader.join().unwrap_or_default(), "through the pipe");
        use std::os::unix::fs::FileTypeExt;
        assert!(fs::symlink_metadata(&fifo).is_ok_and(|m| m.file_type().is_fifo()));
        assert_eq!(temp_files(dir.path()), 0);

        let w = write_atomic("/dev/null", "x").map_err(|e| e.to_string());
        assert!(matches!(&w, Ok(Written::Direct(_))), "{w:?}");
        assert!(fs::metadata("/dev/null").is_ok_and(|m| m.file_type().is_char_device()));
    }

    /// `same_file` sees a file through a link, a relative path and a hard link.
    #[cfg(unix)]
    #[test]
    fn same_file_resolves_links() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let a = dir.path().join("a.toml");
        fs::write(&a, "a").unwrap_or_else(|e| panic!("{e}"));
        let l = dir.path().join("l.toml");
        std::os::unix::fs::symlink(&a, &l).unwrap_or_else(|e| panic!("{e}"));
        let h = dir.path().join("h.toml");
        fs::hard_link(&a, &h).unwrap_or_else(|e| panic!("{e}"));
        assert!(same_file(&a, &l));
        assert!(same_file(&a, &h));
        assert!(same_file(&a, &dir.path().join(".").join("a.toml")));
        assert!(!same_file(&a, &dir.path().join("b.toml")));
    }
}
