//! The synthetic cell shared by the fusion bench and the `fusion_golden` example: `n` cameras as
//! stereo pairs in a ring 3 m around the operator, 1280×720, mild distortion, and BlazePose-33
//! frames of a body seen with deterministic pixel noise.
//!
//! Included with `#[path]` (a bench and an example cannot share a module otherwise); not part of
//! the library's API.

#![allow(dead_code, clippy::unwrap_used)]

use ergocell_perception::detections::{Keypoint2, View2};
use ergocell_perception::{Camera, CameraId, CameraRig, Distortion, Frame2, Intrinsics};
use ergocell_skeleton::{Landmark, LANDMARK_COUNT};
use nalgebra::{Point3, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// `n` cameras (`n` even): pair `j` at angle `j·2π/(n/2)`, both cameras looking the same way
/// (parallel axes, 12 cm baseline).
pub fn rig(n: usize) -> CameraRig {
    let cams = (0..n)
        .map(|k| {
            let pair = k / 2;
            let angle = pair as f64 * std::f64::consts::TAU / (n / 2) as f64;
            let centre = Point3::new(3.0 * angle.cos(), 3.0 * angle.sin(), 2.0);
            let target = Point3::new(0.0, 0.0, 1.0);
            let x = (target - centre).cross(&Vector3::z()).normalize();
            let offset = x * if k % 2 == 0 { -0.06 } else { 0.06 };
            Camera::look_at(
                CameraId::new(format!("cam_{k}")).unwrap(),
                centre + offset,
                target + offset,
                Vector3::z(),
                Intrinsics {
                    fx: 700.0,
                    fy: 700.0,
                    cx: 640.0,
                    cy: 360.0,
                    skew: 0.0,
                    width_px: 1280,
                    height_px: 720,
                },
                Distortion {
                    k1: -0.04,
                    k2: 0.01,
                    p1: 0.0002,
                    p2: -0.0003,
                    k3: 0.0,
                },
            )
            .unwrap()
        })
        .collect();
    CameraRig::new(cams, &[], None).unwrap()
}

/// A rough 33-point body standing at the origin.
fn body(phase: f64) -> [Point3<f64>; LANDMARK_COUNT] {
    std::array::from_fn(|i| {
        let sway = 0.05 * (phase + i as f64 * 0.3).sin();
        Point3::new(
            0.1 * ((i * 7) % 5) as f64 - 0.2 + sway,
            0.05 * ((i * 3) % 4) as f64 - 0.1,
            0.1 + 1.6 * i as f64 / 33.0,
        )
    })
}

/// The bench's frame: every camera sees every landmark, ≈ 2 px fixed noise, confidence 0.9.
pub fn frame(rig: &CameraRig) -> Frame2 {
    let body = body(0.0);
    let views = rig
        .cameras()
        .iter()
        .enumerate()
        .map(|(k, cam)| {
            let mut v = View2::empty(k, 0);
            for lm in Landmark::ALL {
                let px = cam.project(&body[lm.index()]).unwrap();
                let noise = ((k * 31 + lm.index() * 17) % 9) as f64 * 0.5 - 2.0;
                v.set(
                    lm,
                    Some(Keypoint2::new(px.x + noise, px.y - 0.7 * noise, 0.9).unwrap()),
                );
            }
            v
        })
        .collect();
    Frame2 {
        stamp_nanos: 0,
        views,
    }
}

/// A moving body over `frames` frames at 30 Hz, seen with Gaussian-ish 2 px noise, 5 % of keypoints
/// missing, 2 % gross errors (up to 60 px), confidences 0.05–1 and, now and then, a whole camera
/// absent: what the fusion meets in a real cell, reproducible from `seed`.
pub fn sequence(rig: &CameraRig, frames: usize, seed: u64) -> impl Iterator<Item = Frame2> + '_ {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..frames).map(move |f| {
        let stamp_nanos = f as i64 * 33_333_333;
        let body = body(f as f64 / 30.0);
        let mut views = Vec::new();
        for (k, cam) in rig.cameras().iter().enumerate() {
            if rng.random::<f64>() < 0.01 {
                continue;
            }
            {
                let mut v = View2::empty(k, stamp_nanos);
                for lm in Landmark::ALL {
                    if rng.random::<f64>() < 0.05 {
                        continue;
                    }
                    let Ok(px) = cam.project(&body[lm.index()]) else {
                        continue;
                    };
                    let mut du = (rng.random::<f64>() + rng.random::<f64>() - 1.0) * 3.5;
                    let mut dv = (rng.random::<f64>() + rng.random::<f64>() - 1.0) * 3.5;
                    if rng.random::<f64>() < 0.02 {
                        du += rng.random_range(-60.0..60.0);
                        dv += rng.random_range(-60.0..60.0);
                    }
                    let confidence = rng.random_range(0.05..1.0);
                    v.set(lm, Keypoint2::new(px.x + du, px.y + dv, confidence).ok());
                }
                views.push(v);
            }
        }
        Frame2 { stamp_nanos, views }
    })
}
