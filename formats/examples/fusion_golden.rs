//! The fusion's answers, bit for bit, to compare two versions of the code.
//!
//! `cargo run --release -p ergocell_formats --example fusion_golden -- write OUT [data dir]`
//! fuses (default and paper methods) synthetic sequences of the bench's 6-, 8- and 16-camera rigs
//! (moving body, noise, missing keypoints, gross errors, absent cameras; `perception/benches/rig.rs`) and
//! caliscope's real 4-camera recording, and writes every fused coordinate and count;
//! `… -- compare A B` prints the largest change of any coordinate (metres), and any landmark present
//! in one and absent in the other. Used to show that a speed-up changed no answer.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::io::Write;
use std::path::{Path, PathBuf};

use ergocell_formats::import::parse_caliscope_xy;
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::detections::ImportStats;
use ergocell_perception::{CameraRig, Frame2, FusionEngine, FusionMethod};
use ergocell_skeleton::Landmark;

#[path = "../../perception/benches/rig.rs"]
mod rig;

/// One value per line: `name frame landmark axis value` (value NaN when not fused).
fn fuse_all(out: &mut impl Write, name: &str, rig: &CameraRig, frames: &[Frame2]) {
    for method in [FusionMethod::Default, FusionMethod::Paper] {
        let mut engine = FusionEngine::new(rig.clone(), method).unwrap();
        for (f, frame) in frames.iter().enumerate() {
            let fused = engine.fuse(frame).unwrap();
            writeln!(
                out,
                "{name}/{method:?} {f} rejected {}",
                fused.rejected_views
            )
            .unwrap();
            for lm in Landmark::ALL {
                let p = fused.skeleton.get(lm).map(|e| e.position_m);
                for axis in 0..3 {
                    let v = p.map_or(f64::NAN, |p| p[axis]);
                    writeln!(out, "{name}/{method:?} {f} {} {axis} {v:e}", lm.index()).unwrap();
                }
            }
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("write") => {
            let out_path = PathBuf::from(args.get(1).expect("write OUT [data dir]"));
            assert!(!out_path.exists(), "{} exists", out_path.display());
            let data = PathBuf::from(
                args.get(2)
                    .cloned()
                    .unwrap_or_else(|| "../shared/data/caliscope-4cam".into()),
            );
            let mut out = std::io::BufWriter::new(std::fs::File::create(&out_path).unwrap());
            for n in [6usize, 8, 16] {
                let rig = rig::rig(n);
                let frames: Vec<Frame2> = rig::sequence(&rig, 600, n as u64).collect();
                fuse_all(&mut out, &format!("ring{n}"), &rig, &frames);
            }
            let (rig, frames) = caliscope(&data);
            fuse_all(&mut out, "caliscope", &rig, &frames);
        }
        Some("compare") => compare(Path::new(&args[1]), Path::new(&args[2])),
        _ => eprintln!("usage: fusion_golden write OUT [data dir] | compare A B"),
    }
}

fn caliscope(dir: &Path) -> (CameraRig, Vec<Frame2>) {
    let config = std::fs::read_to_string(dir.join("config.toml")).expect("config.toml");
    let (rig, _) = parse_rig(&config, "config.toml").unwrap();
    let xy = std::fs::read_to_string(dir.join("xy_pose33.csv")).expect("xy_pose33.csv");
    let frames =
        parse_caliscope_xy(&xy, "xy_pose33.csv", &rig, &mut ImportStats::default()).unwrap();
    (rig, frames)
}

fn compare(a: &Path, b: &Path) {
    let a = std::fs::read_to_string(a).unwrap();
    let b = std::fs::read_to_string(b).unwrap();
    let (mut worst, mut worst_at, mut presence, mut counts, mut values) = (0.0_f64, "", 0, 0, 0);
    let mut per_run: std::collections::BTreeMap<&str, f64> = std::collections::BTreeMap::new();
    for (la, lb) in a.lines().zip(b.lines()) {
        let (ka, va) = la.rsplit_once(' ').unwrap();
        let (kb, vb) = lb.rsplit_once(' ').unwrap();
        assert_eq!(ka, kb, "the files list different things");
        if ka.contains(" rejected") {
            counts += usize::from(va != vb);
            continue;
        }
        values += 1;
        let (x, y): (f64, f64) = (va.parse().unwrap(), vb.parse().unwrap());
        if x.is_nan() != y.is_nan() {
            presence += 1;
        } else if !x.is_nan() {
            let run = ka.split(' ').next().unwrap_or("");
            let e = per_run.entry(run).or_default();
            *e = e.max((x - y).abs());
            if (x - y).abs() > worst {
                worst = (x - y).abs();
                worst_at = ka;
            }
        }
    }
    assert_eq!(a.lines().count(), b.lines().count(), "different lengths");
    for (run, w) in &per_run {
        println!("{run:>20}: largest change {w:.3e} m");
    }
    println!(
        "{values} coordinates: largest change {worst:.3e} m (at {worst_at}); {presence} present in one only; {counts} frames with a different rejected-view count"
    );
}
