//! `ergocell exposure` end to end: a session's numbers are the report's (the streamed reader and
//! the whole-file reader agree); sessions add up per operator and week as seconds; a recording
//! named twice counts once; what cannot be read is named and left out; the operator is the
//! recording's pseudonymous id.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};
use std::process::Command;

mod common;
use common::Scratch;

fn ergocell(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .output()
        .unwrap()
}

fn rows(path: &Path) -> Vec<csv::StringRecord> {
    csv::Reader::from_path(path)
        .unwrap()
        .records()
        .map(Result::unwrap)
        .collect()
}

fn header(path: &Path) -> csv::StringRecord {
    csv::Reader::from_path(path)
        .unwrap()
        .headers()
        .unwrap()
        .clone()
}

/// The value of `column` in `row` of the file at `path`.
fn cell(path: &Path, row: &csv::StringRecord, column: &str) -> String {
    let k = header(path).iter().position(|h| h == column).unwrap();
    row[k].to_owned()
}

fn num(path: &Path, row: &csv::StringRecord, column: &str) -> f64 {
    cell(path, row, column).parse().unwrap()
}

fn exposure(inputs: &[&Path], out: &Path) -> std::process::Output {
    let mut args = vec!["exposure".to_owned()];
    args.extend(inputs.iter().map(|p| p.display().to_string()));
    args.extend(["--out".to_owned(), out.display().to_string()]);
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    ergocell(&args)
}

#[test]
fn a_sessions_exposure_is_the_reports_summary() {
    let scratch = Scratch::new("exposure-report");
    let rec = common::demo_recording("exposure-demo.mcap");
    let out = scratch.0.join("out");
    let o = exposure(&[rec], &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let html = scratch.0.join("r.html");
    let o = ergocell(&[
        "report",
        rec.to_str().unwrap(),
        "--out",
        html.to_str().unwrap(),
    ]);
    assert!(o.status.success());
    let html = std::fs::read_to_string(&html).unwrap();
    let start = html.find("window.ERGOCELL_REVIEW_DATA = ").unwrap() + 30;
    let end = start + html[start..].find(";</script>").unwrap();
    let data: serde_json::Value = serde_json::from_str(&html[start..end]).unwrap();
    let summary = &data["sessions"][0]["summary"];

    let sessions = out.join("sessions.csv");
    let all: Vec<_> = rows(&sessions);
    let whole = all
        .iter()
        .find(|r| cell(&sessions, r, "segment") == "all")
        .unwrap();
    assert_eq!(
        cell(&sessions, whole, "operator"),
        "demo-7",
        "demo's synthetic id"
    );
    let close = |a: f64, b: f64| (a - b).abs() < 1e-9 * b.abs().max(1.0);
    let duration = summary["duration_secs"].as_f64().unwrap();
    assert!(close(num(&sessions, whole, "duration_s"), duration));
    let scored = duration * (1.0 - summary["unscored_share"].as_f64().unwrap());
    for level in 1..=4 {
        let share = summary["action_level_share"][level - 1].as_f64().unwrap();
        assert!(close(
            num(&sessions, whole, &format!("rula_al{level}_s")),
            share * scored
        ));
    }
    assert!(scored > 0.0 && num(&sessions, whole, "rula_al1_s") > 0.0);
    // Every task segment the report shows, with its time.
    let phases = summary["phases"].as_array().unwrap();
    assert!(phases.len() >= 2, "{phases:?}");
    for p in phases {
        let row = all
            .iter()
            .find(|r| cell(&sessions, r, "segment") == p["phase"].as_str().unwrap())
            .unwrap();
        assert!(close(
            num(&sessions, row, "duration_s"),
            p["duration_secs"].as_f64().unwrap()
        ));
    }
    let parts = data["sessions"][0]["facts"]["parts_taken"]
        .as_array()
        .unwrap()
        .len();
    assert_eq!(num(&sessions, whole, "parts_taken") as usize, parts);
    assert!(parts >= 1);
}

fn demo(out: &Path, seed: &str, operator: &str, start: &str) {
    let o = ergocell(&[
        "demo",
        "--cycles",
        "1",
        "--seed",
        seed,
        "--operator",
        operator,
        "--start-time",
        start,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn sessions_add_up_per_operator_and_week_in_seconds() {
    let scratch = Scratch::new("exposure-weeks");
    let dir = scratch.0.join("shifts");
    std::fs::create_dir_all(dir.join("later")).unwrap();
    // Monday and Tuesday of ISO week 48 (2026), and the next Monday (week 49); in the past (the
    // demo's approvals are stamped at the start, and an approval from the future is refused).
    demo(&dir.join("mon.mcap"), "7", "op-a", "2026-11-23T06:00:00Z");
    demo(
        &dir.join("later/tue.mcap"),
        "8",
        "op-a",
        "2026-11-24T14:00:00+01:00",
    );
    demo(&dir.join("next.mcap"), "9", "op-b", "2026-11-30T06:00:00Z");
    std::fs::write(dir.join("notes.mcap"), b"not a recording").unwrap();
    let out = scratch.0.join("out");
    // The folder, and one recording in it again: counted once.
    let o = exposure(&[&dir, &dir.join("mon.mcap")], &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(stderr.contains("notes.mcap: left out"), "{stderr}");
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains("3 recording(s), 3 session(s), 1 left out"),
        "{stdout}"
    );

    let sessions = out.join("sessions.csv");
    let srows = rows(&sessions);
    let whole: Vec<_> = srows
        .iter()
        .filter(|r| cell(&sessions, r, "segment") == "all")
        .collect();
    assert_eq!(whole.len(), 3);
    let weeks: Vec<String> = whole.iter().map(|r| cell(&sessions, r, "week")).collect();
    assert_eq!(
        weeks,
        ["2026-W48", "2026-W48", "2026-W49"],
        "sorted by path: later/, mon, next"
    );
    let op_a: Vec<_> = whole
        .iter()
        .filter(|r| cell(&sessions, r, "operator") == "op-a")
        .collect();
    let sum = |c: &str| op_a.iter().map(|r| num(&sessions, r, c)).sum::<f64>();
    let expected = (sum("rula_al3_s") + sum("rula_al4_s")) / sum("rula_scored_s");

    let groups = out.join("exposure.csv");
    let g = rows(&groups);
    let week = g
        .iter()
        .find(|r| {
            cell(&groups, r, "operator") == "op-a"
                && cell(&groups, r, "period") == "week"
                && cell(&groups, r, "period_start") == "2026-W48"
                && cell(&groups, r, "class") == "all"
                && cell(&groups, r, "segment") == "all"
        })
        .unwrap();
    assert_eq!(num(&groups, week, "sessions"), 2.0);
    assert!((num(&groups, week, "rula_al3plus_share") - expected).abs() < 1e-12);
    let days: Vec<String> = g
        .iter()
        .filter(|r| {
            cell(&groups, r, "operator") == "op-a"
                && cell(&groups, r, "period") == "day"
                && cell(&groups, r, "class") == "all"
                && cell(&groups, r, "segment") == "all"
        })
        .map(|r| cell(&groups, r, "period_start"))
        .collect();
    assert_eq!(days, ["2026-11-23", "2026-11-24"]);
    // No landmark, angle or name in either file: ids, times, seconds and counts.
    for h in header(&groups).iter().chain(header(&sessions).iter()) {
        assert!(
            !h.contains("angle") && !h.contains("landmark") && !h.contains("name"),
            "{h}"
        );
    }

    // The page: each operator's weeks and days, no script, nothing fetched.
    let html = std::fs::read_to_string(out.join("exposure.html")).unwrap();
    for want in [
        "Operator op-a",
        "Operator op-b",
        "2026-W48",
        "2026-11-24",
        "default-src 'none'",
    ] {
        assert!(html.contains(want), "{want}");
    }
    assert!(!html.contains("<script"));
    assert!(std::fs::read(out.join("sessions.parquet"))
        .unwrap()
        .starts_with(b"PAR1"));

    // Run again onto the same folder: refused without --force, the files kept.
    let before = std::fs::read(&groups).unwrap();
    let o = exposure(&[&dir], &out);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--force"));
    assert_eq!(std::fs::read(&groups).unwrap(), before);
}

#[test]
fn bad_input_is_refused_with_a_reason() {
    let scratch = Scratch::new("exposure-bad");
    let junk = scratch.0.join("junk.mcap");
    std::fs::write(&junk, b"not a recording").unwrap();
    let o = exposure(&[&junk], &scratch.0.join("out"));
    assert_eq!(
        o.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(!scratch.0.join("out").exists(), "nothing written");
    let empty = scratch.0.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    let o = exposure(&[&empty], &scratch.0.join("out"));
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("no .mcap recording"));
    let o = exposure(
        &[&PathBuf::from("/nonexistent/x.mcap")],
        &scratch.0.join("out"),
    );
    assert_eq!(o.status.code(), Some(2));
    // A name is not an operator id.
    let o = ergocell(&["demo", "--operator", "Anna Schmidt", "--out", "/dev/null"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("never a name"));
    let o = ergocell(&["demo", "--start-time", "yesterday", "--out", "/dev/null"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("RFC 3339"));
}

#[test]
fn two_operators_in_one_recording_are_two_sessions_of_its_operator() {
    use ergocell_bridge::session_info::OperatorId;
    let scratch = Scratch::new("exposure-two");
    let path = scratch.0.join("two.mcap");
    let mut rec = ergocell::recording::McapRecorder::create(&path).unwrap();
    rec.write_operator(&OperatorId::new("op-7").unwrap())
        .unwrap();
    let epoch = 1_796_018_400 * 1_000_000_000; // 2026-11-30T06:00:00Z
    common::write_sessions(&mut rec, epoch, &[("c1", 1.60), ("c3", 1.90)], 50, 10);
    rec.finish().unwrap();
    let out = scratch.0.join("out");
    let o = exposure(&[&path], &out);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let sessions = out.join("sessions.csv");
    let r = rows(&sessions);
    let got: Vec<(String, String, String)> = r
        .iter()
        .map(|r| {
            (
                cell(&sessions, r, "operator"),
                cell(&sessions, r, "session"),
                cell(&sessions, r, "class"),
            )
        })
        .collect();
    let want = |a: &str, b: &str, c: &str| (a.to_owned(), b.to_owned(), c.to_owned());
    assert_eq!(got, [want("op-7", "1", "c1"), want("op-7", "2", "c3")]);
    // No RULA was recorded: unscored time, never a share.
    assert_eq!(num(&sessions, &r[0], "rula_scored_s"), 0.0);
    let groups = out.join("exposure.csv");
    assert!(rows(&groups)
        .iter()
        .all(|g| cell(&groups, g, "rula_al3plus_share").is_empty()));
}

/// `rec` rewritten with each message's log time replaced by `log_time(index, count, original)`
/// (metadata kept): a recording whose clock lies.
fn with_log_times(rec: &Path, out: &Path, log_time: impl Fn(u64, u64, u64) -> u64) {
    let bytes = std::fs::read(rec).unwrap();
    let count = mcap::MessageStream::new(&bytes).unwrap().count() as u64;
    let mut w =
        mcap::Writer::new(std::io::BufWriter::new(std::fs::File::create(out).unwrap())).unwrap();
    for record in mcap::read::LinearReader::new(&bytes).unwrap() {
        if let mcap::records::Record::Metadata(m) = record.unwrap() {
            w.write_metadata(&m).unwrap();
        }
    }
    for (k, m) in mcap::MessageStream::new(&bytes).unwrap().enumerate() {
        let mut m = m.unwrap();
        m.log_time = log_time(k as u64, count, m.log_time);
        m.publish_time = m.log_time;
        w.write(&m).unwrap();
    }
    w.finish().unwrap();
}

/// A recording whose log times disagree with its own capture stamps (one time for every message;
/// times running backwards) is read by the capture stamps, and says so: the exposure files the
/// session under the same day and week with the same seconds, and the report spans the same time,
/// through the whole-file reader and the overview's streamed one alike.
#[test]
fn a_recording_whose_clock_disagrees_with_its_capture_stamps_is_read_by_the_stamps() {
    // The demo's fixed-lag smoother, seconds.
    const FIXED_LAG_S: f64 = ergocell_cell::pipeline::DEFAULT_FIXED_LAG_S;
    let scratch = Scratch::new("exposure-clock");
    let rec = common::demo_recording("exposure-demo.mcap");
    // The honest recording's longest stretch without a camera frame (its log times are the
    // capture stamps).
    let longest_camera_gap_s = {
        let bytes = std::fs::read(rec).unwrap();
        let mut t: Vec<u64> = mcap::MessageStream::new(&bytes)
            .unwrap()
            .map(Result::unwrap)
            .filter(|m| {
                m.channel
                    .topic
                    .starts_with(ergocell_bridge::topics::CAMERA_PREFIX)
            })
            .map(|m| m.log_time)
            .collect();
        t.sort_unstable();
        t.windows(2).map(|w| w[1] - w[0]).max().unwrap_or(0) as f64 * 1e-9
    };
    // The whole-file reader, and the overview's streamed one keeping every frame.
    let overview: &[&str] = &[
        "--page-frames",
        "overview",
        "--overview-frames",
        "1000000",
        "--window-frames",
        "1000000",
    ];
    let report_with = |r: &Path, name: &str, extra: &[&str]| {
        let html = scratch.0.join(name);
        let mut args = vec![
            "report",
            r.to_str().unwrap(),
            "--out",
            html.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let o = ergocell(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let html = std::fs::read_to_string(&html).unwrap();
        let start = html.find("window.ERGOCELL_REVIEW_DATA = ").unwrap() + 30;
        let end = start + html[start..].find(";</script>").unwrap();
        let data: serde_json::Value = serde_json::from_str(&html[start..end]).unwrap();
        data["sessions"][0].clone()
    };
    let report_of = |r: &Path, name: &str| report_with(r, name, &[]);
    let original = report_of(rec, "original.html");
    let span = |s: &serde_json::Value| {
        s["frames"]["t"]
            .as_array()
            .unwrap()
            .last()
            .unwrap()
            .as_f64()
            .unwrap()
    };
    let problems = |s: &serde_json::Value| s["source"]["problems"].as_array().unwrap().len();
    let o = exposure(&[rec], &scratch.0.join("original"));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let sessions = scratch.0.join("original/sessions.csv");
    let honest = rows(&sessions);
    // one time for every message (a clock that never ran); then times running backwards from a day
    // later
    let constant = scratch.0.join("constant.mcap");
    with_log_times(rec, &constant, |_, _, _| 1);
    let reversed = scratch.0.join("reversed.mcap");
    let day = 86_400_000_000_000u64;
    with_log_times(rec, &reversed, |k, n, t| t + day + (n - k) * 100_000_000);
    for (lying, name) in [(&constant, "constant"), (&reversed, "reversed")] {
        let s = report_of(lying, &format!("{name}.html"));
        // the overview's reader reads the same frames at the same times and names the clock too
        // (its first disagreeing message is the file's first, the whole-file reader's the first
        // in log-time order)
        let streamed = report_with(lying, &format!("{name}-overview.html"), overview);
        assert_eq!(
            streamed["frames"]["t"], s["frames"]["t"],
            "{name}: overview"
        );
        assert_eq!(problems(&streamed), problems(&s), "{name}: overview");
        // thinned to a small page: frames kept (a constant clock once kept none), each one of the
        // whole-file reader's at its time
        let thin = report_with(
            lying,
            &format!("{name}-thin.html"),
            &[
                "--page-frames",
                "overview",
                "--overview-frames",
                "20",
                "--window-frames",
                "20",
            ],
        );
        let times = |v: &serde_json::Value| -> Vec<f64> {
            v["frames"]["t"]
                .as_array()
                .unwrap()
                .iter()
                .map(|t| t.as_f64().unwrap())
                .collect()
        };
        let (kept, all) = (times(&thin), times(&s));
        assert!(
            !kept.is_empty() && kept.len() < all.len(),
            "{name}: {} of {}",
            kept.len(),
            all.len()
        );
        assert!(kept.iter().all(|t| all.contains(t)), "{name}");
        assert_eq!(
            s["frames"]["t"].as_array().unwrap().len(),
            original["frames"]["t"].as_array().unwrap().len(),
            "{name}"
        );
        // read by the capture stamps: the first frame's capture precedes its logging by under a
        // frame period
        assert!(
            (span(&s) - span(&original)).abs() < 0.1,
            "{name}: {} s against {} s",
            span(&s),
            span(&original)
        );
        // named: one problem more than the honest recording's
        assert_eq!(
            problems(&s),
            problems(&original) + 1,
            "{name}: {}",
            s["source"]["problems"]
        );
        let out = scratch.0.join(name);
        let o = exposure(&[lying], &out);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        // the same rows: each column as the honest recording's but the file's name, and the start
        // (its first capture rather than its first logging) within a frame period
        let lying_sessions = out.join("sessions.csv");
        let got = rows(&lying_sessions);
        assert_eq!(got.len(), honest.len(), "{name}");
        for (g, h) in got.iter().zip(&honest) {
            for column in ["operator", "day", "week", "class", "segment", "parts_taken"] {
                assert_eq!(
                    cell(&lying_sessions, g, column),
                    cell(&sessions, h, column),
                    "{name}: {column}"
                );
            }
            // the whole session's seconds exactly; a segment's within the fixed lag and the
            // longest stretch without a camera frame: the robot's commands carry no capture stamp
            // of their own (stamp 0 is "now" to the controller) and are placed at the latest
            // stamp read before them, which a camera blackout holds back
            let seconds = |p: &Path, r: &csv::StringRecord| num(p, r, "duration_s");
            let off = (seconds(&lying_sessions, g) - seconds(&sessions, h)).abs();
            let whole = cell(&sessions, h, "segment") == "all";
            assert!(
                if whole {
                    off < 1e-9
                } else {
                    off < FIXED_LAG_S + longest_camera_gap_s + 0.05
                },
                "{name}: {} off by {off} s",
                cell(&sessions, h, "segment")
            );
            let start = |p: &Path, r: &csv::StringRecord| num(p, r, "start_unix_s");
            assert!(
                (start(&lying_sessions, g) - start(&sessions, h)).abs() < 0.1,
                "{name}"
            );
        }
    }
}
