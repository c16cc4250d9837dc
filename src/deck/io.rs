//! Atomic deck saving: temporary file in the same directory, fsync, backup, rename.

use std::fs::{self, File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};

use super::error::DeckError;

/// Writes `text` to `path` so that a crash or a failure never leaves a truncated deck:
/// write `.<name>.tmp-<pid>` beside it, fsync, copy the previous file to `<name>.bak`,
/// then rename the temporary file over `path`. On any failure the temporary file is
/// removed and `path` is untouched.
pub(crate) fn save_atomic(path: &Path, text: &str) -> Result<(), DeckError> {
    let io_err = |path: PathBuf, action: &'static str| {
        move |source: std::io::Error| DeckError::Io {
            path,
            action,
            source,
        }
    };
    let file_name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .ok_or_else(|| {
            io_err(path.to_path_buf(), "cannot save")(std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                "path has no file name",
            ))
        })?;
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let tmp = dir.join(format!(".{file_name}.tmp-{}", std::process::id()));
    let write = || -> std::io::Result<()> {
        let mut f = OpenOptions::new()
            .write(true)
            .create(true)
            .truncate(true)
            .open(&tmp)?;
        f.write_all(text.as_bytes())?;
        f.sync_all()
    };
    if let Err(e) = write() {
        let _ = fs::remove_file(&tmp);
        return Err(io_err(tmp.clone(), "cannot write temporary file")(e));
    }
    if path.exists() {
        let bak = dir.join(format!("{file_name}.bak"));
        if let Err(e) = fs::copy(path, &bak) {
            let _ = fs::remove_file(&tmp);
            return Err(io_err(bak, "cannot keep the previous deck as backup")(e));
        }
    }
    if let Err(e) = fs::rename(&tmp, path) {
        let _ = fs::remove_file(&tmp);
        return Err(io_err(path.to_path_buf(), "cannot replace the deck")(e));
    }
    // Make the rename durable; best effort (not all platforms can fsync a directory).
    if let Ok(d) = File::open(&dir) {
        let _ = d.sync_all();
    }
    Ok(())
}
