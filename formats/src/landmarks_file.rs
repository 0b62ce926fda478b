//! 3D landmark files: what `ergocell triangulate` writes and `ergocell rula track` / `height` read.
//!
//! | extension | layout |
//! |---|---|
//! | `.json` | a JSON array of [`Skeleton3`] (stamp, and per landmark position, confidence, reprojection error, views) |
//! | `.csv` | long format: `frame, time_s, landmark, x_m, y_m, z_m, confidence, reprojection_error_px, views` |
//! | `.trc` | OpenSim's marker file as Pose2Sim writes it (metres; unobserved markers left empty) |
//!
//! Positions are metres in the calibration's world frame. No I/O here: text in, text out.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use ergocell_perception::metrics::frame_rate_hz;
use ergocell_skeleton::{Landmark, LandmarkEstimate, Skeleton3};
use nalgebra::Point3;
use serde::{Deserialize, Serialize};

use crate::error::{parse_err, PerceptionError, Result};

/// The supported 3D landmark file formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LandmarksFormat {
    Json,
    Csv,
    Trc,
}

impl LandmarksFormat {
    /// The format of a file name, from its extension.
    pub fn from_path(path: &std::path::Path) -> Result<Self> {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
        {
            Some("json") => Ok(Self::Json),
            Some("csv") => Ok(Self::Csv),
            Some("trc") => Ok(Self::Trc),
            _ => Err(PerceptionError::Unsupported(format!(
                "{}: expected a .json, .csv or .trc file",
                path.display()
            ))),
        }
    }
}

/// Writes a recording of skeletons. `rate_hz` is written into TRC headers.
pub fn write_landmarks(
    frames: &[Skeleton3],
    format: LandmarksFormat,
    name: &str,
    rate_hz: f64,
) -> String {
    let mut encoder = LandmarksEncoder::new(format, name, rate_hz, frames.len());
    let mut out = encoder.header();
    for f in frames {
        encoder.frame_into(f, &mut out);
    }
    out.push_str(&encoder.footer());
    out
}

/// A landmark file written piece by piece — the header, one frame at a time, the footer — so a long
/// recording is written as it is triangulated (memory flat in its length). The pieces concatenated
/// are exactly [`write_landmarks`]'s text. The frame count is stated up front (a TRC header holds
/// it); the frames pushed must be that many.
#[derive(Debug, Clone)]
pub struct LandmarksEncoder {
    format: LandmarksFormat,
    name: String,
    rate_hz: f64,
    frame_count: usize,
    written: usize,
    t0: Option<i64>,
    /// CSV: the header row is written with the first row (a file with no rows is empty).
    csv_header_done: bool,
}

impl LandmarksEncoder {
    /// An encoder for `frame_count` frames.
    pub fn new(format: LandmarksFormat, name: &str, rate_hz: f64, frame_count: usize) -> Self {
        Self {
            format,
            name: name.to_owned(),
            rate_hz,
            frame_count,
            written: 0,
            t0: None,
            csv_header_done: false,
        }
    }

    /// Frames encoded so far.
    pub fn frames_written(&self) -> usize {
        self.written
    }

    /// The text before the first frame.
    pub fn header(&self) -> String {
        match self.format {
            LandmarksFormat::Json => "[".to_owned(),
            LandmarksFormat::Csv => String::new(),
            LandmarksFormat::Trc => trc_header(&self.name, self.rate_hz, self.frame_count),
        }
    }

    /// Appends one frame's text to `out`.
    pub fn frame_into(&mut self, s: &Skeleton3, out: &mut String) {
        let t0 = *self.t0.get_or_insert(s.stamp_nanos);
        let i = self.written;
        self.written += 1;
        match self.format {
            LandmarksFormat::Json => {
                if i > 0 {
                    out.push(',');
                }
                out.push_str(&serde_json::to_string(s).unwrap_or_else(|_| "null".to_owned()));
            }
            LandmarksFormat::Csv => {
                let mut w = csv::WriterBuilder::new()
                    .has_headers(!self.csv_header_done)
                    .from_writer(Vec::new());
                for lm in Landmark::ALL {
                    if let Some(e) = s.get(lm) {
                        let _ = w.serialize(CsvRow {
                            frame: i,
                            time_s: (s.stamp_nanos - t0) as f64 * 1e-9,
                            landmark: lm.name().to_owned(),
                            x_m: e.position_m.x,
                            y_m: e.position_m.y,
                            z_m: e.position_m.z,
                            confidence: e.confidence,
                            reprojection_error_px: e.reprojection_error_px,
                            views: e.views,
                        });
                        self.csv_header_done = true;
                    }
                }
                out.push_str(
                    &String::from_utf8(w.into_inner().unwrap_or_default()).unwrap_or_default(),
                );
            }
            LandmarksFormat::Trc => {
                let _ = write!(out, "{}\t{:.6}", i + 1, (s.stamp_nanos - t0) as f64 * 1e-9);
                for lm in Landmark::ALL {
                    match s.position(lm) {
                        Some(p) => {
                            let _ = write!(out, "\t{:.6}\t{:.6}\t{:.6}", p.x, p.y, p.z);
                        }
                        None => out.push_str("\t\t\t"),
                    }
                }
                out.push('\n');
            }
        }
    }

    /// The text after the last frame.
    pub fn footer(&self) -> String {
        match self.format {
            LandmarksFormat::Json => "]".to_owned(),
            LandmarksFormat::Csv | LandmarksFormat::Trc => String::new(),
        }
    }
}

/// A landmark file written as the frames of a recording arrive, when its frame rate is known only
/// from their stamps (OpenPose frames carry none, a caliscope file has its own): the first
/// [`StreamingEncoder::RATE_FRAMES`] frames (the whole recording when it is shorter) are held back to
/// estimate the rate a TRC header states ([`frame_rate_hz`], else the given rate), then every frame
/// is encoded into a text the caller takes and writes piece by piece. The pieces concatenated are
/// exactly [`write_landmarks`]'s text at that rate.
#[derive(Debug, Clone)]
pub struct StreamingEncoder {
    format: LandmarksFormat,
    name: String,
    fallback_rate_hz: f64,
    frame_count: usize,
    held: Vec<Skeleton3>,
    encoder: Option<LandmarksEncoder>,
    text: String,
}

impl StreamingEncoder {
    /// Frames held back to estimate the frame rate.
    pub const RATE_FRAMES: usize = 1000;

    /// An encoder for `frame_count` frames named `name`, at `fallback_rate_hz` when the stamps give
    /// no rate.
    pub fn new(
        format: LandmarksFormat,
        name: &str,
        fallback_rate_hz: f64,
        frame_count: usize,
    ) -> Self {
        Self {
            format,
            name: name.to_owned(),
            fallback_rate_hz,
            frame_count,
            held: Vec::new(),
            encoder: None,
            text: String::new(),
        }
    }

    /// Adds the next frame: held back until the rate is known, encoded from then on.
    pub fn push(&mut self, skeleton: Skeleton3) {
        if let Some(e) = self.encoder.as_mut() {
            e.frame_into(&skeleton, &mut self.text);
        } else {
            self.held.push(skeleton);
            if self.held.len() == Self::RATE_FRAMES {
                let e = self.start();
                self.encoder = Some(e);
            }
        }
    }

    /// The text encoded and not taken yet, once it is longer than `min_bytes` (the caller writes it).
    pub fn take_text_over(&mut self, min_bytes: usize) -> Option<String> {
        (self.text.len() > min_bytes).then(|| std::mem::take(&mut self.text))
    }

    /// The rest of the file (the frames still held, the footer) and how many frames were encoded in
    /// all.
    pub fn finish(mut self) -> (String, usize) {
        let e = match self.encoder.take() {
            Some(e) => e,
            None => self.start(),
        };
        let written = e.frames_written();
        self.text.push_str(&e.footer());
        (self.text, written)
    }

    /// The encoder at the rate of the held frames: the header and the held frames into the text.
    fn start(&mut self) -> LandmarksEncoder {
        let rate = frame_rate_hz(&self.held).unwrap_or(self.fallback_rate_hz);
        let mut e = LandmarksEncoder::new(self.format, &self.name, rate, self.frame_count);
        self.text.push_str(&e.header());
        for s in self.held.drain(..) {
            e.frame_into(&s, &mut self.text);
        }
        e
    }
}

/// The farthest a landmark may lie from the world's origin, metres: a camera rig watches a person
/// within a few metres of it. Beyond, the file is not in metres or not sound (landmarks × 1e300 once
/// scored a plausible RULA and a stature of "inf m").
pub const MAX_DISTANCE_M: f64 = 1.0e4;

/// Reads a recording of skeletons. A landmark farther than [`MAX_DISTANCE_M`] from the origin is an
/// error naming its frame.
pub fn read_landmarks(
    text: &str,
    format: LandmarksFormat,
    source_name: &str,
) -> Result<Vec<Skeleton3>> {
    let frames = match format {
        LandmarksFormat::Json => {
            serde_json::from_str(text).map_err(|e| parse_err(source_name, "(file)", e))?
        }
        LandmarksFormat::Csv => read_csv(text, source_name)?,
        LandmarksFormat::Trc => read_trc(text, source_name)?,
    };
    for (i, s) in frames.iter().enumerate() {
        for lm in Landmark::ALL {
            if let Some(p) = s.position(lm) {
                let d = p.coords.amax();
                if d > MAX_DISTANCE_M {
                    return Err(parse_err(
                        source_name,
                        format!("frame {i}, {}", lm.name()),
                        format!(
                            "at ({}, {}, {}): {d:e} m from the origin, not a person a camera rig watches (a file not in metres?)",
                            p.x, p.y, p.z
                        ),
                    ));
                }
            }
        }
    }
    Ok(frames)
}

#[derive(Debug, Serialize, Deserialize)]
struct CsvRow {
    frame: usize,
    time_s: f64,
    landmark: String,
    x_m: f64,
    y_m: f64,
    z_m: f64,
    confidence: f64,
    reprojection_error_px: Option<f64>,
    views: u32,
}

fn read_csv(text: &str, source_name: &str) -> Result<Vec<Skeleton3>> {
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let mut frames: BTreeMap<usize, Skeleton3> = BTreeMap::new();
    for (line, row) in reader.deserialize::<CsvRow>().enumerate() {
        let row = row.map_err(|e| parse_err(source_name, format!("row {}", line + 2), e))?;
        let lm = Landmark::from_name(&row.landmark).ok_or_else(|| {
            parse_err(
                source_name,
                format!("row {}: landmark", line + 2),
                format!("unknown landmark `{}`", row.landmark),
            )
        })?;
        let stamp = (row.time_s * 1e9).round() as i64;
        let skeleton = frames
            .entry(row.frame)
            .or_insert_with(|| Skeleton3::empty(stamp));
        let e = LandmarkEstimate {
            position_m: Point3::new(row.x_m, row.y_m, row.z_m),
            confidence: row.confidence,
            reprojection_error_px: row.reprojection_error_px,
            views: row.views,
            position_sd_m: None,
        };
        skeleton
            .set(lm, Some(e))
            .map_err(|err| parse_err(source_name, format!("row {}", line + 2), err))?;
    }
    Ok(frames.into_values().collect())
}

fn trc_header(name: &str, rate_hz: f64, n: usize) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "PathFileType\t4\t(X/Y/Z)\t{name}");
    let _ = writeln!(out, "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames");
    let _ = writeln!(
        out,
        "{rate_hz:.2}\t{rate_hz:.2}\t{n}\t{}\tm\t{rate_hz:.2}\t1\t{n}",
        Landmark::ALL.len()
    );
    out.push_str("Frame#\tTime");
    for lm in Landmark::ALL {
        let _ = write!(out, "\t{}\t\t", lm.name());
    }
    out.push_str("\n\t");
    for i in 1..=Landmark::ALL.len() {
        let _ = write!(out, "\tX{i}\tY{i}\tZ{i}");
    }
    out.push_str("\n\n");
    out
}

fn read_trc(text: &str, source_name: &str) -> Result<Vec<Skeleton3>> {
    let mut lines = text.lines();
    let header: Vec<&str> = lines.by_ref().take(5).collect();
    if header.len() < 5 || !header[0].starts_with("PathFileType") {
        return Err(parse_err(source_name, "(header)", "not a TRC file"));
    }
    let units = header[2].split('\t').nth(4).unwrap_or("m").trim();
    let scale = match units {
        "m" => 1.0,
        "mm" => 0.001,
        other => {
            return Err(parse_err(
                source_name,
                "Units",
                format!("unsupported unit `{other}`"),
            ))
        }
    };
    let names: Vec<Option<Landmark>> = header[3]
        .split('\t')
        .skip(2)
        .filter(|s| !s.trim().is_empty())
        .map(|s| Landmark::from_name(s.trim()))
        .collect();
    let mut frames = Vec::new();
    for (line_no, line) in lines.enumerate().filter(|(_, l)| !l.trim().is_empty()) {
        let cols: Vec<&str> = line.split('\t').collect();
        let field = |c: usize| cols.get(c).map_or("", |s| s.trim());
        let time: f64 = field(1).parse().map_err(|_| {
            parse_err(
                source_name,
                format!("line {}: Time", line_no + 6),
                format!("`{}`", field(1)),
            )
        })?;
        let mut s = Skeleton3::empty((time * 1e9).round() as i64);
        for (m, lm) in names.iter().enumerate() {
            let Some(lm) = lm else { continue };
            let xyz: Vec<&str> = (0..3).map(|a| field(2 + 3 * m + a)).collect();
            if xyz
                .iter()
                .any(|v| v.is_empty() || v.eq_ignore_ascii_case("nan"))
            {
                continue;
            }
            let mut p = [0.0; 3];
            for (a, v) in xyz.iter().enumerate() {
                p[a] = v.parse::<f64>().map_err(|_| {
                    parse_err(
                        source_name,
                        format!("line {}: {}", line_no + 6, lm.name()),
                        format!("`{v}`"),
                    )
                })? * scale;
            }
            let e = LandmarkEstimate {
                position_m: Point3::from(p),
                confidence: 1.0,
                reprojection_error_px: None,
                views: 0,
                position_sd_m: None,
            };
            s.set(*lm, Some(e))
                .map_err(|err| parse_err(source_name, format!("line {}", line_no + 6), err))?;
        }
        frames.push(s);
    }
    Ok(frames)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn recording() -> Vec<Skeleton3> {
        (0..3)
            .map(|k| {
                let mut s = Skeleton3::empty(k * 100_000_000);
                for (i, lm) in Landmark::ALL
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| !(i + k as usize).is_multiple_of(4))
                {
                    let e = LandmarkEstimate {
                        position_m: Point3::new(i as f64 * 0.01, -0.5 + k as f64 * 0.1, 1.25),
                        confidence: 0.75,
                        reprojection_error_px: Some(1.5),
                        views: 3,
                        position_sd_m: None,
                    };
                    s.set(*lm, Some(e)).unwrap();
                }
                s
            })
            .collect()
    }

    #[test]
    fn every_format_round_trips_positions_and_gaps() {
        let rec = recording();
        for format in [
            LandmarksFormat::Json,
            LandmarksFormat::Csv,
            LandmarksFormat::Trc,
        ] {
            let text = write_landmarks(&rec, format, "rec.trc", 10.0);
            let back = read_landmarks(&text, format, "rec").unwrap();
            assert_eq!(back.len(), rec.len(), "{format:?}");
            for (a, b) in rec.iter().zip(&back) {
                assert_eq!(a.stamp_nanos, b.stamp_nanos, "{format:?}");
                for lm in Landmark::ALL {
                    match (a.position(lm), b.position(lm)) {
                        (Some(p), Some(q)) => assert!((p - q).norm() < 2e-6, "{format:?} {lm}"),
                        (None, None) => {}
                        other => panic!("{format:?} {lm}: {other:?}"),
                    }
                }
            }
        }
    }

    /// Streamed with every piece taken as soon as there is one, the file is the whole-recording
    /// writer's at the rate of the stamps (10 Hz), not the fallback.
    #[test]
    fn a_streamed_file_is_the_whole_file_at_the_rate_of_its_stamps() {
        let rec = recording();
        for format in [
            LandmarksFormat::Json,
            LandmarksFormat::Csv,
            LandmarksFormat::Trc,
        ] {
            let mut e = StreamingEncoder::new(format, "rec.trc", 30.0, rec.len());
            for s in &rec {
                e.push(s.clone());
                // fewer frames than RATE_FRAMES: all held until the end
                assert_eq!(e.take_text_over(0), None, "{format:?}");
            }
            let (text, written) = e.finish();
            assert_eq!(written, rec.len(), "{format:?}");
            assert_eq!(
                text,
                write_landmarks(&rec, format, "rec.trc", 10.0),
                "{format:?}"
            );
        }
    }

    #[test]
    fn the_rate_comes_from_the_first_frames_or_the_fallback() {
        let n = StreamingEncoder::RATE_FRAMES + 1;
        let mut e = StreamingEncoder::new(LandmarksFormat::Trc, "r.trc", 30.0, n);
        for k in 0..StreamingEncoder::RATE_FRAMES - 1 {
            e.push(Skeleton3::empty(k as i64 * 50_000_000));
            assert_eq!(e.take_text_over(0), None);
        }
        e.push(Skeleton3::empty(999 * 50_000_000));
        let head = e.take_text_over(0).unwrap();
        // the header (five lines and a blank one) states 20 Hz and the frames announced; the held
        // frames follow it
        assert_eq!(
            head.lines().nth(2),
            Some("20.00\t20.00\t1001\t33\tm\t20.00\t1\t1001")
        );
        assert_eq!(head.lines().count(), 6 + StreamingEncoder::RATE_FRAMES);
        assert_eq!(e.take_text_over(0), None);
        e.push(Skeleton3::empty(1000 * 50_000_000));
        assert!(e
            .take_text_over(0)
            .unwrap()
            .starts_with("1001\t50.000000\t"));
        assert_eq!(e.finish(), (String::new(), n));
        // one frame: no interval, the fallback rate
        let mut one = StreamingEncoder::new(LandmarksFormat::Trc, "r.trc", 30.0, 1);
        one.push(Skeleton3::empty(0));
        let (text, written) = one.finish();
        assert_eq!(written, 1);
        assert_eq!(
            text.lines().nth(2),
            Some("30.00\t30.00\t1\t33\tm\t30.00\t1\t1")
        );
    }

    #[test]
    fn malformed_files_name_the_place() {
        let err = read_landmarks("frame,time_s\n1,2\n", LandmarksFormat::Csv, "x.csv")
            .unwrap_err()
            .to_string();
        assert!(err.contains("x.csv") && err.contains("row 2"), "{err}");
        let err = read_landmarks("hello", LandmarksFormat::Trc, "x.trc")
            .unwrap_err()
            .to_string();
        assert!(err.contains("not a TRC"), "{err}");
        assert!(LandmarksFormat::from_path(std::path::Path::new("a.txt")).is_err());
    }

    /// A landmark beyond 10 km of the origin (× 1e300, or a file not in metres) is refused naming
    /// the frame and landmark, in every format.
    #[test]
    fn landmarks_far_beyond_a_camera_rig_are_refused() {
        let mut rec = recording();
        let far = LandmarkEstimate {
            position_m: Point3::new(0.1e300, 0.0, 1.0),
            confidence: 0.75,
            reprojection_error_px: None,
            views: 2,
            position_sd_m: None,
        };
        rec[1].set(Landmark::LeftWrist, Some(far)).unwrap();
        for format in [
            LandmarksFormat::Json,
            LandmarksFormat::Csv,
            LandmarksFormat::Trc,
        ] {
            let text = write_landmarks(&rec, format, "rec.trc", 10.0);
            let err = read_landmarks(&text, format, "rec")
                .unwrap_err()
                .to_string();
            assert!(
                err.contains("frame 1, left_wrist") && err.contains("from the origin"),
                "{format:?}: {err}"
            );
        }
    }
}
