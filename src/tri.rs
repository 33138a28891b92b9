//! The `.tri` text format: triangles in window coordinates.
//!
//! UTF-8 text; `#` starts a comment; each non-empty line is one vertex
//! `x y z w r g b`: window coordinates in pixels (y down, fractional and
//! off-screen allowed), depth `z` (0 near, 1 far), clip-space `w > 0` (for
//! perspective-correct interpolation; 1 for affine) and a color 0–255.
//! Every three vertices make a triangle, drawn in file order.
//!
//! The parser is `no_std` and allocation-free: it yields triangles one by
//! one, and the first error (naming its line) ends the iteration.

use embedded_graphics::pixelcolor::Rgb888;

/// One vertex of a window-space triangle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriVertex {
    /// x in pixels (right).
    pub x: f64,
    /// y in pixels (down).
    pub y: f64,
    /// Depth, 0 near to 1 far.
    pub z: f32,
    /// Clip-space w (> 0).
    pub w: f32,
    /// Color.
    pub color: Rgb888,
}

/// What is wrong with a line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TriErrorKind {
    /// The line does not have 7 fields.
    FieldCount(usize),
    /// Field number `n` (1-based) is not a number.
    NotANumber(usize),
    /// Field number `n` (1-based) is infinite or NaN.
    NotFinite(usize),
    /// `w` is zero or negative.
    NonPositiveW,
    /// Color field number `n` (1-based) is not in 0–255.
    ColorRange(usize),
    /// The file ends inside a triangle (vertex count not a multiple of 3).
    IncompleteTriangle,
}

/// A `.tri` parse error at a 1-based line number.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TriError {
    /// Line number (1-based).
    pub line: usize,
    /// What is wrong.
    pub kind: TriErrorKind,
}

impl core::fmt::Display for TriError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "line {}: ", self.line)?;
        match self.kind {
            TriErrorKind::FieldCount(n) => write!(f, "expected 7 numbers `x y z w r g b`, found {n} fields"),
            TriErrorKind::NotANumber(i) => write!(f, "field {i} is not a number"),
            TriErrorKind::NotFinite(i) => write!(f, "field {i} is not finite"),
            TriErrorKind::NonPositiveW => write!(f, "w must be greater than 0"),
            TriErrorKind::ColorRange(i) => write!(f, "color field {i} must be in 0-255"),
            TriErrorKind::IncompleteTriangle => write!(f, "file ends inside a triangle (vertex count is not a multiple of 3)"),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for TriError {}

/// Parses one vertex line (without comment). `Ok(None)` for a blank line.
pub fn parse_vertex(line: &str, line_no: usize) -> Result<Option<TriVertex>, TriError> {
    let line = line.split('#').next().unwrap_or("");
    let err = |kind| TriError { line: line_no, kind };
    let mut f = [0.0f64; 7];
    let mut n = 0;
    for (i, tok) in line.split_whitespace().enumerate() {
        if i < 7 {
            f[i] = tok.parse::<f64>().map_err(|_| err(TriErrorKind::NotANumber(i + 1)))?;
            if !f[i].is_finite() {
                return Err(err(TriErrorKind::NotFinite(i + 1)));
            }
        }
        n = i + 1;
    }
    if n == 0 {
        return Ok(None);
    }
    if n != 7 {
        return Err(err(TriErrorKind::FieldCount(n)));
    }
    let (z, w) = (f[2] as f32, f[3] as f32);
    if !z.is_finite() {
        return Err(err(TriErrorKind::NotFinite(3)));
    }
    if w.is_nan() || w <= 0.0 || !w.is_finite() {
        return Err(err(if w.is_finite() { TriErrorKind::NonPositiveW } else { TriErrorKind::NotFinite(4) }));
    }
    let mut rgb = [0u8; 3];
    for (k, c) in rgb.iter_mut().enumerate() {
        let v = f[4 + k];
        if !(0.0..=255.0).contains(&v) {
            return Err(err(TriErrorKind::ColorRange(5 + k)));
        }
        *c = (v + 0.5) as u8;
    }
    Ok(Some(TriVertex { x: f[0], y: f[1], z, w, color: Rgb888::new(rgb[0], rgb[1], rgb[2]) }))
}

/// Iterates over the triangles of a `.tri` text. After an error it yields
/// nothing more.
pub fn parse(text: &str) -> TriParser<'_> {
    // A UTF-8 byte order mark is not part of the first line.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    TriParser { lines: text.lines().enumerate(), done: false }
}

/// Iterator returned by [`parse`].
pub struct TriParser<'a> {
    lines: core::iter::Enumerate<core::str::Lines<'a>>,
    done: bool,
}

impl Iterator for TriParser<'_> {
    type Item = Result<[TriVertex; 3], TriError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.done {
            return None;
        }
        let mut tri = [TriVertex { x: 0.0, y: 0.0, z: 0.0, w: 1.0, color: Rgb888::new(0, 0, 0) }; 3];
        let mut k = 0;
        let mut last_line = 0;
        for (i, line) in self.lines.by_ref() {
            last_line = i + 1;
            match parse_vertex(line, i + 1) {
                Ok(None) => continue,
                Ok(Some(v)) => {
                    tri[k] = v;
                    k += 1;
                    if k == 3 {
                        return Some(Ok(tri));
                    }
                }
                Err(e) => {
                    self.done = true;
                    return Some(Err(e));
                }
            }
        }
        self.done = true;
        if k == 0 {
            None
        } else {
            Some(Err(TriError { line: last_line, kind: TriErrorKind::IncompleteTriangle }))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_vertices_comments_and_blank_lines() {
        let text = "# a triangle\n0 0 0.5 1 255 0 0\n\n10.5 0 0.5 1 0 255 0 # right\n0 10 0.5 2 0 0 255\n";
        let tris: Result<std::vec::Vec<_>, _> = parse(text).collect();
        let tris = tris.unwrap();
        assert_eq!(tris.len(), 1);
        assert_eq!(tris[0][1].x, 10.5);
        assert_eq!(tris[0][2].w, 2.0);
        assert_eq!(tris[0][2].color, Rgb888::new(0, 0, 255));
    }

    #[test]
    fn accepts_crlf_and_a_byte_order_mark() {
        let tris: std::vec::Vec<_> = parse("\u{feff}0 0 0 1 1 2 3\r\n1 0 0 1 1 2 3\r\n0 1 0 1 1 2 3\r\n").collect();
        assert_eq!(tris.len(), 1);
        assert!(tris[0].is_ok());
    }

    #[test]
    fn errors_name_the_line() {
        let first_err = |t: &str| parse(t).find_map(|r| r.err()).unwrap();
        assert_eq!(first_err("0 0 0 1 0 0 0\n0 0 0 1 0 0\n"), TriError { line: 2, kind: TriErrorKind::FieldCount(6) });
        assert_eq!(first_err("\n\n0 0 0 x 0 0 0\n"), TriError { line: 3, kind: TriErrorKind::NotANumber(4) });
        assert_eq!(first_err("0 0 0 0 0 0 0\n"), TriError { line: 1, kind: TriErrorKind::NonPositiveW });
        assert_eq!(first_err("0 0 0 -1 0 0 0\n"), TriError { line: 1, kind: TriErrorKind::NonPositiveW });
        assert_eq!(first_err("nan 0 0 1 0 0 0\n"), TriError { line: 1, kind: TriErrorKind::NotFinite(1) });
        assert_eq!(first_err("0 inf 0 1 0 0 0\n"), TriError { line: 1, kind: TriErrorKind::NotFinite(2) });
        assert_eq!(first_err("0 0 0 1 0 300 0\n"), TriError { line: 1, kind: TriErrorKind::ColorRange(6) });
        assert_eq!(first_err("0 0 0 1 0 0 0\n1 1 0 1 0 0 0\n"), TriError { line: 2, kind: TriErrorKind::IncompleteTriangle });
        assert_eq!(first_err("0 0 1e39 1 0 0 0\n"), TriError { line: 1, kind: TriErrorKind::NotFinite(3) });
    }
}
