//! Reading a whole WKT or vertex-list input into memory, chunk by chunk, refusing at once what
//! cannot be text: the first NUL byte or invalid UTF-8 sequence stops the reading (so
//! `/dev/zero` or `/dev/urandom` fail after one chunk, in little memory), and so does an input
//! above [`MAX_TEXT`] bytes (an endless stream of valid text stops there). The same cap bounds
//! what one streamed GeoJSON feature or value, or one line of GeoJSON Lines, may hold before it
//! is parsed ([`too_large`] words the error; see `super::geojson_stream` and `crate::batch`).
//!
//! Complexity: linear in the bytes read; memory: the text read so far, plus one chunk.

use super::{not_text, ParseError};
use std::io::{self, BufRead, Read};

/// The largest WKT or vertex-list input read, in bytes (4 GiB), and the largest GeoJSON
/// feature, top-level value or line of GeoJSON Lines (GeoJSON is streamed, one feature at a
/// time, so the input as a whole is not bound).
pub const MAX_TEXT: u64 = 4 << 30;

/// Environment variable read by the `minitri` command (not by the library): a number of bytes
/// below [`MAX_TEXT`] taken as the cap instead, so that tests can reach it without writing
/// gigabytes. For tests only; a value that is not a number, or above the default, is ignored.
pub const LIMIT_FOR_TESTS: &str = "MINITRI_INPUT_LIMIT_FOR_TESTS";

/// The cap in force: [`MAX_TEXT`], or the smaller number `value` holds (the value of
/// [`LIMIT_FOR_TESTS`], when set).
///
/// # Examples
/// ```
/// use minitri::io::read::limits::{limit_from, MAX_TEXT};
/// assert_eq!(limit_from(None), MAX_TEXT);
/// assert_eq!(limit_from(Some("1000".as_ref())), 1000);
/// assert_eq!(limit_from(Some("lots".as_ref())), MAX_TEXT);
/// ```
pub fn limit_from(value: Option<&std::ffi::OsStr>) -> u64 {
    value
        .and_then(|v| v.to_str())
        .and_then(|v| v.trim().parse::<u64>().ok())
        .map_or(MAX_TEXT, |v| v.min(MAX_TEXT))
}

/// The message for a part of an input above `limit` bytes: `what` names the part (`one
/// GeoJSON feature`, ...), `byte` is the input's byte (from 1) at which reading stopped.
///
/// # Examples
/// ```
/// use minitri::io::read::limits::too_large;
/// assert_eq!(
///     too_large(1000, "one GeoJSON feature", 1234),
///     "too large: more than 1000 bytes in one GeoJSON feature (the most read before it is \
///      parsed); reading stopped at byte 1234 of the input"
/// );
/// ```
pub fn too_large(limit: u64, what: &str, byte: u64) -> String {
    format!(
        "too large: more than {limit} bytes in {what} (the most read before it is parsed); \
         reading stopped at byte {byte} of the input"
    )
}

/// The most vertices (positions) one polygon may hold while it is read, all its rings together
/// (2^25 = 33,554,432); in GeoJSON, one feature, all its polygons together (a MultiPolygon's, a
/// GeometryCollection's). A vertex takes 64 bytes as read (two exact decimals), and a ring's
/// storage grows by doubling, so one polygon holds at most 2 to 4 GiB; the largest real
/// boundaries have a few million vertices. The command's `--max-vertices` chooses another cap.
pub const MAX_VERTICES: usize = 1 << 25;

/// The message for a polygon (or feature: `what`) with more than `max` vertices.
///
/// # Examples
/// ```
/// use minitri::io::read::limits::too_many_vertices;
/// assert_eq!(
///     too_many_vertices(33_554_432, "one polygon"),
///     "too many vertices: more than 33,554,432 in one polygon (the most held while reading; \
///      --max-vertices raises it); the rest of it was read but not kept"
/// );
/// ```
pub fn too_many_vertices(max: usize, what: &str) -> String {
    format!(
        "too many vertices: more than {} in {what} (the most held while reading; \
         --max-vertices raises it); the rest of it was read but not kept",
        grouped(max as u64)
    )
}

/// `n` with its digits in groups of three (`33,554,432`).
///
/// # Examples
/// ```
/// use minitri::io::read::limits::grouped;
/// assert_eq!((grouped(0), grouped(999), grouped(1000), grouped(1234567)), ("0".into(), "999".into(), "1,000".into(), "1,234,567".into()));
/// ```
pub fn grouped(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::with_capacity(digits.len() + digits.len() / 3);
    for (k, c) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

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
/// (with its line and column), past `limit` bytes, or when memory for the text cannot be had.
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
pub fn read_text(reader: impl Read, limit: u64, expected: u64) -> Result<String, NotRead> {
    read_text_noted(reader, limit, expected, "")
}

/// [`read_text`], with `note` after the number of bytes in the message of an input above the
/// cap (` decompressed` for a gzip-compressed input, whose decompressed bytes count).
///
/// # Errors
/// As [`read_text`].
pub fn read_text_noted(
    mut reader: impl Read,
    limit: u64,
    expected: u64,
    note: &str,
) -> Result<String, NotRead> {
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
                "input too large: more than {limit} bytes{note} (the most read as WKT or a vertex list)"
            ))));
        }
        // A failed reservation is reported (the run goes on with the next input), not an abort.
        if bytes.try_reserve(got).is_err() {
            return Err(NotRead::Parse(ParseError::new(format!(
                "not enough memory to read the input: {} bytes read, no room for more",
                bytes.len()
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

/// The whole of `reader` as bytes (WKB, binary or hex), at most `limit` bytes, `expected`
/// bytes reserved at once; `note` as for [`read_text_noted`].
///
/// # Errors
/// [`NotRead::Io`] for a read error, [`NotRead::Parse`] past `limit` bytes or when memory
/// cannot be had.
///
/// # Examples
/// ```
/// use minitri::io::read::limits::{read_bytes, NotRead};
/// let Err(NotRead::Parse(e)) = read_bytes(std::io::repeat(1), 1000, 0, "") else { panic!() };
/// assert_eq!(e.to_string(), "input too large: more than 1000 bytes (the most read as WKB)");
/// assert_eq!(read_bytes(&[1u8, 2][..], 1000, 0, "").ok(), Some(vec![1, 2]));
/// ```
pub fn read_bytes(
    mut reader: impl Read,
    limit: u64,
    expected: u64,
    note: &str,
) -> Result<Vec<u8>, NotRead> {
    let mut bytes: Vec<u8> = Vec::new();
    let reserve = usize::try_from(expected.min(limit)).unwrap_or(0);
    let _ = bytes.try_reserve_exact(reserve.saturating_add(1));
    let mut chunk = vec![0; CHUNK];
    loop {
        let got = match reader.read(&mut chunk) {
            Ok(0) => return Ok(bytes),
            Ok(got) => got,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(NotRead::Io(e)),
        };
        if bytes.len() as u64 + got as u64 > limit {
            return Err(NotRead::Parse(ParseError::new(format!(
                "input too large: more than {limit} bytes{note} (the most read as WKB)"
            ))));
        }
        if bytes.try_reserve(got).is_err() {
            return Err(NotRead::Parse(ParseError::new(format!(
                "not enough memory to read the input: {} bytes read, no room for more",
                bytes.len()
            ))));
        }
        bytes.extend_from_slice(&chunk[..got]);
    }
}

/// What [`read_line`] read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LineRead {
    /// Bytes taken from the reader (0 at the end of the input).
    pub bytes: u64,
    /// The line went on past the cap: reading stopped after `bytes` bytes of it.
    pub too_long: bool,
    /// The line holds a NUL byte: reading stopped after the block of bytes holding it.
    pub binary: bool,
}

/// Reads one line of `reader` into `line` (emptied first), its end of line included, taking
/// at most `limit` bytes before the end of line. A line holding a NUL byte is read only up to
/// the block of bytes (of the reader's buffer) where the NUL appears: it cannot be text, and
/// its error needs no more (an endless line of `/dev/zero` stops there at once).
///
/// # Errors
/// An I/O error of `reader`.
///
/// # Examples
/// ```
/// use minitri::io::read::limits::{read_line, LineRead};
/// use std::io::{BufReader, Read};
/// let mut reader = BufReader::new("ab\ncd".as_bytes());
/// let mut line = Vec::new();
/// let read = read_line(&mut reader, &mut line, 10)?;
/// assert_eq!((read.bytes, read.too_long, read.binary), (3, false, false));
/// assert_eq!(line, b"ab\n");
/// read_line(&mut reader, &mut line, 10)?;
/// assert_eq!(line, b"cd");
/// assert_eq!(read_line(&mut reader, &mut line, 10)?.bytes, 0, "the end");
/// // An endless line stops at the cap, or at once when it is binary.
/// let mut spaces = BufReader::new(std::io::repeat(b' '));
/// let read = read_line(&mut spaces, &mut line, 100_000)?;
/// assert_eq!((read.bytes, read.too_long, line.len()), (100_000, true, 100_000));
/// let mut zeros = BufReader::new(std::io::repeat(0));
/// let read = read_line(&mut zeros, &mut line, 100_000)?;
/// assert!(read.binary && line.len() <= 8192, "{}", line.len());
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn read_line(
    reader: &mut impl BufRead,
    line: &mut Vec<u8>,
    limit: u64,
) -> io::Result<LineRead> {
    line.clear();
    let mut read = 0u64;
    loop {
        let block = match reader.fill_buf() {
            Ok(block) => block,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        let (take, ends) = match block.iter().position(|&b| b == b'\n') {
            Some(i) => (i + 1, true),
            None => (block.len(), block.is_empty()),
        };
        let content = (take - usize::from(ends && take > 0)) as u64;
        let (take, too_long) = if read + content > limit {
            (usize::try_from(limit - read).unwrap_or(take), true)
        } else {
            (take, false)
        };
        line.extend_from_slice(&block[..take]);
        let binary = block[..take].contains(&0);
        reader.consume(take);
        read += take as u64;
        if ends || too_long || binary {
            return Ok(LineRead {
                bytes: read,
                too_long,
                binary,
            });
        }
    }
}

/// The error for `bytes`, known not to be text, at the first byte at fault.
fn located(bytes: &[u8]) -> ParseError {
    not_text(bytes, true).unwrap_or_else(|| ParseError::new("not UTF-8 text"))
}
