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

    /// Flushes, syncs and renames the temporary file over the target.
    ///
    /// # Errors
    /// Any I/O error; the temporary file is then removed and the target left as it was.
    pub fn commit(mut self) -> io::Result<()> {
        let file = self.file.take().ok_or_else(closed)?;
        file.into_inner().map_err(|e| e.into_error())?.sync_all()?;
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
