//! Output files written whole or not at all: a temporary file beside the target, renamed over
//! it once complete.
//!
//! Guarantee: the target path holds either its previous content (or nothing) or the complete new
//! output, never a truncated one, whatever happens to the process. A temporary file
//! `.NAME.minitri-PID-HOST-RANDOM.tmp` lives beside the target while it is written; it is
//! removed when the output is abandoned (an error, or [`AtomicFile`] dropped without
//! [`AtomicFile::commit`]) and on an interruption ([`exit_removing_temporaries`], which the
//! binary calls on SIGINT, SIGTERM and SIGHUP); only a process killed outright (SIGKILL, a crash)
//! can leave one behind (a rename is atomic on POSIX file systems), and a later write into the
//! same directory removes it once it is proved stale ([`remove_stale`]). The name is shortened
//! to fit 255 bytes (`NAME` cut at a character boundary). A target that exists and is read-only
//! is not replaced (an error: renaming over it would succeed on POSIX).
//!
//! Every step is made through the output's directory held open ([`super::dir`]): the temporary
//! file is created there with `O_CREAT | O_EXCL | O_NOFOLLOW` (`openat`) under a name with a
//! random part (named by the `tempfile` crate), so that a link or a file planted at its path is
//! never written through and its name cannot be guessed in advance; the file it replaces is
//! looked at there (`fstatat`, not following a link); and it is renamed within that directory
//! (`renameat`) after checking that its name is still the file written. No path is resolved
//! again after it was checked, so a link swapped into the output's path meanwhile is never
//! followed. Its writer holds an exclusive lock on it (`flock`) until it is renamed or removed.
//! Replacing a file carries over its permission bits (and its owner and group where the process
//! may set them), as `install` and editors do: a 0600 output stays 0600. A new file gets 0666
//! less the umask, as `File::create`.
//!
//! Two exceptions: a target that is a device or a pipe (`/dev/stdout`, a FIFO) is written
//! directly, like standard output (there is no file to replace; renaming over it would replace
//! the device node); a target of [`AtomicFile::create`] (`-o FILE`) that is a symbolic link has
//! the file it points to replaced, the link itself stays, while below a batch's output directory
//! ([`AtomicFile::create_beneath`]) a link is refused.

use super::dir::{self, Dir, Entry, Kind, Linked};
use super::guard::FileId;
use std::ffi::{OsStr, OsString};
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, MutexGuard, OnceLock};
use std::time::Duration;

/// A temporary file of this process not yet renamed or removed: its directory (held open) and
/// its name there.
type Live = (Arc<Dir>, OsString);

/// The temporary files of this process not yet renamed or removed. Its lock is held across
/// every rename and removal, so [`exit_removing_temporaries`] sees each file either still
/// temporary or already complete under its final name.
static LIVE: Mutex<Vec<Live>> = Mutex::new(Vec::new());

fn live() -> MutexGuard<'static, Vec<Live>> {
    // A panic elsewhere while holding the lock leaves the list itself intact.
    LIVE.lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

fn forget(live: &mut Vec<Live>, dir: &Arc<Dir>, temp: &OsStr) {
    if let Some(k) = live
        .iter()
        .position(|(d, t)| Arc::ptr_eq(d, dir) && t == temp)
    {
        live.swap_remove(k);
    }
}

/// Removes every temporary file of this process and exits with `code`, without running any
/// further output: what an interruption (Ctrl-C) does, so that it leaves neither a truncated
/// output nor a temporary file. Outputs already committed stay, complete.
pub fn exit_removing_temporaries(code: i32) -> ! {
    let live = live(); // held until the exit: no rename can start after this point
    for (dir, temp) in live.iter() {
        let _ = dir.remove(temp);
    }
    std::process::exit(code)
}

/// Where a temporary file is, and the entry it is to replace, all in one directory held open.
#[derive(Debug)]
struct Place {
    dir: Arc<Dir>,
    /// The entry replaced.
    name: OsString,
    /// The temporary file; empty once renamed.
    temp: OsString,
}

/// An output file being written; it replaces its target only on [`AtomicFile::commit`].
#[derive(Debug)]
pub struct AtomicFile {
    target: PathBuf,
    /// `None` for a device or a pipe, written directly.
    place: Option<Place>,
    file: Option<BufWriter<File>>,
}

/// Random characters in a temporary file's name (62 possible each: about 60 bits).
const RANDOM_CHARS: usize = 10;

#[cfg(test)]
thread_local! {
    /// Called by [`AtomicFile::commit`] just before the rename (tests plant links there).
    static BEFORE_RENAME: std::cell::RefCell<Option<Box<dyn FnMut()>>> =
        const { std::cell::RefCell::new(None) };
}

impl AtomicFile {
    /// Starts writing `target` (its directory must exist), the path as the user gave it: its
    /// links are followed (a link as last component: the file it points to is replaced, the
    /// link stays).
    ///
    /// # Errors
    /// When the temporary file cannot be created (the message names the directory that
    /// refuses it), or its permissions cannot be set to the replaced file's.
    pub fn create(target: &Path) -> io::Result<AtomicFile> {
        // A device or a pipe (`/dev/stdout`, `/dev/null`, a FIFO) is written directly, as
        // standard output is: renaming a file over it would replace the device itself. (Opened
        // by path: `/dev/stdout` is a link the kernel resolves, not one that can be read.)
        if std::fs::metadata(target).is_ok_and(|m| !m.is_file() && !m.is_dir()) {
            let file = std::fs::OpenOptions::new().write(true).open(target)?;
            // Replaced by a regular file since: never written in place.
            if !file.metadata().is_ok_and(|m| m.is_file()) {
                return Ok(AtomicFile::direct(target, file));
            }
        }
        let Some(name) = target.file_name() else {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                "not the name of a file",
            ));
        };
        let parent = target.parent().unwrap_or(Path::new(""));
        let dir = Dir::open(parent).map_err(|e| refused(parent, &e))?;
        let (dir, name) = dir.follow(name.to_os_string())?;
        AtomicFile::place(dir, name, false)
    }

    /// Starts writing `relative` below the directory `root` (an output of a batch), creating
    /// the directories missing on the way, and following no link below `root` (`root` itself,
    /// the user's own path, is followed): a link on the way, the output itself included, is an
    /// error holding [`Linked`]; a directory that cannot be made, one holding
    /// [`dir::NotCreated`]. A FIFO, socket or device at the output's name is an error too (no
    /// one named it; a FIFO would be waited on). Every later step is made relative to the output's directory held
    /// open: no path is resolved again.
    ///
    /// # Errors
    /// As above, and as [`AtomicFile::create`].
    pub fn create_beneath(root: &Path, relative: &Path) -> io::Result<AtomicFile> {
        let (dir, name) = Dir::beneath(root, relative)?;
        AtomicFile::place(dir, name, true)
    }

    fn direct(target: &Path, file: File) -> AtomicFile {
        AtomicFile {
            target: target.to_path_buf(),
            place: None,
            file: Some(BufWriter::new(file)),
        }
    }

    /// Starts writing the entry `name` of `dir`; `no_link`: a link there is refused.
    fn place(dir: Dir, name: OsString, no_link: bool) -> io::Result<AtomicFile> {
        let target = dir.join(&name);
        let mut replaced = dir.entry(&name)?;
        match replaced.as_ref().map(|e| e.kind) {
            Some(Kind::Link) if no_link => {
                let to = dir.read_link(&name)?;
                let link = target.clone();
                let last = true;
                return Err(io::Error::other(Linked { link, to, last }));
            }
            // In a batch, a FIFO (or device) found in the output tree is not written into:
            // no one named it, and opening a FIFO waits for a reader, forever if none comes.
            Some(Kind::Other(what)) if no_link => {
                return Err(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    format!("it is {what}, not a regular file; not replaced (name it with -o to write into it)"),
                ));
            }
            Some(Kind::Other(_)) => {
                let file = dir.open_write(&name, false)?;
                if !file.metadata().is_ok_and(|m| m.is_file()) {
                    return Ok(AtomicFile::direct(&target, file));
                }
                replaced = dir.entry(&name)?; // a regular file since: replaced as one
            }
            _ => {}
        }
        let replaced: Option<Entry> = replaced.filter(|e| e.kind == Kind::File);
        if replaced.as_ref().is_some_and(|e| e.readonly) {
            return Err(io::Error::new(
                io::ErrorKind::PermissionDenied,
                "the file is read-only; not replaced",
            ));
        }
        remove_stale(&dir);
        let prefix = temporary_prefix(
            &name.to_string_lossy(),
            std::process::id(),
            host_namespace(),
        );
        let dir = Arc::new(dir);
        let (file, temp) = {
            let mut live = live();
            let made = tempfile::Builder::new()
                .prefix(&prefix)
                .suffix(".tmp")
                .rand_bytes(RANDOM_CHARS)
                .disable_cleanup(true)
                .make_in(dir.path(), |path| {
                    let temp = path.file_name().unwrap_or_default();
                    dir.create_new(temp).map(|file| (file, temp.to_os_string()))
                })
                .map_err(|e| refused(dir.path(), &e))?;
            let ((file, temp), _) = made.into_parts();
            live.push((Arc::clone(&dir), temp.clone()));
            (file, temp)
        };
        let mut atomic = AtomicFile {
            target,
            place: Some(Place { dir, name, temp }),
            file: None,
        };
        // Held until the file is renamed or removed: proof that it is not stale (a lock that is
        // not to be had, as on some network file systems, proves nothing either way).
        let _ = file.try_lock();
        if let Some(replaced) = &replaced {
            carry_over(&file, replaced).map_err(|e| atomic.named(e))?;
        }
        atomic.file = Some(BufWriter::new(file));
        Ok(atomic)
    }

    /// Is the target a device or a pipe, written directly (so nothing can be held back)?
    pub fn is_direct(&self) -> bool {
        self.place.is_none()
    }

    /// The file that [`AtomicFile::commit`] replaces: the target with the links of its last
    /// component resolved.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// The identity of the file [`AtomicFile::commit`] would replace now (looked at in the
    /// directory held open, not following a link: a link there is replaced, never followed),
    /// if there is one: what a caller compares with its inputs.
    pub fn replaced(&self) -> Option<FileId> {
        let place = self.place.as_ref()?;
        let entry = place.dir.entry(&place.name).ok()??;
        entry.id.filter(|_| entry.kind == Kind::File)
    }

    /// An error of the temporary file, naming it.
    fn named(&self, e: io::Error) -> io::Error {
        let Some(place) = &self.place else {
            return e;
        };
        let temp = place.dir.join(&place.temp);
        let temp = temp.display();
        io::Error::new(e.kind(), format!("{e} (temporary file {temp}, removed)"))
    }

    /// Flushes, syncs and renames the temporary file over the target, within the directory
    /// held open (`renameat`): the entry replaced is never followed if it is a link.
    ///
    /// # Errors
    /// Any I/O error (also the temporary file replaced meanwhile); the temporary file is then
    /// removed and the target left as it was.
    pub fn commit(mut self) -> io::Result<()> {
        let file = self.file.take().ok_or_else(closed)?;
        let file = file.into_inner().map_err(|e| self.named(e.into_error()))?;
        let Some(place) = &self.place else {
            return Ok(()); // a device or a pipe, written directly
        };
        file.sync_all().map_err(|e| self.named(e))?;
        #[cfg(test)]
        BEFORE_RENAME.with(|hook| {
            if let Some(hook) = hook.borrow_mut().as_mut() {
                hook();
            }
        });
        let mut live = live();
        // The temporary's name must still be this file (someone who can write the directory
        // could have put another there).
        let ours = dir::id_of(&file);
        let there = place
            .dir
            .entry(&place.temp)
            .ok()
            .flatten()
            .and_then(|e| e.id);
        if ours.is_some() && there != ours {
            let e = io::Error::other("the temporary file was replaced while it was written");
            return Err(self.named(e));
        }
        let (dir, temp) = (Arc::clone(&place.dir), place.temp.clone());
        dir.rename(&temp, &place.name).map_err(|e| self.named(e))?;
        forget(&mut live, &dir, &temp);
        if let Some(place) = &mut self.place {
            place.temp = OsString::new(); // nothing left to remove
        }
        Ok(())
    }
}

/// The error of a directory that refuses the temporary file.
fn refused(dir: &Path, e: &io::Error) -> io::Error {
    let dir = if dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        dir
    };
    let dir = dir.display();
    io::Error::new(
        e.kind(),
        format!("the directory {dir} refuses a new file ({e}): the output is written to a temporary file there first"),
    )
}

/// Gives the new file `file` the permissions (and, where permitted, the owner and group) of
/// `replaced`, the file it is to replace. The owner first: changing it may clear set-id bits.
fn carry_over(file: &File, replaced: &Entry) -> io::Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let (mode, uid, gid) = replaced.mode;
        // Refused unless the process may (root, or a group it belongs to): then the new file
        // keeps the writer's owner, as a file written anew would.
        let _ = std::os::unix::fs::fchown(file, Some(uid), Some(gid));
        file.set_permissions(std::fs::Permissions::from_mode(mode))
    }
    #[cfg(not(unix))]
    {
        file.set_permissions(replaced.permissions.clone())
    }
}

/// The longest file name most file systems take, in bytes.
const NAME_MAX: usize = 255;

/// `.NAME.minitri-PID-HOST-` (the random part and `.tmp` follow), `NAME` shortened (at a
/// character boundary) so that the whole name fits [`NAME_MAX`].
fn temporary_prefix(name: &str, pid: u32, host: &str) -> String {
    let tail = format!(".minitri-{pid}-{host}-");
    let room = NAME_MAX - 1 - tail.len() - RANDOM_CHARS - ".tmp".len();
    let mut cut = name.len().min(room);
    while !name.is_char_boundary(cut) {
        cut -= 1;
    }
    format!(".{}{tail}", &name[..cut])
}

/// Who made a temporary file of this module's form.
#[derive(Debug, PartialEq, Eq)]
struct Owner {
    pid: u32,
    /// Its host and process namespace ([`host_namespace`]), `None` for the older form
    /// `.NAME.minitri-PID-K.tmp`, which did not say.
    host: Option<String>,
}

/// The process that made a temporary file of this module's form, if the name is one.
fn temporary_owner(name: &str) -> Option<Owner> {
    let rest = name.strip_prefix('.')?.strip_suffix(".tmp")?;
    let (_, numbers) = rest.rsplit_once(".minitri-")?;
    let mut fields = numbers.split('-');
    let pid = fields.next()?.parse().ok()?;
    let (a, b, none) = (fields.next()?, fields.next(), fields.next());
    match (b, none) {
        (None, _) => {
            a.parse::<usize>().ok()?;
            Some(Owner { pid, host: None })
        }
        (Some(random), None) if random.chars().all(|c| c.is_ascii_alphanumeric()) => Some(Owner {
            pid,
            host: Some(a.to_string()),
        }),
        _ => None,
    }
}

/// Sixteen hex digits naming this machine's boot and this process's PID namespace (Linux:
/// `/proc/sys/kernel/random/boot_id` and `/proc/self/ns/pid`), or `x` where they cannot be
/// known: two processes with the same value see the same process IDs, so one can tell whether
/// the other is still running.
fn host_namespace() -> &'static str {
    static HOST: OnceLock<String> = OnceLock::new();
    HOST.get_or_init(|| {
        let boot = std::fs::read_to_string("/proc/sys/kernel/random/boot_id");
        let namespace = std::fs::read_link("/proc/self/ns/pid");
        match (boot, namespace) {
            (Ok(boot), Ok(namespace)) if cfg!(target_os = "linux") => {
                // FNV-1a, 64 bits: a fingerprint, not a secret.
                let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
                let text = format!("{}\n{}", boot.trim(), namespace.display());
                for byte in text.bytes() {
                    hash = (hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
                }
                format!("{hash:016x}")
            }
            _ => "x".to_string(),
        }
    })
}

/// Is process `pid` (of this PID namespace) running? Its `/proc` entry exists. Asked only when
/// [`host_namespace`] is known, that is when `/proc/self` is this process, so that `/proc` shows
/// this PID namespace.
fn running(pid: u32) -> bool {
    pid == 0 || Path::new("/proc").join(pid.to_string()).exists()
}

/// How old a temporary file of another host or process namespace (or of the older form) must
/// be before it may be removed, besides its lock being free: the lock proves that no process
/// holds the file open any more, the age that its maker is past creating it (and allows for
/// clocks of network file systems that differ by minutes).
pub const STALE_AGE: Duration = Duration::from_secs(3600);

/// Directories already cleaned by this process.
static CLEANED: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Removes, once per directory and process, the temporary files left in `dir` by a process
/// killed outright, those (and only those) that can be proved stale: a name of the form
/// `.NAME.minitri-PID-HOST-RANDOM.tmp`, a regular file (never a link), whose lock is free
/// (its writer holds it while it lives), and either made on this host and in this PID
/// namespace by a process that is gone, or older than [`STALE_AGE`] (another container or
/// machine sharing the directory, whose process IDs mean nothing here). Errors are ignored:
/// cleaning is a courtesy.
pub fn remove_stale(dir: &Dir) {
    let path = dir.path();
    let key = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    {
        let mut cleaned = CLEANED
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if cleaned.contains(&key) {
            return;
        }
        cleaned.push(key);
    }
    // Names only are read by path; every file is opened and removed through `dir`.
    let Ok(entries) = std::fs::read_dir(path) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(owner) = name.to_str().and_then(temporary_owner) else {
            continue;
        };
        if let Some(held) = stale(dir, &name, &owner) {
            let _ = dir.remove(&name);
            drop(held); // its lock held until it is removed
        }
    }
}

/// The temporary file `name` of `dir`, made by `owner`, open and locked, if it can be proved
/// stale (see [`remove_stale`]).
fn stale(dir: &Dir, name: &OsStr, owner: &Owner) -> Option<File> {
    let here = host_namespace();
    let ours = here != "x" && owner.host.as_deref() == Some(here);
    if ours && owner.pid == std::process::id() {
        return None; // this process's own
    }
    // Never through a link, never waiting on a FIFO; a regular file only.
    let file = dir.open_write(name, true).ok()?;
    let meta = file.metadata().ok().filter(std::fs::Metadata::is_file)?;
    let gone = ours && !running(owner.pid);
    let old = meta
        .modified()
        .is_ok_and(|t| t.elapsed().is_ok_and(|age| age > STALE_AGE));
    if !gone && !old {
        return None;
    }
    match file.try_lock() {
        Ok(()) => Some(file), // no process holds it
        Err(std::fs::TryLockError::WouldBlock) => None,
        // Locks not to be had here: the process gone is proof enough, age alone is not.
        Err(std::fs::TryLockError::Error(_)) => gone.then_some(file),
    }
}

fn closed() -> io::Error {
    io::Error::other("output file already closed")
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        let written = self.file.as_mut().ok_or_else(closed)?.write(buf);
        written.map_err(|e| self.named(e))
    }

    fn flush(&mut self) -> io::Result<()> {
        let flushed = self.file.as_mut().ok_or_else(closed)?.flush();
        flushed.map_err(|e| self.named(e))
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        drop(self.file.take());
        if let Some(place) = &self.place {
            if !place.temp.is_empty() {
                let mut live = live();
                let _ = place.dir.remove(&place.temp);
                forget(&mut live, &place.dir, &place.temp);
            }
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
        let host = "0123456789abcdef";
        let name = temporary_prefix(&long, 4_000_000, host) + "AbCdE12345.tmp";
        assert!(name.len() <= 255, "{}", name.len());
        let owner = temporary_owner(&name).unwrap();
        assert_eq!((owner.pid, owner.host.as_deref()), (4_000_000, Some(host)));
        // The older form, which did not name its host.
        let old = Owner {
            pid: 12,
            host: None,
        };
        assert_eq!(temporary_owner(".a.json.minitri-12-3.tmp"), Some(old));
        assert_eq!(temporary_owner("a.json"), None);
        assert_eq!(temporary_owner(".a.minitri-x-3.tmp"), None);
        assert_eq!(temporary_owner(".a.minitri-1-x-a.b.tmp"), None);
    }

    #[test]
    fn a_replaced_file_keeps_its_mode_and_a_new_one_gets_the_default() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("secret.json");
        std::fs::write(&path, "old").unwrap();
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o600)).unwrap();
        write_atomically(&path, |out| out.write_all(b"new")).unwrap();
        let mode = std::fs::metadata(&path).unwrap().permissions().mode() & 0o7777;
        assert_eq!(mode, 0o600);
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "new");
        // A new file: 0666 less the umask, like File::create (not tempfile's 0600).
        let plain = dir.path().join("plain");
        File::create(&plain).unwrap();
        let new = dir.path().join("new.json");
        write_atomically(&new, |out| out.write_all(b"x")).unwrap();
        let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o7777;
        assert_eq!(mode(&new), mode(&plain));
    }

    #[test]
    fn a_link_planted_at_a_temporary_path_is_never_followed() {
        let dir = tempfile::tempdir().unwrap();
        let victim = dir.path().join("victim");
        std::fs::write(&victim, "precious").unwrap();
        // Every name the old scheme would have used for this process's first outputs.
        for k in 0..4 {
            let name = format!(".out.json.minitri-{}-{k}.tmp", std::process::id());
            symlink(&victim, dir.path().join(name)).unwrap();
        }
        let out = dir.path().join("out.json");
        write_atomically(&out, |o| o.write_all(b"result")).unwrap();
        assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious");
        assert_eq!(std::fs::read_to_string(&out).unwrap(), "result");
        // create_new refuses a link, dangling or not.
        let planted = dir.path().join("planted");
        symlink(dir.path().join("nowhere"), &planted).unwrap();
        assert_eq!(
            Dir::open(dir.path())
                .unwrap()
                .create_new(OsStr::new("planted"))
                .unwrap_err()
                .kind(),
            io::ErrorKind::AlreadyExists
        );
        assert!(!dir.path().join("nowhere").exists());
    }

    #[test]
    fn only_provably_stale_temporaries_are_removed() {
        let dir = tempfile::tempdir().unwrap();
        let here = host_namespace();
        // A live writer of this namespace (this very process's parent, which runs): kept.
        let parent = std::os::unix::process::parent_id();
        let live = dir
            .path()
            .join(format!(".a.minitri-{parent}-{here}-aaaaaaaaaa.tmp"));
        // Another namespace or host, process ID meaningless here, new: kept.
        let elsewhere = dir
            .path()
            .join(".b.minitri-1-fedcba9876543210-bbbbbbbbbb.tmp");
        // This namespace, a process ID that cannot run (above the kernel's maximum): removed.
        let gone = dir
            .path()
            .join(format!(".c.minitri-2147483646-{here}-cccccccccc.tmp"));
        // The same but locked by a live writer (this process holds the lock): kept.
        let locked = dir
            .path()
            .join(format!(".d.minitri-2147483645-{here}-dddddddddd.tmp"));
        for path in [&live, &elsewhere, &gone, &locked] {
            std::fs::write(path, "x").unwrap();
        }
        let holder = File::open(&locked).unwrap();
        holder.try_lock().unwrap();
        remove_stale(&Dir::open(dir.path()).unwrap());
        assert!(live.exists() && elsewhere.exists() && locked.exists());
        if here != "x" {
            assert!(
                !gone.exists(),
                "a temporary of a process gone here is removed"
            );
        }
        drop(holder);
        // An old one of another namespace whose lock is free: removed.
        let other = tempfile::tempdir().unwrap();
        let old = other
            .path()
            .join(".e.minitri-1-fedcba9876543210-eeeeeeeeee.tmp");
        std::fs::write(&old, "x").unwrap();
        let long_ago = std::time::SystemTime::now() - STALE_AGE - Duration::from_secs(60);
        File::options()
            .write(true)
            .open(&old)
            .unwrap()
            .set_modified(long_ago)
            .unwrap();
        remove_stale(&Dir::open(other.path()).unwrap());
        assert!(!old.exists());
    }

    /// Runs `swap` between the writing of `file` and its rename (the test seam of
    /// [`AtomicFile::commit`]), then commits.
    fn commit_after(file: AtomicFile, swap: impl FnMut() + 'static) -> io::Result<()> {
        BEFORE_RENAME.with(|hook| *hook.borrow_mut() = Some(Box::new(swap)));
        let committed = file.commit();
        BEFORE_RENAME.with(|hook| *hook.borrow_mut() = None);
        committed
    }

    /// The names in `dir`, sorted.
    fn names(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn links_swapped_in_before_the_rename_are_never_followed() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path();
        let input = root.join("in");
        std::fs::create_dir(&input).unwrap();
        std::fs::write(input.join("a.json"), "precious").unwrap();
        let out = root.join("out");
        // A batch's output: its directory swapped for a link into the input tree, and the
        // output itself for a link to an input, after every check.
        let mut file = AtomicFile::create_beneath(&out, Path::new("sub/a.json")).unwrap();
        file.write_all(b"result").unwrap();
        let (o, i) = (out.clone(), input.clone());
        commit_after(file, move || {
            std::fs::rename(o.join("sub"), o.join("moved")).unwrap();
            symlink(&i, o.join("sub")).unwrap();
            symlink(i.join("a.json"), o.join("moved/a.json")).unwrap();
        })
        .unwrap();
        assert_eq!(names(&input), ["a.json"]);
        assert_eq!(
            std::fs::read_to_string(input.join("a.json")).unwrap(),
            "precious"
        );
        // The rename took place in the directory held open, over the link (not through it).
        let placed = out.join("moved/a.json");
        assert!(std::fs::symlink_metadata(&placed).unwrap().is_file());
        assert_eq!(std::fs::read_to_string(&placed).unwrap(), "result");
        // `-o FILE`: its directory swapped for a link, the same.
        let dir = root.join("d");
        std::fs::create_dir(&dir).unwrap();
        let mut file = AtomicFile::create(&dir.join("a.json")).unwrap();
        file.write_all(b"single").unwrap();
        let (r, i) = (root.to_path_buf(), input.clone());
        commit_after(file, move || {
            std::fs::rename(r.join("d"), r.join("d2")).unwrap();
            symlink(&i, r.join("d")).unwrap();
        })
        .unwrap();
        assert_eq!(
            std::fs::read_to_string(input.join("a.json")).unwrap(),
            "precious"
        );
        assert_eq!(
            std::fs::read_to_string(root.join("d2/a.json")).unwrap(),
            "single"
        );
        assert_eq!(names(&root.join("d2")), ["a.json"], "no temporary left");
    }

    #[test]
    fn a_temporary_replaced_while_written_is_not_renamed() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path().to_path_buf();
        std::fs::write(dir.join("victim"), "precious").unwrap();
        let mut file = AtomicFile::create(&dir.join("out.json")).unwrap();
        file.write_all(b"result").unwrap();
        let d = dir.clone();
        let e = commit_after(file, move || {
            let temp = names(&d).into_iter().find(|n| n.ends_with(".tmp")).unwrap();
            std::fs::remove_file(d.join(&temp)).unwrap();
            std::fs::hard_link(d.join("victim"), d.join(&temp)).unwrap();
        })
        .unwrap_err();
        assert!(
            e.to_string().starts_with(
                "the temporary file was replaced while it was written (temporary file "
            ),
            "{e}"
        );
        assert!(!dir.join("out.json").exists());
        assert_eq!(
            std::fs::read_to_string(dir.join("victim")).unwrap(),
            "precious"
        );
    }

    #[test]
    fn a_batch_output_that_is_a_link_is_refused() {
        let tmp = tempfile::tempdir().unwrap();
        let out = tmp.path().join("out");
        std::fs::create_dir(&out).unwrap();
        std::fs::write(tmp.path().join("victim"), "precious").unwrap();
        symlink("../victim", out.join("a.json")).unwrap();
        let e = AtomicFile::create_beneath(&out, Path::new("a.json")).unwrap_err();
        let linked = e
            .get_ref()
            .and_then(|e| e.downcast_ref::<Linked>())
            .unwrap();
        assert!(linked.last);
        assert_eq!(
            linked.to_string(),
            "is a symbolic link (to ../victim); links inside the output directory are not followed (remove the link)"
        );
        assert_eq!(names(&out), ["a.json"], "no temporary made");
        assert_eq!(
            std::fs::read_to_string(tmp.path().join("victim")).unwrap(),
            "precious"
        );
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
