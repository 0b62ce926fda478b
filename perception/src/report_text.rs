//! The texts `ergocell triangulate` prints: the run's summary (frames, landmarks triangulated,
//! reprojection per camera, left/right swaps, rejected views, bone-length variation, throughput) and
//! the detector-error tables ([`crate::detector_error`]).
//!
//! A layout of [`RunTally`]'s and [`DetectorErrorReport`]'s facts; the only arithmetic here turns
//! fractions into per cent for display. No I/O: the caller prints the text.

use std::fmt::Write as _;

use nalgebra::Vector2;

use crate::detector_error::{DetectorErrorReport, ErrorStats, Quantiles};
use crate::metrics::{throughput_fps, RunTally};
use crate::CameraRig;

/// The summary of a reconstruction run: `tally` over the run, each camera's image offset the fusion
/// learnt (`learnt_offsets_px`, by rig index), the fusion and filter names as given, and the wall
/// time the run took (reading, fusion and writing).
pub fn triangulation_summary(
    rig: &CameraRig,
    tally: &RunTally,
    learnt_offsets_px: &[Option<Vector2<f64>>],
    fusion: &str,
    filter: &str,
    elapsed_s: f64,
) -> String {
    let stats = &tally.stats;
    let frames = stats.frames();
    let mut out = String::new();
    let _ = writeln!(out, "frames:                   {frames}");
    let _ = writeln!(
        out,
        "landmarks triangulated:   {} of {} ({:.1}%)",
        stats.landmarks(),
        stats.landmark_slots(),
        stats.landmark_percent()
    );
    let _ = writeln!(out, "fusion:                   {fusion} (filter: {filter})");
    if let Some(m) = stats.median_reprojection_px() {
        let _ = writeln!(out, "median reprojection err:  {m:.2} px");
    }
    for (i, c) in rig.cameras().iter().enumerate() {
        if let Some(median) = tally.per_camera.median_px(i) {
            let offset = learnt_offsets_px.get(i).copied().flatten();
            out.push_str(&camera_line(
                c.id.as_str(),
                median,
                tally.per_camera.views(i),
                offset,
            ));
        }
    }
    let swaps = tally.per_camera.swap_totals(rig.len());
    let _ = writeln!(
        out,
        "left/right swaps:         {} of {} views ({:.1}%) had the person's left and right swapped and were used mirrored",
        swaps.swapped,
        swaps.views,
        swaps.percent()
    );
    let _ = writeln!(
        out,
        "views rejected:           {} (outliers or behind the camera), {} keypoints outside the lens model",
        tally.rejected_views, tally.undistortion_failures
    );
    bone_lines(&mut out, tally);
    let _ = writeln!(
        out,
        "throughput:               {:.0} frames/s ({frames} frames in {elapsed_s:.2} s: reading, fusion and writing)",
        throughput_fps(frames, elapsed_s)
    );
    out
}

/// One camera's line of the summary: its median reprojection error and keypoint count
/// (`(median_px, keypoints)`), its views and of those the ones used mirrored
/// (`(views, swapped)`), and the image offset learnt for it, if any.
pub fn camera_line(
    id: &str,
    (median_px, keypoints): (f64, u64),
    (views, swapped): (usize, usize),
    learnt_offset_px: Option<Vector2<f64>>,
) -> String {
    let learnt = learnt_offset_px
        .map(|o| format!("; image offset learnt ({:+.1}, {:+.1}) px", o.x, o.y))
        .unwrap_or_default();
    format!(
        "  camera {id:<12} median reprojection {median_px:.2} px over {keypoints} keypoints as delivered; {swapped} of {views} views left/right-swapped, corrected{learnt}\n"
    )
}

/// The bone-length variation and one line per bone, when a bone was seen in two frames.
fn bone_lines(out: &mut String, tally: &RunTally) {
    let Some(cv) = tally.stats.bone_length_variation_percent() else {
        return;
    };
    let _ = writeln!(
        out,
        "bone-length variation:    {cv:.2}% (mean coefficient of variation over bones)"
    );
    for b in tally.stats.bone_stats() {
        let _ = writeln!(
            out,
            "  {:>15} – {:<15} {:>6.3} m  ±{:>5.2}%  ({} frames)",
            b.bone.0.name(),
            b.bone.1.name(),
            b.mean_m,
            b.cv_percent,
            b.frames
        );
    }
}

/// The detector-error tables, relative errors in per cent of the person's image height (median and
/// 90th percentile), after a blank line.
pub fn detector_error_tables(r: &DetectorErrorReport) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "\ndetector error, each view against the other views ({} frames; % of the person's image height, median p90; persistent = mean over {} s):",
        r.frames, r.window_s
    );
    let _ = writeln!(
        out,
        "  {:<16} {:>7} {:>11} {:>11} {:>11} {:>13}",
        "", "n", "total", "persistent", "jitter", "total px"
    );
    out.push_str(&error_row("all", &r.all));
    let _ = writeln!(
        out,
        "  {:<16} persistent part shared by the view's landmarks {}, each landmark's own {}",
        "",
        percent_pair(&r.all.persistent_shared),
        percent_pair(&r.all.persistent_own)
    );
    let v = &r.view_structure;
    let _ = writeln!(
        out,
        "  {:<16} per view and frame: shift {}, scale error {}, rotation {:.1} {:.1}°; left per landmark {}",
        "",
        percent_pair(&v.shift),
        percent_pair(&v.scale_error),
        v.rotation_deg.p50,
        v.rotation_deg.p90,
        percent_pair(&v.remainder)
    );
    for (name, s) in &r.groups {
        out.push_str(&error_row(name, s));
    }
    for c in &r.cameras {
        out.push_str(&error_row(&format!("camera {}", c.camera), &c.error));
        let _ = writeln!(
            out,
            "  {:<16} seen in {} frames, missing in {}, {:.1}% of landmarks dropped, {} frames left/right-swapped, {} someone else",
            "", c.frames_seen, c.frames_missing, 100.0 * c.landmark_dropout, c.swapped_frames, c.identity_switches
        );
    }
    binned_lines(&mut out, r);
    if !r.persistence.is_empty() {
        let _ = writeln!(out, "  how long a landmark's own error lasts (its correlation with itself a lag later, the view's shift taken out):");
        let lags: Vec<String> = r
            .persistence
            .iter()
            .map(|l| format!("{:.2} s {:.2}", l.lag_s, l.correlation))
            .collect();
        let _ = writeln!(out, "    {}", lags.join("   "));
    }
    out
}

/// The error by the detector's confidence (and whether it predicts the error) and by the viewing
/// angle.
fn binned_lines(out: &mut String, r: &DetectorErrorReport) {
    let _ = writeln!(out, "  by confidence:");
    for b in &r.by_confidence {
        let _ = writeln!(
            out,
            "    {:.2}–{:.2}  n {:>6}  {}",
            b.from,
            b.to,
            b.total.count,
            percent_pair(&b.total)
        );
    }
    if let Some(rho) = r.confidence_error_spearman {
        let _ = writeln!(out, "    Spearman(confidence, error) = {rho:.2}");
    } else {
        let _ = writeln!(out, "    (the detections carry no confidence)");
    }
    let _ = writeln!(
        out,
        "  by viewing angle (0° = camera in front of the person):"
    );
    for b in &r.by_view_angle_deg {
        let _ = writeln!(
            out,
            "    {:>3.0}–{:<3.0}°  n {:>6}  {}",
            b.from,
            b.to,
            b.total.count,
            percent_pair(&b.total)
        );
    }
}

/// One row of the table: the residual count, total, persistent and jitter (per cent of the image
/// height) and the total in pixels, median and p90 each.
pub fn error_row(name: &str, s: &ErrorStats) -> String {
    format!(
        "  {name:<16} {:>7} {:>11} {:>11} {:>11} {:>6.1} {:>6.1}\n",
        s.total.count,
        percent_pair(&s.total),
        percent_pair(&s.persistent),
        percent_pair(&s.jitter),
        s.total_px.p50,
        s.total_px.p90
    )
}

/// The median and p90 of a fraction of the image height, in per cent.
fn percent_pair(q: &Quantiles) -> String {
    format!("{:>5.2} {:>5.2}", 100.0 * q.p50, 100.0 * q.p90)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::detector_error::{BinRow, CameraRow, LagRow, ViewStructure};
    use crate::fusion::tests::ring_rig;
    use ergocell_skeleton::{Skeleton3, BONES, LANDMARK_COUNT};
    use nalgebra::Point3;

    fn q(count: usize, p50: f64, p90: f64) -> Quantiles {
        Quantiles {
            count,
            p50,
            p90,
            p99: p90,
        }
    }

    /// `frames` rigid skeletons 1/30 s apart (landmark `i` at x = 0.1·i m), every landmark seen with
    /// a 2.5 px reprojection error.
    fn tally(frames: usize) -> RunTally {
        let mut t = RunTally::default();
        for k in 0..frames {
            let pts: [Point3<f64>; LANDMARK_COUNT] =
                std::array::from_fn(|i| Point3::new(0.1 * i as f64, 0.0, 1.0));
            let mut s = Skeleton3::from_points(k as i64 * 33_333_333, &pts).unwrap();
            for lm in ergocell_skeleton::Landmark::ALL {
                let mut e = *s.get(lm).unwrap();
                e.reprojection_error_px = Some(2.5);
                s.set(lm, Some(e)).unwrap();
            }
            t.stats.push(&s);
        }
        t.rejected_views = 7;
        t.undistortion_failures = 2;
        t
    }

    #[test]
    fn the_summary_states_the_tallies_figures() {
        let rig = ring_rig(2);
        let text = triangulation_summary(&rig, &tally(4), &[], "default", "none", 2.0);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[..4],
            [
                "frames:                   4",
                "landmarks triangulated:   132 of 132 (100.0%)",
                "fusion:                   default (filter: none)",
                "median reprojection err:  2.50 px",
            ]
        );
        // no camera was compared: no camera line, and no swap out of no view
        assert_eq!(
            lines[4],
            "left/right swaps:         0 of 0 views (0.0%) had the person's left and right swapped and were used mirrored"
        );
        assert_eq!(
            lines[5],
            "views rejected:           7 (outliers or behind the camera), 2 keypoints outside the lens model"
        );
        assert_eq!(
            lines[6],
            "bone-length variation:    0.00% (mean coefficient of variation over bones)"
        );
        // one line per bone (every bone seen in all four frames), then the throughput
        assert_eq!(lines.len(), 7 + BONES.len() + 1);
        assert_eq!(
            lines[7],
            "    left_shoulder – left_elbow       0.200 m  ± 0.00%  (4 frames)"
        );
        assert_eq!(
            lines[lines.len() - 1],
            "throughput:               2 frames/s (4 frames in 2.00 s: reading, fusion and writing)"
        );
        assert!(text.ends_with('\n'));
    }

    #[test]
    fn an_empty_run_has_no_median_and_no_bones() {
        let text = triangulation_summary(
            &ring_rig(2),
            &RunTally::default(),
            &[],
            "paper",
            "causal",
            0.0,
        );
        assert!(!text.contains("median reprojection"), "{text}");
        assert!(!text.contains("bone-length"), "{text}");
        assert!(
            text.contains("landmarks triangulated:   0 of 0 (NaN%)"),
            "{text}"
        );
        assert!(
            text.contains("throughput:               0 frames/s"),
            "{text}"
        );
    }

    #[test]
    fn a_camera_line_names_its_swaps_and_learnt_offset() {
        assert_eq!(
            camera_line("cam_1", (1.234, 500), (40, 3), Some(Vector2::new(1.26, -0.5))),
            "  camera cam_1        median reprojection 1.23 px over 500 keypoints as delivered; 3 of 40 views left/right-swapped, corrected; image offset learnt (+1.3, -0.5) px\n"
        );
        assert_eq!(
            camera_line("c", (0.5, 1), (1, 0), None),
            "  camera c            median reprojection 0.50 px over 1 keypoints as delivered; 0 of 1 views left/right-swapped, corrected\n"
        );
    }

    #[test]
    fn an_error_row_is_in_per_cent_of_the_image_height() {
        let s = ErrorStats {
            total: q(120, 0.0123, 0.0456),
            persistent: q(120, 0.01, 0.02),
            jitter: q(120, 0.005, 0.0075),
            total_px: q(120, 3.24, 12.04),
            ..ErrorStats::default()
        };
        assert_eq!(
            error_row("all", &s),
            "  all                  120  1.23  4.56  1.00  2.00  0.50  0.75    3.2   12.0\n"
        );
    }

    fn report() -> DetectorErrorReport {
        let stats = ErrorStats {
            total: q(10, 0.02, 0.05),
            total_px: q(10, 4.0, 9.0),
            ..ErrorStats::default()
        };
        DetectorErrorReport {
            frames: 267,
            frame_rate_hz: Some(30.0),
            window_s: 1.0,
            person: None,
            all: stats,
            groups: vec![("torso".to_owned(), stats)],
            landmarks: Vec::new(),
            cameras: vec![CameraRow {
                camera: "cam_0".to_owned(),
                error: stats,
                frames_seen: 260,
                frames_missing: 7,
                landmark_dropout: 0.031,
                swapped_frames: 2,
                identity_switches: 1,
            }],
            by_confidence: vec![BinRow {
                from: 0.5,
                to: 0.8,
                total: q(10, 0.02, 0.05),
            }],
            by_view_angle_deg: vec![BinRow {
                from: 45.0,
                to: 90.0,
                total: q(10, 0.02, 0.05),
            }],
            confidence_error_spearman: None,
            gross_error_share: 0.0,
            view_structure: ViewStructure {
                rotation_deg: q(10, 1.24, 3.5),
                ..ViewStructure::default()
            },
            persistence: vec![
                LagRow {
                    lag_s: 0.05,
                    pairs: 300,
                    correlation: 0.9,
                },
                LagRow {
                    lag_s: 1.0,
                    pairs: 300,
                    correlation: 0.25,
                },
            ],
        }
    }

    #[test]
    fn the_detector_error_tables_lay_out_every_row() {
        let text = detector_error_tables(&report());
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "");
        assert_eq!(
            lines[1],
            "detector error, each view against the other views (267 frames; % of the person's image height, median p90; persistent = mean over 1 s):"
        );
        assert_eq!(
            lines[2],
            "                         n       total  persistent      jitter      total px"
        );
        assert_eq!(
            lines[3],
            "  all                   10  2.00  5.00  0.00  0.00  0.00  0.00    4.0    9.0"
        );
        assert_eq!(
            lines[4],
            "                   persistent part shared by the view's landmarks  0.00  0.00, each landmark's own  0.00  0.00"
        );
        assert_eq!(
            lines[5],
            "                   per view and frame: shift  0.00  0.00, scale error  0.00  0.00, rotation 1.2 3.5°; left per landmark  0.00  0.00"
        );
        assert_eq!(
            lines[6],
            "  torso                 10  2.00  5.00  0.00  0.00  0.00  0.00    4.0    9.0"
        );
        assert_eq!(
            lines[7],
            "  camera cam_0          10  2.00  5.00  0.00  0.00  0.00  0.00    4.0    9.0"
        );
        assert_eq!(
            lines[8],
            "                   seen in 260 frames, missing in 7, 3.1% of landmarks dropped, 2 frames left/right-swapped, 1 someone else"
        );
        assert_eq!(lines[9], "  by confidence:");
        assert_eq!(lines[10], "    0.50–0.80  n     10   2.00  5.00");
        assert_eq!(lines[11], "    (the detections carry no confidence)");
        assert_eq!(lines[13], "     45–90 °  n     10   2.00  5.00");
        assert_eq!(lines[15], "    0.05 s 0.90   1.00 s 0.25");
        assert_eq!(lines.len(), 16);
    }
}
