//! Output files written whole or not at all: a temporary file beside the target, renamed over
//! it once complete.
//!
//! Guarantee: the target path holds either its previous content (or nothing) or the complete new
//! output, never a truncated one, whatever happens to the process. A temporary file
//! `.NAME.minitri-PID-K.tmp` lives beside the target while it is written; it is removed when the
//! output is abandoned (an error, or [`AtomicFile`] dropped without [`AtomicFile::commit`]) and
//! on an interruption ([`exit_removing_temporaries`], which the binary calls on Ctrl-C); only a
//! process killed outright (SIGKILL, a crash) can leave one behind (a rename is atomic on POSIX
//! file systems).
//!
//! Two exceptions: a target that is a device or a pipe (`/dev/stdout`, a FIFO) is written
//! directly, like standard output (there is no file to replace; renaming over it would replace
//! the device node); a target that is a symbolic link has the file it points to replaced, the
//! link itself stays.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, MutexGuard};

/// Distinguishes the temporary files of one process.
static NEXT: AtomicUsize = AtomicUsize::new(0);

/// The temporary files of this process not yet renamed or removed. Its lock is held across
/// every rename and removal, so [`exit_removing_temporaries`] sees each file either still
/// temporary or already complete under its final name.
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn live() -> MutexGuard<'static, Vec<PathBuf>> {
    // A panic elsewhere while holding the lock leaves the list itself intact.
    LIVE.lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

fn forget(live: &mut Vec<PathBuf>, temp: &Path) {
    if let Some(k) = live.iter().position(|p| p == temp) {
        live.swap_remove(k);
    }
}

/// Removes every temporary file of this process and exits with `code`, without running any
/// further output: what an interruption (Ctrl-C) does, so that it leaves neither a truncated
/// output nor a temporary file. Outputs already committed stay, complete.
pub fn exit_removing_temporaries(code: i32) -> ! {
    let live = live(); // held until the exit: no rename can start after this point
    for temp in live.iter() {
        let _ = std::fs::remove_file(temp);
    }
    std::process::exit(code)
}

/// An output file being written; it replaces its target only on [`AtomicFile::commit`].
#[derive(Debug)]
pub struct AtomicFile {
    target: PathBuf,
    temp: PathBuf,
    file: Option<BufWriter<File>>,
}

impl AtomicFile {
    /// Starts writing `target` (its directory must exist).
    ///
    /// # Errors
    /// When the temporary file cannot be created.
    pub fn create(target: &Path) -> io::Result<AtomicFile> {
        // A device or a pipe (`/dev/stdout`, `/dev/null`, a FIFO) is written directly, as
        // standard output is: renaming a file over it would replace the device itself.
        if std::fs::metadata(target).is_ok_and(|m| !m.is_file() && !m.is_dir()) {
            let file = std::fs::OpenOptions::new().write(true).open(target)?;
            return Ok(AtomicFile {
                target: target.to_path_buf(),
                temp: PathBuf::new(),
                file: Some(BufWriter::new(file)),
            });
        }
        // A symbolic link: the file it points to is replaced, and the link stays.
        let resolved;
        let target = if std::fs::symlink_metadata(target).is_ok_and(|m| m.is_symlink()) {
            // (A dangling link: the file it names, relative to the link's directory.)
            resolved = std::fs::canonicalize(target).or_else(|_| {
                let named = std::fs::read_link(target)?;
                Ok::<_, io::Error>(target.parent().unwrap_or(Path::new("")).join(named))
            })?;
            resolved.as_path()
        } else {
            target
        };
        let dir = target
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let k = NEXT.fetch_add(1, Ordering::Relaxed);
        let temp = dir.join(format!(".{name}.minitri-{}-{k}.tmp", std::process::id()));
        let file = {
            let mut live = live();
            let file = File::create(&temp)?;
            live.push(temp.clone());
            file
        };
        Ok(AtomicFile {
            target: target.to_path_buf(),
            temp,
            file: Some(BufWriter::new(file)),
        })
    }

    /// Is the target a device or a pipe, written directly (so nothing can be held back)?
    pub fn is_direct(&self) -> bool {
        self.temp.as_os_str().is_empty()
    }

    /// Flushes, syncs and renames the temporary file over the target.
    ///
    /// # Errors
    /// Any I/O error; the temporary file is then removed and the target left as it was.
    pub fn commit(mut self) -> io::Result<()> {
        let file = self.file.take().ok_or_else(closed)?;
        let file = file.into_inner().map_err(|e| e.into_error())?;
        if self.is_direct() {
            return Ok(()); // a device or a pipe, written directly
        }
        file.sync_all()?;
        let mut live = live();
        std::fs::rename(&self.temp, &self.target)?;
        forget(&mut live, &self.temp);
        self.temp = PathBuf::new(); // nothing left to remove
        Ok(())
    }
}

fn closed() -> io::Error {
    io::Error::other("output file already closed")
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.file.as_mut().ok_or_else(closed)?.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.file.as_mut().ok_or_else(closed)?.flush()
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        drop(self.file.take());
        if !self.temp.as_os_str().is_empty() {
            let mut live = live();
            let _ = std::fs::remove_file(&self.temp);
            forget(&mut live, &self.temp);
        }
    }
}

/// Writes `path` atomically: `body` writes the content, then the file replaces `path`.
///
/// # Errors
/// Any I/O error, of `body` or of the file system; `path` is then left as it was.
///
/// # Examples
/// ```
/// use std::io::Write;
/// let dir = tempfile::tempdir()?;
/// let path = dir.path().join("out.txt");
/// minitri::batch::write_atomically(&path, |out| out.write_all(b"whole"))?;
/// assert_eq!(std::fs::read_to_string(&path)?, "whole");
/// let failed = minitri::batch::write_atomically(&path, |_| Err(std::io::Error::other("no")));
/// assert!(failed.is_err());
/// assert_eq!(std::fs::read_to_string(&path)?, "whole", "left as it was");
/// assert_eq!(std::fs::read_dir(dir.path())?.count(), 1, "no temporary file left");
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn write_atomically(
    path: &Path,
    body: impl FnOnce(&mut AtomicFile) -> io::Result<()>,
) -> io::Result<()> {
    let mut file = AtomicFile::create(path)?;
    body(&mut file)?;
    file.commit()
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;
    use std::os::unix::fs::{symlink, FileTypeExt};

    #[test]
    fn a_link_keeps_pointing_to_the_replaced_file() {
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("real.json");
        let link = dir.path().join("link.json");
        std::fs::write(&real, "old").unwrap();
        symlink("real.json", &link).unwrap();
        write_atomically(&link, |out| out.write_all(b"new")).unwrap();
        assert!(std::fs::symlink_metadata(&link).unwrap().is_symlink());
        assert_eq!(std::fs::read_to_string(&real).unwrap(), "new");
        // A dangling link: the file it names is created.
        let dangling = dir.path().join("dangling.json");
        symlink("made.json", &dangling).unwrap();
        write_atomically(&dangling, |out| out.write_all(b"made")).unwrap();
        assert!(std::fs::symlink_metadata(&dangling).unwrap().is_symlink());
        assert_eq!(
            std::fs::read_to_string(dir.path().join("made.json")).unwrap(),
            "made"
        );
        assert_eq!(
            std::fs::read_dir(dir.path()).unwrap().count(),
            4,
            "no temporary file"
        );
    }

    #[test]
    fn a_device_is_written_directly_and_stays_a_device() {
        let null = Path::new("/dev/null");
        if !std::fs::metadata(null).is_ok_and(|m| m.file_type().is_char_device()) {
            return; // no /dev/null here: nothing to check
        }
        let mut file = AtomicFile::create(null).unwrap();
        assert!(file.is_direct());
        file.write_all(b"discarded").unwrap();
        file.commit().unwrap();
        assert!(std::fs::metadata(null)
            .unwrap()
            .file_type()
            .is_char_device());
    }
}
