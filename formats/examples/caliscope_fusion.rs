//! Figure: bone-length variation on caliscope's real 4-camera recording, per fusion method.
//!
//! `cargo run --release -p ergocell_formats --example caliscope_fusion -- [data dir] [out.svg]`
//! (defaults: `../shared/data/caliscope-4cam`, `docs/fusion_bone_lengths.svg`). Prints the numbers
//! it plots. The same comparison is asserted in `formats/tests/caliscope.rs`.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;

use ergocell_formats::import::parse_caliscope_xy;
use ergocell_formats::rig_file::parse_rig;
use ergocell_perception::detections::ImportStats;
use ergocell_perception::metrics::{bone_stats, common_bone_variation_percent};
use ergocell_perception::temporal::{OneEuroFilter, OneEuroParams};
use ergocell_perception::{FusionEngine, FusionMethod};
use ergocell_skeleton::{Landmark, Skeleton3, BONES, LANDMARK_COUNT};
use nalgebra::Point3;
use plotters::prelude::*;

fn to_skeletons(points: &[[Option<Point3<f64>>; LANDMARK_COUNT]]) -> Vec<Skeleton3> {
    points
        .iter()
        .enumerate()
        .map(|(k, pts)| Skeleton3::from_optional_points(k as i64, pts).unwrap())
        .collect()
}

fn short(l: Landmark) -> String {
    l.name()
        .replace("left_", "L ")
        .replace("right_", "R ")
        .replace("shoulder", "sh")
        .replace("elbow", "elb")
        .replace("wrist", "wr")
        .replace("ankle", "ank")
}

fn main() {
    let mut args = std::env::args().skip(1);
    let dir = PathBuf::from(
        args.next()
            .unwrap_or_else(|| "../shared/data/caliscope-4cam".into()),
    );
    let out = PathBuf::from(
        args.next()
            .unwrap_or_else(|| "docs/fusion_bone_lengths.svg".into()),
    );
    let config = std::fs::read_to_string(dir.join("config.toml")).expect("config.toml");
    let (rig, _) = parse_rig(&config, "config.toml").unwrap();
    let xy = std::fs::read_to_string(dir.join("xy_pose33.csv")).expect("xy_pose33.csv");
    let frames =
        parse_caliscope_xy(&xy, "xy_pose33.csv", &rig, &mut ImportStats::default()).unwrap();

    let mut paper = FusionEngine::new(rig.clone(), FusionMethod::Paper).unwrap();
    let mut no_prior = FusionEngine::new(rig.clone(), FusionMethod::Default)
        .unwrap()
        .with_bone_prior(None);
    let mut default = FusionEngine::new(rig.clone(), FusionMethod::Default).unwrap();
    let mut default_filtered = FusionEngine::new(rig, FusionMethod::Default).unwrap();
    let mut filter = OneEuroFilter::new(OneEuroParams::default());
    let dlt: Vec<_> = frames
        .iter()
        .map(|f| default.raw_pixel_dlt(f).unwrap())
        .collect();
    let undistorted: Vec<_> = frames
        .iter()
        .map(|f| default.weighted_dlt(f).unwrap())
        .collect();
    let methods: Vec<(&str, Vec<Skeleton3>, RGBColor)> = vec![
        (
            "paper graph-Laplacian fusion",
            frames
                .iter()
                .map(|f| paper.fuse(f).unwrap().skeleton)
                .collect(),
            RGBColor(214, 39, 40),
        ),
        (
            "N-view DLT, raw pixels",
            to_skeletons(&dlt),
            RGBColor(255, 127, 14),
        ),
        (
            "N-view DLT, undistorted",
            to_skeletons(&undistorted),
            RGBColor(148, 103, 189),
        ),
        (
            "robust N-view, no bone prior",
            frames
                .iter()
                .map(|f| no_prior.fuse(f).unwrap().skeleton)
                .collect(),
            RGBColor(140, 86, 75),
        ),
        (
            "ergocell default fusion",
            frames
                .iter()
                .map(|f| default.fuse(f).unwrap().skeleton)
                .collect(),
            RGBColor(31, 119, 180),
        ),
        (
            "default + causal One-Euro",
            frames
                .iter()
                .map(|f| filter.filter(&default_filtered.fuse(f).unwrap().skeleton))
                .collect(),
            RGBColor(44, 160, 44),
        ),
    ];
    let stats: Vec<_> = methods.iter().map(|(_, s, _)| bone_stats(s)).collect();
    let recordings: Vec<&[Skeleton3]> = methods.iter().map(|(_, s, _)| s.as_slice()).collect();
    let (common, common_means) = common_bone_variation_percent(&recordings).unwrap();
    println!("bone-length variation: mean over the {} bones every method observed | over the bones each observed", common.len());
    for (((name, _, _), st), common_mean) in methods.iter().zip(&stats).zip(&common_means) {
        let mean = st.iter().map(|b| b.cv_percent).sum::<f64>() / st.len() as f64;
        println!(
            "  {name:30} {common_mean:5.2}% | {mean:5.2}% ({} bones)",
            st.len()
        );
    }

    let bones: Vec<String> = BONES
        .iter()
        .map(|b| format!("{}–{}", short(b.0), short(b.1)))
        .collect();
    let max = stats
        .iter()
        .flatten()
        .map(|b| b.cv_percent)
        .fold(0.0, f64::max)
        * 1.15;
    let root = SVGBackend::new(&out, (1100, 540)).into_drawing_area();
    root.fill(&WHITE).unwrap();
    let n_bones = bones.len();
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Bone-length variation per bone, caliscope real 4-camera recording (lower is better; no bar: never observed)",
            ("sans-serif", 17),
        )
        .margin(15)
        .x_label_area_size(60)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..n_bones as f64, 0.0..max)
        .unwrap();
    chart
        .configure_mesh()
        .disable_x_mesh()
        .x_labels(n_bones * 2 + 1)
        .x_label_formatter(&|x| {
            let i = x.floor() as usize;
            if (x - i as f64 - 0.5).abs() < 0.01 && i < bones.len() {
                bones[i].clone()
            } else {
                String::new()
            }
        })
        .y_desc("coefficient of variation of bone length, %")
        .draw()
        .unwrap();
    let width = 0.8 / methods.len() as f64;
    for (m, ((name, _, color), st)) in methods.iter().zip(&stats).enumerate() {
        let color = *color;
        chart
            .draw_series(st.iter().map(|b| {
                let i = BONES.iter().position(|x| *x == b.bone).unwrap_or(0);
                let x0 = i as f64 + 0.1 + m as f64 * width;
                Rectangle::new(
                    [(x0, 0.0), (x0 + width * 0.9, b.cv_percent)],
                    color.filled(),
                )
            }))
            .unwrap()
            .label(format!("{name} ({:.2}% on common bones)", common_means[m]))
            .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], color.filled()));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .unwrap();
    root.present().unwrap();
    println!("wrote {}", out.display());
}
