//! The exposure store: [`SegmentRow`]s as one Parquet file, the open columnar format an embedded
//! engine (DuckDB on the ergonomist's laptop) queries with SQL and a distributed one (Spark, Trino,
//! DuckDB over object storage) reads unchanged.
//!
//! The schema is [`SCHEMA`]: one row per session and task segment (`segment = 'all'` for the whole
//! session), times in seconds so that shares over any group are sums divided by sums; `start` a UTC
//! timestamp in microseconds (the unit every engine reads, Spark included), `day` a date. The operator is
//! the recording's pseudonymous id; no landmark, angle or name is stored. Written with the `parquet`
//! crate's own column writers (no Arrow, no engine compiled in). No I/O here: the caller hands the
//! writer.

use std::io::Write;
use std::sync::Arc;

use parquet::basic::Compression;
use parquet::column::writer::ColumnWriter;
use parquet::data_type::ByteArray;
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;

use crate::exposure::SegmentRow;

/// The Parquet schema of the store (column order is the file's).
pub const SCHEMA: &str = "message ergocell_exposure_segments {
  OPTIONAL BYTE_ARRAY operator (STRING);
  REQUIRED BYTE_ARRAY file (STRING);
  REQUIRED INT32 session;
  REQUIRED INT64 start (TIMESTAMP(MICROS,true));
  REQUIRED INT32 day (DATE);
  REQUIRED BYTE_ARRAY week (STRING);
  OPTIONAL BYTE_ARRAY class (STRING);
  REQUIRED BYTE_ARRAY segment (STRING);
  REQUIRED DOUBLE duration_s;
  REQUIRED DOUBLE rula_scored_s;
  REQUIRED DOUBLE rula_al1_s;
  REQUIRED DOUBLE rula_al2_s;
  REQUIRED DOUBLE rula_al3_s;
  REQUIRED DOUBLE rula_al4_s;
  REQUIRED DOUBLE reba_scored_s;
  REQUIRED DOUBLE reba_al0_s;
  REQUIRED DOUBLE reba_al1_s;
  REQUIRED DOUBLE reba_al2_s;
  REQUIRED DOUBLE reba_al3_s;
  REQUIRED DOUBLE reba_al4_s;
  REQUIRED DOUBLE rula_al3_longest_s;
  REQUIRED INT32 peak_grand_score;
  REQUIRED INT32 static_holds;
  REQUIRED INT32 static_holds_exceeded;
  REQUIRED INT32 parts_taken;
  REQUIRED DOUBLE posture_cost_s;
  REQUIRED DOUBLE posture_cost_point_s;
}";

/// The store could not be written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum StoreError {
    /// The Parquet writer failed.
    #[error("writing the Parquet store: {0}")]
    Parquet(#[from] parquet::errors::ParquetError),
    /// A row's day is not a `YYYY-MM-DD` date a 32-bit day count holds.
    #[error("writing the Parquet store: day {day:?} is not a YYYY-MM-DD date within ±5.8 million years of 1970")]
    Day { day: String },
    /// The columns written do not match the schema (a bug here, not bad input).
    #[error("writing the Parquet store: the schema has {schema} columns where {written} were written, or a column's type differs")]
    Schema { schema: usize, written: usize },
}

/// One column's values, in row order (`None`: null).
enum Column {
    Text(Vec<Option<String>>),
    Int32(Vec<i32>),
    Int64(Vec<i64>),
    Double(Vec<f64>),
}

/// Days since 1970-01-01 of a `YYYY-MM-DD` day.
fn epoch_day(day: &str) -> Result<i32, StoreError> {
    let d = chrono::NaiveDate::parse_from_str(day, "%Y-%m-%d").map_err(|_| StoreError::Day {
        day: day.to_owned(),
    })?;
    let epoch = chrono::NaiveDate::from_ymd_opt(1970, 1, 1).unwrap_or_default();
    i32::try_from((d - epoch).num_days()).map_err(|_| StoreError::Day {
        day: day.to_owned(),
    })
}

fn int(x: u32) -> i32 {
    i32::try_from(x).unwrap_or(i32::MAX)
}

/// The columns of `rows`, in [`SCHEMA`]'s order.
fn columns(rows: &[SegmentRow]) -> Result<Vec<Column>, StoreError> {
    let text =
        |f: &dyn Fn(&SegmentRow) -> Option<String>| Column::Text(rows.iter().map(f).collect());
    let double = |f: &dyn Fn(&SegmentRow) -> f64| Column::Double(rows.iter().map(f).collect());
    let int32 = |f: &dyn Fn(&SegmentRow) -> i32| Column::Int32(rows.iter().map(f).collect());
    let days = rows
        .iter()
        .map(|r| epoch_day(&r.day))
        .collect::<Result<Vec<i32>, StoreError>>()?;
    let mut out = vec![
        text(&|r| r.operator.clone()),
        text(&|r| Some(r.file.clone())),
        int32(&|r| int(r.session)),
        Column::Int64(
            rows.iter()
                .map(|r| r.start_unix_nanos.div_euclid(1000))
                .collect(),
        ),
        Column::Int32(days),
        text(&|r| Some(r.week.clone())),
        text(&|r| r.class.clone()),
        text(&|r| Some(r.segment.clone())),
        double(&|r| r.duration_s),
        double(&|r| r.rula_scored_s),
    ];
    for k in 0..4 {
        out.push(double(&|r| r.rula_al_s[k]));
    }
    out.push(double(&|r| r.reba_scored_s));
    for k in 0..5 {
        out.push(double(&|r| r.reba_al_s[k]));
    }
    out.extend([
        double(&|r| r.rula_al3_longest_s),
        int32(&|r| i32::from(r.peak_grand_score)),
        int32(&|r| int(r.static_holds)),
        int32(&|r| int(r.static_holds_exceeded)),
        int32(&|r| int(r.parts_taken)),
        double(&|r| r.posture_cost_s),
        double(&|r| r.posture_cost_point_s),
    ]);
    Ok(out)
}

/// Writes `rows` as one Parquet file (one row group, Snappy-free: uncompressed) into `sink`.
///
/// # Errors
/// [`StoreError`] when `sink` fails or a row's day is not a date.
pub fn write_parquet<W: Write + Send>(rows: &[SegmentRow], sink: W) -> Result<(), StoreError> {
    let schema = Arc::new(parquet::schema::parser::parse_message_type(SCHEMA)?);
    let props = Arc::new(
        WriterProperties::builder()
            .set_compression(Compression::UNCOMPRESSED)
            .set_created_by(concat!("ergocell ", env!("CARGO_PKG_VERSION")).to_owned())
            .build(),
    );
    let columns = columns(rows)?;
    let mismatch = StoreError::Schema {
        schema: schema.get_fields().len(),
        written: columns.len(),
    };
    let mut writer = SerializedFileWriter::new(sink, schema, props)?;
    let mut group = writer.next_row_group()?;
    let mut values = columns.into_iter();
    while let Some(mut column) = group.next_column()? {
        let Some(data) = values.next() else {
            return Err(mismatch);
        };
        let written = match (column.untyped(), data) {
            (ColumnWriter::ByteArrayColumnWriter(w), Column::Text(v)) => {
                let present: Vec<ByteArray> = v
                    .iter()
                    .flatten()
                    .map(|s| ByteArray::from(s.as_str()))
                    .collect();
                let levels: Vec<i16> = v.iter().map(|x| i16::from(x.is_some())).collect();
                w.write_batch(&present, Some(&levels), None)
            }
            (ColumnWriter::Int32ColumnWriter(w), Column::Int32(v)) => w.write_batch(&v, None, None),
            (ColumnWriter::Int64ColumnWriter(w), Column::Int64(v)) => w.write_batch(&v, None, None),
            (ColumnWriter::DoubleColumnWriter(w), Column::Double(v)) => {
                w.write_batch(&v, None, None)
            }
            _ => return Err(mismatch),
        };
        written?;
        column.close()?;
    }
    if values.next().is_some() {
        return Err(mismatch);
    }
    group.close()?;
    writer.close()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use parquet::file::reader::{FileReader, SerializedFileReader};
    use parquet::record::Field;

    fn row(operator: Option<&str>, segment: &str, scored: f64) -> SegmentRow {
        SegmentRow {
            operator: operator.map(str::to_owned),
            file: "shift.mcap".into(),
            session: 2,
            start_unix_nanos: 1_795_413_600_000_000_000, // 2026-11-23T06:00:00Z
            day: "2026-11-23".into(),
            week: "2026-W48".into(),
            class: None,
            segment: segment.into(),
            duration_s: scored + 1.0,
            rula_scored_s: scored,
            rula_al_s: [scored * 0.5, scored * 0.25, scored * 0.25, 0.0],
            reba_scored_s: scored,
            reba_al_s: [0.0, scored, 0.0, 0.0, 0.0],
            rula_al3_longest_s: 2.5,
            peak_grand_score: 5,
            posture_cost_s: 60.0,
            posture_cost_point_s: 190.0,
            static_holds: 3,
            static_holds_exceeded: 1,
            parts_taken: 4,
        }
    }

    #[test]
    fn rows_round_trip_through_parquet_with_nulls_dates_and_times() {
        let rows = vec![row(Some("op-7"), "all", 100.0), row(None, "handover", 40.0)];
        let mut bytes = Vec::new();
        write_parquet(&rows, &mut bytes).unwrap();
        assert_eq!(&bytes[..4], b"PAR1");
        let reader = SerializedFileReader::new(bytes::Bytes::from(bytes)).unwrap();
        assert_eq!(reader.metadata().file_metadata().num_rows(), 2);
        let read: Vec<_> = reader
            .get_row_iter(None)
            .unwrap()
            .map(Result::unwrap)
            .collect();
        let get = |r: usize, name: &str| {
            read[r]
                .get_column_iter()
                .find(|(n, _)| n.as_str() == name)
                .map(|(_, f)| f.clone())
                .unwrap()
        };
        assert_eq!(get(0, "operator"), Field::Str("op-7".into()));
        assert_eq!(get(1, "operator"), Field::Null);
        assert_eq!(get(1, "class"), Field::Null);
        assert_eq!(get(1, "segment"), Field::Str("handover".into()));
        // 2026-11-23 is day 20780 since 1970-01-01 (Python: date(2026, 11, 23) - date(1970, 1, 1)).
        assert_eq!(get(0, "day"), Field::Date(20780));
        assert_eq!(
            get(0, "start"),
            Field::TimestampMicros(1_795_413_600_000_000)
        );
        assert_eq!(get(0, "rula_al3_s"), Field::Double(25.0));
        assert_eq!(get(1, "reba_al1_s"), Field::Double(40.0));
        assert_eq!(get(0, "parts_taken"), Field::Int(4));
        assert_eq!(get(0, "posture_cost_s"), Field::Double(60.0));
        assert_eq!(get(0, "posture_cost_point_s"), Field::Double(190.0));
        let columns = reader
            .metadata()
            .file_metadata()
            .schema_descr()
            .num_columns();
        assert_eq!(columns, SCHEMA.matches(';').count());
    }

    #[test]
    fn a_malformed_day_is_an_error_not_a_file() {
        let mut r = row(Some("op-7"), "all", 1.0);
        r.day = "23.11.2026".into();
        let err = write_parquet(&[r], Vec::new()).unwrap_err();
        assert!(err.to_string().contains("23.11.2026"), "{err}");
    }
}
