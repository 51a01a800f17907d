//! Directories held open while an output is placed in them: every check and every change (the
//! temporary file created, the file it replaces looked at, the rename, a stale temporary
//! removed) is made relative to one directory descriptor, so that no path is resolved again
//! after it was checked (issue 34).
//!
//! Two ways to reach an output's directory:
//! - [`Dir::open`]: a path as the user gave it (`-o FILE`'s directory, `-o DIR` itself), links
//!   followed, as any program follows the paths it is given;
//! - [`Dir::beneath`]: a relative path below such a directory (an output of a batch), each
//!   component opened with `O_NOFOLLOW | O_DIRECTORY` (created with `mkdirat` when missing) and
//!   checked with `fstat`: a symbolic link anywhere below the output directory is refused
//!   ([`Linked`]), never followed, so that a linked subdirectory cannot lead outputs into the
//!   input tree (or anywhere else).
//!
//! Why `rustix`: it is already a dependency (batch/run.rs), and its safe wrappers are exactly the
//! system calls needed (`openat`, `mkdirat`, `fstatat`, `readlinkat`, `renameat`, `unlinkat`).
//! `cap-std` sandboxes whole paths beneath a directory (emulating link resolution, refusing
//! `..`), which is more than the rule here (no link at all below the output root) and not what
//! `-o FILE` wants (links followed), and would add about ten crates.
//!
//! Elsewhere than on Unix the same operations are made by path (no directory descriptors in the
//! standard library): links are still refused below the output root, but a link swapped in
//! while the run writes is not caught.

use super::guard::FileId;
use std::ffi::{OsStr, OsString};
use std::fs::File;
use std::io;
use std::path::{Component, Path, PathBuf};

/// A directory held open (on Unix, a descriptor), with the path it was reached by, for messages.
#[derive(Debug)]
pub struct Dir {
    #[cfg(unix)]
    fd: std::os::fd::OwnedFd,
    path: PathBuf,
}

/// What a directory entry is, not following a link.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    File,
    Dir,
    Link,
    /// A device, a FIFO, a socket: what it is (`a FIFO`).
    Other(&'static str),
}

/// A directory entry's type, identity and permissions, not following a link (`fstatat` with
/// `AT_SYMLINK_NOFOLLOW`).
#[derive(Clone, Debug)]
pub struct Entry {
    pub kind: Kind,
    pub id: Option<FileId>,
    /// No write permission for anyone.
    pub readonly: bool,
    /// Permission bits, owner and group.
    #[cfg(unix)]
    pub mode: (u32, u32, u32),
    #[cfg(not(unix))]
    pub permissions: std::fs::Permissions,
}

/// An output refused because a symbolic link lies on its way below the output directory.
#[derive(Debug)]
pub struct Linked {
    /// The link.
    pub link: PathBuf,
    /// What it points to.
    pub to: PathBuf,
    /// Is the link the output itself (not a directory on the way)?
    pub last: bool,
}

impl std::fmt::Display for Linked {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (link, to) = (self.link.display(), self.to.display());
        if self.last {
            write!(f, "is a symbolic link (to {to})")?;
        } else {
            write!(f, "is reached through the symbolic link {link} (to {to})")?;
        }
        write!(
            f,
            "; links inside the output directory are not followed (remove the link)"
        )
    }
}

impl std::error::Error for Linked {}

/// A directory of an output's path that could not be created.
#[derive(Debug)]
pub struct NotCreated {
    pub dir: PathBuf,
    pub error: io::Error,
}

impl std::fmt::Display for NotCreated {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "cannot create directory {}: {}",
            self.dir.display(),
            self.error
        )
    }
}

impl std::error::Error for NotCreated {}

fn wrap(e: impl std::error::Error + Send + Sync + 'static, kind: io::ErrorKind) -> io::Error {
    io::Error::new(kind, e)
}

/// The most links followed from `-o FILE` (as `SYMLOOP_MAX` on Linux).
const MAX_LINKS: usize = 40;

impl Dir {
    /// The path this directory was reached by.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// `dir/name`, for messages.
    pub fn join(&self, name: &OsStr) -> PathBuf {
        self.path.join(name)
    }

    /// Opens the directory `path` as given (links followed: the caller's own path).
    pub fn open(path: &Path) -> io::Result<Dir> {
        let shown = if path.as_os_str().is_empty() {
            Path::new(".")
        } else {
            path
        };
        #[cfg(unix)]
        {
            let fd = sys::open_dir(rustix::fs::CWD, shown, true)?;
            Ok(Dir {
                fd,
                path: shown.to_path_buf(),
            })
        }
        #[cfg(not(unix))]
        {
            if !std::fs::metadata(shown)?.is_dir() {
                return Err(io::Error::new(
                    io::ErrorKind::NotADirectory,
                    "not a directory",
                ));
            }
            Ok(Dir {
                path: shown.to_path_buf(),
            })
        }
    }

    /// The directory of `relative`'s last component below `root` (created, with `root`, where
    /// missing), and that last component. No link below `root` is followed: one on the way is
    /// an error holding [`Linked`] (`root` itself is the caller's own path, links followed). A
    /// directory that cannot be created is an error holding [`NotCreated`].
    pub fn beneath(root: &Path, relative: &Path) -> io::Result<(Dir, OsString)> {
        let mut parts = Vec::new();
        for component in relative.components() {
            match component {
                Component::Normal(part) => parts.push(part),
                Component::CurDir => {}
                _ => {
                    return Err(io::Error::new(
                        io::ErrorKind::InvalidInput,
                        format!(
                            "{} is not a path below the output directory",
                            relative.display()
                        ),
                    ))
                }
            }
        }
        let Some(name) = parts.pop() else {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                "no file name below the output directory",
            ));
        };
        if !root.as_os_str().is_empty() {
            std::fs::create_dir_all(root).map_err(|error| {
                let dir = root.to_path_buf();
                wrap(NotCreated { dir, error }, io::ErrorKind::Other)
            })?;
        }
        let mut dir = Dir::open(root)?;
        for part in parts {
            dir = dir.child(part)?;
        }
        Ok((dir, name.to_os_string()))
    }

    /// The subdirectory `name` (one component), created when missing, never through a link.
    fn child(&self, name: &OsStr) -> io::Result<Dir> {
        let path = self.join(name);
        let refused = |dir: &Dir| match dir.read_link(name) {
            Ok(to) => wrap(
                Linked {
                    link: path.clone(),
                    to,
                    last: false,
                },
                io::ErrorKind::Other,
            ),
            Err(_) => io::Error::new(
                io::ErrorKind::NotADirectory,
                format!("{} is not a directory", path.display()),
            ),
        };
        for _ in 0..2 {
            match self.entry(name)? {
                None => match self.make_dir(name) {
                    Ok(()) => {}
                    Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {} // made meanwhile
                    Err(error) => {
                        let dir = path.clone();
                        return Err(wrap(NotCreated { dir, error }, io::ErrorKind::Other));
                    }
                },
                Some(entry) if entry.kind == Kind::Dir => {}
                Some(_) => return Err(refused(self)),
            }
            #[cfg(unix)]
            match sys::open_dir(&self.fd, Path::new(name), false) {
                Ok(fd) => return Ok(Dir { fd, path }),
                // Replaced meanwhile (by a link, a file; or removed): looked at again.
                Err(e) if e.kind() == io::ErrorKind::NotFound => continue,
                Err(_) => return Err(refused(self)),
            }
            #[cfg(not(unix))]
            return Ok(Dir { path });
        }
        Err(refused(self))
    }

    /// Makes the subdirectory `name` (mode 0777 less the umask, as `create_dir`).
    fn make_dir(&self, name: &OsStr) -> io::Result<()> {
        #[cfg(unix)]
        {
            use rustix::fs::Mode;
            Ok(rustix::fs::mkdirat(
                &self.fd,
                name,
                Mode::from_raw_mode(0o777),
            )?)
        }
        #[cfg(not(unix))]
        std::fs::create_dir(self.join(name))
    }

    /// The entry `name`, not following a link; `None` when there is none.
    pub fn entry(&self, name: &OsStr) -> io::Result<Option<Entry>> {
        #[cfg(unix)]
        {
            match rustix::fs::statat(&self.fd, name, rustix::fs::AtFlags::SYMLINK_NOFOLLOW) {
                Ok(stat) => Ok(Some(sys::entry(&stat))),
                Err(rustix::io::Errno::NOENT) => Ok(None),
                Err(e) => Err(e.into()),
            }
        }
        #[cfg(not(unix))]
        {
            let path = self.join(name);
            let meta = match std::fs::symlink_metadata(&path) {
                Ok(meta) => meta,
                Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(None),
                Err(e) => return Err(e),
            };
            let kind = match meta.file_type() {
                t if t.is_symlink() => Kind::Link,
                t if t.is_dir() => Kind::Dir,
                t if t.is_file() => Kind::File,
                _ => Kind::Other("a special file"),
            };
            Ok(Some(Entry {
                kind,
                id: (kind != Kind::Link)
                    .then(|| super::guard::file_id(&path))
                    .flatten(),
                readonly: meta.permissions().readonly(),
                permissions: meta.permissions(),
            }))
        }
    }

    /// Where the link `name` points.
    pub fn read_link(&self, name: &OsStr) -> io::Result<PathBuf> {
        #[cfg(unix)]
        {
            use std::os::unix::ffi::OsStringExt;
            let target = rustix::fs::readlinkat(&self.fd, name, Vec::new())?;
            Ok(PathBuf::from(OsString::from_vec(target.into_bytes())))
        }
        #[cfg(not(unix))]
        std::fs::read_link(self.join(name))
    }

    /// Follows the link `name` of this directory (and the links it leads to, at most
    /// [`MAX_LINKS`]) to the directory and name of the entry that is no link (or none): what a
    /// write to `-o FILE` replaces when `FILE` is a link (links followed, the user's own path).
    pub fn follow(self, name: OsString) -> io::Result<(Dir, OsString)> {
        let (mut dir, mut name) = (self, name);
        for _ in 0..MAX_LINKS {
            if !dir.entry(&name)?.is_some_and(|e| e.kind == Kind::Link) {
                return Ok((dir, name));
            }
            let to = dir.read_link(&name)?;
            let Some(last) = to.file_name() else {
                let shown = dir.join(&name).display().to_string();
                return Err(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    format!("{shown} is a link to a directory ({})", to.display()),
                ));
            };
            let parent = to.parent().unwrap_or(Path::new(""));
            let next = dir.path.join(parent);
            #[cfg(unix)]
            let next = Dir {
                fd: if parent.as_os_str().is_empty() {
                    rustix::io::dup(&dir.fd)?
                } else {
                    sys::open_dir(&dir.fd, parent, true)?
                },
                path: next,
            };
            #[cfg(not(unix))]
            let next = Dir { path: next };
            (dir, name) = (next, last.to_os_string());
        }
        Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "too many levels of symbolic links",
        ))
    }

    /// Creates the file `name`, new, never through a link or over an entry already there
    /// (`O_CREAT | O_EXCL | O_NOFOLLOW`), mode 0666 less the umask (as `File::create`).
    pub fn create_new(&self, name: &OsStr) -> io::Result<File> {
        #[cfg(unix)]
        {
            use rustix::fs::{Mode, OFlags};
            let flags =
                OFlags::WRONLY | OFlags::CREATE | OFlags::EXCL | OFlags::NOFOLLOW | OFlags::CLOEXEC;
            let fd = rustix::fs::openat(&self.fd, name, flags, Mode::from_raw_mode(0o666))?;
            Ok(File::from(fd))
        }
        #[cfg(not(unix))]
        std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(self.join(name))
    }

    /// Opens the existing entry `name` for writing, never through a link, without truncating it
    /// (a device or a FIFO written directly; `nonblocking` for one that must not be waited on).
    pub fn open_write(&self, name: &OsStr, nonblocking: bool) -> io::Result<File> {
        #[cfg(unix)]
        {
            use rustix::fs::{Mode, OFlags};
            let mut flags = OFlags::WRONLY | OFlags::NOFOLLOW | OFlags::CLOEXEC;
            if nonblocking {
                flags |= OFlags::NONBLOCK;
            }
            let fd = rustix::fs::openat(&self.fd, name, flags, Mode::empty())?;
            Ok(File::from(fd))
        }
        #[cfg(not(unix))]
        {
            let _ = nonblocking;
            std::fs::OpenOptions::new()
                .write(true)
                .open(self.join(name))
        }
    }

    /// Renames the entry `from` to `to`, both in this directory (replacing `to`'s entry, never
    /// following it).
    pub fn rename(&self, from: &OsStr, to: &OsStr) -> io::Result<()> {
        #[cfg(unix)]
        {
            Ok(rustix::fs::renameat(&self.fd, from, &self.fd, to)?)
        }
        #[cfg(not(unix))]
        std::fs::rename(self.join(from), self.join(to))
    }

    /// Removes the file (or link) `name`.
    pub fn remove(&self, name: &OsStr) -> io::Result<()> {
        #[cfg(unix)]
        {
            Ok(rustix::fs::unlinkat(
                &self.fd,
                name,
                rustix::fs::AtFlags::empty(),
            )?)
        }
        #[cfg(not(unix))]
        std::fs::remove_file(self.join(name))
    }
}

/// The identity of an open file (`fstat`).
pub fn id_of(file: &File) -> Option<FileId> {
    #[cfg(unix)]
    {
        file.metadata().ok().map(|m| super::guard::file_id_of(&m))
    }
    #[cfg(not(unix))]
    {
        let _ = file;
        None
    }
}

#[cfg(unix)]
mod sys {
    use super::{Entry, Kind};
    use rustix::fs::{FileType, Mode, OFlags, Stat};
    use std::os::fd::{AsFd, OwnedFd};
    use std::path::Path;

    /// Opens the directory `path` relative to `at`: `follow` or not a link as last component
    /// (`O_NOFOLLOW`), and checked to be a directory (`fstat`). Linux opens it `O_PATH`: no read
    /// permission needed on it (a directory of mode 0300 takes outputs).
    pub fn open_dir(at: impl AsFd, path: &Path, follow: bool) -> std::io::Result<OwnedFd> {
        let mut flags = OFlags::DIRECTORY | OFlags::CLOEXEC;
        #[cfg(any(target_os = "linux", target_os = "android"))]
        {
            flags |= OFlags::PATH;
        }
        #[cfg(not(any(target_os = "linux", target_os = "android")))]
        {
            flags |= OFlags::RDONLY;
        }
        if !follow {
            flags |= OFlags::NOFOLLOW;
        }
        let fd = rustix::fs::openat(at, path, flags, Mode::empty())?;
        // With O_PATH | O_NOFOLLOW, Linux may hand out the link itself: only a directory passes.
        let stat = rustix::fs::fstat(&fd)?;
        if FileType::from_raw_mode(stat.st_mode) != FileType::Directory {
            return Err(std::io::Error::new(
                std::io::ErrorKind::NotADirectory,
                "not a directory",
            ));
        }
        Ok(fd)
    }

    /// The entry of a `stat`.
    #[allow(clippy::unnecessary_cast, clippy::useless_conversion)] // the types differ by platform
    pub fn entry(stat: &Stat) -> Entry {
        let kind = match FileType::from_raw_mode(stat.st_mode) {
            FileType::RegularFile => Kind::File,
            FileType::Directory => Kind::Dir,
            FileType::Symlink => Kind::Link,
            FileType::Fifo => Kind::Other("a FIFO"),
            FileType::Socket => Kind::Other("a socket"),
            _ => Kind::Other("a device"),
        };
        let mode = stat.st_mode as u32;
        Entry {
            kind,
            id: (kind != Kind::Link)
                .then(|| super::super::guard::file_id_from(stat.st_dev as u64, stat.st_ino as u64)),
            readonly: mode & 0o222 == 0,
            mode: (mode & 0o7777, stat.st_uid as u32, stat.st_gid as u32),
        }
    }
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;
    use std::os::unix::fs::symlink;

    #[test]
    fn beneath_creates_directories_and_refuses_every_link() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path().join("out");
        let elsewhere = tmp.path().join("elsewhere");
        std::fs::create_dir(&elsewhere).unwrap();
        let (dir, name) = Dir::beneath(&root, Path::new("a/b/c.json")).unwrap();
        assert_eq!(name, "c.json");
        assert_eq!(dir.path(), root.join("a/b"));
        assert!(root.join("a/b").is_dir());
        // A link as a directory on the way, at every depth: refused, nothing made through it.
        symlink(&elsewhere, root.join("l")).unwrap();
        symlink(&elsewhere, root.join("a/l")).unwrap();
        for relative in ["l/x.json", "a/l/x.json", "l/new/x.json"] {
            let e = Dir::beneath(&root, Path::new(relative)).unwrap_err();
            let linked = e.get_ref().and_then(|e| e.downcast_ref::<Linked>());
            assert!(linked.is_some_and(|l| !l.last), "{relative}: {e}");
        }
        assert_eq!(std::fs::read_dir(&elsewhere).unwrap().count(), 0);
        // The root itself may be a link (the user's own path).
        let linked_root = tmp.path().join("root-link");
        symlink(&root, &linked_root).unwrap();
        assert!(Dir::beneath(&linked_root, Path::new("a/y.json")).is_ok());
        // A file on the way is no directory.
        std::fs::write(root.join("f"), "x").unwrap();
        let e = Dir::beneath(&root, Path::new("f/x.json")).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::NotADirectory, "{e}");
        assert!(Dir::beneath(&root, Path::new("../x.json")).is_err());
    }
}
