//! gzip-compressed inputs, decompressed as they are read (`flate2`, every member of a
//! multi-member file in turn), recognised by their first two bytes whatever their name.
//!
//! The caps of [`super::limits`] apply to the decompressed bytes (what is held and parsed), so
//! a small file that decompresses to an endless stream (a "gzip bomb") stops at the cap with
//! the same message as an uncompressed input of that size. Errors of the compressed stream
//! (a corrupt or truncated file) are read errors saying so. Complexity: linear in the
//! decompressed size; memory: flate2's window and one buffer.

use std::io::{self, BufRead, Read};

/// Does an input starting with `start` hold gzip (its magic bytes `1f 8b`)?
///
/// # Examples
/// ```
/// use minitri::io::read::gzip::is_gzip;
/// assert!(is_gzip(&[0x1f, 0x8b, 8, 0]));
/// assert!(!is_gzip(b"POLYGON"));
/// ```
pub fn is_gzip(start: &[u8]) -> bool {
    start.starts_with(&[0x1f, 0x8b])
}

/// The decompressed bytes of a gzip stream.
pub struct Decompressed<R: BufRead> {
    decoder: flate2::bufread::MultiGzDecoder<R>,
}

/// Reads `reader`, known to hold gzip ([`is_gzip`]), decompressed.
///
/// # Examples
/// ```
/// use std::io::{Read, Write};
/// let mut packed = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
/// packed.write_all(b"POLYGON ((0 0, 1 0, 0 1))")?;
/// let packed = packed.finish()?;
/// let mut text = String::new();
/// minitri::io::read::gzip::decompress(&packed[..]).read_to_string(&mut text)?;
/// assert_eq!(text, "POLYGON ((0 0, 1 0, 0 1))");
/// // Cut short: an error saying what is wrong with it.
/// let error = minitri::io::read::gzip::decompress(&packed[..20]).read_to_end(&mut Vec::new());
/// assert!(error.unwrap_err().to_string().starts_with("not a valid gzip stream"));
/// # Ok::<(), std::io::Error>(())
/// ```
pub fn decompress<R: BufRead>(reader: R) -> Decompressed<R> {
    Decompressed {
        decoder: flate2::bufread::MultiGzDecoder::new(reader),
    }
}

impl<R: BufRead> Read for Decompressed<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        self.decoder.read(buf).map_err(|e| {
            if e.kind() == io::ErrorKind::Interrupted {
                return e;
            }
            let what = match e.kind() {
                io::ErrorKind::UnexpectedEof => {
                    "cut short, the compressed data ends too early".to_string()
                }
                _ => e.to_string(),
            };
            io::Error::new(e.kind(), format!("not a valid gzip stream: {what}"))
        })
    }
}
