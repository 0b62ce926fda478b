//! `ergocell exposure`'s two CSV files, as bytes: `exposure.csv`, a row per group of an
//! [`ExposureTable`] (shares of scored time, hours), and `sessions.csv`, a row per [`SegmentRow`]
//! (seconds, the Parquet store's columns, for any engine to add up).
//!
//! The rows' layout and units live here, beside the exposure they lay out, so the binary only writes
//! the bytes. Every text cell goes through [`csv_text`] (a recording's names are whatever it says).
//! No I/O.

use std::borrow::Cow;

use ergocell_ergonomics::export::csv_text;

use crate::exposure::{ExposureTable, SegmentRow};
use crate::ReviewError;

/// Seconds as hours.
pub fn hours(secs: f64) -> f64 {
    secs / 3600.0
}

/// Nanoseconds since the Unix epoch as seconds.
pub fn unix_secs(unix_nanos: i64) -> f64 {
    unix_nanos as f64 * 1e-9
}

/// One `exposure.csv` row (shares of scored time, hours).
#[derive(serde::Serialize)]
struct GroupCsv<'a> {
    operator: Cow<'a, str>,
    period: Cow<'a, str>,
    period_start: Cow<'a, str>,
    class: Cow<'a, str>,
    segment: Cow<'a, str>,
    sessions: u32,
    hours: f64,
    rula_scored_hours: f64,
    rula_al1_share: Option<f64>,
    rula_al2_share: Option<f64>,
    rula_al3_share: Option<f64>,
    rula_al4_share: Option<f64>,
    rula_al3plus_share: Option<f64>,
    reba_scored_hours: f64,
    reba_al3plus_share: Option<f64>,
    rula_al3_longest_s: f64,
    peak_grand_score: u8,
    mean_posture_cost: Option<f64>,
    static_holds: u32,
    static_holds_exceeded: u32,
    parts_taken: u32,
}

/// One `sessions.csv` row (seconds).
#[derive(serde::Serialize)]
struct SessionCsv<'a> {
    operator: Cow<'a, str>,
    file: Cow<'a, str>,
    session: u32,
    start_unix_s: f64,
    day: Cow<'a, str>,
    week: Cow<'a, str>,
    class: Cow<'a, str>,
    segment: Cow<'a, str>,
    duration_s: f64,
    rula_scored_s: f64,
    rula_al1_s: f64,
    rula_al2_s: f64,
    rula_al3_s: f64,
    rula_al4_s: f64,
    reba_scored_s: f64,
    reba_al0_s: f64,
    reba_al1_s: f64,
    reba_al2_s: f64,
    reba_al3_s: f64,
    reba_al4_s: f64,
    rula_al3_longest_s: f64,
    peak_grand_score: u8,
    static_holds: u32,
    static_holds_exceeded: u32,
    parts_taken: u32,
    // last, as in the Parquet store
    posture_cost_s: f64,
    posture_cost_point_s: f64,
}

impl<'a> From<&'a SegmentRow> for SessionCsv<'a> {
    fn from(r: &'a SegmentRow) -> Self {
        Self {
            operator: csv_text(r.operator.as_deref().unwrap_or("-")),
            file: csv_text(&r.file),
            session: r.session,
            start_unix_s: unix_secs(r.start_unix_nanos),
            day: csv_text(&r.day),
            week: csv_text(&r.week),
            class: csv_text(r.class.as_deref().unwrap_or("-")),
            segment: csv_text(&r.segment),
            duration_s: r.duration_s,
            rula_scored_s: r.rula_scored_s,
            rula_al1_s: r.rula_al_s[0],
            rula_al2_s: r.rula_al_s[1],
            rula_al3_s: r.rula_al_s[2],
            rula_al4_s: r.rula_al_s[3],
            reba_scored_s: r.reba_scored_s,
            reba_al0_s: r.reba_al_s[0],
            reba_al1_s: r.reba_al_s[1],
            reba_al2_s: r.reba_al_s[2],
            reba_al3_s: r.reba_al_s[3],
            reba_al4_s: r.reba_al_s[4],
            rula_al3_longest_s: r.rula_al3_longest_s,
            peak_grand_score: r.peak_grand_score,
            posture_cost_s: r.posture_cost_s,
            posture_cost_point_s: r.posture_cost_point_s,
            static_holds: r.static_holds,
            static_holds_exceeded: r.static_holds_exceeded,
            parts_taken: r.parts_taken,
        }
    }
}

fn csv_bytes<T: serde::Serialize>(
    rows: impl IntoIterator<Item = T>,
) -> Result<Vec<u8>, ReviewError> {
    let export = |reason: String| ReviewError::Export { reason };
    let mut w = csv::Writer::from_writer(Vec::new());
    for row in rows {
        w.serialize(row).map_err(|e| export(e.to_string()))?;
    }
    w.into_inner().map_err(|e| export(e.to_string()))
}

/// `exposure.csv`: a row per group of `table`, in its order (operator, period, start, class,
/// segment), with the header.
pub fn groups_csv(table: &ExposureTable) -> Result<Vec<u8>, ReviewError> {
    csv_bytes(table.groups.iter().map(|(k, g)| GroupCsv {
        operator: csv_text(&k.operator),
        period: csv_text(k.period),
        period_start: csv_text(&k.period_start),
        class: csv_text(&k.class),
        segment: csv_text(&k.segment),
        sessions: g.sessions,
        hours: hours(g.duration_s),
        rula_scored_hours: hours(g.rula_scored_s),
        rula_al1_share: g.rula_level_share(1),
        rula_al2_share: g.rula_level_share(2),
        rula_al3_share: g.rula_level_share(3),
        rula_al4_share: g.rula_level_share(4),
        rula_al3plus_share: g.rula_share(3),
        reba_scored_hours: hours(g.reba_scored_s),
        reba_al3plus_share: g.reba_share(3),
        rula_al3_longest_s: g.rula_al3_longest_s,
        peak_grand_score: g.peak_grand_score,
        mean_posture_cost: g.mean_posture_cost(),
        static_holds: g.static_holds,
        static_holds_exceeded: g.static_holds_exceeded,
        parts_taken: g.parts_taken,
    }))
}

/// `sessions.csv`: a row per session and segment, in the order given, with the header.
pub fn sessions_csv(rows: &[SegmentRow]) -> Result<Vec<u8>, ReviewError> {
    csv_bytes(rows.iter().map(SessionCsv::from))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exposure::ALL;

    fn row(operator: Option<&str>, duration_s: f64, al: [f64; 4]) -> SegmentRow {
        SegmentRow {
            operator: operator.map(str::to_owned),
            file: "=cmd.mcap".into(),
            session: 2,
            start_unix_nanos: 1_700_000_000_500_000_000,
            day: "2023-11-14".into(),
            week: "2023-W46".into(),
            class: None,
            segment: ALL.into(),
            duration_s,
            rula_scored_s: duration_s,
            rula_al_s: al,
            reba_scored_s: 0.0,
            reba_al_s: [0.0; 5],
            rula_al3_longest_s: al[2],
            peak_grand_score: 5,
            posture_cost_s: 0.0,
            posture_cost_point_s: 0.0,
            static_holds: 1,
            static_holds_exceeded: 0,
            parts_taken: 3,
        }
    }

    fn records(bytes: &[u8]) -> (csv::StringRecord, Vec<csv::StringRecord>) {
        let mut r = csv::Reader::from_reader(bytes);
        let header = r.headers().unwrap().clone();
        let rows = r.records().map(Result::unwrap).collect();
        (header, rows)
    }

    fn field(header: &csv::StringRecord, row: &csv::StringRecord, name: &str) -> String {
        let k = header.iter().position(|h| h == name).unwrap();
        row[k].to_owned()
    }

    #[test]
    fn units_convert() {
        assert_eq!(hours(7200.0), 2.0);
        assert_eq!(hours(0.0), 0.0);
        assert!((unix_secs(1_500_000_000) - 1.5).abs() < 1e-12);
        assert!((unix_secs(-2_000_000_000) + 2.0).abs() < 1e-12);
    }

    #[test]
    fn a_group_row_holds_hours_and_shares_of_scored_time() {
        let mut t = ExposureTable::default();
        t.add(&row(Some("op-1"), 1800.0, [900.0, 0.0, 900.0, 0.0]));
        t.add(&row(Some("op-1"), 1800.0, [1800.0, 0.0, 0.0, 0.0]));
        let (header, rows) = records(&groups_csv(&t).unwrap());
        assert_eq!(&header[0], "operator");
        assert_eq!(&header[header.len() - 1], "parts_taken");
        // One operator, a day and a week, its class (none: "-") and all classes.
        assert_eq!(rows.len(), t.groups.len());
        let first = &rows[0];
        let num = |name: &str| field(&header, first, name).parse::<f64>().unwrap();
        assert_eq!(num("sessions"), 2.0);
        assert_eq!(num("hours"), 1.0);
        assert_eq!(num("rula_scored_hours"), 1.0);
        assert_eq!(num("rula_al1_share"), 0.75);
        assert_eq!(num("rula_al3plus_share"), 0.25);
        assert_eq!(num("parts_taken"), 6.0);
        // Never scored by REBA: an empty cell, not 0.
        assert_eq!(field(&header, first, "reba_al3plus_share"), "");
    }

    #[test]
    fn a_session_row_holds_seconds_and_escapes_text() {
        let rows = [row(None, 60.0, [60.0, 0.0, 0.0, 0.0])];
        let (header, read) = records(&sessions_csv(&rows).unwrap());
        assert_eq!(read.len(), 1);
        let r = &read[0];
        assert_eq!(field(&header, r, "operator"), "-");
        assert_eq!(field(&header, r, "class"), "-");
        assert_eq!(field(&header, r, "file"), "'=cmd.mcap");
        let start: f64 = field(&header, r, "start_unix_s").parse().unwrap();
        assert!((start - 1_700_000_000.5).abs() < 1e-6);
        assert_eq!(
            field(&header, r, "rula_al1_s").parse::<f64>().unwrap(),
            60.0
        );
        // The Parquet store's column order: the posture cost last.
        assert_eq!(&header[header.len() - 1], "posture_cost_point_s");
    }
}
