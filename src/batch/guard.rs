//! Guards against writing over what a run reads: an output that is an input (any spelling, a
//! link, standard input redirected from it), an output directory that is an input directory.
//!
//! Files are compared by device and inode number from their metadata (`stat`, which follows
//! links and never opens the file, so a FIFO is not blocked on); where the platform has no
//! inode numbers, by their canonical paths. Complexity: one `stat` per input.

use std::path::{Path, PathBuf};

/// The identity of an existing file: its device and inode numbers (following links), or where
/// the platform has none, its canonical path.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct FileId(#[cfg(unix)] (u64, u64), #[cfg(not(unix))] PathBuf);

/// The identity of the file `path` names, following links, if it exists.
pub fn file_id(path: &Path) -> Option<FileId> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        std::fs::metadata(path)
            .ok()
            .map(|m| FileId((m.dev(), m.ino())))
    }
    #[cfg(not(unix))]
    {
        std::fs::canonicalize(path).ok().map(FileId)
    }
}

/// The identity of a file from its metadata (an open descriptor's `fstat`).
#[cfg(unix)]
pub fn file_id_of(meta: &std::fs::Metadata) -> FileId {
    use std::os::unix::fs::MetadataExt;
    FileId((meta.dev(), meta.ino()))
}

/// The identity of a file from its device and inode numbers (a directory descriptor's
/// `fstatat`).
#[cfg(unix)]
pub(super) fn file_id_from(dev: u64, ino: u64) -> FileId {
    FileId((dev, ino))
}

/// Do `a` and `b` name the same existing file or directory?
pub fn same_file(a: &Path, b: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        match (std::fs::metadata(a), std::fs::metadata(b)) {
            (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
            _ => false,
        }
    }
    #[cfg(not(unix))]
    {
        match (std::fs::canonicalize(a), std::fs::canonicalize(b)) {
            (Ok(a), Ok(b)) => a == b,
            _ => false,
        }
    }
}

/// The first input that is `output` itself (`-` standing for standard input, when it is
/// redirected from a file: `/dev/stdin` is compared). Only an output that is a regular file or
/// a directory can be overwritten; a device or a FIFO is written into, never replaced.
pub fn input_that_is<'a>(inputs: &'a [PathBuf], output: &Path) -> Option<&'a Path> {
    if !std::fs::metadata(output).is_ok_and(|m| m.is_file() || m.is_dir()) {
        return None;
    }
    inputs.iter().map(PathBuf::as_path).find(|input| {
        if *input == Path::new("-") {
            cfg!(unix) && same_file(Path::new("/dev/stdin"), output)
        } else {
            same_file(input, output)
        }
    })
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    #[test]
    fn spellings_and_links_of_one_file_are_the_same() {
        let dir = tempfile::tempdir().unwrap();
        let a = dir.path().join("a.wkt");
        std::fs::write(&a, "x").unwrap();
        std::fs::create_dir(dir.path().join("d")).unwrap();
        let spelled = dir.path().join("d/../a.wkt");
        let link = dir.path().join("l.wkt");
        std::os::unix::fs::symlink(&a, &link).unwrap();
        assert!(same_file(&a, &spelled) && same_file(&a, &link));
        assert!(!same_file(&a, &dir.path().join("missing.wkt")));
        assert!(!same_file(&a, &dir.path().join("d")));
        let inputs = vec![PathBuf::from("-"), a.clone()];
        assert_eq!(input_that_is(&inputs, &link), Some(a.as_path()));
        assert_eq!(input_that_is(&inputs, &dir.path().join("b.json")), None);
    }
}
