//! The temporary files of a commit: created exclusively with a random name, listed so
//! that a signal handler can remove them (a signal runs no destructors), removed on drop.
//! Separate from the plan (`super`) because it is the one piece with global state.

use super::*;
/// The temporary files that exist now, for the signal handler to remove
/// ([`remove_temporaries_on_signals`]): a signal runs no destructors.
pub(super) static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The list of temporary files, even if a thread panicked while holding it (the list
/// itself is always whole: pushes and removals only).
pub(super) fn temporaries() -> MutexGuard<'static, Vec<PathBuf>> {
    TEMPORARIES.lock().unwrap_or_else(|p| p.into_inner())
}

/// Installs (once) a thread that, on SIGINT, SIGTERM, SIGHUP or SIGQUIT, removes every
/// temporary file of this module and then ends the process by that signal, as it would
/// have ended without the handler (exit status 128 + n in a shell; `exit(128 + n)` if
/// the default action cannot be re-raised). For the CLI; the workbench has its own
/// handling (it restores the terminal) and saves without it.
pub fn remove_temporaries_on_signals() -> io::Result<()> {
    static INSTALLED: OnceLock<()> = OnceLock::new();
    if INSTALLED.get().is_some() {
        return Ok(());
    }
    #[cfg(unix)]
    {
        use signal_hook::consts::{SIGHUP, SIGINT, SIGQUIT, SIGTERM};
        let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP, SIGQUIT])?;
        std::thread::Builder::new()
            .name("remove-temporaries".into())
            .spawn(move || {
                if let Some(sig) = signals.forever().next() {
                    // Held to the end: no new temporary file is created meanwhile.
                    let mut list = temporaries();
                    for p in list.drain(..) {
                        let _ = fs::remove_file(&p);
                    }
                    let _ = signal_hook::low_level::emulate_default_handler(sig);
                    std::process::exit(128 + sig);
                }
            })?;
    }
    let _ = INSTALLED.set(());
    Ok(())
}

/// A temporary file beside its destination, created exclusively under a random name and
/// listed in [`TEMPORARIES`]; removed when dropped unless renamed into place.
pub(super) struct Staged {
    tmp: Option<tempfile::NamedTempFile>,
    path: PathBuf,
}

impl Staged {
    /// Creates `.<name>.<random>.tmp` in `dir` (`O_CREAT|O_EXCL`: never an existing file or
    /// link), with the permissions of `like` if given (else 0666 less the umask, as any new
    /// file), and lists it for the signal handler.
    pub(super) fn create(dir: &Path, name: &OsStr, like: Option<&Path>) -> io::Result<Staged> {
        let mut prefix = OsString::from(".");
        prefix.push(name);
        prefix.push(".");
        let mut b = tempfile::Builder::new();
        b.prefix(&prefix).suffix(".tmp");
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            b.permissions(fs::Permissions::from_mode(0o666));
        }
        // Created and listed under the lock, so that a signal never misses it.
        let mut list = temporaries();
        let tmp = b.tempfile_in(dir)?;
        let path = tmp.path().to_path_buf();
        list.push(path.clone());
        drop(list);
        let staged = Staged {
            tmp: Some(tmp),
            path,
        };
        // The replaced file keeps its permissions (a 0600 deck stays private).
        if let Some(m) = like.and_then(|p| fs::metadata(p).ok()) {
            staged.path_file()?.set_permissions(m.permissions())?;
        }
        Ok(staged)
    }

    /// The temporary file for `dest` holding `bytes`, fsynced.
    pub(super) fn write(dest: &Path, bytes: &[u8]) -> io::Result<Staged> {
        let (dir, name) = split(dest)?;
        let mut st = Staged::create(&dir, &name, Some(dest))?;
        let f = st.file()?;
        f.write_all(bytes)?;
        f.sync_all()?;
        Ok(st)
    }

    pub(super) fn path_file(&self) -> io::Result<&File> {
        self.tmp
            .as_ref()
            .map(tempfile::NamedTempFile::as_file)
            .ok_or_else(|| io::Error::other("temporary file already renamed"))
    }

    pub(super) fn file(&mut self) -> io::Result<&mut File> {
        self.tmp
            .as_mut()
            .map(tempfile::NamedTempFile::as_file_mut)
            .ok_or_else(|| io::Error::other("temporary file already renamed"))
    }

    /// Renames the temporary file over `dest` (a link at `dest` is replaced, never
    /// followed); on failure it is removed.
    pub(super) fn rename_to(mut self, dest: &Path) -> io::Result<()> {
        let tmp = self
            .tmp
            .take()
            .ok_or_else(|| io::Error::other("temporary file already renamed"))?;
        let r = tmp.persist(dest).map(drop).map_err(|e| {
            let _ = fs::remove_file(&self.path);
            e.error
        });
        unlist(&self.path);
        r
    }
}

pub(super) fn unlist(path: &Path) {
    temporaries().retain(|p| p != path);
}

impl Drop for Staged {
    fn drop(&mut self) {
        if let Some(tmp) = self.tmp.take() {
            // Removed before it leaves the list, so that a signal in between still finds it.
            let _ = tmp.close();
            unlist(&self.path);
        }
    }
}
