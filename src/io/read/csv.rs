//! Delimited text with a WKT geometry column: what `--to csv` writes, and what GDAL's CSV driver
//! and QGIS read, read back.
//!
//! Input contract: RFC 4180 CSV (comma-separated, fields in double quotes when they hold a
//! comma, a quote or a line break, quotes doubled inside; CRLF or LF), a header row first with
//! a column named `WKT` (any case). Output guarantee: the polygons of each row's WKT, in row
//! order, numbered on over the rows, as [`super::wkt`] reads them; an empty field (a failure
//! of an input as a whole, in minitri's CSV) and a geometry that is EMPTY are skipped. A row
//! whose WKT is not a polygon geometry is an error at its line, and the other rows go on.
//! Complexity: linear in the input.

use super::{wkt, ParseError, RawPolygon};

/// Is `line` a CSV header with a column named `WKT`? (Any case, the name optionally quoted;
/// at least one comma.)
///
/// # Examples
/// ```
/// use minitri::io::read::csv::is_wkt_header;
/// assert!(is_wkt_header("WKT,source,feature"));
/// assert!(is_wkt_header("id,\"wkt\""));
/// assert!(!is_wkt_header("x,y") && !is_wkt_header("WKT"));
/// ```
pub fn is_wkt_header(line: &str) -> bool {
    line.contains(',') && line.split(',').any(is_wkt_name)
}

/// Is `field` the name `WKT` (any case, blanks and quotes around it allowed)?
fn is_wkt_name(field: &str) -> bool {
    field
        .trim()
        .trim_matches('"')
        .trim()
        .eq_ignore_ascii_case("WKT")
}

/// The records of `text`: each with the line (from 1) it starts on.
fn records(text: &str) -> Result<Vec<(usize, Vec<String>)>, ParseError> {
    let mut records = Vec::new();
    let (mut record, mut field) = (Vec::new(), String::new());
    let (mut line, mut start) = (1, 1);
    let mut quoted = false;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match (quoted, c) {
            (true, '"') if chars.peek() == Some(&'"') => {
                chars.next();
                field.push('"');
            }
            (true, '"') => quoted = false,
            (true, c) => {
                if c == '\n' {
                    line += 1;
                }
                field.push(c);
            }
            (false, '"') if field.is_empty() => quoted = true,
            (false, ',') => record.push(std::mem::take(&mut field)),
            (false, '\r') if chars.peek() == Some(&'\n') => {}
            (false, '\n') => {
                record.push(std::mem::take(&mut field));
                records.push((start, std::mem::take(&mut record)));
                line += 1;
                start = line;
            }
            (false, c) => field.push(c),
        }
    }
    if quoted {
        return Err(ParseError::new(format!(
            "line {start}: a quoted field is not closed before the end of the input"
        )));
    }
    if !field.is_empty() || !record.is_empty() {
        record.push(field);
        records.push((start, record));
    }
    Ok(records)
}

/// Every part of a CSV input with a `WKT` column, in row order (see the module documentation);
/// `max_vertices` caps one polygon, as for WKT. Errors of a row are named by its line:
/// `line 3: WKT: ...` (the position after it is within the field).
///
/// # Errors
/// No header with a `WKT` column, a quoted field left open, an input with no polygon.
///
/// # Examples
/// ```
/// use minitri::io::read::csv::read_parts_within;
/// let text = "WKT,id\r\n\"GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1, 0 0)))\",a\r\n\
///             GEOMETRYCOLLECTION EMPTY,b\r\n,c\r\nPOINT (1 2),d\r\n";
/// let parts = read_parts_within(text, 1000)?;
/// assert_eq!(parts.len(), 2);
/// assert_eq!(parts[0].as_ref().map(|p| p.rings[0].len()), Ok(3));
/// assert_eq!(
///     parts[1].as_ref().unwrap_err().to_string(),
///     "line 5: WKT: line 1, column 1: expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found POINT"
/// );
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_parts_within(
    text: &str,
    max_vertices: usize,
) -> Result<Vec<Result<RawPolygon, ParseError>>, ParseError> {
    let records = records(text)?;
    let mut rows = records
        .into_iter()
        .filter(|(_, r)| !(r.len() == 1 && r[0].trim().is_empty()));
    let Some((_, header)) = rows.next() else {
        return Err(ParseError::new("empty input: no polygon found"));
    };
    let Some(column) = header.iter().position(|f| is_wkt_name(f)) else {
        return Err(ParseError::new(
            "line 1: a CSV header without a WKT column (the geometry column must be named WKT)",
        ));
    };
    let mut parts = Vec::new();
    let mut any = false;
    for (line, row) in rows {
        let field = row.get(column).map_or("", |f| f.trim());
        any = true;
        if field.is_empty() || field.to_ascii_uppercase().ends_with("EMPTY") {
            continue;
        }
        let named = |e: ParseError| ParseError::new(format!("line {line}: WKT: {e}"));
        match wkt::read_parts_within(field, max_vertices) {
            Ok(read) => parts.extend(read.into_iter().map(|p| p.map_err(named))),
            Err(e) => parts.push(Err(named(e))),
        }
    }
    if parts.is_empty() {
        return Err(ParseError::new(if any {
            "no polygon found: the geometry is EMPTY"
        } else {
            "empty input: no polygon found"
        }));
    }
    Ok(parts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoted_fields_line_breaks_and_errors_at_their_line() {
        let text = "id,properties,wkt\n\
                    1,\"{\"\"a\"\": \"\"x,\ny\"\"}\",\"POLYGON ((0 0, 1 0, 0 1))\"\n\
                    2,,\"POLYGON ((0 0, 1 0\"\n\
                    3,,\"MULTIPOLYGON (((0 0, 2 0, 0 2)))\"";
        let parts = read_parts_within(text, 100).unwrap();
        assert_eq!(parts.len(), 3);
        assert!(parts[0].is_ok() && parts[2].is_ok(), "{parts:?}");
        assert_eq!(
            parts[1].as_ref().unwrap_err().to_string(),
            "line 4: WKT: line 1, column 19: expected ')' or ',' but reached the end of the input"
        );
        assert_eq!(
            read_parts_within("id,wkt\n1,\"open", 100)
                .unwrap_err()
                .to_string(),
            "line 2: a quoted field is not closed before the end of the input"
        );
        assert_eq!(
            read_parts_within("WKT,id\n,1\n", 100)
                .unwrap_err()
                .to_string(),
            "no polygon found: the geometry is EMPTY"
        );
    }
}
