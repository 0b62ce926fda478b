//! A view of a different board than declared is rejected, never used.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_calibration::{detect_checkerboard, BoardSpec, GrayImage, Rejection};

fn image(name: &str) -> GrayImage {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../shared/data/opencv-stereo-sample")
        .join(name);
    GrayImage::decode(&std::fs::read(path).unwrap(), name).unwrap()
}

#[test]
fn a_smaller_declared_board_is_rejected_as_wrong_size() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let img = image("left01.jpg");
    for (cols, rows) in [(8, 6), (9, 5), (7, 5), (5, 6)] {
        let board = BoardSpec::new(cols, rows, 0.025).unwrap();
        let got = detect_checkerboard(&img, &board);
        assert!(
            matches!(got, Err(Rejection::WrongGridSize { .. })),
            "{cols}x{rows}: {got:?}"
        );
    }
}

#[test]
fn a_larger_declared_board_is_rejected() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let img = image("right03.jpg");
    for (cols, rows) in [(10, 6), (9, 7), (11, 8)] {
        let board = BoardSpec::new(cols, rows, 0.025).unwrap();
        assert!(detect_checkerboard(&img, &board).is_err(), "{cols}x{rows}");
    }
}

#[test]
fn a_blank_image_has_no_board() {
    let img = GrayImage::from_vec(320, 240, vec![128.0; 320 * 240]).unwrap();
    let board = BoardSpec::new(9, 6, 0.025).unwrap();
    let got = detect_checkerboard(&img, &board);
    assert!(
        matches!(got, Err(Rejection::TooFewCorners { .. })),
        "{got:?}"
    );
}

/// A 9x6 board declared 6x9 is the same board turned a quarter: found, with 6 corners per row.
#[test]
fn a_transposed_declaration_finds_the_same_corners() {
    if ergocell_testdata::skip_without("data/opencv-stereo-sample") {
        return;
    }
    let img = image("left01.jpg");
    let a = detect_checkerboard(&img, &BoardSpec::new(9, 6, 0.025).unwrap()).unwrap();
    let b = detect_checkerboard(&img, &BoardSpec::new(6, 9, 0.025).unwrap()).unwrap();
    for p in &a.corners {
        assert!(b.corners.iter().any(|q| (p - q).norm() < 1e-9));
    }
}
