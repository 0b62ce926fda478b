//! Bad input never panics: it gives a rejection or an error that names the problem.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_calibration::{
    calibrate_camera, calibrate_rig, detect_checkerboard, BoardSpec, CalibrationError, CameraViews,
    GrayImage, RigOptions, SolveOptions,
};
use ergocell_perception::CameraId;
use nalgebra::Point2;

fn grid(board: &BoardSpec, shift: f64) -> Vec<Point2<f64>> {
    (0..board.rows())
        .flat_map(|r| {
            (0..board.cols())
                .map(move |c| Point2::new(100.0 + 30.0 * c as f64 + shift, 80.0 + 30.0 * r as f64))
        })
        .collect()
}

#[test]
fn tiny_flat_and_noisy_images_are_rejected_not_panicking() {
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    for (w, h) in [(1, 1), (5, 3), (14, 14), (40, 30)] {
        let img = GrayImage::from_vec(w, h, vec![0.0; w * h]).unwrap();
        assert!(detect_checkerboard(&img, &board).is_err());
    }
    // pseudo-random texture: corners everywhere, no board
    let mut state = 12_345u32;
    let data = (0..320 * 240)
        .map(|_| {
            state = state.wrapping_mul(1_103_515_245).wrapping_add(12_345);
            f32::from((state >> 16) as u8)
        })
        .collect();
    let img = GrayImage::from_vec(320, 240, data).unwrap();
    assert!(detect_checkerboard(&img, &board).is_err());
    assert!(GrayImage::from_vec(3, 3, vec![0.0; 8]).is_none());
    assert!(matches!(
        GrayImage::decode(b"not an image", "junk.jpg"),
        Err(CalibrationError::Decode { .. })
    ));
}

#[test]
fn too_few_wrong_sized_or_degenerate_views_are_errors() {
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let views = vec![grid(&board, 0.0); 2];
    assert!(matches!(
        calibrate_camera(&views, &board, (640, 480), SolveOptions::default()),
        Err(CalibrationError::TooFewViews {
            usable: 2,
            needed: 3,
            ..
        })
    ));
    let mut short = vec![grid(&board, 0.0); 3];
    short[1].pop();
    assert!(matches!(
        calibrate_camera(&short, &board, (640, 480), SolveOptions::default()),
        Err(CalibrationError::CornerCount {
            view: 1,
            got: 53,
            expected: 54
        })
    ));
    // fronto-parallel boards only: no focal length is observable. Refused as degenerate, or — when the
    // solver runs off to an absurd focal length — by the camera model's focal-length range, naming it.
    let parallel = vec![grid(&board, 0.0), grid(&board, 20.0), grid(&board, 40.0)];
    let got = calibrate_camera(&parallel, &board, (640, 480), SolveOptions::default());
    assert!(
        matches!(
            &got,
            Err(CalibrationError::Degenerate { .. } | CalibrationError::Initialisation(_))
        ) || matches!(
            &got,
            Err(CalibrationError::Camera(
                ergocell_perception::PerceptionError::BadCameraParameter { field, .. }
            )) if *field == "fx" || *field == "fy"
        ),
        "{got:?}"
    );
    // NaN corners
    let mut nan = vec![grid(&board, 0.0); 3];
    nan[2][5].x = f64::NAN;
    assert!(calibrate_camera(&nan, &board, (640, 480), SolveOptions::default()).is_err());
}

#[test]
fn rig_inputs_must_correspond() {
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let cam = |id: &str, frames: usize| CameraViews {
        id: CameraId::new(id).unwrap(),
        image_size_px: (640, 480),
        frames: vec![None; frames],
    };
    let one = calibrate_rig(&[cam("a", 3)], &board, &[], RigOptions::default());
    assert!(matches!(one, Err(CalibrationError::TooFewViews { .. })));
    let mismatched = calibrate_rig(
        &[cam("a", 3), cam("b", 4)],
        &board,
        &[],
        RigOptions::default(),
    );
    assert!(matches!(
        mismatched,
        Err(CalibrationError::TooFewViews { .. })
    ));
    let empty = calibrate_rig(
        &[cam("a", 3), cam("b", 3)],
        &board,
        &[],
        RigOptions::default(),
    );
    assert!(matches!(
        empty,
        Err(CalibrationError::TooFewViews { usable: 0, .. })
    ));
}
