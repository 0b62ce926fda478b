//! The three RULA lookup tables, kept as data in one place.
//!
//! `data/rula_tables.json` is a verbatim copy of `shared/reference/rula_tables.json` (McAtamney &
//! Corlett 1993, as reproduced cell for cell by eight independent implementations). It is embedded at
//! compile time and parsed once, on first use, into fixed-size arrays so that a lookup is an index,
//! not a search. The shape is checked while parsing: Table A 6×3×4×2, Table B 6×6×2, Table C 8×7.

use std::sync::LazyLock;

use serde::Deserialize;

use crate::ErgonomicsError;

const A: &str = "6x3x4x2";
const B: &str = "6x6x2";
const C: &str = "8x7";

/// The embedded JSON text of the tables.
const TABLES_JSON: &str = include_str!("../data/rula_tables.json");

/// Table A: `[upper_arm-1][lower_arm-1][wrist-1][wrist_twist-1]`.
pub type TableA = [[[[u8; 2]; 4]; 3]; 6];
/// Table B: `[neck-1][trunk-1][legs-1]`.
pub type TableB = [[[u8; 2]; 6]; 6];
/// Table C: `[min(score_c,8)-1][min(score_d,7)-1]`.
pub type TableC = [[u8; 7]; 8];

/// The parsed RULA tables.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RulaTables {
    pub table_a: TableA,
    pub table_b: TableB,
    pub table_c: TableC,
}

#[derive(Deserialize)]
struct RawTable<T> {
    values: T,
}

// Field names are the JSON file's keys.
#[allow(clippy::struct_field_names)]
#[derive(Deserialize)]
struct RawTables {
    table_a: RawTable<Vec<Vec<Vec<Vec<u8>>>>>,
    table_b: RawTable<Vec<Vec<Vec<u8>>>>,
    table_c: RawTable<Vec<Vec<u8>>>,
}

static TABLES: LazyLock<Result<RulaTables, ErgonomicsError>> =
    LazyLock::new(|| parse_tables(TABLES_JSON));

/// The RULA tables, parsed once from the embedded data.
pub fn rula_tables() -> Result<&'static RulaTables, ErgonomicsError> {
    TABLES.as_ref().map_err(Clone::clone)
}

fn shape_error(table: &'static str, expected: &'static str) -> ErgonomicsError {
    ErgonomicsError::TableShape { table, expected }
}

fn fixed<T: Copy + Default, const N: usize>(
    v: &[T],
    table: &'static str,
    expected: &'static str,
) -> Result<[T; N], ErgonomicsError> {
    if v.len() != N {
        return Err(shape_error(table, expected));
    }
    let mut out = [T::default(); N];
    out.copy_from_slice(v);
    Ok(out)
}

/// Parses and shape-checks tables from JSON text (the embedded copy in production).
pub fn parse_tables(json: &str) -> Result<RulaTables, ErgonomicsError> {
    let raw: RawTables = serde_json::from_str(json).map_err(|e| ErgonomicsError::TableShape {
        table: "rula_tables.json",
        expected: leak_free_reason(&e),
    })?;

    let mut table_a: TableA = [[[[0; 2]; 4]; 3]; 6];
    if raw.table_a.values.len() != 6 {
        return Err(shape_error("table_a", A));
    }
    for (u, upper) in raw.table_a.values.iter().enumerate() {
        if upper.len() != 3 {
            return Err(shape_error("table_a", A));
        }
        for (l, lower) in upper.iter().enumerate() {
            if lower.len() != 4 {
                return Err(shape_error("table_a", A));
            }
            for (w, wrist) in lower.iter().enumerate() {
                table_a[u][l][w] = fixed::<u8, 2>(wrist, "table_a", A)?;
            }
        }
    }

    let mut table_b: TableB = [[[0; 2]; 6]; 6];
    if raw.table_b.values.len() != 6 {
        return Err(shape_error("table_b", B));
    }
    for (n, neck) in raw.table_b.values.iter().enumerate() {
        if neck.len() != 6 {
            return Err(shape_error("table_b", B));
        }
        for (t, trunk) in neck.iter().enumerate() {
            table_b[n][t] = fixed::<u8, 2>(trunk, "table_b", B)?;
        }
    }

    let mut table_c: TableC = [[0; 7]; 8];
    if raw.table_c.values.len() != 8 {
        return Err(shape_error("table_c", C));
    }
    for (c, row) in raw.table_c.values.iter().enumerate() {
        table_c[c] = fixed::<u8, 7>(row, "table_c", C)?;
    }

    let in_range = |v: u8, max: u8| (1..=max).contains(&v);
    if !table_a
        .iter()
        .flatten()
        .flatten()
        .flatten()
        .all(|&v| in_range(v, 9))
    {
        return Err(shape_error("table_a", "values in 1..=9"));
    }
    if !table_b.iter().flatten().flatten().all(|&v| in_range(v, 9)) {
        return Err(shape_error("table_b", "values in 1..=9"));
    }
    if !table_c.iter().flatten().all(|&v| in_range(v, 7)) {
        return Err(shape_error("table_c", "values in 1..=7"));
    }
    Ok(RulaTables {
        table_a,
        table_b,
        table_c,
    })
}

fn leak_free_reason(e: &serde_json::Error) -> &'static str {
    if e.is_syntax() || e.is_eof() {
        "valid JSON"
    } else {
        "objects table_a/table_b/table_c with a `values` array"
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_tables_have_the_published_shape_and_known_cells() {
        let t = rula_tables().unwrap();
        // Shapes are fixed by the types; the parse checked the JSON matched them.
        assert_eq!(t.table_a.len(), 6);
        assert_eq!(t.table_a[0].len(), 3);
        assert_eq!(t.table_a[0][0].len(), 4);
        assert_eq!(t.table_a[0][0][0].len(), 2);
        assert_eq!(t.table_b.len(), 6);
        assert_eq!(t.table_b[0].len(), 6);
        assert_eq!(t.table_c.len(), 8);
        assert_eq!(t.table_c[0].len(), 7);
        // Known cells (McAtamney & Corlett 1993).
        assert_eq!(t.table_a[0][0][0][0], 1);
        assert_eq!(t.table_a[5][2][3][1], 9);
        assert_eq!(t.table_a[2][1][2][0], 4);
        assert_eq!(t.table_a[4][0][3][1], 7);
        assert_eq!(t.table_b[0][0][0], 1);
        assert_eq!(t.table_b[0][0][1], 3);
        assert_eq!(t.table_b[3][2][1], 7);
        assert_eq!(t.table_b[5][5][1], 9);
        assert_eq!(t.table_c[0][0], 1);
        assert_eq!(t.table_c[7][6], 7);
        assert_eq!(t.table_c[2][6], 6);
        assert_eq!(t.table_c[4][4], 6);
    }

    #[test]
    fn the_embedded_copy_is_the_shared_reference_verbatim() {
        // The shared reference sits beside the repository on developer machines and in CI.
        if ergocell_testdata::skip_without("reference/rula_tables.json") {
            return;
        }
        let text = std::fs::read_to_string(ergocell_testdata::shared("reference/rula_tables.json"))
            .unwrap();
        assert_eq!(parse_tables(&text).unwrap(), *rula_tables().unwrap());
    }

    #[test]
    fn wrong_shapes_are_rejected() {
        let bad = TABLES_JSON.replacen(
            "[\n    1,\n    2,\n    3,\n    3,\n    4,\n    5,\n    5\n   ]",
            "[1,2,3]",
            1,
        );
        assert_ne!(bad, TABLES_JSON, "the test must actually mutate Table C");
        assert_eq!(
            parse_tables(&bad),
            Err(ErgonomicsError::TableShape {
                table: "table_c",
                expected: "8x7"
            })
        );
        assert!(parse_tables("{").is_err());
    }
}
