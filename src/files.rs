//! Writing files so that a crash or a failure never leaves a truncated one: the one atomic
//! writer of the crate, used by the CLI (`run --output`) and the deck save.
//!
//! Both write `.<name>.tmp-<pid>` in the destination's directory, fsync it and rename it
//! over the destination; on any failure the temporary file is removed and the destination
//! is untouched. [`save_with_backup`] also keeps the previous file as `<name>.bak` and
//! fsyncs the directory after the rename.

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

/// Writes `bytes` to `path` atomically: temporary file in the same directory, fsync,
/// rename. On failure the temporary file is removed and `path` is untouched.
pub fn write_atomic(path: impl AsRef<Path>, bytes: impl AsRef<[u8]>) -> io::Result<()> {
    let path = path.as_ref();
    let tmp = TempFile::write(path, bytes.as_ref())?;
    tmp.rename_to(path)
}

/// Saves `text` to `path` atomically, keeping the previous file: write
/// `.<name>.tmp-<pid>` beside it, fsync, copy the previous file (if any) to `<name>.bak`,
/// rename the temporary file over `path`, then fsync the directory (best effort). On any
/// failure the temporary file is removed and `path` is untouched; the error names the
/// file concerned.
pub fn save_with_backup(path: &Path, text: &str) -> Result<(), FileError> {
    let err = |path: PathBuf, action: &'static str| {
        move |source: io::Error| FileError {
            path,
            action,
            source,
        }
    };
    let (dir, file_name) = split(path).map_err(err(path.to_path_buf(), "cannot save"))?;
    let tmp = TempFile::write(path, text.as_bytes()).map_err(err(
        temp_path(&dir, &file_name),
        "cannot write temporary file",
    ))?;
    if path.exists() {
        let bak = dir.join(format!("{file_name}.bak"));
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
    Ok(())
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
}
