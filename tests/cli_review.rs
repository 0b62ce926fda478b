//! `ergocell review` and `ergocell report` end to end on a recording made here by `ergocell demo`:
//! the analysis holds the session (frames, RULA, height, class, lock, approvers, robot TCP); the
//! server serves only that recording's page (no path traversal) and only to the loopback host it
//! printed; a truncated recording is read up to the cut and says so; a foreign MCAP and a non-MCAP
//! file are refused with what could be read.

// Test helpers outside `#[test]` functions unwrap too (clippy.toml allows it only inside them).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::BTreeMap;
use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::Command;

mod common;
use common::ReviewServer;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn tmp(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name)
}

/// One short demo session, recorded once for all tests of this file.
fn demo_recording() -> &'static Path {
    common::demo_recording("review-demo.mcap")
}

fn ergocell(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_ergocell"))
        .current_dir(root())
        .args(args)
        .output()
        .unwrap()
}

/// The data a report embeds.
fn report_data(html: &str) -> serde_json::Value {
    let start = html.find("window.ERGOCELL_REVIEW_DATA = ").unwrap() + 30;
    let end = start + html[start..].find(";</script>").unwrap();
    serde_json::from_str(&html[start..end]).unwrap()
}

fn report(rec: &Path, name: &str) -> (std::process::Output, Option<serde_json::Value>) {
    let out = tmp(name);
    let _ = std::fs::remove_file(&out);
    let o = ergocell(&[
        "report",
        rec.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    let data = std::fs::read_to_string(&out).ok().map(|h| report_data(&h));
    (o, data)
}

#[test]
fn report_holds_the_whole_session() {
    let (o, data) = report(demo_recording(), "review-report.html");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let data = data.unwrap();
    assert_eq!(data["version"], 1);
    let s = &data["sessions"][0];
    assert_eq!(s["source"]["complete"], true);
    assert_eq!(s["source"]["problems"].as_array().unwrap().len(), 0);
    // The demo operator is 1.69 m, 1 cm above the c1/c2 boundary: measured within 2 cm, served by
    // c1 across the boundary (the decision's basis, probability and expected cost recorded), locked
    // and (demo-)approved.
    let h = s["facts"]["height_m"].as_f64().unwrap();
    assert!((h - 1.69).abs() < 0.02, "height {h}");
    assert_eq!(s["facts"]["height_class"], "c1");
    assert_eq!(s["facts"]["decision_basis"], "expected_rula");
    let p = s["facts"]["class_probability"].as_f64().unwrap();
    let cost = s["facts"]["expected_rula_cost"].as_f64().unwrap();
    // across the boundary neither class is certain, and the class chosen for its lower expected
    // RULA costs nothing in expectation
    assert!(
        (0.05..0.95).contains(&p) && (-1.0..=0.0).contains(&cost),
        "{p} {cost}"
    );
    assert_eq!(s["facts"]["trajectory_sha256"].as_str().unwrap().len(), 64);
    assert!(!s["facts"]["approved_by"].as_array().unwrap().is_empty());
    let states: Vec<&str> = s["facts"]["states"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x["state"].as_str().unwrap())
        .collect();
    assert!(states.contains(&"working") && states.contains(&"session_ended"));

    let f = &s["frames"];
    let n = f["t"].as_array().unwrap().len();
    assert!(n > 50, "{n} frames");
    for key in [
        "positions",
        "strain",
        "grand_left",
        "grand_right",
        "action_level",
    ] {
        assert_eq!(f[key].as_array().unwrap().len(), n, "{key}");
    }
    let times: Vec<f64> = f["t"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert!(times.windows(2).all(|w| w[0] < w[1]), "time increases");
    // Every frame has 99 coordinates and 33 strains in 0..1; a standing operator's nose is 1.4–1.9 m up.
    let mut scored = 0;
    for (k, row) in f["positions"].as_array().unwrap().iter().enumerate() {
        let row = row.as_array().unwrap();
        assert_eq!(row.len(), 99);
        if let Some(z) = row[2].as_f64() {
            assert!((0.3..2.1).contains(&z), "nose z {z}");
        }
        let strain = f["strain"][k].as_array().unwrap();
        assert_eq!(strain.len(), 33);
        for v in strain.iter().filter_map(serde_json::Value::as_f64) {
            assert!((0.0..=1.0).contains(&v));
        }
        if f["grand_right"][k].is_u64() {
            scored += 1;
            let g = f["grand_right"][k].as_u64().unwrap();
            assert!((1..=7).contains(&g));
        }
    }
    assert!(scored > n / 2, "{scored} of {n} frames scored");
    // Regions: shares of each region sum to 1 where it was scored.
    for r in s["regions"].as_array().unwrap() {
        if r["samples"].as_u64().unwrap() > 0 {
            let sum: f64 = r["time_share"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .sum();
            assert!((sum - 1.0).abs() < 1e-9, "{r}");
        }
    }
    let angles: Vec<&str> = s["angles"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a["name"].as_str().unwrap())
        .collect();
    assert!(angles.contains(&"trunk flexion") && angles.contains(&"elbow flexion"));
    // The robot: a TCP track inside the cell and the handover point in front of the operator.
    let tcp = s["robot"]["tcp"]["positions"].as_array().unwrap();
    assert!(tcp.len() > 50);
    let hp = s["robot"]["handover_point"].as_array().unwrap();
    let hz = hp[2].as_f64().unwrap();
    assert!((0.8..1.6).contains(&hz), "handover height {hz}");
    // The cell's cycle: the legs the robot was sent alternate, home → handover first; the twin's
    // controller answers as a real one, so each leg ends at its reported result.
    let legs = s["robot"]["legs"].as_array().unwrap();
    assert!(legs.len() >= 2, "{legs:?}");
    for (k, leg) in legs.iter().enumerate() {
        let name = if k % 2 == 0 {
            "home → handover"
        } else {
            "handover → home"
        };
        assert_eq!(leg["leg"], name, "leg {k}: {leg}");
        let (a, b) = (
            leg["t_start"].as_f64().unwrap(),
            leg["t_end"].as_f64().unwrap(),
        );
        assert!(b > a, "leg {k}: {leg}");
        assert!(leg["planned_s"].as_f64().unwrap() > 0.0, "leg {k}: {leg}");
        if leg["end_known"] == true {
            assert_eq!(leg["outcome"], "succeeded", "leg {k}: {leg}");
        }
    }
    assert!(
        legs.iter().filter(|l| l["end_known"] == true).count() >= 2,
        "{legs:?}"
    );
    // The driver's readiness, as a KUKA driver's is recorded: ready before the first leg.
    let driver: Vec<&str> = s["robot"]["events"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["kind"] == "driver")
        .map(|e| e["status"].as_str().unwrap())
        .collect();
    assert_eq!(driver.last(), Some(&"ready"), "{driver:?}");
}

#[test]
fn a_truncated_recording_is_read_up_to_the_cut_and_says_so() {
    let bytes = std::fs::read(demo_recording()).unwrap();
    let cut = tmp("review-cut.mcap");
    std::fs::write(&cut, &bytes[..bytes.len() * 6 / 10]).unwrap();
    let (o, data) = report(&cut, "review-cut.html");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(stderr.contains("cut short"), "{stderr}");
    let s = &data.unwrap()["sessions"][0];
    assert_eq!(s["source"]["complete"], false);
    assert!(!s["source"]["problems"].as_array().unwrap().is_empty());
    let (_, full) = report(demo_recording(), "review-full.html");
    let n_full = full.unwrap()["sessions"][0]["frames"]["t"]
        .as_array()
        .unwrap()
        .len();
    let n_cut = s["frames"]["t"].as_array().unwrap().len();
    assert!(n_cut > 0 && n_cut < n_full, "{n_cut} of {n_full}");
}

#[test]
fn a_foreign_mcap_and_a_non_mcap_file_are_refused_with_what_could_be_read() {
    let foreign = tmp("review-foreign.mcap");
    {
        let mut w = mcap::Writer::new(std::io::BufWriter::new(
            std::fs::File::create(&foreign).unwrap(),
        ))
        .unwrap();
        let schema = w
            .add_schema("std_msgs/msg/String", "ros2msg", b"string data\n")
            .unwrap();
        let channel = w
            .add_channel(schema, "/chatter", "cdr", &BTreeMap::new())
            .unwrap();
        for k in 0..3u64 {
            w.write_to_known_channel(
                &mcap::records::MessageHeader {
                    channel_id: channel,
                    sequence: k as u32,
                    log_time: k,
                    publish_time: k,
                },
                &[0, 1, 0, 0, 3, 0, 0, 0, b'h', b'i', 0, 0],
            )
            .unwrap();
        }
        w.finish().unwrap();
    }
    let (o, _) = report(&foreign, "review-foreign.html");
    assert_eq!(o.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        stderr.contains("not an ergocell session recording") && stderr.contains("/chatter"),
        "{stderr}"
    );
    assert!(stderr.contains("std_msgs/msg/String"), "{stderr}");

    let text = tmp("review-not-mcap.mcap");
    std::fs::write(&text, "hello, I am a text file\n").unwrap();
    let (o, _) = report(&text, "review-text.html");
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("not a readable MCAP file"));
}

fn serve(rec: &Path) -> ReviewServer {
    let server = ReviewServer::start(&root(), rec, &[]);
    assert!(
        server.url.starts_with("http://127.0.0.1:"),
        "{}",
        server.url
    );
    server
}

/// A raw HTTP/1.1 request (the target is sent verbatim, so `..` reaches the server unnormalised):
/// (status, headers + body).
fn get(port: u16, method: &str, target: &str, host: &str) -> (u16, String) {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    write!(
        s,
        "{method} {target} HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut buf = Vec::new();
    if let Err(e) = s.read_to_end(&mut buf) {
        panic!(
            "{method} {target} (Host {host}): {e}; read {} bytes",
            buf.len()
        );
    }
    let text = String::from_utf8_lossy(&buf).into_owned();
    let status = text
        .split_whitespace()
        .nth(1)
        .and_then(|c| c.parse().ok())
        .unwrap_or(0);
    (status, text)
}

#[test]
fn the_server_serves_only_the_recordings_review_and_only_to_loopback() {
    let server = serve(demo_recording());
    let host = format!("127.0.0.1:{}", server.port);
    let (status, page) = get(server.port, "GET", "/", &host);
    assert_eq!(status, 200);
    assert!(page.contains("<div id=\"app\"></div>") && page.contains("assets/review.js"));
    assert!(page
        .to_ascii_lowercase()
        .contains("content-security-policy"));
    let (status, js) = get(server.port, "GET", "/assets/review.js", &host);
    assert_eq!(status, 200);
    assert!(js.len() > 1000);
    let (status, json) = get(server.port, "GET", "/api/review.json", &host);
    assert_eq!(status, 200);
    let body = &json[json.find("\r\n\r\n").unwrap() + 4..];
    let data: serde_json::Value = serde_json::from_str(body).unwrap();
    assert_eq!(data["sessions"][0]["facts"]["height_class"], "c1");
    // `localhost` works too.
    assert_eq!(
        get(
            server.port,
            "GET",
            "/",
            &format!("localhost:{}", server.port)
        )
        .0,
        200
    );

    // No path reaches the file system: the recording, the repository, /etc.
    let rec_path = demo_recording().to_str().unwrap().to_owned();
    for target in [
        "/assets/../Cargo.toml",
        "/assets/..%2f..%2fCargo.toml",
        "/%2e%2e/%2e%2e/Cargo.toml",
        "/api/review.json/../../Cargo.toml",
        "/../../../../etc/passwd",
        "/review-demo.mcap",
        "/Cargo.toml",
        "/assets/",
        rec_path.as_str(),
    ] {
        let (status, text) = get(server.port, "GET", target, &host);
        assert!(status == 404 || status == 400, "{target}: {status}");
        assert!(
            !text.contains("[package]") && !text.contains("root:"),
            "{target}"
        );
        assert!(
            !text.as_bytes().windows(5).any(|w| w == b"\x89MCAP"),
            "{target}"
        );
    }
    // Other hosts (DNS rebinding) and other methods are refused.
    assert_eq!(get(server.port, "GET", "/", "evil.example").0, 403);
    assert_eq!(
        get(server.port, "GET", "/api/review.json", "evil.example:80").0,
        403
    );
    assert_eq!(get(server.port, "POST", "/", &host).0, 405);
    // Nothing but loopback is listening: the server is not reachable on another address of this
    // machine (when it has one).
    if let Some(ip) = non_loopback_ip() {
        assert!(
            TcpStream::connect((ip, server.port)).is_err(),
            "review reachable on {ip}"
        );
    }
}

/// An address of this machine that is not loopback, if any (the source address of a UDP socket
/// "connected" to a public address; nothing is sent).
fn non_loopback_ip() -> Option<std::net::IpAddr> {
    let s = std::net::UdpSocket::bind("0.0.0.0:0").ok()?;
    s.connect("192.0.2.1:9").ok()?;
    let ip = s.local_addr().ok()?.ip();
    (!ip.is_loopback() && !ip.is_unspecified()).then_some(ip)
}

#[test]
fn a_damaged_chunk_is_skipped_and_named_and_the_rest_is_read() {
    let mut bytes = std::fs::read(demo_recording()).unwrap();
    // One flipped byte in the middle of the file (inside a chunk's messages).
    let k = bytes.len() / 2;
    bytes[k] ^= 0xff;
    let bad = tmp("review-damaged.mcap");
    std::fs::write(&bad, &bytes).unwrap();
    let (o, data) = report(&bad, "review-damaged.html");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(stderr.contains("skipped"), "{stderr}");
    let s = &data.unwrap()["sessions"][0];
    assert_eq!(s["source"]["complete"], false);
    let (_, full) = report(demo_recording(), "review-undamaged.html");
    let n_full = full.unwrap()["sessions"][0]["frames"]["t"]
        .as_array()
        .unwrap()
        .len();
    let n = s["frames"]["t"].as_array().unwrap().len();
    assert!(n > n_full / 2 && n < n_full, "{n} of {n_full} frames");
}

/// A recording of two operator sessions, as `ergocell run --record` writes them one after another.
fn two_sessions() -> PathBuf {
    let path = tmp("review-two-sessions.mcap");
    let mut rec = ergocell::recording::McapRecorder::create(&path).unwrap();
    common::write_sessions(&mut rec, 0, &[("c1", 1.60), ("c3", 1.90)], 50, 10);
    rec.finish().unwrap();
    path
}

#[test]
fn a_recording_of_two_operators_is_reviewed_one_session_at_a_time() {
    let rec = two_sessions();
    let html = tmp("review-two.html");
    let run = |extra: &[&str]| {
        // One page, written again for each session: overwritten on purpose.
        let mut args = vec![
            "report",
            rec.to_str().unwrap(),
            "--out",
            html.to_str().unwrap(),
            "--force",
        ];
        args.extend_from_slice(extra);
        let o = ergocell(&args);
        let data = o
            .status
            .success()
            .then(|| report_data(&std::fs::read_to_string(&html).unwrap()));
        (o, data)
    };
    let (o, data) = run(&[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = &data.unwrap()["sessions"][0];
    assert_eq!(s["facts"]["height_class"], "c1", "session 1 by default");
    assert_eq!(s["frames"]["t"].as_array().unwrap().len(), 50);
    let problems = s["source"]["problems"].to_string();
    assert!(problems.contains("2 operator sessions"), "{problems}");
    let (o, data) = run(&["--session", "2"]);
    assert!(o.status.success());
    let s = &data.unwrap()["sessions"][0];
    assert_eq!(s["facts"]["height_class"], "c3");
    assert!((s["facts"]["height_m"].as_f64().unwrap() - 1.90).abs() < 1e-12);
    assert_eq!(s["frames"]["t"].as_array().unwrap().len(), 50);
    let (o, _) = run(&["--session", "3"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("2 operator session"));
}

#[test]
fn an_overview_reads_each_session_as_the_whole_file_reader_does() {
    // With every frame kept (a short recording), the streamed page is the whole-file reader's:
    // the same sessions and their bounds, late answers, clock, label, problems and numbers.
    let recordings = [
        (two_sessions(), 2),
        (robot_cycle(), 2),
        (demo_recording().to_path_buf(), 1),
    ];
    for (rec, sessions) in &recordings {
        for session in 1..=*sessions {
            let n = session.to_string();
            let (_, all) = report_with(
                rec,
                "sessions-all.html",
                &["--session", &n, "--page-frames", "all"],
            );
            let (_, over) = report_with(
                rec,
                "sessions-overview.html",
                &["--session", &n, "--page-frames", "overview"],
            );
            assert_eq!(all, over, "{} session {session}", rec.display());
        }
        let o = ergocell(&[
            "report",
            rec.to_str().unwrap(),
            "--session",
            &(sessions + 1).to_string(),
            "--page-frames",
            "overview",
            "--force",
            "--out",
            tmp("sessions-none.html").to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(2));
        assert!(
            String::from_utf8_lossy(&o.stderr).contains(&format!("{sessions} operator session"))
        );
    }
    // Thinned, session 2 of two is still session 2: its class, its clock, its summary.
    let rec = two_sessions();
    let (_, all) = report_with(
        &rec,
        "sessions-all2.html",
        &["--session", "2", "--page-frames", "all"],
    );
    let (_, over) = report_with(
        &rec,
        "sessions-over2.html",
        &[
            "--session",
            "2",
            "--page-frames",
            "overview",
            "--overview-frames",
            "5",
            "--window-frames",
            "10",
        ],
    );
    let (a, b) = (&all["sessions"][0], &over["sessions"][0]);
    assert!(
        b["frames"]["t"].as_array().unwrap().len() < a["frames"]["t"].as_array().unwrap().len()
    );
    for key in ["label", "facts", "summary", "regions", "angles", "warnings"] {
        assert_eq!(a[key], b[key], "{key}");
    }
    assert_eq!(a["source"]["problems"], b["source"]["problems"]);
}

#[test]
fn the_allowed_host_is_the_bound_address_and_two_hosts_are_refused() {
    let server = ReviewServer::start(&root(), demo_recording(), &["--bind", "127.0.0.2"]);
    let (authority, port) = (server.authority.clone(), server.port);
    assert!(authority.starts_with("127.0.0.2:"), "{}", server.url);
    let get2 = |host_lines: &str| {
        let mut s = TcpStream::connect(("127.0.0.2", port)).unwrap();
        write!(s, "GET / HTTP/1.1\r\n{host_lines}Connection: close\r\n\r\n").unwrap();
        let mut buf = String::new();
        let _ = s.read_to_string(&mut buf);
        buf.split_whitespace().nth(1).unwrap_or("").to_owned()
    };
    assert_eq!(get2(&format!("Host: {authority}\r\n")), "200");
    assert_eq!(get2(&format!("Host: localhost:{port}\r\n")), "200");
    assert_eq!(get2(&format!("Host: 127.0.0.1:{port}\r\n")), "403");
    assert_eq!(
        get2(&format!("Host: {authority}\r\nHost: evil.example\r\n")),
        "400"
    );
    drop(server);

    // An SSH tunnel's Host is accepted when named (`--allow-host`), and only then.
    let server = ReviewServer::start(
        &root(),
        demo_recording(),
        &["--allow-host", "localhost:9000"],
    );
    assert_eq!(get(server.port, "GET", "/", "localhost:9000").0, 200);
    assert_eq!(get(server.port, "GET", "/", "localhost:9001").0, 403);
    drop(server);
}

/// A recording of the cell's cycle as `ergocell run --record` writes it in action mode: each leg's
/// `JointTrajectory` with its `goal_sent`, the controller's answers (feedback, results), a hold, a
/// part taken, and a late `finished` after `session_ended`; then a second operator whose one leg
/// gets no answer (topic mode), with a driver event right after the first session.
fn robot_cycle() -> PathBuf {
    use ergocell::recording::{topics, McapRecorder};
    use ergocell_bridge::msg::{
        ControllerEvent, Duration, Header, JointTrajectory, JointTrajectoryPoint, OperatorPose,
        SessionState,
    };
    /// One message of the recording (the recorder's log times never go back: written in order).
    enum Msg {
        State(SessionState),
        Pose(OperatorPose),
        Command(JointTrajectory),
        Event(ControllerEvent),
    }
    let s = 1_000_000_000i64;
    let ms = 1_000_000i64;
    let home = [0.0, -1.57, 1.57];
    let handover = [0.4, -1.1, 1.2];
    let leg = |from: [f64; 3], to: [f64; 3]| {
        Msg::Command(JointTrajectory {
            joint_names: vec!["a1".into(), "a2".into(), "a3".into()],
            points: [(from, 0.0), (to, 2.0)]
                .iter()
                .map(|(q, t)| JointTrajectoryPoint {
                    positions: q.to_vec(),
                    time_from_start: Duration::from_secs_f64(*t),
                    ..JointTrajectoryPoint::default()
                })
                .collect(),
            ..JointTrajectory::default()
        })
    };
    // The leg as `ergocell run` records it: its constant and its words.
    let event = |t: i64, kind: &str, leg: &str| ControllerEvent {
        header: Header::new(t, ""),
        kind: kind.to_owned(),
        leg: leg.to_owned(),
        leg_id: match leg {
            "home → handover" => ControllerEvent::LEG_TO_HANDOVER,
            "handover → home" => ControllerEvent::LEG_TO_HOME,
            _ => ControllerEvent::LEG_NONE,
        },
        max_error: f64::NAN,
        ..ControllerEvent::default()
    };
    let finished = |t: i64, leg: &str, status: &str, count: u32| ControllerEvent {
        status: status.to_owned(),
        feedback_count: count,
        ..event(t, "finished", leg)
    };
    let state = |t: i64, name: &str, reason: &str| SessionState {
        header: Header::new(t, "world"),
        state: name.to_owned(),
        reason: reason.to_owned(),
        height_m: 1.75,
        height_class: "c2".to_owned(),
        ..SessionState::default()
    };
    let (ho, hh) = ("home → handover", "handover → home");
    let mut messages: Vec<(i64, Msg)> = Vec::new();
    for k in 0..2 {
        let t0 = k * 20 * s;
        messages.push((t0, Msg::State(state(t0, "working", ""))));
        for f in 0..120 {
            let t = t0 + f * s / 10;
            let pose = OperatorPose {
                header: Header::new(t, "world"),
                x: vec![0.0; 33],
                y: vec![0.0; 33],
                z: vec![1.0; 33],
                ..OperatorPose::default()
            };
            messages.push((t, Msg::Pose(pose)));
        }
        let end = t0 + 12 * s;
        messages.push((
            end,
            Msg::State(state(end, "session_ended", "the operator left")),
        ));
    }
    let mut add = |t: i64, m: Msg| messages.push((t, m));
    // Session 1. Leg 1 at 1 s, home → handover: accepted, three feedback messages, succeeded.
    add(s, leg(home, handover));
    add(s, Msg::Event(event(s, "goal_sent", ho)));
    add(s + 10 * ms, Msg::Event(event(s + 10 * ms, "accepted", ho)));
    for (t, count, err) in [(1100, 1, 0.002), (2000, 25, f64::NAN), (2900, 50, 0.003)] {
        let e = ControllerEvent {
            feedback_count: count,
            max_error: err,
            ..event(t * ms, "feedback", ho)
        };
        add(t * ms, Msg::Event(e));
    }
    add(
        3100 * ms,
        Msg::Event(finished(3100 * ms, ho, "succeeded", 52)),
    );
    // The operator takes the part at 4 s; leg 2 at 5 s, handover → home, held at 6 s: canceled.
    let taken = "part 1 taken: the operator's left hand came to 0.052 m of the handover point and left it; robot going home for the next part";
    add(4 * s, Msg::State(state(4 * s, "working", taken)));
    add(5 * s, leg(handover, home));
    add(5 * s, Msg::Event(event(5 * s, "goal_sent", hh)));
    let hold = JointTrajectory {
        header: Header::new(6 * s, ""),
        ..JointTrajectory::default()
    };
    add(6 * s, Msg::Command(hold));
    add(6 * s, Msg::Event(event(6 * s, "cancel_requested", hh)));
    add(
        6050 * ms,
        Msg::Event(finished(6050 * ms, hh, "canceled", 20)),
    );
    // Leg 3 at 8 s, home again; its result comes 1.5 s after the session ended (12 s).
    add(8 * s, leg([0.2, -1.3, 1.4], home));
    add(8 * s, Msg::Event(event(8 * s, "goal_sent", hh)));
    add(
        13_500 * ms,
        Msg::Event(finished(13_500 * ms, hh, "succeeded", 51)),
    );
    // The driver's state right after: about no leg, so the next session's.
    let driver = ControllerEvent {
        status: "ready".to_owned(),
        ..event(13_600 * ms, "driver", "")
    };
    add(13_600 * ms, Msg::Event(driver));
    // Session 2 (20–32 s): one leg in topic mode, nothing answers it.
    add(21 * s, leg(home, handover));
    messages.sort_by_key(|(t, _)| *t);

    let path = tmp("review-robot-cycle.mcap");
    let mut rec = McapRecorder::create(&path).unwrap();
    for (t, m) in &messages {
        match m {
            Msg::State(m) => rec.write(topics::SESSION_STATE, *t, m),
            Msg::Pose(m) => rec.write(topics::OPERATOR_POSE, *t, m),
            Msg::Command(m) => rec.write(topics::JOINT_TRAJECTORY, *t, m),
            Msg::Event(m) => rec.write(topics::CONTROLLER_EVENTS, *t, m),
        }
        .unwrap();
    }
    rec.finish().unwrap();
    path
}

#[test]
fn the_review_shows_each_robot_leg_and_the_controllers_events() {
    let rec = robot_cycle();
    let data = |session: &str| {
        let html = tmp(&format!("review-robot-{session}.html"));
        let o = ergocell(&[
            "report",
            rec.to_str().unwrap(),
            "--session",
            session,
            "--out",
            html.to_str().unwrap(),
            "--force",
        ]);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        report_data(&std::fs::read_to_string(&html).unwrap())["sessions"][0].clone()
    };
    let s = data("1");
    let legs = s["robot"]["legs"].as_array().unwrap();
    let summary: Vec<(&str, f64, f64, &str, bool)> = legs
        .iter()
        .map(|l| {
            (
                l["leg"].as_str().unwrap(),
                l["t_start"].as_f64().unwrap(),
                l["t_end"].as_f64().unwrap(),
                l["outcome"].as_str().unwrap(),
                l["end_known"].as_bool().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        summary,
        [
            ("home → handover", 1.0, 3.1, "succeeded", true),
            ("handover → home", 5.0, 6.05, "canceled", true),
            // Its result came after session_ended and stays with it.
            ("handover → home", 8.0, 13.5, "succeeded", true),
        ]
    );
    // Feedback folded into its leg: the result's count, the largest finite error.
    assert_eq!(legs[0]["feedback_count"], 52);
    assert_eq!(legs[0]["max_error"], 0.003);
    assert_eq!(legs[0]["planned_s"], 2.0);
    assert_eq!(s["robot"]["holds"], serde_json::json!([6.0]));
    let kinds: Vec<&str> = s["robot"]["events"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e["kind"].as_str().unwrap())
        .collect();
    assert_eq!(
        kinds,
        [
            "goal_sent",
            "accepted",
            "finished",
            "goal_sent",
            "cancel_requested",
            "finished",
            "goal_sent",
            "finished"
        ],
        "no feedback listed, the next session's driver event not here"
    );
    let parts = s["facts"]["parts_taken"].as_array().unwrap();
    assert_eq!(parts.len(), 1);
    assert_eq!(
        (&parts[0]["t"], &parts[0]["part"], &parts[0]["hand"]),
        (
            &serde_json::json!(4.0),
            &serde_json::json!(1),
            &serde_json::json!("left")
        )
    );
    assert_eq!(parts[0]["distance_m"], 0.052);

    // Session 2: its leg, named by where it starts (home), ends only as planned.
    let s = data("2");
    let legs = s["robot"]["legs"].as_array().unwrap();
    assert_eq!(legs.len(), 1, "{legs:?}");
    let l = &legs[0];
    assert_eq!(
        (&l["leg"], &l["outcome"], &l["end_known"]),
        (
            &serde_json::json!("home → handover"),
            &serde_json::json!("sent"),
            &serde_json::json!(false)
        )
    );
    let span = l["t_end"].as_f64().unwrap() - l["t_start"].as_f64().unwrap();
    assert!((span - 2.0).abs() < 1e-6, "{l}");
    assert!(
        l["feedback_count"].is_null() && l["max_error"].is_null(),
        "{l}"
    );
    let events = s["robot"]["events"].as_array().unwrap();
    assert_eq!(events.len(), 1);
    assert_eq!(
        (&events[0]["kind"], &events[0]["status"]),
        (&serde_json::json!("driver"), &serde_json::json!("ready"))
    );
    assert!(s["facts"]["parts_taken"].as_array().unwrap().is_empty());
}

/// A report of `rec` with `extra` arguments, and its data.
fn report_with(
    rec: &Path,
    name: &str,
    extra: &[&str],
) -> (std::process::Output, serde_json::Value) {
    let out = tmp(name);
    let _ = std::fs::remove_file(&out);
    let mut args = vec![
        "report",
        rec.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let o = ergocell(&args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let data = report_data(&std::fs::read_to_string(&out).unwrap());
    (o, data)
}

#[test]
fn an_overview_holds_the_worst_moments_and_the_numbers_of_every_frame() {
    let rec = demo_recording();
    let (_, all) = report_with(rec, "overview-all.html", &["--page-frames", "all"]);
    // A page of a few frames: the overview's choice is what a shift gets, at a small scale.
    let (o, over) = report_with(
        rec,
        "overview-small.html",
        &[
            "--page-frames",
            "overview",
            "--overview-frames",
            "20",
            "--window-frames",
            "150",
        ],
    );
    let (a, b) = (&all["sessions"][0], &over["sessions"][0]);
    assert!(
        a.get("overview").is_none(),
        "a page of every frame says nothing"
    );
    let ov = &b["overview"];
    let t_all: Vec<f64> = a["frames"]["t"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    let t_kept: Vec<f64> = b["frames"]["t"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(
        ov["frames_recorded"].as_u64().unwrap() as usize,
        t_all.len()
    );
    assert_eq!(ov["frames_kept"].as_u64().unwrap() as usize, t_kept.len());
    assert!(
        t_kept.len() < t_all.len() && t_kept.len() <= 20 + 1 + 150,
        "{} of {}",
        t_kept.len(),
        t_all.len()
    );
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        stdout.contains(&format!("{} frames over", t_all.len())),
        "{stdout}"
    );
    assert!(
        stdout.contains(&format!("the page holds {}", t_kept.len())),
        "{stdout}"
    );
    // The numbers are over every frame: the same summary, rows, angle distributions, warnings,
    // robot and facts as the page of every frame.
    for key in ["summary", "regions", "angles", "warnings", "robot", "facts"] {
        if key == "robot" {
            // The robot's TCP track is thinned with the frames; its legs and events are whole.
            for k in ["legs", "holds", "events", "handover_point"] {
                assert_eq!(a[key][k], b[key][k], "robot.{k}");
            }
        } else {
            assert_eq!(a[key], b[key], "{key}");
        }
    }
    // Each kept frame is the recorded frame at that time, whole.
    for (j, t) in t_kept.iter().enumerate() {
        let i = t_all.iter().position(|x| x == t).unwrap();
        for series in [
            "positions",
            "strain",
            "grand_left",
            "grand_right",
            "action_level",
            "phase",
            "reba_left",
        ] {
            assert_eq!(
                a["frames"][series][i], b["frames"][series][j],
                "{series} at {t} s"
            );
        }
    }
    // The worst moment (the longest stretch at the highest action level, here 3) is kept at the
    // recorded rate: every frame within its window.
    let level = |i: usize| a["frames"]["action_level"][i].as_u64().unwrap();
    let top = (0..t_all.len()).map(level).max().unwrap();
    assert!(top >= 3, "the demo reaches action level 3");
    let mut runs: Vec<(usize, usize)> = Vec::new();
    for i in 0..t_all.len() {
        if level(i) >= top {
            match runs.last_mut() {
                Some(r) if r.1 + 1 == i => r.1 = i,
                _ => runs.push((i, i)),
            }
        }
    }
    let longest = runs
        .iter()
        .max_by_key(|r| (r.1 - r.0, std::cmp::Reverse(r.0)))
        .unwrap();
    let middle = t_all[usize::midpoint(longest.0, longest.1)];
    let windows = ov["windows"].as_array().unwrap();
    let window = windows
        .iter()
        .map(|w| (w[0].as_f64().unwrap(), w[1].as_f64().unwrap()))
        .find(|&(lo, hi)| lo <= middle && middle <= hi)
        .expect("the longest stretch at the highest action level is in a window");
    let inside = |ts: &[f64]| {
        ts.iter()
            .filter(|&&t| window.0 <= t && t <= window.1)
            .count()
    };
    assert_eq!(inside(&t_kept), inside(&t_all));
    // Outside the windows, at most one frame per bucket.
    let bucket = ov["bucket_s"].as_f64().unwrap();
    assert!(bucket >= 1.0);
    let in_any = |t: f64| {
        windows
            .iter()
            .any(|w| w[0].as_f64().unwrap() <= t && t <= w[1].as_f64().unwrap())
    };
    let outside = t_kept.iter().filter(|&&t| !in_any(t)).count();
    assert!(outside <= 20, "{outside} frames outside the windows");
    // A span asked for is kept whole, besides the budget.
    let (_, asked) = report_with(
        rec,
        "overview-window.html",
        &[
            "--overview-frames",
            "20",
            "--window-frames",
            "150",
            "--window",
            "2..5.5",
        ],
    );
    let c = &asked["sessions"][0];
    let t_asked: Vec<f64> = c["frames"]["t"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    let span = |ts: &[f64]| ts.iter().filter(|&&t| (2.0..=5.5).contains(&t)).count();
    assert!(span(&t_all) > 20);
    assert_eq!(span(&t_asked), span(&t_all));
    assert!(c["overview"]["windows"]
        .as_array()
        .unwrap()
        .iter()
        .any(|w| w[0].as_f64().unwrap() <= 2.0 && w[1].as_f64().unwrap() >= 5.5));
    let bad_out = tmp("overview-bad.html");
    for bad in [
        &["--window", "5..2"][..],
        &["--window", "x..2"][..],
        &["--window", "1..2", "--page-frames", "all"][..],
    ] {
        let mut args = vec![
            "report",
            rec.to_str().unwrap(),
            "--force",
            "--out",
            bad_out.to_str().unwrap(),
        ];
        args.extend_from_slice(bad);
        let o = ergocell(&args);
        assert_eq!(o.status.code(), Some(2), "{bad:?}");
    }
    // The frames CSV needs every frame.
    let csv = tmp("overview.csv");
    let o = ergocell(&[
        "report",
        rec.to_str().unwrap(),
        "--out",
        tmp("overview-csv.html").to_str().unwrap(),
        "--force",
        "--page-frames",
        "overview",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--csv writes every frame"));
}
