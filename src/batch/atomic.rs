//! Output files written whole or not at all: a temporary file beside the target, renamed over
//! it once complete.
//!
//! Guarantee: the target path holds either its previous content (or nothing) or the complete new
//! output, never a truncated one, whatever happens to the process. A temporary file
//! `.NAME.minitri-PID-K.tmp` lives beside the target while it is written; it is removed when the
//! output is abandoned (an error, or [`AtomicFile`] dropped without [`AtomicFile::commit`]) and
//! on an interruption ([`exit_removing_temporaries`], which the binary calls on SIGINT, SIGTERM
//! and SIGHUP); only a process killed outright (SIGKILL, a crash) can leave one behind (a rename
//! is atomic on POSIX file systems), and the next write into the same directory removes it (a
//! temporary file of this form whose process is gone, [`remove_stale`]). The name is
//! shortened to fit 255 bytes (`NAME` cut at a character boundary). A target that exists and is
//! read-only is not replaced (an error: renaming over it would succeed on POSIX).
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
        if std::fs::metadata(target).is_ok_and(|m| m.permissions().readonly()) {
            return Err(io::Error::new(
                io::ErrorKind::PermissionDenied,
                "the file is read-only; not replaced",
            ));
        }
        remove_stale(dir);
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let k = NEXT.fetch_add(1, Ordering::Relaxed);
        let temp = dir.join(temporary_name(&name, std::process::id(), k));
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

/// The longest file name most file systems take, in bytes.
const NAME_MAX: usize = 255;

/// `.NAME.minitri-PID-K.tmp`, `NAME` shortened (at a character boundary) to fit [`NAME_MAX`].
fn temporary_name(name: &str, pid: u32, k: usize) -> String {
    let tail = format!(".minitri-{pid}-{k}.tmp");
    let room = NAME_MAX - 1 - tail.len();
    let mut cut = name.len().min(room);
    while !name.is_char_boundary(cut) {
        cut -= 1;
    }
    format!(".{}{tail}", &name[..cut])
}

/// The process that made a temporary file of this module's form, if the name is one.
fn temporary_owner(name: &str) -> Option<u32> {
    let rest = name.strip_prefix('.')?.strip_suffix(".tmp")?;
    let (_, numbers) = rest.rsplit_once(".minitri-")?;
    let (pid, k) = numbers.split_once('-')?;
    k.parse::<usize>().ok()?;
    pid.parse().ok()
}

/// Is process `pid` still running? (Linux: its `/proc` entry; elsewhere assumed running unless
/// the file is more than a day old, see [`remove_stale`].)
fn running(pid: u32) -> Option<bool> {
    if cfg!(target_os = "linux") {
        Some(Path::new("/proc").join(pid.to_string()).exists())
    } else {
        None
    }
}

/// Directories already cleaned by this process.
static CLEANED: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Removes, once per directory and process, the temporary files left in `dir` by a process
/// killed outright: names of the form `.NAME.minitri-PID-K.tmp` whose process is gone (on
/// Linux; elsewhere, those more than a day old). Errors are ignored: cleaning is a courtesy.
pub fn remove_stale(dir: &Path) {
    let key = std::path::absolute(dir).unwrap_or_else(|_| dir.to_path_buf());
    {
        let mut cleaned = CLEANED
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if cleaned.contains(&key) {
            return;
        }
        cleaned.push(key);
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let me = std::process::id();
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(pid) = name.to_str().and_then(temporary_owner) else {
            continue;
        };
        let stale = pid != me
            && match running(pid) {
                Some(alive) => !alive,
                None => entry
                    .metadata()
                    .and_then(|m| m.modified())
                    .is_ok_and(|t| t.elapsed().is_ok_and(|a| a.as_secs() > 86_400)),
            };
        if stale && entry.file_type().is_ok_and(|t| t.is_file()) {
            let _ = std::fs::remove_file(entry.path());
        }
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
    fn temporary_names_fit_255_bytes_and_are_recognised() {
        let long = "é".repeat(126) + ".json"; // 257 bytes
        let name = temporary_name(&long, 4_000_000, 12);
        assert!(name.len() <= 255, "{}", name.len());
        assert_eq!(temporary_owner(&name), Some(4_000_000));
        assert_eq!(temporary_owner(".a.json.minitri-12-3.tmp"), Some(12));
        assert_eq!(temporary_owner("a.json"), None);
        assert_eq!(temporary_owner(".a.minitri-x-3.tmp"), None);
    }

    #[test]
    fn a_read_only_target_is_not_replaced() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("ro.json");
        std::fs::write(&path, "old").unwrap();
        let mut perms = std::fs::metadata(&path).unwrap().permissions();
        perms.set_readonly(true);
        std::fs::set_permissions(&path, perms).unwrap();
        let e = write_atomically(&path, |out| out.write_all(b"new")).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::PermissionDenied);
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "old");
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
