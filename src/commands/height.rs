//! `ergocell height`: the operator's stature and height class from a 3D landmark recording.
//!
//! ```text
//! ergocell height --landmarks frames.json [--up x,y,z | --rig config/rig.toml] [--floor-height-m 0] [--c1-below-m 1.68]
//!                 [--c2-up-to-m 1.82] [--json]
//! ```
//!
//! Prints the estimate with its uncertainty (1σ), each estimator, and the class with the frame it was
//! decided at, or "undecided" and why.

use std::path::PathBuf;

use ergocell_ergonomics::height::{ClassThresholds, DecisionBasis, HeightEstimate};
use ergocell_ergonomics::{HeightConfig, HeightEstimator, HeightStatus, UpVector};

use super::rula::{parse_up, read_skeletons, resolve_up};
use super::UsageError;

/// Arguments of `ergocell height`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// 3D landmark file from `ergocell triangulate` (.json, .csv or .trc).
    #[arg(long)]
    pub landmarks: PathBuf,
    /// The world's up vector in the file's frame, `x,y,z` (default: the `up` of the rig file).
    #[arg(long, value_parser = parse_up, allow_hyphen_values = true)]
    pub up: Option<UpVector>,
    /// The calibration the landmarks were triangulated with; its `up` is the default for `--up`.
    #[arg(long, default_value = "config/rig.toml")]
    pub rig: PathBuf,
    /// Floor height along up, metres (default: the lowest foot landmark of each frame).
    #[arg(long, allow_hyphen_values = true)]
    pub floor_height_m: Option<f64>,
    /// Class c1 is below this stature, metres.
    #[arg(long, default_value_t = 1.68)]
    pub c1_below_m: f64,
    /// Class c2 reaches up to and including this stature, metres; c3 is above.
    #[arg(long, default_value_t = 1.82)]
    pub c2_up_to_m: f64,
    /// Print the status as JSON.
    #[arg(long)]
    pub json: bool,
}

fn print_estimate(e: &HeightEstimate) {
    println!(
        "stature: {:.3} m ± {:.3} m (1σ), from {} upright frames",
        e.height_m, e.uncertainty_m, e.frames_used
    );
    let o = &e.ear_offset;
    match o.calibrated_sessions {
        Some(n) => println!(
            "  ear landmark offset {:+.4} ± {:.4} m, calibrated on {n} sessions",
            o.offset_m, o.sigma_m
        ),
        None => println!(
            "  ear landmark offset uncalibrated: {:+.4} ± {:.4} m assumed (`ergocell height calibrate` measures it)",
            o.offset_m, o.sigma_m
        ),
    }
    for x in &e.estimators {
        println!(
            "  {:<14} {:.3} m ± {:.3} m ({} frames)",
            x.name, x.height_m, x.sigma_m, x.frames
        );
    }
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    let frames = read_skeletons(&args.landmarks)?;
    let mut config = HeightConfig::new(resolve_up(args.up, &args.rig)?);
    config.floor_height_m = args.floor_height_m;
    config.thresholds = ClassThresholds::new(args.c1_below_m, args.c2_up_to_m)
        .map_err(|e| UsageError(e.to_string()))?;
    let mut estimator = HeightEstimator::new(config);
    let mut decided_at = None;
    for (i, f) in frames.iter().enumerate() {
        if estimator.push(f).is_some() {
            decided_at = Some(i);
        }
    }
    let status = estimator.status();
    let segments = estimator.segment_estimate();
    if args.json {
        let doc = serde_json::json!({
            "status": status,
            "segment_lengths_any_posture": segments,
            "decided_at_frame": decided_at,
            "final_estimate": estimator.estimate(),
            "frames": frames.len(),
        });
        println!("{}", serde_json::to_string_pretty(&doc)?);
        return Ok(());
    }
    println!(
        "{} frames read from {}",
        frames.len(),
        args.landmarks.display()
    );
    match &status {
        HeightStatus::Decided(d) => {
            print_estimate(&d.estimate);
            let [lo, hi] = d.interval_m;
            let basis = match d.basis {
                DecisionBasis::Interval => format!(
                    "the ±{}σ interval {lo:.3}–{hi:.3} m lies inside the class",
                    d.sigmas
                ),
                DecisionBasis::ExpectedRula => format!(
                    "the ±{}σ interval {lo:.3}–{hi:.3} m straddles a boundary: the lowest expected RULA",
                    d.sigmas
                ),
                DecisionBasis::MostProbable => format!(
                    "the ±{}σ interval {lo:.3}–{hi:.3} m straddles a boundary: the most probable class",
                    d.sigmas
                ),
            };
            println!(
                "class: {} (decided at frame {}: {basis})",
                d.class.name(),
                decided_at.map_or_else(|| "?".to_owned(), |i| i.to_string())
            );
            for o in &d.options {
                println!(
                    "  {}: probability {:.3}{}{}",
                    o.class.name(),
                    o.probability,
                    o.expected_rula
                        .map_or(String::new(), |r| format!(", expected RULA {r:.2}")),
                    if o.served {
                        ""
                    } else {
                        ", its trajectory does not serve this interval"
                    }
                );
            }
            if let Some(cost) = d.expected_rula_cost {
                println!("expected cost against the true class: {cost:+.3} RULA grand score");
            }
            if let Some(now) = estimator.estimate() {
                if now.frames_used > d.estimate.frames_used {
                    println!(
                        "over the whole recording: {:.3} m ± {:.3} m from {} upright frames",
                        now.height_m, now.uncertainty_m, now.frames_used
                    );
                }
            }
        }
        HeightStatus::Measuring {
            estimate,
            why,
            frames_seen,
            upright_frames,
        } => {
            if let Some(e) = estimate {
                print_estimate(e);
            }
            println!(
                "class: undecided — still measuring ({upright_frames} upright of {frames_seen} frames): {why}"
            );
        }
    }
    if let Some(seg) = segments {
        println!(
            "segment lengths (any posture, never decides the class): {:.3} m ± {:.3} m (1σ) over {} frames",
            seg.height_m, seg.sigma_m, seg.frames
        );
    }
    Ok(())
}
