//! Writing files so that a crash, a failure or a signal never leaves a truncated one, and
//! a user's data is never lost or silently replaced: the one writer of the crate, used by
//! the CLI (`run --output`, `run --series`, `stiffness --output`, `sweep --output`) and the
//! deck save.
//!
//! The rules (issues 14 and 24), applied by [`plan`] and [`Plan::commit`] (and through
//! them by [`write_atomic`] and [`save_with_backup`]):
//!
//! * **Checked first.** Every output is checked before anything is computed or written
//!   ([`plan`]): its directory exists and takes a new file, it is not a directory, not a
//!   read-only file, not a dangling link, not the deck being read, and it is not the same
//!   file as another output. Outputs are compared by what they resolve to: device and
//!   inode when the file exists, else the canonical directory and the name (following
//!   links), so `new.json`, `./new.json`, its absolute path and a link to it are one file
//!   whether or not it exists yet. Outputs written in place (standard streams, devices,
//!   FIFOs) may share a file: they are written one after the other, in order.
//! * **Temporary, then rename.** A regular file (or a new one) is written to a temporary
//!   file `.<name>.<random>.tmp` in its directory, created exclusively (`O_CREAT|O_EXCL`,
//!   by the `tempfile` crate: a file or link planted at a guessable name is never opened,
//!   let alone followed), fsynced and renamed over the destination. The file keeps its
//!   permissions; a new one gets 0666 less the umask, as any new file.
//! * **All or nothing.** [`Plan::commit`] writes every temporary file first, then what is
//!   written in place, and renames the temporaries only when all of that succeeded; on
//!   any failure the temporaries are removed and every destination that would have been
//!   replaced is untouched. The temporaries are removed on every exit path: a failure or a
//!   panic drops them, and a SIGINT, SIGTERM, SIGHUP or SIGQUIT removes them before the
//!   process ends by that signal (once [`remove_temporaries_on_signals`] is installed, as
//!   the CLI does).
//! * **Links.** A symbolic link is written *through*: the rename replaces the file the
//!   link resolves to, and the link stays a link (a dangling link is refused).
//! * **Read-only.** A read-only file is refused with a clear message, never replaced.
//! * **Standard streams.** A path that names one of this process's standard streams
//!   (`/dev/stdout`, `/dev/stderr`, `/dev/stdin`, `/dev/fd/N`, `/proc/self/fd/N`, a link
//!   to one of them), or that resolves to the file descriptor 1 or 2 is open on (the file
//!   a shell appends standard output to), is written to that descriptor in place,
//!   never replaced: `--output /dev/stdout >> log.txt` appends to `log.txt`. A path naming
//!   another open descriptor (`/dev/fd/N`, N > 2) is reopened to append.
//! * **In place.** Anything else that is not a regular file is written in place, without
//!   a temporary file or a rename: a device such as `/dev/null`, or a FIFO. A FIFO is
//!   opened without blocking; with no reader yet the CLI waits for one, saying so on
//!   standard error, at most [`FIFO_WAIT`], then gives up with nothing written to any
//!   output; the deck save does not wait.
//! * `-` (or no file at all) means standard output.
//!
//! [`save_with_backup`] also keeps the previous file as `<name>.bak`, written as a
//! temporary file and renamed like the file itself (a link planted at `<name>.bak` is
//! replaced by the backup, its target never written), and fsyncs the directory after the
//! renames. [`same_file`] compares two existing files.

use std::ffi::{OsStr, OsString};
use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Component, Path, PathBuf};
use std::sync::{Mutex, MutexGuard, OnceLock};
use std::time::{Duration, Instant};

mod destination;
mod staged;
use destination::*;
pub use staged::remove_temporaries_on_signals;
use staged::*;

/// How long the CLI waits for a reader to open a FIFO named as an output before giving
/// up (nothing written to any output). Long enough for `rollbench … --output p & cat p`
/// started by hand; short enough that a forgotten reader does not hang a script.
pub const FIFO_WAIT: Duration = Duration::from_secs(10);

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

/// An output refused or not written, named as the user named it.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{what}: {reason}")]
pub struct OutputError {
    /// The output: its flag and path (`--series out.csv`), or "standard output".
    pub what: String,
    /// Why, for a person: what is wrong and what to do.
    pub reason: String,
    /// The kind of the OS error behind it (`Other` when the rules refused it).
    pub kind: io::ErrorKind,
}

/// How a write reached its destination.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Written {
    /// Standard output (`-`, or no file named).
    Stdout,
    /// A path naming one of this process's open descriptors (`/dev/stdout`, the file
    /// standard output is redirected to, `/dev/fd/N`), written in place.
    Descriptor {
        /// The path as named.
        path: PathBuf,
        /// The descriptor it names.
        fd: u32,
    },
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
            Written::Descriptor { path, fd } => {
                write!(f, "{} (descriptor {fd}, written in place)", path.display())
            }
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

/// Where and how an output is written, by the rules of the module documentation.
#[derive(Debug, Clone)]
enum Dest {
    /// Standard output (`-` or no file).
    Stdout,
    /// One of this process's descriptors, named by `path`: 0, 1, 2 written through the
    /// process's own descriptor (at its offset, or appending if it was opened so); a
    /// higher one reopened to append.
    Fd { path: PathBuf, fd: u32 },
    /// A device or FIFO, written in place.
    InPlace(PathBuf),
    /// A regular file (or a new one): temporary file, then rename over `file`.
    Replace { file: PathBuf, via: Option<PathBuf> },
}

impl Dest {
    fn in_place(&self) -> bool {
        !matches!(self, Dest::Replace { .. })
    }
}

/// One checked output.
#[derive(Debug, Clone)]
struct Item {
    what: String,
    dest: Dest,
}

/// Outputs checked by [`plan`], to be written together by [`Plan::commit`].
#[derive(Debug, Clone)]
pub struct Plan {
    items: Vec<Item>,
    fifo_wait: Duration,
}

/// What a file is, to tell two outputs (or an output and the deck) apart.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Identity {
    /// An existing file: its device and inode (its canonical path off unix).
    #[cfg(unix)]
    Inode(u64, u64),
    #[cfg(not(unix))]
    Canonical(PathBuf),
    /// A file not created yet: the canonical directory it will be in, joined with its name.
    Name(PathBuf),
}

/// Checks every output before anything is computed or written, by the rules of the
/// module documentation. `outputs` are `(flag, path)`: `None` or `-` is standard output;
/// `inputs` are `(what, path)` of the files being read (`"the deck being read"`), which
/// no output may be. The first refusal is returned, naming the output and why.
pub fn plan(
    outputs: &[(&str, Option<&Path>)],
    inputs: &[(&str, &Path)],
) -> Result<Plan, OutputError> {
    let named: Vec<(String, Option<&Path>)> = outputs
        .iter()
        .map(|&(flag, path)| match path {
            Some(p) if p.as_os_str() != "-" => (format!("{flag} {}", p.display()), Some(p)),
            _ => ("standard output".to_string(), None),
        })
        .collect();
    let refuse = |what: &str, reason: String| OutputError {
        what: what.to_string(),
        reason,
        kind: io::ErrorKind::Other,
    };
    // Identities first, so that a clash is named as such even where the output would be
    // refused for another reason too (a link to a file the other output creates).
    let ids: Vec<Option<Identity>> = named.iter().map(|(_, p)| p.and_then(identity)).collect();
    for ((what, path), id) in named.iter().zip(&ids) {
        let (Some(_), Some(id)) = (path, id) else {
            continue;
        };
        for &(desc, input) in inputs {
            if identity(input).as_ref() == Some(id) {
                return Err(refuse(
                    what,
                    format!("is {desc} ({}); refusing to overwrite it", input.display()),
                ));
            }
        }
    }
    let dests: Vec<io::Result<Dest>> = named
        .iter()
        .map(|(_, path)| path.map_or(Ok(Dest::Stdout), classify))
        .collect();
    let in_place = |d: &io::Result<Dest>| d.as_ref().is_ok_and(Dest::in_place);
    for j in 0..named.len() {
        for i in 0..j {
            let both_in_place = in_place(&dests[i]) && in_place(&dests[j]);
            if !both_in_place && ids[i].is_some() && ids[i] == ids[j] {
                return Err(refuse(
                    &named[j].0,
                    format!(
                        "is the same file as {}; refusing to write either (name two \
                         different files)",
                        named[i].0
                    ),
                ));
            }
        }
    }
    let mut items = Vec::with_capacity(named.len());
    for ((what, _), dest) in named.into_iter().zip(dests) {
        let dest = dest.map_err(|e| OutputError {
            what: what.clone(),
            reason: e.to_string(),
            kind: e.kind(),
        })?;
        items.push(Item { what, dest });
    }
    Ok(Plan {
        items,
        fifo_wait: FIFO_WAIT,
    })
}

impl Plan {
    /// How long to wait for a reader on a FIFO output (default [`FIFO_WAIT`]; zero: do
    /// not wait, refuse at once).
    pub fn fifo_wait(mut self, wait: Duration) -> Plan {
        self.fifo_wait = wait;
        self
    }

    /// Writes `contents[i]` to the `i`-th output of the plan, all or nothing: every
    /// temporary file first, then the outputs written in place, then the renames. On a
    /// failure before the renames no replaced destination is touched and no temporary file
    /// remains. (A rename failing after others succeeded, which needs the directory to
    /// change under the write, leaves the earlier outputs written: the message says so.)
    pub fn commit(&self, contents: &[&[u8]]) -> Result<Vec<Written>, OutputError> {
        if contents.len() != self.items.len() {
            return Err(OutputError {
                what: "outputs".into(),
                reason: format!(
                    "{} contents for {} outputs (a bug: please report it)",
                    contents.len(),
                    self.items.len()
                ),
                kind: io::ErrorKind::InvalidInput,
            });
        }
        let fail = |item: &Item, e: io::Error| OutputError {
            what: item.what.clone(),
            reason: format!("{e}; nothing was written"),
            kind: e.kind(),
        };
        let mut staged = Vec::with_capacity(self.items.len());
        for (item, bytes) in self.items.iter().zip(contents) {
            staged.push(match &item.dest {
                Dest::Replace { file, .. } => {
                    Some(Staged::write(file, bytes).map_err(|e| fail(item, e))?)
                }
                _ => None,
            });
        }
        for (item, bytes) in self.items.iter().zip(contents) {
            match &item.dest {
                Dest::Stdout => write_fd(1, bytes),
                Dest::Fd { path, fd } => write_descriptor(path, *fd, bytes),
                Dest::InPlace(p) => write_in_place(p, bytes, self.fifo_wait),
                Dest::Replace { .. } => Ok(()),
            }
            .map_err(|e| fail(item, e))?;
        }
        let mut written = Vec::with_capacity(self.items.len());
        let mut renamed = 0;
        for (item, st) in self.items.iter().zip(staged) {
            written.push(match (&item.dest, st) {
                (Dest::Replace { file, via }, Some(st)) => {
                    st.rename_to(file).map_err(|e| OutputError {
                        what: item.what.clone(),
                        reason: if renamed == 0 {
                            format!("{e}; nothing was replaced")
                        } else {
                            format!("{e}; the outputs before it were written")
                        },
                        kind: e.kind(),
                    })?;
                    renamed += 1;
                    sync_dir(file);
                    Written::Replaced {
                        file: file.clone(),
                        via: via.clone(),
                    }
                }
                (Dest::Stdout, _) => Written::Stdout,
                (Dest::Fd { path, fd }, _) => Written::Descriptor {
                    path: path.clone(),
                    fd: *fd,
                },
                (Dest::InPlace(p), _) | (Dest::Replace { file: p, .. }, None) => {
                    Written::Direct(p.clone())
                }
            });
        }
        Ok(written)
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

/// Writes `bytes` to `path` by the rules of the module documentation (one output: see
/// [`plan`] for several written together). On failure a regular destination is untouched.
pub fn write_atomic(path: impl AsRef<Path>, bytes: impl AsRef<[u8]>) -> io::Result<Written> {
    let err = |e: OutputError| io::Error::new(e.kind, e.reason);
    let mut w = plan(&[("", Some(path.as_ref()))], &[])
        .map_err(err)?
        .commit(&[bytes.as_ref()])
        .map_err(err)?;
    w.pop()
        .ok_or_else(|| io::Error::other("nothing was written"))
}

/// Saves `text` to `path` by the rules of the module documentation, keeping the previous
/// file: the new text and (if there is a previous file) a copy of it are written as
/// temporary files beside it and fsynced, the copy is renamed to `<name>.bak` (replacing
/// whatever is there, a link included, never writing through it), the new text renamed
/// over `path`, then the directory is fsynced (best effort). A link is saved through
/// (backup beside the file it points to); a read-only deck is refused; a FIFO with no
/// reader is refused at once. On any failure no temporary file remains and `path` is
/// untouched; the error names the file concerned.
pub fn save_with_backup(path: &Path, text: &str) -> Result<Written, FileError> {
    let err = |path: PathBuf, action: &'static str| {
        move |source: io::Error| FileError {
            path,
            action,
            source,
        }
    };
    let dest = if path.as_os_str() == "-" {
        // A deck named `-` is a file of that name, not standard output.
        classify(&Path::new(".").join(path))
    } else {
        classify(path)
    }
    .map_err(err(path.to_path_buf(), "cannot save"))?;
    let (file, via) = match dest {
        Dest::Replace { file, via } => (file, via),
        Dest::InPlace(p) => {
            write_in_place(&p, text.as_bytes(), Duration::ZERO)
                .map_err(err(p.clone(), "cannot save"))?;
            return Ok(Written::Direct(p));
        }
        Dest::Fd { path: p, fd } => {
            write_descriptor(&p, fd, text.as_bytes()).map_err(err(p.clone(), "cannot save"))?;
            return Ok(Written::Descriptor { path: p, fd });
        }
        Dest::Stdout => (path.to_path_buf(), None),
    };
    let path = file.as_path();
    let (dir, file_name) = split(path).map_err(err(path.to_path_buf(), "cannot save"))?;
    let tmp = Staged::write(path, text.as_bytes())
        .map_err(err(dir.clone(), "cannot write temporary file"))?;
    let bak = dir.join({
        let mut n = file_name.clone();
        n.push(".bak");
        n
    });
    if path.exists() {
        let keep = (|| -> io::Result<()> {
            let mut old = File::open(path)?;
            let mut copy = Staged::create(&dir, bak.file_name().unwrap_or_default(), Some(path))?;
            io::copy(&mut old, copy.file()?)?;
            copy.file()?.sync_all()?;
            copy.rename_to(&bak)
        })();
        keep.map_err(err(bak.clone(), "cannot keep the previous deck as backup"))?;
    }
    tmp.rename_to(path)
        .map_err(err(path.to_path_buf(), "cannot replace the deck"))?;
    sync_dir(path);
    Ok(Written::Replaced {
        file: path.to_path_buf(),
        via,
    })
}

/// The directory `path` is in (`.` for a bare name) and its file name.
fn split(path: &Path) -> io::Result<(PathBuf, OsString)> {
    let file_name = path
        .file_name()
        .map(OsStr::to_os_string)
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "path has no file name"))?;
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    Ok((dir, file_name))
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

    /// Writes a new file and replaces an existing one, leaving no temporary file nor
    /// backup; a directory planted at a guessable temporary name is no obstacle (the name
    /// is random); a missing directory is an error naming it, with nothing created.
    #[test]
    fn write_atomic_replaces_or_leaves_untouched() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let path = dir.path().join("r.csv");
        assert!(write_atomic(&path, "one").is_ok());
        assert!(write_atomic(&path, b"two").is_ok());
        assert_eq!(read(&path), "two");
        assert_eq!(temp_files(dir.path()), 0);
        assert!(!dir.path().join("r.csv.bak").exists(), "no backup");

        let blocker = dir
            .path()
            .join(format!(".r.csv.tmp-{}", std::process::id()));
        fs::create_dir(&blocker).unwrap_or_else(|e| panic!("{e}"));
        assert!(write_atomic(&path, "three").is_ok());
        assert_eq!(read(&path), "three");
        fs::remove_dir(&blocker).unwrap_or_else(|e| panic!("{e}"));

        let e = write_atomic(dir.path().join("no/such/dir/r.csv"), "x").map_err(|e| e.to_string());
        assert!(
            matches!(&e, Err(m) if m.contains("no/such/dir") && m.contains("does not exist")),
            "{e:?}"
        );
        assert_eq!(temp_files(dir.path()), 0);
    }

    /// All or nothing (issue 24, item 4): with a second output that cannot be written
    /// (`/dev/full`: ENOSPC on the write), the first, a regular file, is left exactly as
    /// it was and no temporary file remains; an output in a missing directory is refused
    /// by the plan, before anything is written, naming the output.
    #[cfg(target_os = "linux")]
    #[test]
    fn commit_is_all_or_nothing() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let rep = dir.path().join("rep.json");
        fs::write(&rep, "old").unwrap_or_else(|e| panic!("{e}"));
        let p = plan(
            &[
                ("--output", Some(rep.as_path())),
                ("--series", Some(Path::new("/dev/full"))),
            ],
            &[],
        )
        .unwrap_or_else(|e| panic!("{e}"));
        let e = p.commit(&[b"new", b"series"]).map_err(|e| e.to_string());
        assert!(
            matches!(&e, Err(m) if m.starts_with("--series /dev/full:")
                && m.contains("nothing was written")),
            "{e:?}"
        );
        assert_eq!(read(&rep), "old");
        assert_eq!(temp_files(dir.path()), 0);

        let missing = dir.path().join("nonexistent/s.csv");
        let e = plan(
            &[
                ("--output", Some(rep.as_path())),
                ("--series", Some(&missing)),
            ],
            &[],
        )
        .map(drop)
        .map_err(|e| e.to_string());
        assert!(
            matches!(&e, Err(m) if m.starts_with("--series ") && m.contains("does not exist")),
            "{e:?}"
        );
        let e = plan(&[("--output", Some(dir.path()))], &[]).map(drop);
        assert!(
            matches!(&e, Err(e) if e.reason.contains("is a directory")),
            "{e:?}"
        );
        assert_eq!(read(&rep), "old");
        assert_eq!(temp_files(dir.path()), 0);
    }

    /// Outputs are compared by what they resolve to, existing or not (issue 24, item 2):
    /// `new.json` and `./new.json`, its absolute path, a link to the not-yet-created file,
    /// a hard link; and no output may be the deck. Outputs written in place may share a
    /// file (`/dev/null` twice). Nothing is created by a refused plan.
    #[cfg(unix)]
    #[test]
    fn plan_refuses_two_outputs_that_are_one_file() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let new = dir.path().join("new.json");
        let dot = dir.path().join(".").join("new.json");
        let link = dir.path().join("link.json");
        std::os::unix::fs::symlink("new.json", &link).unwrap_or_else(|e| panic!("{e}"));
        let sub = dir.path().join("sub");
        fs::create_dir(&sub).unwrap_or_else(|e| panic!("{e}"));
        let up = sub.join("..").join("new.json");
        for other in [&dot, &link, &up] {
            let e = plan(
                &[("--output", Some(new.as_path())), ("--series", Some(other))],
                &[],
            )
            .map(drop)
            .map_err(|e| e.to_string());
            assert!(
                matches!(&e, Err(m) if m.contains("is the same file as --output")),
                "{other:?}: {e:?}"
            );
            assert!(!new.exists());
        }
        let deck = dir.path().join("deck.toml");
        fs::write(&deck, "d").unwrap_or_else(|e| panic!("{e}"));
        let hard = dir.path().join("hard.toml");
        fs::hard_link(&deck, &hard).unwrap_or_else(|e| panic!("{e}"));
        let e = plan(
            &[("--output", Some(&hard))],
            &[("the deck being read", &deck)],
        )
        .map(drop)
        .map_err(|e| e.to_string());
        assert!(
            matches!(&e, Err(m) if m.contains("deck being read")),
            "{e:?}"
        );
        let null = Path::new("/dev/null");
        assert!(plan(&[("--output", Some(null)), ("--series", Some(null))], &[]).is_ok());
        assert!(plan(&[("--output", Some(&new)), ("--series", None)], &[]).is_ok());
        assert_eq!(temp_files(dir.path()), 0);
    }

    /// Paths that name a descriptor by their spelling, through a link, or through a
    /// directory that is `/proc/self/fd` by another name (issue 24, item 1).
    #[cfg(target_os = "linux")]
    #[test]
    fn names_of_descriptors() {
        let pid = std::process::id();
        for (p, fd) in [
            ("/dev/stdout", Some(1)),
            ("/dev/stderr", Some(2)),
            ("/dev/stdin", Some(0)),
            ("/dev/./fd/1", Some(1)),
            ("/proc/self/fd/7", Some(7)),
            ("/proc/thread-self/fd/2", Some(2)),
            (&format!("/proc/{pid}/fd/1"), Some(1)),
            (&format!("/proc/{pid}/task/{pid}/fd/1"), Some(1)),
            ("/proc/1/fd/1", None),
            ("/dev/null", None),
            ("/dev/fd/x", None),
            ("out.json", None),
        ] {
            assert_eq!(lexical_descriptor(Path::new(p)), fd, "{p}");
        }
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let link = dir.path().join("out");
        std::os::unix::fs::symlink("/dev/stdout", &link).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(descriptor_named(&link), Some(1));
        let fds = dir.path().join("fds");
        std::os::unix::fs::symlink("/proc/self/fd", &fds).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(descriptor_named(&fds.join("2")), Some(2));
        assert_eq!(descriptor_named(&dir.path().join("plain")), None);
    }

    /// Links planted where a write goes (issue 24, item 3): at the old predictable
    /// temporary name `.NAME.tmp-PID` (now random and created exclusively: never opened)
    /// and at `NAME.bak` (replaced by the backup, a regular file: its target is never
    /// written). The victims keep their text.
    #[cfg(unix)]
    #[test]
    fn planted_links_are_never_written_through() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let victim = dir.path().join("victim.txt");
        fs::write(&victim, "victim").unwrap_or_else(|e| panic!("{e}"));
        let deck = dir.path().join("deck.toml");
        fs::write(&deck, "first").unwrap_or_else(|e| panic!("{e}"));
        let pid = std::process::id();
        for name in [
            format!(".deck.toml.tmp-{pid}"),
            format!(".out.json.tmp-{pid}"),
        ] {
            std::os::unix::fs::symlink(&victim, dir.path().join(name))
                .unwrap_or_else(|e| panic!("{e}"));
        }
        let bak = dir.path().join("deck.toml.bak");
        std::os::unix::fs::symlink(&victim, &bak).unwrap_or_else(|e| panic!("{e}"));

        let w = save_with_backup(&deck, "second").map_err(|e| e.to_string());
        assert!(w.is_ok(), "{w:?}");
        assert!(write_atomic(dir.path().join("out.json"), "report").is_ok());
        assert_eq!(read(&victim), "victim");
        assert_eq!(read(&deck), "second");
        assert_eq!(read(&dir.path().join("out.json")), "report");
        assert!(fs::symlink_metadata(&bak).is_ok_and(|m| m.file_type().is_file()));
        assert_eq!(read(&bak), "first");
    }

    /// A FIFO with no reader (issue 24, item 5): refused at once with no wait, refused
    /// after the wait (100 ms here; measured within 100–400 ms, the poll is 50 ms), and
    /// written when a reader comes during the wait. Never blocks forever.
    #[cfg(unix)]
    #[test]
    fn fifo_without_a_reader_is_waited_for_then_refused() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let fifo = dir.path().join("pipe");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if !made.is_ok_and(|s| s.success()) {
            return; // no mkfifo on this system
        }
        let e = write_in_place(&fifo, b"x", Duration::ZERO).map_err(|e| e.to_string());
        assert!(
            matches!(&e, Err(m) if m.contains("no process opened")),
            "{e:?}"
        );
        let t = Instant::now();
        let e = write_in_place(&fifo, b"x", Duration::from_millis(100)).map_err(|e| e.kind());
        assert_eq!(e, Err(io::ErrorKind::WouldBlock));
        let took = t.elapsed();
        assert!(
            (Duration::from_millis(100)..Duration::from_millis(400)).contains(&took),
            "{took:?}"
        );
        let reader = {
            let fifo = fifo.clone();
            std::thread::spawn(move || {
                std::thread::sleep(Duration::from_millis(150));
                fs::read_to_string(fifo).unwrap_or_default()
            })
        };
        let w = write_in_place(&fifo, b"late reader", Duration::from_secs(5));
        assert!(w.is_ok(), "{w:?}");
        assert_eq!(reader.join().unwrap_or_default(), "late reader");
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
            matches!(&e, Err(m) if m.contains("cannot save")
                && m.contains("no/such/dir does not exist")),
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
