//! The checkerboard: its inner-corner grid, square size and the board frame of its corners.
//!
//! Conventions (OpenCV's `patternSize`): a "9x6" board has 9 inner corners per row and 6 rows.
//! Corner `(r, c)` — row `r` in `0..rows`, column `c` in `0..cols` — is listed at index
//! `r · cols + c` and sits at `(c · s, r · s, 0)` in the board frame (metres), so the board's z axis
//! points away from a camera that sees the board's front with x to the right and y down. The cell
//! between corners `(0,0)`, `(0,1)`, `(1,0)`, `(1,1)` is a dark square: that fixes the 180° ambiguity
//! of boards whose rows + cols is odd (such as 9x6), consistently across cameras.

use nalgebra::Point3;

use crate::error::{CalibrationError, Result};

/// A checkerboard described by its inner corners and square size.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoardSpec {
    cols: usize,
    rows: usize,
    square_m: f64,
}

/// The square sizes a calibration board can have, metres: a size outside is almost always in the
/// wrong unit (millimetres: `--square-m 25` would report an 83-metre baseline).
pub const SQUARE_RANGE_M: std::ops::RangeInclusive<f64> = 0.002..=0.5;

impl BoardSpec {
    /// A board with `cols` inner corners per row, `rows` rows and squares of `square_m` metres.
    pub fn new(cols: usize, rows: usize, square_m: f64) -> Result<Self> {
        let bad = |why| {
            Err(CalibrationError::BadBoard {
                cols,
                rows,
                square_m,
                why,
            })
        };
        if cols < 3 || rows < 3 {
            return bad("at least 3x3 inner corners are needed");
        }
        if cols * rows > 10_000 {
            return bad("more than 10000 corners");
        }
        if !(square_m.is_finite() && square_m > 0.0) {
            return bad("the square size must be a positive number of metres");
        }
        if !SQUARE_RANGE_M.contains(&square_m) {
            return bad(
                "a checkerboard's squares are 2 mm to 0.5 m: give the size in metres (25 mm is 0.025)",
            );
        }
        Ok(Self {
            cols,
            rows,
            square_m,
        })
    }

    /// Parses `"COLSxROWS"` (inner corners, e.g. `"9x6"`).
    pub fn parse(spec: &str, square_m: f64) -> Result<Self> {
        let bad = || CalibrationError::BadBoardSpec(spec.to_owned());
        let (c, r) = spec.trim().split_once(['x', 'X']).ok_or_else(bad)?;
        let cols = c.trim().parse().map_err(|_| bad())?;
        let rows = r.trim().parse().map_err(|_| bad())?;
        Self::new(cols, rows, square_m)
    }

    /// Inner corners per row.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Rows of inner corners.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Square side, metres.
    pub fn square_m(&self) -> f64 {
        self.square_m
    }

    /// Number of inner corners.
    pub fn corner_count(&self) -> usize {
        self.cols * self.rows
    }

    /// True when the square colours tell the board's 180° rotations apart (rows + cols odd):
    /// then every detection has the same corner order in every camera.
    pub fn orientation_from_colour(&self) -> bool {
        (self.rows + self.cols) % 2 == 1
    }

    /// The corners in the board frame, row-major (see the module doc), metres.
    pub fn object_points(&self) -> Vec<Point3<f64>> {
        (0..self.rows)
            .flat_map(|r| {
                (0..self.cols).map(move |c| {
                    Point3::new(c as f64 * self.square_m, r as f64 * self.square_m, 0.0)
                })
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn board_sizes_parse_and_bad_ones_say_why() {
        let b = BoardSpec::parse("9x6", 0.025).unwrap();
        assert_eq!((b.cols(), b.rows(), b.corner_count()), (9, 6, 54));
        assert!(b.orientation_from_colour());
        assert!(!BoardSpec::parse("8X6", 0.02)
            .unwrap()
            .orientation_from_colour());
        assert!(matches!(
            BoardSpec::parse("9by6", 0.025),
            Err(CalibrationError::BadBoardSpec(_))
        ));
        assert!(matches!(
            BoardSpec::parse("2x6", 0.025),
            Err(CalibrationError::BadBoard { cols: 2, .. })
        ));
        assert!(BoardSpec::parse("9x6", 0.0).is_err());
        assert!(BoardSpec::parse("9x6", f64::NAN).is_err());
        // Millimetres for metres is refused, saying so.
        let e = BoardSpec::parse("9x6", 25.0).unwrap_err().to_string();
        assert!(e.contains("in metres"), "{e}");
        assert!(BoardSpec::parse("9x6", 0.001).is_err());
        assert!(BoardSpec::parse("9x6", 0.5).is_ok());
    }

    #[test]
    fn object_points_are_row_major_in_metres() {
        let b = BoardSpec::new(4, 3, 0.03).unwrap();
        let p = b.object_points();
        assert_eq!(p.len(), 12);
        assert_eq!(p[1], Point3::new(0.03, 0.0, 0.0));
        assert_eq!(p[4], Point3::new(0.0, 0.03, 0.0));
        assert_eq!(p[11], Point3::new(0.09, 0.06, 0.0));
    }
}
