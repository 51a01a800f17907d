//! Reading a whole WKT or vertex-list input into memory, chunk by chunk, refusing at once what
//! cannot be text: the first NUL byte or invalid UTF-8 sequence stops the reading (so
//! `/dev/zero` or `/dev/urandom` fail after one chunk, in little memory), and so does an input
//! above [`MAX_TEXT`] bytes (an endless stream of valid text stops there).
//!
//! Complexity: linear in the bytes read; memory: the text read so far, plus one chunk.

use super::{not_text, ParseError};
use std::io::{self, Read};

/// The largest WKT or vertex-list input read, in bytes (4 GiB; GeoJSON is streamed, one
/// polygon at a time, and is not bound by this).
pub const MAX_TEXT: u64 = 4 << 30;

/// Bytes read at a time.
const CHUNK: usize = 1 << 16;

/// Why an input could not be read as text.
#[derive(Debug)]
pub enum NotRead {
    /// The reader failed.
    Io(io::Error),
    /// Not text (a NUL byte, invalid UTF-8), or more than `limit` bytes.
    Parse(ParseError),
}

/// The whole of `reader` as text, at most `limit` bytes, `expected` bytes reserved at once
/// (the file's size, when known: growing by doubling would hold two copies at a time).
///
/// # Errors
/// [`NotRead::Io`] for a read error, [`NotRead::Parse`] at the first byte that cannot be text
/// (with its line and column) or past `limit` bytes.
///
/// # Examples
/// ```
/// use minitri::io::read::limits::{read_text, NotRead};
/// let zeros = std::io::repeat(0); // endless, like /dev/zero
/// let Err(NotRead::Parse(e)) = read_text(zeros, 1 << 30, 0) else { panic!() };
/// assert_eq!(e.to_string(), "line 1, column 1: binary data, not text (a NUL byte)");
/// let spaces = std::io::repeat(b' ');
/// let Err(NotRead::Parse(e)) = read_text(spaces, 1000, 0) else { panic!() };
/// assert!(e.to_string().contains("more than 1000 bytes"));
/// ```
pub fn read_text(mut reader: impl Read, limit: u64, expected: u64) -> Result<String, NotRead> {
    let mut bytes: Vec<u8> = Vec::new();
    let reserve = usize::try_from(expected.min(limit)).unwrap_or(0);
    let _ = bytes.try_reserve_exact(reserve.saturating_add(1));
    let mut checked = 0; // bytes[..checked] is UTF-8 without NUL
    let mut chunk = vec![0; CHUNK];
    loop {
        let got = match reader.read(&mut chunk) {
            Ok(0) => break,
            Ok(got) => got,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(NotRead::Io(e)),
        };
        if bytes.len() as u64 + got as u64 > limit {
            return Err(NotRead::Parse(ParseError::new(format!(
                "input too large: more than {limit} bytes (the most read as WKT or a vertex list)"
            ))));
        }
        bytes.extend_from_slice(&chunk[..got]);
        // Only the new bytes (and a character cut off at the previous chunk's end) are judged.
        let new = &bytes[checked..];
        let valid = match std::str::from_utf8(new) {
            Ok(_) => new.len(),
            Err(e) if e.error_len().is_none() => e.valid_up_to(),
            Err(_) => return Err(NotRead::Parse(located(&bytes))),
        };
        if new[..valid].contains(&0) {
            return Err(NotRead::Parse(located(&bytes)));
        }
        checked += valid;
    }
    if checked < bytes.len() {
        return Err(NotRead::Parse(located(&bytes)));
    }
    String::from_utf8(bytes).map_err(|e| NotRead::Io(io::Error::other(e)))
}

/// The error for `bytes`, known not to be text, at the first byte at fault.
fn located(bytes: &[u8]) -> ParseError {
    not_text(bytes, true).unwrap_or_else(|| ParseError::new("not UTF-8 text"))
}
