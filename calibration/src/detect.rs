//! Checkerboard inner-corner detection to sub-pixel accuracy, with strict grid validation.
//!
//! 1. X-corner candidates: the ChESS response (Bennett & Lasenby, "ChESS – Quick and robust
//!    detection of chess-board features", CVIU 2014) on a ring of 16 pixels at radius 5 of a
//!    σ = 1 px smoothed image, non-maximum suppression in a 5×5 window.
//! 2. Grid growth: from a seed corner and its two nearest non-collinear neighbours, the lattice is
//!    grown cell by cell, each neighbour predicted by linear extrapolation (which follows
//!    perspective) and accepted only within 30 % of the local step.
//! 3. Validation, every failure a [`Rejection`] with its reason: exactly `rows × cols` corners in a
//!    full rectangle, regular steps along every row and column, square colours that alternate.
//! 4. Order: row-major, right-handed in the image (board x to the right of board y as seen from the
//!    front), cell (0,0) dark (see [`crate::board`]), so left and right images of a pair agree.
//! 5. Sub-pixel refinement as OpenCV's `cornerSubPix`: the corner `q` minimises
//!    `Σ w (∇I(p) · (q − p))²` over an 11×11 window (Förstner's operator), iterated to 0.005 px.
//!
//! Per image of a calibration, [`ImageDetection`]: decoded from its bytes and detected, or why not,
//! as `ergocell calibrate`'s tables report it; [`common_size`], [`usable_views`] and
//! [`camera_views`] turn a camera's images into the views a calibration takes.

use std::collections::HashMap;
use std::fmt;

use ergocell_perception::CameraId;
use nalgebra::{Matrix2, Point2, Vector2};

use crate::board::BoardSpec;
use crate::error::CalibrationError;
use crate::gray::GrayImage;
use crate::rig::CameraViews;

/// A validated checkerboard detection: one sub-pixel corner per board corner, row-major.
#[derive(Debug, Clone, PartialEq)]
pub struct Detection {
    /// Pixels (origin at the top-left pixel's centre), index `r · cols + c`.
    pub corners: Vec<Point2<f64>>,
    /// `(width, height)` of the image.
    pub image_size_px: (u32, u32),
    /// How the 180° ambiguity was resolved.
    pub orientation: OrientationSource,
}

impl Detection {
    /// The corners for a stereo or rig calibration, where every camera must list the same physical
    /// corner first: rejected when only the image position fixed the order (a board whose
    /// rows + cols is even looks the same turned 180°, so two cameras may disagree).
    pub fn into_rig_corners(self, board: &BoardSpec) -> Result<Vec<Point2<f64>>, Rejection> {
        match self.orientation {
            OrientationSource::Colour => Ok(self.corners),
            OrientationSource::ImagePosition => Err(Rejection::AmbiguousOrder {
                cols: board.cols(),
                rows: board.rows(),
            }),
        }
    }
}

/// How a detection's corner order was fixed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OrientationSource {
    /// By the square colours: the same physical corner is first in every camera.
    Colour,
    /// The board's colours are symmetric (rows + cols even): corner 0 is the one nearest the image's
    /// top-left. Consistent across cameras only when they see the board the same way up.
    ImagePosition,
}

/// Why an image gives no usable view. Outcomes, not errors: the view is skipped.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Rejection {
    /// Not enough X-corner candidates in the image.
    TooFewCorners { found: usize, expected: usize },
    /// Corners were found but no lattice of the expected size could be grown from them.
    WrongGridSize {
        found_cols: usize,
        found_rows: usize,
        expected_cols: usize,
        expected_rows: usize,
    },
    /// The grown lattice is not a full rectangle (a corner is missing or occluded).
    IncompleteGrid { found: usize, expected: usize },
    /// Steps along a row or column change direction or length too much (a spurious corner).
    IrregularGrid { row: usize, col: usize },
    /// A lattice point is not a checkerboard X-corner (quadrants do not alternate dark/light).
    NotAnXCorner { row: usize, col: usize, score: f64 },
    /// The board's dark and light squares are not distinguishable.
    LowContrast { contrast: f64 },
    /// A square's colour breaks the checkerboard pattern.
    ColoursDoNotAlternate { row: usize, col: usize },
    /// The board is symmetric under a half turn (rows + cols even): its corner order cannot be
    /// matched across cameras.
    AmbiguousOrder { cols: usize, rows: usize },
    /// Sub-pixel refinement moved a corner too far from the lattice.
    RefinementDiverged {
        row: usize,
        col: usize,
        shift_px: f64,
    },
}

impl fmt::Display for Rejection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::TooFewCorners { found, expected } => {
                write!(f, "only {found} corner candidates, the board has {expected}")
            }
            Self::WrongGridSize {
                found_cols,
                found_rows,
                expected_cols,
                expected_rows,
            } => write!(
                f,
                "largest grid is {found_cols}x{found_rows}, expected {expected_cols}x{expected_rows}"
            ),
            Self::IncompleteGrid { found, expected } => {
                write!(f, "grid not rectangular: {found} of {expected} corners")
            }
            Self::IrregularGrid { row, col } => {
                write!(f, "irregular grid spacing at corner (row {row}, col {col})")
            }
            Self::NotAnXCorner { row, col, score } => write!(
                f,
                "lattice point (row {row}, col {col}) is not an X-corner (score {score:.1})"
            ),
            Self::LowContrast { contrast } => {
                write!(f, "dark/light squares differ by only {contrast:.1} grey levels")
            }
            Self::ColoursDoNotAlternate { row, col } => {
                write!(f, "square colours do not alternate at cell (row {row}, col {col})")
            }
            Self::AmbiguousOrder { cols, rows } => write!(
                f,
                "a {cols}x{rows} board looks the same turned 180° (rows + cols even): the corner \
                 order cannot be matched between cameras; use a board such as 9x6"
            ),
            Self::RefinementDiverged { row, col, shift_px } => write!(
                f,
                "sub-pixel refinement moved corner (row {row}, col {col}) by {shift_px:.2} px"
            ),
        }
    }
}

/// ChESS ring radius and the minimum grey-level difference between dark and light squares.
const RING_RADIUS: f64 = 5.0;
const MIN_CONTRAST: f64 = 15.0;
/// Seeds tried before giving up.
const MAX_SEEDS: usize = 40;

/// Detects the inner corners of `board` in `image`.
pub fn detect_checkerboard(image: &GrayImage, board: &BoardSpec) -> Result<Detection, Rejection> {
    let smooth = image.gaussian_blur(1.0);
    let candidates = chess_candidates(&smooth);
    let expected = board.corner_count();
    if candidates.len() < expected {
        return Err(Rejection::TooFewCorners {
            found: candidates.len(),
            expected,
        });
    }
    let points: Vec<Point2<f64>> = candidates.iter().map(|c| c.0).collect();
    let mut best_rejection: Option<(usize, Rejection)> = None;
    let mut covered = vec![false; points.len()];
    for seed in 0..points.len().min(MAX_SEEDS) {
        if covered[seed] {
            continue;
        }
        let Some(grid) = grow_from(seed, &points) else {
            continue;
        };
        for &idx in grid.cells.values() {
            covered[idx] = true;
        }
        let size = grid.cells.len();
        match accept_grid(&grid, &points, board, image, &smooth) {
            Ok(det) => return Ok(det),
            Err(rejection) => {
                if best_rejection.as_ref().is_none_or(|(n, _)| size > *n) {
                    best_rejection = Some((size, rejection));
                }
            }
        }
    }
    Err(best_rejection.map_or(
        Rejection::WrongGridSize {
            found_cols: 0,
            found_rows: 0,
            expected_cols: board.cols(),
            expected_rows: board.rows(),
        },
        |(_, r)| r,
    ))
}

/// ChESS ring offsets: 16 samples at radius 5, starting at 12 o'clock, in circular order.
fn ring() -> [(isize, isize); 16] {
    let mut out = [(0, 0); 16];
    for (n, o) in out.iter_mut().enumerate() {
        let a = std::f64::consts::TAU * n as f64 / 16.0;
        *o = (
            (RING_RADIUS * a.sin()).round() as isize,
            (-RING_RADIUS * a.cos()).round() as isize,
        );
    }
    out
}

/// X-corner candidates `(position, response)` sorted by decreasing response.
fn chess_candidates(img: &GrayImage) -> Vec<(Point2<f64>, f64)> {
    let (w, h) = (img.width(), img.height());
    let ring = ring();
    let border = RING_RADIUS as usize + 2;
    if w <= 2 * border || h <= 2 * border {
        return Vec::new();
    }
    let mut response = vec![0.0f32; w * h];
    let mut max_r = 0.0f32;
    let data = img.data();
    let offsets: Vec<isize> = ring.iter().map(|(dx, dy)| dy * w as isize + dx).collect();
    let mut s = [0.0f32; 16];
    for y in border..h - border {
        for x in border..w - border {
            let idx = y * w + x;
            for (v, o) in s.iter_mut().zip(&offsets) {
                *v = data[idx.wrapping_add_signed(*o)];
            }
            let mut sum_r = 0.0;
            for n in 0..4 {
                sum_r += ((s[n] + s[n + 8]) - (s[n + 4] + s[n + 12])).abs();
            }
            let mut diff_r = 0.0;
            for n in 0..8 {
                diff_r += (s[n] - s[n + 8]).abs();
            }
            let ring_mean = s.iter().sum::<f32>() / 16.0;
            let local_mean =
                (data[idx] + data[idx + 1] + data[idx - 1] + data[idx + w] + data[idx - w]) / 5.0;
            let r = sum_r - diff_r - 16.0 * (ring_mean - local_mean).abs();
            response[idx] = r;
            max_r = max_r.max(r);
        }
    }
    let response: Vec<f64> = response.into_iter().map(f64::from).collect();
    let max_r = f64::from(max_r);
    if max_r <= 0.0 {
        return Vec::new();
    }
    let threshold = 0.05 * max_r;
    let mut out = Vec::new();
    for y in border..h - border {
        'pixel: for x in border..w - border {
            let r = response[y * w + x];
            if r <= threshold {
                continue;
            }
            for dy in -2isize..=2 {
                for dx in -2isize..=2 {
                    if dx == 0 && dy == 0 {
                        continue;
                    }
                    let o = response[(y as isize + dy) as usize * w + (x as isize + dx) as usize];
                    // ties: keep the first in raster order
                    if o > r || (o == r && (dy < 0 || (dy == 0 && dx < 0))) {
                        continue 'pixel;
                    }
                }
            }
            // response-weighted centroid in 3×3 for a better starting point
            let (mut sx, mut sy, mut sw) = (0.0, 0.0, 0.0);
            for dy in -1isize..=1 {
                for dx in -1isize..=1 {
                    let o = response[(y as isize + dy) as usize * w + (x as isize + dx) as usize]
                        .max(0.0);
                    sx += o * dx as f64;
                    sy += o * dy as f64;
                    sw += o;
                }
            }
            out.push((Point2::new(x as f64 + sx / sw, y as f64 + sy / sw), r));
        }
    }
    out.sort_by(|a, b| b.1.total_cmp(&a.1));
    out.truncate(1000);
    out
}

/// A lattice grown over the candidates: cell `(i, j)` → candidate index.
struct Grid {
    cells: HashMap<(i32, i32), usize>,
}

fn nearest_within(
    points: &[Point2<f64>],
    used: &[bool],
    target: &Point2<f64>,
    radius: f64,
) -> Option<usize> {
    let mut best = None;
    let mut best_d2 = radius * radius;
    for (k, p) in points.iter().enumerate() {
        if used[k] {
            continue;
        }
        let d2 = (p - target).norm_squared();
        if d2 < best_d2 {
            best_d2 = d2;
            best = Some(k);
        }
    }
    best
}

fn grow_from(seed: usize, points: &[Point2<f64>]) -> Option<Grid> {
    let s = points[seed];
    let mut near: Vec<(f64, usize)> = points
        .iter()
        .enumerate()
        .filter(|(k, _)| *k != seed)
        .map(|(k, p)| ((p - s).norm(), k))
        .collect();
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    near.truncate(8);
    let &(la, ka) = near.first()?;
    if la < 3.0 {
        return None;
    }
    let a = points[ka] - s;
    let (_, kb) = near.iter().skip(1).copied().find(|&(lb, k)| {
        let b = points[k] - s;
        let cos = a.dot(&b) / (la * lb);
        cos.abs() < 0.6 && lb / la < 2.5
    })?;
    let b = points[kb] - s;
    let mut cells: HashMap<(i32, i32), usize> = HashMap::new();
    let mut used = vec![false; points.len()];
    cells.insert((0, 0), seed);
    used[seed] = true;
    let mut queue = vec![(0i32, 0i32)];
    let limit = 4 * points.len().min(2500);
    while let Some(c) = queue.pop() {
        for d in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
            let t = (c.0 + d.0, c.1 + d.1);
            if cells.contains_key(&t) {
                continue;
            }
            let pc = points[cells[&c]];
            let back = (c.0 - d.0, c.1 - d.1);
            let step = if let Some(&kb) = cells.get(&back) {
                pc - points[kb]
            } else {
                let perp = (d.1.abs(), d.0.abs());
                let mut from_side = None;
                for sgn in [1, -1] {
                    let side = (c.0 + sgn * perp.0, c.1 + sgn * perp.1);
                    let side_t = (side.0 + d.0, side.1 + d.1);
                    if let (Some(&k0), Some(&k1)) = (cells.get(&side), cells.get(&side_t)) {
                        from_side = Some(points[k1] - points[k0]);
                        break;
                    }
                }
                from_side.unwrap_or_else(|| {
                    let axis = if d.0 != 0 { a } else { b };
                    axis * f64::from(d.0 + d.1)
                })
            };
            let pred = pc + step;
            if let Some(k) = nearest_within(points, &used, &pred, 0.3 * step.norm()) {
                used[k] = true;
                cells.insert(t, k);
                queue.push(t);
                if cells.len() > limit {
                    return None;
                }
            }
        }
    }
    Some(Grid { cells })
}

/// Validates a grown grid against the board and builds the ordered, refined detection.
fn accept_grid(
    grid: &Grid,
    points: &[Point2<f64>],
    board: &BoardSpec,
    image: &GrayImage,
    smooth: &GrayImage,
) -> Result<Detection, Rejection> {
    let expected = board.corner_count();
    let mut cells: HashMap<(i32, i32), Point2<f64>> =
        grid.cells.iter().map(|(&c, &k)| (c, points[k])).collect();
    fill_holes(&mut cells);
    let scores = x_scores(&cells, smooth);
    let (imin, imax, jmin, jmax) = cells.keys().fold(
        (i32::MAX, i32::MIN, i32::MAX, i32::MIN),
        |(a, b, c, d), &(i, j)| (a.min(i), b.max(i), c.min(j), d.max(j)),
    );
    let bw = (imax - imin + 1) as usize;
    let bh = (jmax - jmin + 1) as usize;
    // the best full sub-rectangle of the board's size: the one whose weakest corner is strongest
    let mut best: Option<(f64, i32, i32, usize, usize)> = None;
    for (w, h) in [(board.cols(), board.rows()), (board.rows(), board.cols())] {
        if w > bw || h > bh {
            continue;
        }
        for i0 in imin..=imax + 1 - w as i32 {
            for j0 in jmin..=jmax + 1 - h as i32 {
                let mut weakest = f64::INFINITY;
                for i in i0..i0 + w as i32 {
                    for j in j0..j0 + h as i32 {
                        weakest =
                            weakest.min(scores.get(&(i, j)).copied().unwrap_or(f64::NEG_INFINITY));
                    }
                }
                if weakest.is_finite() && best.is_none_or(|b| weakest > b.0) {
                    best = Some((weakest, i0, j0, w, h));
                }
            }
        }
    }
    let Some((weakest, i0, j0, w, h)) = best else {
        let fits = (bw >= board.cols() && bh >= board.rows())
            || (bw >= board.rows() && bh >= board.cols());
        return Err(if fits {
            Rejection::IncompleteGrid {
                found: cells.len(),
                expected,
            }
        } else {
            Rejection::WrongGridSize {
                found_cols: bw.max(bh),
                found_rows: bw.min(bh),
                expected_cols: board.cols(),
                expected_rows: board.rows(),
            }
        });
    };
    let strength = |list: &[(i32, i32)]| {
        let mut v: Vec<f64> = list
            .iter()
            .map(|c| scores.get(c).copied().unwrap_or(0.0))
            .collect();
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied().unwrap_or(0.0)
    };
    let inside: Vec<(i32, i32)> = (i0..i0 + w as i32)
        .flat_map(|i| (j0..j0 + h as i32).map(move |j| (i, j)))
        .collect();
    let typical = strength(&inside);
    let accept_threshold = (0.1 * typical).max(0.5 * MIN_CONTRAST);
    if weakest < accept_threshold {
        let (k, _) = inside
            .iter()
            .enumerate()
            .min_by(|a, b| scores[a.1].total_cmp(&scores[b.1]))
            .unwrap_or((0, &(i0, j0)));
        return Err(Rejection::NotAnXCorner {
            row: k % h,
            col: k / h,
            score: weakest,
        });
    }
    // a full line of X-corners as good as the accepted ones just outside: the board is bigger
    // than declared (a 9x6 board declared 8x6), so no sub-grid of it may be used
    let outside = [
        (0..h as i32).map(|j| (i0 - 1, j0 + j)).collect::<Vec<_>>(),
        (0..h as i32).map(|j| (i0 + w as i32, j0 + j)).collect(),
        (0..w as i32).map(|i| (i0 + i, j0 - 1)).collect(),
        (0..w as i32).map(|i| (i0 + i, j0 + h as i32)).collect(),
    ];
    for line in &outside {
        let line_weakest = line
            .iter()
            .map(|c| scores.get(c).copied().unwrap_or(f64::NEG_INFINITY))
            .fold(f64::INFINITY, f64::min);
        if line_weakest >= accept_threshold {
            let extra_w = usize::from(line[0].1 == line[line.len() - 1].1 && line.len() == w);
            let (fw, fh) = (w + 1 - extra_w, h + extra_w);
            return Err(Rejection::WrongGridSize {
                found_cols: fw.max(fh),
                found_rows: fw.min(fh),
                expected_cols: board.cols(),
                expected_rows: board.rows(),
            });
        }
    }
    // g[j][i]
    let g: Vec<Vec<Point2<f64>>> = (0..h)
        .map(|j| {
            (0..w)
                .map(|i| cells[&(i0 + i as i32, j0 + j as i32)])
                .collect()
        })
        .collect();
    check_regular(&g)?;
    let (dark_parity, _contrast) = check_colours(&g, smooth)?;
    // The 8 symmetries of the rectangle: (transpose, flip rows, flip cols) onto (r, c).
    let mut options: Vec<(Vec<Point2<f64>>, bool)> = Vec::new();
    for transpose in [false, true] {
        let (rows, cols) = if transpose { (w, h) } else { (h, w) };
        if rows != board.rows() || cols != board.cols() {
            continue;
        }
        for flip_r in [false, true] {
            for flip_c in [false, true] {
                let at = |r: usize, c: usize| {
                    let r = if flip_r { rows - 1 - r } else { r };
                    let c = if flip_c { cols - 1 - c } else { c };
                    if transpose {
                        g[c][r]
                    } else {
                        g[r][c]
                    }
                };
                let ordered: Vec<Point2<f64>> = (0..rows)
                    .flat_map(|r| (0..cols).map(move |c| (r, c)))
                    .map(|(r, c)| at(r, c))
                    .collect();
                // handedness: board x (columns) then board y (rows) must turn like image u then v
                let col_dir = ordered[cols - 1] - ordered[0];
                let row_dir = ordered[(rows - 1) * cols] - ordered[0];
                if col_dir.x * row_dir.y - col_dir.y * row_dir.x <= 0.0 {
                    continue;
                }
                // which original cell is (0,0)? parity of its original indices
                let (r0, c0) = (
                    if flip_r { rows - 2 } else { 0 },
                    if flip_c { cols - 2 } else { 0 },
                );
                let (j0, i0) = if transpose { (c0, r0) } else { (r0, c0) };
                let dark_first = (i0 + j0) % 2 == dark_parity;
                options.push((ordered, dark_first));
            }
        }
    }
    let dark: Vec<&(Vec<Point2<f64>>, bool)> = options.iter().filter(|o| o.1).collect();
    let pool: Vec<&(Vec<Point2<f64>>, bool)> = if dark.is_empty() {
        options.iter().collect()
    } else {
        dark
    };
    let orientation = if pool.len() == 1 {
        OrientationSource::Colour
    } else {
        OrientationSource::ImagePosition
    };
    let chosen = pool
        .into_iter()
        .min_by(|a, b| (a.0[0].x + a.0[0].y).total_cmp(&(b.0[0].x + b.0[0].y)))
        .ok_or(Rejection::IncompleteGrid {
            found: grid.cells.len(),
            expected,
        })?;
    let corners = refine_corners(image, &chosen.0, board)?;
    Ok(Detection {
        corners,
        image_size_px: image.size_px(),
        orientation,
    })
}

/// Fills lattice holes (a corner the candidate detector missed) between two known neighbours on
/// a row or column; sub-pixel refinement and validation then treat it like any corner.
fn fill_holes(cells: &mut HashMap<(i32, i32), Point2<f64>>) {
    for _ in 0..3 {
        let mut added = Vec::new();
        let (imin, imax, jmin, jmax) = cells.keys().fold(
            (i32::MAX, i32::MIN, i32::MAX, i32::MIN),
            |(a, b, c, d), &(i, j)| (a.min(i), b.max(i), c.min(j), d.max(j)),
        );
        for i in imin..=imax {
            for j in jmin..=jmax {
                if cells.contains_key(&(i, j)) {
                    continue;
                }
                let pairs = [((i - 1, j), (i + 1, j)), ((i, j - 1), (i, j + 1))];
                let mids: Vec<Point2<f64>> = pairs
                    .iter()
                    .filter_map(|(a, b)| {
                        Some(Point2::from(
                            (cells.get(a)?.coords + cells.get(b)?.coords) / 2.0,
                        ))
                    })
                    .collect();
                if !mids.is_empty() {
                    let mean = mids.iter().fold(Vector2::zeros(), |acc, p| acc + p.coords)
                        / mids.len() as f64;
                    added.push(((i, j), Point2::from(mean)));
                }
            }
        }
        if added.is_empty() {
            break;
        }
        cells.extend(added);
    }
}

/// X-corner score of each lattice point: its four quadrants (half a step along each lattice axis)
/// must alternate dark/light; the score is the smallest of the four adjacent-quadrant differences
/// (grey levels). A T-junction where the outer squares meet the board's margin — which continues
/// the lattice one row or column too far — scores near zero, as does background clutter.
fn x_scores(
    cells: &HashMap<(i32, i32), Point2<f64>>,
    smooth: &GrayImage,
) -> HashMap<(i32, i32), f64> {
    let axis = |c: (i32, i32), d: (i32, i32)| -> Option<Vector2<f64>> {
        let p = cells.get(&c)?;
        let fwd = cells.get(&(c.0 + d.0, c.1 + d.1));
        let back = cells.get(&(c.0 - d.0, c.1 - d.1));
        match (fwd, back) {
            (Some(f), Some(b)) => Some((f - b) / 2.0),
            (Some(f), None) => Some(f - p),
            (None, Some(b)) => Some(p - b),
            (None, None) => None,
        }
    };
    let quadrant = |p: Point2<f64>, v: Vector2<f64>, w: Vector2<f64>| {
        let c = p + v;
        let mut acc = smooth.sample(c.x, c.y);
        for o in [w * 0.15, -w * 0.15, v * 0.15, -v * 0.15] {
            acc += smooth.sample(c.x + o.x, c.y + o.y);
        }
        acc / 5.0
    };
    cells
        .iter()
        .map(|(&c, &p)| {
            let (Some(a), Some(b)) = (axis(c, (1, 0)), axis(c, (0, 1))) else {
                return (c, 0.0);
            };
            let (d1, d2) = ((a + b) * 0.5, (a - b) * 0.5);
            let q1 = quadrant(p, d1, d2);
            let q2 = quadrant(p, d2, d1);
            let q3 = quadrant(p, -d1, d2);
            let q4 = quadrant(p, -d2, d1);
            let s = (q1 + q3 - q2 - q4).signum();
            let score = (s * (q1 - q2))
                .min(s * (q3 - q2))
                .min(s * (q1 - q4))
                .min(s * (q3 - q4));
            (c, score)
        })
        .collect()
}

/// Every step along a row or column keeps its direction (within ~45°) and length (within a
/// factor 1.6) from the previous one.
fn check_regular(g: &[Vec<Point2<f64>>]) -> Result<(), Rejection> {
    let h = g.len();
    let w = g[0].len();
    let ok = |s0: Vector2<f64>, s1: Vector2<f64>| {
        let (l0, l1) = (s0.norm(), s1.norm());
        l0 > 2.0 && l1 > 2.0 && s0.dot(&s1) > 0.7 * l0 * l1 && l1 / l0 < 1.6 && l0 / l1 < 1.6
    };
    for j in 0..h {
        for i in 1..w.saturating_sub(1) {
            if !ok(g[j][i] - g[j][i - 1], g[j][i + 1] - g[j][i]) {
                return Err(Rejection::IrregularGrid { row: j, col: i });
            }
        }
    }
    for i in 0..w {
        for j in 1..h.saturating_sub(1) {
            if !ok(g[j][i] - g[j - 1][i], g[j + 1][i] - g[j][i]) {
                return Err(Rejection::IrregularGrid { row: j, col: i });
            }
        }
    }
    Ok(())
}

/// The squares between corners alternate dark/light. Returns the parity `(i + j) % 2` of the dark
/// cells and the contrast.
fn check_colours(g: &[Vec<Point2<f64>>], smooth: &GrayImage) -> Result<(usize, f64), Rejection> {
    let h = g.len();
    let w = g[0].len();
    let mut values = Vec::with_capacity((h - 1) * (w - 1));
    let mut sums = [0.0f64; 2];
    let mut counts = [0usize; 2];
    for j in 0..h - 1 {
        for i in 0..w - 1 {
            let (p00, p01, p10, p11) = (g[j][i], g[j][i + 1], g[j + 1][i], g[j + 1][i + 1]);
            let c = Point2::from((p00.coords + p01.coords + p10.coords + p11.coords) / 4.0);
            let mut v = 0.0;
            for q in [p00, p01, p10, p11] {
                let s = c + (q - c) * 0.3;
                v += smooth.sample(s.x, s.y);
            }
            v += smooth.sample(c.x, c.y);
            v /= 5.0;
            let parity = (i + j) % 2;
            sums[parity] += v;
            counts[parity] += 1;
            values.push((j, i, parity, v));
        }
    }
    let means = [
        sums[0] / counts[0].max(1) as f64,
        sums[1] / counts[1].max(1) as f64,
    ];
    let contrast = (means[0] - means[1]).abs();
    if contrast < MIN_CONTRAST {
        return Err(Rejection::LowContrast { contrast });
    }
    let dark = usize::from(means[1] < means[0]);
    let mid = 0.5 * (means[0] + means[1]);
    for (j, i, parity, v) in values {
        let should_be_dark = parity == dark;
        let margin = if should_be_dark { mid - v } else { v - mid };
        if margin < 0.2 * contrast {
            return Err(Rejection::ColoursDoNotAlternate { row: j, col: i });
        }
    }
    Ok((dark, contrast))
}

/// OpenCV's `cornerSubPix`: each corner moves to the point whose offset to every window pixel is
/// orthogonal to that pixel's gradient, weighted by a Gaussian, with the window shrunk below half
/// the local grid step so it never reaches a neighbouring corner.
fn refine_corners(
    image: &GrayImage,
    ordered: &[Point2<f64>],
    board: &BoardSpec,
) -> Result<Vec<Point2<f64>>, Rejection> {
    let cols = board.cols();
    let rows = board.rows();
    let mut out = Vec::with_capacity(ordered.len());
    for (k, &p0) in ordered.iter().enumerate() {
        let (r, c) = (k / cols, k % cols);
        // smallest distance to a 4-neighbour
        let mut spacing = f64::INFINITY;
        for (dr, dc) in [(0i64, 1i64), (0, -1), (1, 0), (-1, 0)] {
            let (rr, cc) = (r as i64 + dr, c as i64 + dc);
            if rr >= 0 && cc >= 0 && (rr as usize) < rows && (cc as usize) < cols {
                spacing = spacing.min((ordered[rr as usize * cols + cc as usize] - p0).norm());
            }
        }
        let half = (0.4 * spacing).floor().clamp(2.0, 5.0) as isize;
        let q = corner_subpix(image, p0, half);
        let shift = (q - p0).norm();
        if !(shift.is_finite() && shift <= half as f64) {
            return Err(Rejection::RefinementDiverged {
                row: r,
                col: c,
                shift_px: shift,
            });
        }
        out.push(q);
    }
    Ok(out)
}

fn corner_subpix(image: &GrayImage, start: Point2<f64>, half: isize) -> Point2<f64> {
    let mut q = start;
    let hw = half as f64;
    // the window plus a one-pixel border for the gradients, resampled at q's sub-pixel offset
    // (OpenCV's getRectSubPix), so each iteration samples the image once per pixel
    let side = (2 * half + 3) as usize;
    let mut patch = vec![0.0f64; side * side];
    let weights: Vec<f64> = (-half..=half)
        .flat_map(|dy| {
            (-half..=half).map(move |dx| (-((dx * dx + dy * dy) as f64) / (hw * hw)).exp())
        })
        .collect();
    for _ in 0..40 {
        for (r, row) in patch.chunks_mut(side).enumerate() {
            let y = q.y + r as f64 - (half + 1) as f64;
            for (c, v) in row.iter_mut().enumerate() {
                *v = image.sample(q.x + c as f64 - (half + 1) as f64, y);
            }
        }
        let mut a = Matrix2::zeros();
        let mut bvec = Vector2::zeros();
        let mut k = 0;
        for dy in -half..=half {
            for dx in -half..=half {
                let (r, c) = ((dy + half + 1) as usize, (dx + half + 1) as usize);
                let gx = 0.5 * (patch[r * side + c + 1] - patch[r * side + c - 1]);
                let gy = 0.5 * (patch[(r + 1) * side + c] - patch[(r - 1) * side + c]);
                let wgt = weights[k];
                k += 1;
                let (x, y) = (q.x + dx as f64, q.y + dy as f64);
                let (gxx, gxy, gyy) = (gx * gx * wgt, gx * gy * wgt, gy * gy * wgt);
                a += Matrix2::new(gxx, gxy, gxy, gyy);
                bvec += Vector2::new(gxx * x + gxy * y, gxy * x + gyy * y);
            }
        }
        if a.determinant().abs() < 1e-9 {
            return q;
        }
        let Some(inv) = a.try_inverse() else {
            return q;
        };
        let next = Point2::from(inv * bvec);
        let moved = (next - q).norm();
        q = next;
        if moved < 0.005 || (q - start).norm() > hw {
            break;
        }
    }
    q
}

/// One calibration image's outcome, as `ergocell calibrate`'s tables report it: its name (the path
/// as given), its size when it decoded, and its corners, or why not (it did not decode, or the
/// board's [`Rejection`]).
#[derive(Debug, Clone, PartialEq)]
pub struct ImageDetection {
    pub name: String,
    pub size_px: Option<(u32, u32)>,
    pub corners: Result<Vec<Point2<f64>>, String>,
}

impl ImageDetection {
    /// Decodes the image `name` from `bytes` and detects `board` in it; with `for_rig`, a view whose
    /// corner order the rig's other cameras might not share is rejected
    /// ([`Detection::into_rig_corners`]).
    pub fn detect(bytes: &[u8], name: &str, board: &BoardSpec, for_rig: bool) -> Self {
        let (size_px, corners) = match GrayImage::decode(bytes, name) {
            Ok(image) => {
                let corners = detect_checkerboard(&image, board)
                    .and_then(|d| {
                        if for_rig {
                            d.into_rig_corners(board)
                        } else {
                            Ok(d.corners)
                        }
                    })
                    .map_err(|why| why.to_string());
                (Some(image.size_px()), corners)
            }
            Err(e) => (None, Err(e.to_string())),
        };
        Self {
            name: name.to_owned(),
            size_px,
            corners,
        }
    }

    /// The image's file name without its folder (the tables' first column).
    pub fn file_name(&self) -> String {
        std::path::Path::new(&self.name)
            .file_name()
            .map_or_else(|| self.name.clone(), |n| n.to_string_lossy().into_owned())
    }
}

/// The image size a camera's images share (the first decoded one's): an image of another size is an
/// error naming it, as is a camera none of whose images decoded.
pub fn common_size(
    images: &[ImageDetection],
    camera: &CameraId,
) -> Result<(u32, u32), CalibrationError> {
    let mut size = None;
    for (view, image) in images.iter().enumerate() {
        let Some(s) = image.size_px else { continue };
        match size {
            None => size = Some(s),
            Some(want) if want != s => {
                return Err(CalibrationError::ImageSizeMismatch {
                    camera: camera.to_string(),
                    view,
                    got_w: s.0,
                    got_h: s.1,
                    want_w: want.0,
                    want_h: want.1,
                })
            }
            Some(_) => {}
        }
    }
    size.ok_or_else(|| CalibrationError::NoImageDecoded {
        camera: camera.to_string(),
    })
}

/// The images whose board was found, for a single-camera calibration: their indices among
/// `images`, and their corners.
pub fn usable_views(images: &[ImageDetection]) -> (Vec<usize>, Vec<Vec<Point2<f64>>>) {
    images
        .iter()
        .enumerate()
        .filter_map(|(i, image)| Some((i, image.corners.clone().ok()?)))
        .unzip()
}

/// One camera's views for a rig calibration: one per image (the same frames for every camera),
/// `None` where the board was not found, at the size the images share ([`common_size`]).
pub fn camera_views(
    id: CameraId,
    images: &[ImageDetection],
) -> Result<CameraViews, CalibrationError> {
    let image_size_px = common_size(images, &id)?;
    Ok(CameraViews {
        id,
        image_size_px,
        frames: images.iter().map(|r| r.corners.clone().ok()).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(name: &str, size_px: Option<(u32, u32)>, found: bool) -> ImageDetection {
        ImageDetection {
            name: name.to_owned(),
            size_px,
            corners: if found {
                Ok(vec![Point2::new(1.0, 2.0)])
            } else {
                Err("no board".to_owned())
            },
        }
    }

    #[test]
    fn images_share_the_first_decoded_size_or_the_odd_one_is_named() {
        let id = CameraId::new("left").unwrap();
        let same = [
            image("a.png", None, false),
            image("b.png", Some((640, 480)), true),
            image("c.png", Some((640, 480)), false),
        ];
        assert_eq!(common_size(&same, &id), Ok((640, 480)));
        let odd = [
            image("a.png", Some((640, 480)), true),
            image("b.png", None, false),
            image("c.png", Some((480, 640)), true),
        ];
        assert_eq!(
            common_size(&odd, &id),
            Err(CalibrationError::ImageSizeMismatch {
                camera: "left".to_owned(),
                view: 2,
                got_w: 480,
                got_h: 640,
                want_w: 640,
                want_h: 480,
            })
        );
        assert_eq!(
            common_size(&[image("a.png", None, false)], &id),
            Err(CalibrationError::NoImageDecoded {
                camera: "left".to_owned()
            })
        );
    }

    #[test]
    fn the_views_are_the_images_whose_board_was_found() {
        let images = [
            image("a.png", Some((4, 4)), false),
            image("b.png", Some((4, 4)), true),
            image("c.png", Some((4, 4)), true),
        ];
        let (used, views) = usable_views(&images);
        assert_eq!(used, [1, 2]);
        assert_eq!(
            views,
            [vec![Point2::new(1.0, 2.0)], vec![Point2::new(1.0, 2.0)]]
        );
        let rig_views = camera_views(CameraId::new("cam").unwrap(), &images).unwrap();
        assert_eq!(rig_views.image_size_px, (4, 4));
        let found: Vec<bool> = rig_views.frames.iter().map(Option::is_some).collect();
        assert_eq!(found, [false, true, true]);
    }

    #[test]
    fn an_image_that_does_not_decode_is_rejected_naming_it() {
        let board = BoardSpec::parse("9x6", 0.025).unwrap();
        let d = ImageDetection::detect(b"not an image", "data/left01.jpg", &board, false);
        assert_eq!(d.size_px, None);
        assert!(
            d.corners
                .as_ref()
                .is_err_and(|why| why.contains("data/left01.jpg")),
            "{d:?}"
        );
        assert_eq!(d.file_name(), "left01.jpg");
        assert_eq!(image("top.png", None, false).file_name(), "top.png");
    }
}
