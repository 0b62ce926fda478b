//! Entry points of the coverage-guided fuzz targets (`fuzz/`), one per parser that reads outside data,
//! shared with the corpus replay test (`fuzzing/tests/corpus.rs`) so that CI runs every committed corpus
//! input and every crash found through exactly the code the fuzzer ran.
//!
//! Each entry takes arbitrary bytes and must return: a parse error is a fine answer, a panic, a hang
//! or an abort is a bug. Where a parse succeeds, each also checks a property the parser promises
//! (a round trip, a value range, a header on every answer), so the fuzzer finds silent garbage too,
//! not only crashes. The entries use `assert!` on purpose: an assertion here is the fuzzer's finding.
//!
//! Targets (the same names as `fuzz/fuzz_targets/*.rs`): [`rig`] (ergocell TOML, Anipose TOML and
//! caliscope TOML rigs, chosen by content as `--calibration` does), [`openpose_json`],
//! [`caliscope_csv`], [`landmarks_file`] (JSON, CSV, TRC), [`urdf`] (through our loader and `k`),
//! [`trajectory_toml`], [`cell_toml`] (both crates' readers of `config/cell.toml`), [`lock_toml`],
//! [`approvals_toml`], [`mcap_recording`] (the review's and `replay`'s readers), [`cdr_messages`]
//! (every message `bridge` decodes), [`rula_json`] (`rula score` worksheets and tables),
//! [`review_request`] (raw HTTP/1 bytes into the review server), [`detector_model`] (the twin's
//! fitted detector and the real measurement it is fitted to) and [`place_points`] (`calibrate
//! place`'s measured points). Three more build inputs that nest as
//! deep as the fuzzer asks and hand them to every reader of one format: [`nesting_xml`],
//! [`nesting_toml`], [`nesting_json`].
#![allow(clippy::missing_panics_doc)]

use std::net::{Ipv4Addr, SocketAddr};
use std::sync::{Arc, OnceLock};
use std::time::Duration;

use ergocell_bridge::msg;
use ergocell_formats::landmarks_file::{read_landmarks, LandmarksFormat};
use ergocell_formats::{import, rig_file};
use ergocell_perception::detections::ImportStats;
use ergocell_perception::detections::Keypoint2;
use ergocell_perception::{CameraRig, KeypointFormat};
use ergocell_robot::lock::{ApprovalsFile, LockFile};
use ergocell_robot::{CellConfig, RobotModel, TrajectoryClass, TrajectorySpec};

use ergocell_web::review_server::{self, Limits, Served};

fn text(data: &[u8]) -> Option<&str> {
    std::str::from_utf8(data).ok()
}

/// The reference cell's rig (`config/rig.toml`, four cameras `cam_0`…), which the CSV and the
/// placing targets read against.
fn shipped_rig() -> &'static CameraRig {
    static RIG: OnceLock<CameraRig> = OnceLock::new();
    RIG.get_or_init(
        || match rig_file::parse_rig(SHIPPED_RIG, "config/rig.toml") {
            Ok((rig, _)) => rig,
            Err(e) => panic!("the shipped rig does not parse: {e}"),
        },
    )
}

const SHIPPED_RIG: &str = include_str!("../../config/rig.toml");

/// A rig file of any format `parse_rig` recognises. A rig that parses has finite, positive focal
/// lengths on every camera (what the parser promises to check).
pub fn rig(data: &[u8]) {
    let Some(text) = text(data) else { return };
    if let Ok((rig, _format)) = rig_file::parse_rig(text, "fuzz") {
        for camera in rig.cameras() {
            let k = &camera.intrinsics;
            assert!(
                k.fx.is_finite() && k.fy.is_finite() && k.fx > 0.0 && k.fy > 0.0,
                "a parsed rig has a non-finite or non-positive focal length: {k:?}"
            );
        }
    }
}

/// A `calibrate place` points file, placed against the shipped rig taken as one group: every point
/// read has finite coordinates and a unique name, and placing them never panics (an error, or a rig
/// whose cameras are valid).
pub fn place_points(data: &[u8]) {
    let Some(text) = text(data) else { return };
    let Ok(points) = ergocell_calibration::place::parse_points(text, "fuzz") else {
        return;
    };
    for (i, p) in points.iter().enumerate() {
        assert!(
            p.cell_m.iter().all(|v| v.is_finite())
                && p.seen
                    .values()
                    .all(|px| px.x.is_finite() && px.y.is_finite()),
            "a parsed point is not finite: {p:?}"
        );
        assert!(
            points[..i].iter().all(|q| q.name != p.name),
            "a name read twice: {}",
            p.name
        );
    }
    let _ = ergocell_calibration::place::place(std::slice::from_ref(shipped_rig()), &points);
}

/// One OpenPose JSON frame, read in each keypoint layout. Every person returned has only finite
/// pixels.
pub fn openpose_json(data: &[u8]) {
    let Some(text) = text(data) else { return };
    for format in [
        KeypointFormat::BlazePose33,
        KeypointFormat::Body25,
        KeypointFormat::Body25B,
        KeypointFormat::Coco17,
        KeypointFormat::Halpe26,
    ] {
        let mut stats = ImportStats::default();
        if let Ok(people) = import::parse_openpose_frame(text, "fuzz", format, &mut stats) {
            for person in &people {
                assert_finite_pixels(person.keypoints.iter().flatten());
            }
        }
    }
}

/// caliscope's long `xy_*.csv`, raw bytes. Every keypoint kept has a finite pixel, and a camera is
/// seen at most once per frame.
pub fn caliscope_csv(data: &[u8]) {
    let mut stats = ImportStats::default();
    if let Ok(frames) = import::parse_caliscope_xy_bytes(data, "fuzz", shipped_rig(), &mut stats) {
        for frame in &frames {
            let mut cameras: Vec<_> = frame.views.iter().map(|v| v.camera).collect();
            cameras.sort_unstable();
            cameras.dedup();
            assert_eq!(
                cameras.len(),
                frame.views.len(),
                "a camera twice in one frame"
            );
            for view in &frame.views {
                assert_finite_pixels(view.keypoints().iter().flatten());
            }
        }
    }
}

fn assert_finite_pixels<'a>(keypoints: impl Iterator<Item = &'a Keypoint2>) {
    for k in keypoints {
        let p = k.pixel();
        assert!(
            p.x.is_finite() && p.y.is_finite(),
            "non-finite pixel kept: {k:?}"
        );
    }
}

/// A 3D landmark recording (JSON, CSV, TRC: the first byte picks the reader).
pub fn landmarks_file(data: &[u8]) {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    let Some(text) = text(rest) else { return };
    let format = match selector % 3 {
        0 => LandmarksFormat::Json,
        1 => LandmarksFormat::Csv,
        _ => LandmarksFormat::Trc,
    };
    let _ = read_landmarks(text, format, "fuzz");
}

/// A URDF through `RobotModel::from_urdf_str` (our checks, then `k`'s conversion). A model that
/// loads has ordered, finite limits on every joint, and forward kinematics at the middle of the
/// limits is finite.
pub fn urdf(data: &[u8]) {
    let Some(text) = text(data) else { return };
    if let Ok(model) = RobotModel::from_urdf_str(text, "link_0", "flange") {
        let mid: Vec<f64> = model
            .joints()
            .iter()
            .map(|j| {
                assert!(
                    j.lower_rad.is_finite()
                        && j.upper_rad.is_finite()
                        && j.lower_rad <= j.upper_rad,
                    "a loaded joint has bad limits: {j:?}"
                );
                0.5 * (j.lower_rad + j.upper_rad)
            })
            .collect();
        if let Ok(T_base_flange) = model.fk_flange(&mid) {
            assert!(
                T_base_flange
                    .translation
                    .vector
                    .iter()
                    .all(|v| v.is_finite()),
                "forward kinematics is not finite"
            );
        }
    }
}

/// A class trajectory file (`trajectories/c*.toml`).
pub fn trajectory_toml(data: &[u8]) {
    let Some(text) = text(data) else { return };
    let _ = TrajectorySpec::from_toml_str(text);
}

/// The cell file, through both readers (the robot's section, the whole cell's settings).
pub fn cell_toml(data: &[u8]) {
    let Some(text) = text(data) else { return };
    let _ = CellConfig::from_toml_str(text);
    let _ = ergocell_cell::CellSettings::from_toml_str(text, "fuzz");
}

/// A lock file. A lock that parses re-serialises to one that parses to the same lock (its hash is
/// recomputed on the way in, so the round trip also checks the hash is stable).
pub fn lock_toml(data: &[u8]) {
    let Some(text) = text(data) else { return };
    for class in [
        TrajectoryClass::C1,
        TrajectoryClass::C2,
        TrajectoryClass::C3,
    ] {
        if let Ok(lock) = LockFile::from_toml_str(class, text) {
            let written = match lock.to_toml() {
                Ok(written) => written,
                Err(e) => panic!("a parsed lock does not serialise: {e}"),
            };
            match LockFile::from_toml_str(class, &written) {
                Ok(again) => assert_eq!(again, lock, "lock round trip changed it"),
                Err(e) => panic!("a written lock does not parse: {e}"),
            }
        }
    }
}

/// The twin's detector model file (`sim --detector`) and the real detector-error JSON that
/// `sim fit-detector --real` reads: a model that parses round-trips through its own writer and makes
/// a detector that validates.
pub fn detector_model(data: &[u8]) {
    let Some(text) = text(data) else { return };
    if let Ok(model) = ergocell_sim::detector_fit::DetectorModel::from_toml_str(text) {
        let again = model
            .to_toml()
            .map(|t| ergocell_sim::detector_fit::DetectorModel::from_toml_str(&t));
        assert!(
            matches!(&again, Ok(Ok(m)) if *m == model),
            "a parsed model must round-trip: {again:?}"
        );
        assert!(model
            .apply(ergocell_sim::DetectorNoise::default())
            .validate()
            .is_ok());
    }
    let _ = serde_json::from_str::<ergocell_perception::detector_error::DetectorErrorReport>(text);
}

/// An approvals file: parsed, and its hash chain checked; the same bytes as the approvers' files,
/// the site authority's key file and its signature.
pub fn approvals_toml(data: &[u8]) {
    let Some(text) = text(data) else { return };
    if let Ok(file) = ApprovalsFile::from_toml_str(text) {
        let _ = file.check_chain();
        // Every entry's claim and signature through the verifier (no key is trusted: refused, never
        // a panic), and its message through the two-step flow's parser: a round trip.
        let nobody = ergocell_robot::TrustedSigners::default();
        for a in &file.approval {
            assert!(nobody.verify(&a.claim(), &a.signature).is_err());
            if ergocell_robot::signing::check_claim(&a.claim()).is_ok() {
                let (action, fields) =
                    ergocell_robot::signing::parse_approval_message(&a.message())
                        .unwrap_or_else(|e| panic!("a checked claim's message must parse: {e}"));
                assert_eq!(fields[2], a.approved_by);
                assert_eq!(action, a.action);
            }
        }
        // What the chain decides, and the witness's check and next line: in range, never a panic.
        for class in ergocell_robot::TrajectoryClass::ALL {
            let standing = file.standing(class);
            assert!(standing
                .approvals
                .iter()
                .chain(standing.withdrawn.iter())
                .all(|&i| i < file.approval.len()));
            let Ok(witness) = ergocell_robot::witness::Witness::parse(text.as_bytes()) else {
                continue;
            };
            if witness.check("a", class, &file).is_ok() {
                let _ = witness.sighting_line("a", class, &file, &nobody, "2026-12-05T00:00:00Z");
            }
        }
    }
    // The same bytes as an allowed-signers file and a revocation list.
    let _ = ergocell_robot::TrustedSigners::parse(text, text);
    // As the site authority's key file, and as its signature over approvers' files: no bytes but
    // the authority's own signature make a list that trusts keys count.
    let _ = ergocell_robot::authority::Authority::parse(text, text);
    let site = ergocell_robot::signing::key_from_seed(&[90; 32], "site");
    if let Ok(line) = ergocell_robot::signing::public_key_openssh(&site) {
        if let Ok(authority) = ergocell_robot::authority::Authority::parse(&line, "") {
            let allowed = format!(
                "a@b namespaces=\"{}\" {line}\n",
                ergocell_robot::signing::APPROVAL_NAMESPACE
            );
            assert!(ergocell_robot::authority::anchored_signers(
                &allowed,
                "",
                Some(text),
                Ok(&authority)
            )
            .is_err());
        }
    }
}

/// A session recording (MCAP), through the review's reader and `replay`'s camera reader.
pub fn mcap_recording(data: &[u8]) {
    if let Ok(recording) = ergocell_review::read_recording(data) {
        let _ = ergocell_review::read::split_sessions(&recording);
    }
    let _ = ergocell_ros_backend::recording::read_camera_landmarks(data);
}

fn cdr_round_trip<M>(payload: &[u8])
where
    M: serde::Serialize + serde::de::DeserializeOwned + PartialEq + std::fmt::Debug,
{
    if let Ok(message) = ergocell_bridge::cdr::decode::<M>(payload) {
        let encoded = match ergocell_bridge::cdr::encode(&message) {
            Ok(encoded) => encoded,
            Err(e) => panic!("a decoded message does not encode: {e}"),
        };
        match ergocell_bridge::cdr::decode::<M>(&encoded) {
            // NaN fields make `==` false on an exact round trip: compare the encodings instead.
            Ok(again) => assert!(
                again == message || ergocell_bridge::cdr::encode(&again).ok() == Some(encoded),
                "CDR round trip changed the message"
            ),
            Err(e) => panic!("an encoded message does not decode: {e}"),
        }
    }
}

/// A CDR payload as each message `bridge` decodes (the first byte picks the type): what decodes
/// encodes and decodes back to the same message.
pub fn cdr_messages(data: &[u8]) {
    let Some((&selector, payload)) = data.split_first() else {
        return;
    };
    match selector % 9 {
        0 => cdr_round_trip::<msg::CameraLandmarks>(payload),
        1 => cdr_round_trip::<msg::JointState>(payload),
        2 => cdr_round_trip::<msg::JointTrajectory>(payload),
        3 => cdr_round_trip::<msg::SessionState>(payload),
        4 => cdr_round_trip::<msg::ErgonomicState>(payload),
        5 => cdr_round_trip::<msg::PostureWarning>(payload),
        6 => cdr_round_trip::<msg::OperatorPose>(payload),
        7 => cdr_round_trip::<msg::MarkerArray>(payload),
        _ => cdr_round_trip::<msg::RebaState>(payload),
    }
}

/// `rula score` input: worksheets JSON and tables JSON.
pub fn rula_json(data: &[u8]) {
    let Some(text) = text(data) else { return };
    if let Ok(worksheets) = ergocell_ergonomics::rula::parse_worksheets(text) {
        for input in &worksheets {
            let _ = ergocell_ergonomics::rula::score_worksheet(input);
        }
    }
    let _ = ergocell_ergonomics::tables::parse_tables(text);
}

/// The deepest nesting the nesting entries build.
pub const MAX_FUZZ_DEPTH: usize = 200_000;

/// A nesting entry's input: its shape byte, the depth it asks for (three bytes, so the fuzzer
/// reaches any depth up to [`MAX_FUZZ_DEPTH`] at once rather than by growing an input level by
/// level) and the rest as a fragment of text.
fn depth_and_fragment(data: &[u8]) -> Option<(u8, usize, String)> {
    let (&[shape, a, b, c], rest) = data.split_first_chunk::<4>()?;
    let depth =
        (usize::from(a) << 16 | usize::from(b) << 8 | usize::from(c)) % (MAX_FUZZ_DEPTH + 1);
    let fragment: String = String::from_utf8_lossy(rest).chars().take(64).collect();
    Some((shape, depth, fragment))
}

/// XML nested as deep as the input asks (up to [`MAX_FUZZ_DEPTH`]), in the shapes ergocell's two
/// XML readers meet: a URDF's `<robot>` or a Qualisys calibration's `<calibration><cameras>` around
/// elements that open (and close, or never close), with the fuzzer's bytes inside each tag, in a
/// comment and in CDATA. Both readers take every text: the URDF loader and the rig reader (which
/// recognises a Qualisys export by its content).
pub fn nesting_xml(data: &[u8]) {
    let Some((shape, depth, fragment)) = depth_and_fragment(data) else {
        return;
    };
    let (head, tail) = if shape & 1 == 0 {
        ("<robot name=\"r\">", "</robot>")
    } else {
        (
            "<?xml version=\"1.0\"?><calibration><cameras>",
            "</cameras></calibration>",
        )
    };
    let (open, close) = match (shape >> 1) % 4 {
        0 => (format!("<link{fragment}>"), "</link>".to_owned()),
        1 => (format!("<x a=\"{fragment}\">"), "</x>".to_owned()),
        2 => (
            format!("<x><!--{fragment}--><![CDATA[{fragment}]]>"),
            "</x>".to_owned(),
        ),
        _ => (format!("<x><y/>{fragment}"), "</x>".to_owned()),
    };
    let closed = shape & 8 == 0;
    let mut text = String::with_capacity(head.len() + depth * (open.len() + close.len()));
    text.push_str(head);
    for _ in 0..depth {
        text.push_str(&open);
    }
    if closed {
        for _ in 0..depth {
            text.push_str(&close);
        }
        text.push_str(tail);
    }
    urdf(text.as_bytes());
    rig(text.as_bytes());
}

/// The top-level tables and keys ergocell's TOML files have, so that a nested value lands where a
/// reader looks rather than only in a key it ignores.
const TOML_KEYS: &[&str] = &[
    "cameras",
    "stereo_pairs",
    "robot",
    "station",
    "ros",
    "pipeline",
    "warnings",
    "assessment",
    "approval",
    "lock",
    "waypoints",
    "tasks",
    "mix",
    "faults",
    "noise",
    "calibration",
    "x",
];

/// TOML nested as deep as the input asks, after the fuzzer's own text: arrays in arrays, inline
/// tables in inline tables, arrays of inline tables, and the two nestings the parser does not
/// recurse for but a reader's deserialiser and drop do (a dotted key and a dotted table header,
/// each one level per dot). Every TOML reader takes every text: rigs (three formats), the cell file
/// (robot, session settings and `[ros]`), trajectories, locks, approvals, the detector model, the
/// task mix, the fault schedule and the expected handover RULA.
pub fn nesting_toml(data: &[u8]) {
    let Some((shape, depth, fragment)) = depth_and_fragment(data) else {
        return;
    };
    let key = TOML_KEYS[usize::from(shape >> 3) % TOML_KEYS.len()];
    let mut text = String::with_capacity(fragment.len() + 16 + depth * 8);
    text.push_str(&fragment);
    text.push('\n');
    let repeat = |text: &mut String, s: &str| {
        for _ in 0..depth {
            text.push_str(s);
        }
    };
    match shape % 6 {
        0 => {
            text.push_str(key);
            text.push_str(" = ");
            repeat(&mut text, "[");
            repeat(&mut text, "]");
        }
        1 => {
            text.push_str(key);
            text.push_str(" = ");
            repeat(&mut text, "{ a = ");
            text.push('1');
            repeat(&mut text, " }");
        }
        2 => {
            text.push_str(key);
            text.push_str(" = ");
            repeat(&mut text, "[{ a = ");
            text.push('1');
            repeat(&mut text, " }]");
        }
        3 => {
            text.push_str(key);
            repeat(&mut text, ".a");
            text.push_str(" = 1");
        }
        4 => {
            text.push('[');
            text.push_str(key);
            repeat(&mut text, ".a");
            text.push_str("]\nb = 1");
        }
        _ => {
            text.push_str("[[");
            text.push_str(key);
            repeat(&mut text, ".a");
            text.push_str("]]\nb = 1");
        }
    }
    text.push('\n');
    let bytes = text.as_bytes();
    rig(bytes);
    cell_toml(bytes);
    trajectory_toml(bytes);
    lock_toml(bytes);
    approvals_toml(bytes);
    detector_model(bytes);
    place_points(bytes);
    let _ = ergocell_bridge::transport::RosConfig::from_cell_toml(&text);
    let _ = ergocell_sim::tasks::TaskMix::from_toml_str(&text);
    let _ = ergocell_sim::faults::FaultSchedule::from_toml_str(&text, "fuzz", &["cam_0", "cam_1"]);
    let _ = toml::from_str::<ergocell_ergonomics::height::HandoverRula>(&text);
}

/// JSON nested as deep as the input asks: arrays, objects, arrays of objects, with the fuzzer's
/// text innermost. Every JSON reader takes every text: `rula score` worksheets and tables, OpenPose
/// frames, JSON landmark recordings, the detector-error report and the approval witness (as a line).
pub fn nesting_json(data: &[u8]) {
    let Some((shape, depth, fragment)) = depth_and_fragment(data) else {
        return;
    };
    let (open, close) = match shape % 3 {
        0 => ("[", "]"),
        1 => ("{\"people\":", "}"),
        _ => ("[{\"format\":", "}]"),
    };
    let mut text = String::with_capacity(depth * (open.len() + close.len()) + fragment.len() + 1);
    for _ in 0..depth {
        text.push_str(open);
    }
    text.push_str(&fragment);
    if shape & 4 == 0 {
        for _ in 0..depth {
            text.push_str(close);
        }
    }
    rula_json(text.as_bytes());
    openpose_json(text.as_bytes());
    let mut selected = Vec::with_capacity(text.len() + 1);
    selected.push(0); // landmarks_file's selector: JSON
    selected.extend_from_slice(text.as_bytes());
    landmarks_file(&selected);
    detector_model(text.as_bytes());
    text.push('\n');
    let _ = ergocell_robot::witness::Witness::parse(text.as_bytes());
}

fn runtime() -> &'static tokio::runtime::Runtime {
    static RUNTIME: OnceLock<tokio::runtime::Runtime> = OnceLock::new();
    RUNTIME.get_or_init(|| {
        match tokio::runtime::Builder::new_current_thread()
            .enable_time()
            .build()
        {
            Ok(runtime) => runtime,
            Err(e) => panic!("tokio runtime: {e}"),
        }
    })
}

/// Raw bytes from a client on loopback into the review server (hyper's HTTP/1 parser, the Host and
/// method guard, the routes), the client closing its side after sending them. The server must
/// finish the connection (no hang: a 5 s limit, far beyond its 1 s header timeout here), answer in
/// HTTP/1 (the request's version), and put its security headers on every page it serves.
pub fn review_request(data: &[u8]) {
    use tokio::io::{AsyncReadExt as _, AsyncWriteExt as _};
    let served = Arc::new(Served::new(
        "<!doctype html><title>fuzz</title>",
        "{}",
        Some(vec![
            "127.0.0.1:8765".to_owned(),
            "localhost:8765".to_owned(),
        ]),
    ));
    let app = review_server::router(served);
    let limits = Limits {
        header_timeout: Duration::from_secs(1),
        stall_timeout: Duration::from_secs(2),
        max_connections: 1,
        shutdown_grace: Duration::from_millis(10),
    };
    let peer = SocketAddr::from((Ipv4Addr::LOCALHOST, 40_000));
    let (mut client, server) = tokio::io::duplex(1 << 16);
    let exchange = async move {
        let serving = review_server::serve_io(server, peer, app, limits);
        let talking = async {
            let _ = client.write_all(data).await;
            let _ = client.shutdown().await;
            let mut answer = Vec::new();
            let _ = client.read_to_end(&mut answer).await;
            answer
        };
        let ((), answer) = tokio::join!(serving, talking);
        answer
    };
    let outcome =
        runtime().block_on(async { tokio::time::timeout(Duration::from_secs(5), exchange).await });
    let Ok(answer) = outcome else {
        panic!("the review server did not finish a closed connection within 5 s");
    };
    if answer.is_empty() {
        return;
    }
    assert!(
        answer.starts_with(b"HTTP/1.1 ") || answer.starts_with(b"HTTP/1.0 "),
        "not an HTTP/1 answer: {:?}",
        String::from_utf8_lossy(&answer[..answer.len().min(64)])
    );
    let text = String::from_utf8_lossy(&answer).to_ascii_lowercase();
    for response in text.split("http/1.").skip(1) {
        if response.get(2..5) == Some("200") {
            assert!(
                response.contains("content-security-policy:"),
                "a 200 response without its security headers"
            );
        }
    }
}
