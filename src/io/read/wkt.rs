//! Reader stub (being written).
use super::{ParseError, RawPolygon};

/// Reads every polygon in `text`.
///
/// # Errors
/// See [`super::read`].
pub fn read(_text: &str) -> Result<Vec<RawPolygon>, ParseError> {
    Err(ParseError::new("not implemented"))
}
