//! Where an output goes: what a path names (a standard stream, a device, a FIFO, a
//! regular file, through links) and how a destination that is not a regular file is
//! written in place. Separate from the plan (`super`) because it is the part that reads
//! the file system and the process's descriptors, not the all-or-nothing commit.

use super::*;
/// Classifies `path` (not `-`) by the rules of the module documentation, refusing what
/// cannot or must not be written.
pub(super) fn classify(path: &Path) -> io::Result<Dest> {
    if let Some(fd) = descriptor_named(path).or_else(|| std_stream_of(path)) {
        if fs::metadata(path).is_err() {
            return Err(io::Error::new(
                io::ErrorKind::NotFound,
                format!("names descriptor {fd}, which is not open"),
            ));
        }
        return Ok(Dest::Fd {
            path: path.to_path_buf(),
            fd,
        });
    }
    let is_link = fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink());
    match fs::metadata(path) {
        Ok(m) if m.is_dir() => Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "is a directory, not a file",
        )),
        Ok(m) if !m.is_file() => Ok(Dest::InPlace(path.to_path_buf())),
        Ok(m) => {
            if m.permissions().readonly() {
                return Err(refused(
                    "the file is read-only; it is not replaced (make it writable or \
                     choose another file)",
                ));
            }
            let (file, via) = if is_link {
                (fs::canonicalize(path)?, Some(path.to_path_buf()))
            } else {
                (path.to_path_buf(), None)
            };
            probe_dir(&file)?;
            Ok(Dest::Replace { file, via })
        }
        Err(_) if is_link => Err(io::Error::new(
            io::ErrorKind::NotFound,
            "is a symbolic link to a missing file; not written (create the target or \
             choose another file)",
        )),
        Err(e) if e.kind() != io::ErrorKind::NotFound => Err(e),
        Err(_) => {
            probe_dir(path)?;
            Ok(Dest::Replace {
                file: path.to_path_buf(),
                via: None,
            })
        }
    }
}

pub(super) fn refused(msg: &str) -> io::Error {
    io::Error::new(io::ErrorKind::PermissionDenied, msg.to_string())
}

/// Checks that the directory of `file` exists and takes a new file, by creating (and at
/// once removing) a temporary file there, exactly as the write will.
pub(super) fn probe_dir(file: &Path) -> io::Result<()> {
    let (dir, name) = split(file)?;
    match fs::metadata(&dir) {
        Ok(m) if m.is_dir() => {}
        Ok(_) => {
            return Err(io::Error::new(
                io::ErrorKind::NotFound,
                format!("{} is not a directory", dir.display()),
            ))
        }
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            return Err(io::Error::new(
                io::ErrorKind::NotFound,
                format!("the directory {} does not exist", dir.display()),
            ))
        }
        Err(e) => return Err(e),
    }
    Staged::create(&dir, &name, None).map(drop).map_err(|e| {
        io::Error::new(
            e.kind(),
            format!("cannot create a file in {}: {e}", dir.display()),
        )
    })
}

/// What `path` resolves to (see [`Identity`]); `None` when its directory does not exist.
pub(super) fn identity(path: &Path) -> Option<Identity> {
    if let Ok(m) = fs::metadata(path) {
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            return Some(Identity::Inode(m.dev(), m.ino()));
        }
        #[cfg(not(unix))]
        {
            let _ = m;
            return fs::canonicalize(path).ok().map(Identity::Canonical);
        }
    }
    // Not there (yet): follow links to the name that a write would create.
    let mut p = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match fs::read_link(&p) {
            Ok(target) => p = resolve_link(&p, target),
            Err(_) => break,
        }
    }
    let (dir, name) = split(&p).ok()?;
    Some(Identity::Name(fs::canonicalize(dir).ok()?.join(name)))
}

/// Links followed at most, as the kernel's own limit (Linux ELOOP after 40).
pub(super) const MAX_LINKS: usize = 40;

/// The path a link at `link` pointing to `target` names.
pub(super) fn resolve_link(link: &Path, target: PathBuf) -> PathBuf {
    if target.is_absolute() {
        target
    } else {
        link.parent().unwrap_or(Path::new("")).join(target)
    }
}

/// The descriptor `path` names by its name (`/dev/stdout`, `/dev/fd/N`,
/// `/proc/self/fd/N`, `/proc/<this pid>/fd/N`, …), following links to such a name and
/// seeing through a directory that is `/proc/self/fd` by another name.
pub(super) fn descriptor_named(path: &Path) -> Option<u32> {
    let mut p = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        if let Some(fd) = lexical_descriptor(&p) {
            return Some(fd);
        }
        if let Ok((dir, name)) = split(&p) {
            if let Ok(dir) = fs::canonicalize(dir) {
                if let Some(fd) = lexical_descriptor(&dir.join(name)) {
                    return Some(fd);
                }
            }
        }
        match fs::read_link(&p) {
            Ok(target) => p = resolve_link(&p, target),
            Err(_) => return None,
        }
    }
    None
}

/// The descriptor an absolute path names by its spelling alone.
pub(super) fn lexical_descriptor(path: &Path) -> Option<u32> {
    let parts: Vec<&OsStr> = path
        .components()
        .filter(|c| !matches!(c, Component::CurDir))
        .map(|c| match c {
            Component::RootDir => OsStr::new("/"),
            c => c.as_os_str(),
        })
        .collect();
    let s: Vec<&str> = parts.iter().map(|p| p.to_str()).collect::<Option<_>>()?;
    let pid = std::process::id().to_string();
    let own = |x: &str| x == "self" || x == "thread-self" || x == pid;
    let num = |x: &str| x.parse::<u32>().ok();
    match s.as_slice() {
        ["/", "dev", "stdin"] => Some(0),
        ["/", "dev", "stdout"] => Some(1),
        ["/", "dev", "stderr"] => Some(2),
        ["/", "dev", "fd", n] => num(n),
        ["/", "proc", who, "fd", n] if own(who) => num(n),
        ["/", "proc", who, "task", _, "fd", n] if own(who) => num(n),
        _ => None,
    }
}

/// The standard output stream (1, then 2) whose open file `path` resolves to, if any: the
/// file a shell redirected it to, its terminal, or `/dev/null`. Standard input is not
/// matched so: it is read, not written (a path naming it, `/dev/stdin`, still is).
#[cfg(unix)]
pub(super) fn std_stream_of(path: &Path) -> Option<u32> {
    use std::os::fd::AsFd;
    use std::os::unix::fs::MetadataExt;
    let m = fs::metadata(path).ok()?;
    let id = (m.dev(), m.ino());
    let of = |fd: io::Result<std::os::fd::OwnedFd>| {
        fd.and_then(|fd| File::from(fd).metadata())
            .ok()
            .map(|m| (m.dev(), m.ino()))
    };
    if of(io::stdout().as_fd().try_clone_to_owned()) == Some(id) {
        Some(1)
    } else if of(io::stderr().as_fd().try_clone_to_owned()) == Some(id) {
        Some(2)
    } else {
        None
    }
}

#[cfg(not(unix))]
pub(super) fn std_stream_of(_path: &Path) -> Option<u32> {
    None
}

/// Writes to standard output (1) or standard error (2) through the process's stream.
pub(super) fn write_fd(fd: u32, bytes: &[u8]) -> io::Result<()> {
    if fd == 2 {
        let mut e = io::stderr().lock();
        e.write_all(bytes)?;
        e.flush()
    } else {
        let mut o = io::stdout().lock();
        o.write_all(bytes)?;
        o.flush()
    }
}

/// Writes to the descriptor `fd` that `path` names: 1 and 2 through the process's streams,
/// 0 through a duplicate of it, a higher one by reopening `path` to append.
pub(super) fn write_descriptor(path: &Path, fd: u32, bytes: &[u8]) -> io::Result<()> {
    match fd {
        1 | 2 => write_fd(fd, bytes),
        #[cfg(unix)]
        0 => {
            use std::os::fd::AsFd;
            let mut f = File::from(io::stdin().as_fd().try_clone_to_owned()?);
            f.write_all(bytes).map_err(|e| match e.raw_os_error() {
                Some(n) if n == rustix::io::Errno::BADF.raw_os_error() => io::Error::new(
                    e.kind(),
                    "names standard input, which is not open for writing",
                ),
                _ => e,
            })?;
            f.flush()
        }
        _ => {
            let mut f = OpenOptions::new().append(true).open(path)?;
            f.write_all(bytes)?;
            f.flush()
        }
    }
}

/// Writes to a device or FIFO in place (no create, no rename). A FIFO is opened without
/// blocking: with no reader yet, waits up to `wait` for one (saying so on standard error)
/// and then refuses.
pub(super) fn write_in_place(path: &Path, bytes: &[u8], wait: Duration) -> io::Result<()> {
    let is_fifo = {
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            fs::metadata(path).is_ok_and(|m| m.file_type().is_fifo())
        }
        #[cfg(not(unix))]
        false
    };
    let mut f = if is_fifo {
        open_fifo(path, wait)?
    } else {
        OpenOptions::new().write(true).open(path)?
    };
    f.write_all(bytes)?;
    f.flush()
}

/// Opens a FIFO for writing without blocking forever: `O_NONBLOCK` fails with ENXIO while
/// no process has it open for reading; retried every 50 ms up to `wait`, then refused.
/// Once open, the descriptor is made blocking again so that the write waits for the reader
/// to drain the pipe.
#[cfg(unix)]
pub(super) fn open_fifo(path: &Path, wait: Duration) -> io::Result<File> {
    use rustix::fs::OFlags;
    use std::os::unix::fs::OpenOptionsExt;
    let start = Instant::now();
    let mut said = false;
    loop {
        let opened = OpenOptions::new()
            .write(true)
            .custom_flags(OFlags::NONBLOCK.bits() as i32)
            .open(path);
        match opened {
            Ok(f) => {
                let flags = rustix::fs::fcntl_getfl(&f)?;
                rustix::fs::fcntl_setfl(&f, flags - OFlags::NONBLOCK)?;
                return Ok(f);
            }
            Err(e) if e.raw_os_error() == Some(rustix::io::Errno::NXIO.raw_os_error()) => {
                if start.elapsed() >= wait {
                    return Err(io::Error::new(
                        io::ErrorKind::WouldBlock,
                        format!(
                            "is a FIFO that no process opened for reading{}; not written \
                             (start its reader first)",
                            if wait.is_zero() {
                                String::new()
                            } else {
                                format!(" within {} s", wait.as_secs_f64())
                            }
                        ),
                    ));
                }
                if !said {
                    eprintln!(
                        "waiting for a reader on FIFO {} (at most {} s)…",
                        path.display(),
                        wait.as_secs_f64()
                    );
                    said = true;
                }
                std::thread::sleep(Duration::from_millis(50));
            }
            Err(e) => return Err(e),
        }
    }
}

#[cfg(not(unix))]
pub(super) fn open_fifo(path: &Path, _wait: Duration) -> io::Result<File> {
    OpenOptions::new().write(true).open(path)
}

/// Best effort: makes a rename in the directory of `file` durable (not every platform can
/// fsync a directory).
pub(super) fn sync_dir(file: &Path) {
    if let Ok((dir, _)) = split(file) {
        if let Ok(d) = File::open(dir) {
            let _ = d.sync_all();
        }
    }
}
