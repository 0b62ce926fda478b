//! The real detector's error, measured from calibrated multi-view detections alone.
//!
//! There is no ground truth in a real recording, so each view is judged by the others: for every
//! frame, view and landmark, the landmark is triangulated from the **other** views only
//! ([`RobustTriangulator`], at least two of them) and projected into the held-out view; the
//! residual is the detection minus that projection, in pixels (leave-one-view-out). Reprojecting a
//! point fused from all views would hide part of each view's error, as the point is pulled towards
//! it. The residual still holds the other views' error, projected: with four views it overstates
//! the held-out view's own error a little, which is the conservative side for a twin fitted to it.
//!
//! Each residual is divided by the person's **image height** in that view and frame (the vertical
//! extent of the view's detected landmarks, eyes to heels: a person standing 750 px tall in a
//! portrait video and 350 px tall in a far camera then compare), and split per view and landmark
//! into a **persistent** part, the mean residual over a centred window of `window_s` seconds (a
//! joint the detector places consistently off the anatomical point in that view), and **jitter**,
//! what is left frame to frame.
//!
//! Views whose left and right are swapped (judged like the fusion does: the mirrored labels fit the
//! other views' points better) are counted and left out of the residuals; dropouts are landmarks a
//! view does not report while it sees the person. Besides the quantiles per landmark group and per
//! camera, the report bins the error by the detector's confidence (does it predict the error?) and
//! by the viewing angle (the camera's bearing from the person's facing direction: 0° in front).

use nalgebra::{Point3, Vector2, Vector3};
use serde::{Deserialize, Serialize};

use crate::detections::Frame2;
use crate::rig::CameraRig;
use crate::triangulation::{NormalizedView, RobustTriangulator};
use ergocell_skeleton::{Landmark, LANDMARK_COUNT};

/// Landmark groups of the report: face, shoulders and arms, hips, legs.
pub const GROUPS: [(&str, std::ops::RangeInclusive<usize>); 4] = [
    ("face", 0..=10),
    ("shoulders_arms", 11..=22),
    ("hips", 23..=24),
    ("legs", 25..=32),
];

/// The group a landmark index belongs to.
pub fn group_of(index: usize) -> Option<&'static str> {
    GROUPS
        .iter()
        .find(|(_, r)| r.contains(&index))
        .map(|(name, _)| *name)
}

/// Confidence bins' lower edges (the last runs to 1).
pub const CONFIDENCE_EDGES: [f64; 5] = [0.0, 0.5, 0.8, 0.95, 0.99];

/// Viewing-angle bins' lower edges, degrees (0 = camera in front of the person, 180 = behind).
pub const ANGLE_EDGES_DEG: [f64; 4] = [0.0, 45.0, 90.0, 135.0];

/// How the measurement is made.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeasureConfig {
    /// Width of the centred window whose mean residual is the persistent part, seconds.
    pub window_s: f64,
    /// A view is measured only where it shows at least this many landmarks (for its image height).
    pub min_landmarks_in_view: usize,
    /// The triangulator of the held-out point.
    pub triangulator: RobustTriangulator,
    /// A view whose median residual exceeds this fraction of the person's image height shows
    /// someone else (an identity switch, two people in view): counted, and left out of the
    /// residuals. The real single-person videos' p99 per landmark is below 0.15.
    pub identity_switch_fraction: f64,
}

impl Default for MeasureConfig {
    fn default() -> Self {
        Self {
            window_s: 1.0,
            min_landmarks_in_view: 20,
            triangulator: RobustTriangulator::default(),
            identity_switch_fraction: 0.25,
        }
    }
}

/// One measured residual.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Residual {
    pub frame: usize,
    pub stamp_nanos: i64,
    pub camera: usize,
    pub landmark: usize,
    /// Where the other views put the landmark in this view (their point projected), pixels.
    pub predicted_px: Vector2<f64>,
    /// Detection minus the other views' point projected, pixels.
    pub residual_px: Vector2<f64>,
    pub confidence: f64,
    /// The person's image height in this view and frame, pixels.
    pub height_px: f64,
    /// The camera's bearing from the person's facing direction, degrees (when the torso was seen).
    pub view_angle_deg: Option<f64>,
}

/// Quantiles of a magnitude relative to the image height (0.02 = 2 % of the person's height).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
pub struct Quantiles {
    pub count: usize,
    pub p50: f64,
    pub p90: f64,
    pub p99: f64,
}

impl Quantiles {
    /// Quantiles of `values` (NaNs dropped; all zero when empty).
    pub fn of(mut values: Vec<f64>) -> Self {
        values.retain(|v| !v.is_nan());
        values.sort_by(f64::total_cmp);
        let q = |p: f64| {
            if values.is_empty() {
                0.0
            } else {
                // nearest rank
                let rank = ((p * values.len() as f64).ceil() as usize).clamp(1, values.len());
                values[rank - 1]
            }
        };
        Self {
            count: values.len(),
            p50: q(0.5),
            p90: q(0.9),
            p99: q(0.99),
        }
    }
}

/// The error of one subset of residuals: total, persistent and jitter magnitudes, each relative to
/// the image height, and the total in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
pub struct ErrorStats {
    pub total: Quantiles,
    pub persistent: Quantiles,
    pub jitter: Quantiles,
    /// The persistent part shared by every landmark of the view in that frame (its mean over the
    /// view's landmarks: the whole body shifted in one camera, which moves the fused skeleton but
    /// hardly its joint angles).
    pub persistent_shared: Quantiles,
    /// The persistent part of the landmark's own (persistent minus the shared part: what bends the
    /// angles between landmarks).
    pub persistent_own: Quantiles,
    pub total_px: Quantiles,
    /// Mean image height of the person over these residuals, pixels.
    pub mean_height_px: f64,
}

/// One row of a binned table (confidence or viewing angle).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BinRow {
    /// Lower and upper edge of the bin.
    pub from: f64,
    pub to: f64,
    pub total: Quantiles,
}

/// Per camera: how often it dropped landmarks or swapped sides.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CameraRow {
    pub camera: String,
    pub error: ErrorStats,
    /// Frames the camera showed the person in (at least `min_landmarks_in_view` landmarks).
    pub frames_seen: usize,
    /// Frames it had no usable view in.
    pub frames_missing: usize,
    /// Of the landmarks of frames it saw, the share it did not report.
    pub landmark_dropout: f64,
    /// Frames whose view had left and right swapped (left out of the residuals).
    pub swapped_frames: usize,
    /// Frames whose view showed someone else (left out of the residuals).
    pub identity_switches: usize,
}

/// Where the person stood and faced (medians over the frames whose torso was triangulated), so that
/// a twin can be placed likewise.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PersonPlace {
    /// Mid-hip, world coordinates, metres.
    pub mid_hip_m: [f64; 3],
    /// The way the chest faces (unit, world).
    pub facing: [f64; 3],
    /// Mid-hip to mid-shoulder (unit, world).
    pub up: [f64; 3],
}

/// What [`measure`] found.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DetectorErrorReport {
    pub frames: usize,
    /// Median frame rate of the recording, Hz (`None` for fewer than two frames).
    pub frame_rate_hz: Option<f64>,
    pub window_s: f64,
    /// Where the person stood, when their torso was seen.
    pub person: Option<PersonPlace>,
    pub all: ErrorStats,
    /// Per landmark group, in [`GROUPS`] order: `(name, stats)`.
    pub groups: Vec<(String, ErrorStats)>,
    /// Per landmark (BlazePose name), for the landmarks measured at all.
    pub landmarks: Vec<(String, ErrorStats)>,
    pub cameras: Vec<CameraRow>,
    pub by_confidence: Vec<BinRow>,
    pub by_view_angle_deg: Vec<BinRow>,
    /// Spearman rank correlation of confidence with the relative error (negative: a confident
    /// detection is a better one; near 0: confidence says nothing of the error). `None` when the
    /// detections carry no confidence (all equal).
    pub confidence_error_spearman: Option<f64>,
    /// Share of the residuals beyond [`GROSS_ERROR_FRACTION`] of the image height: gross errors.
    pub gross_error_share: f64,
    /// How a view's persistent offsets are structured: the similarity (shift, scale, rotation) that
    /// best maps the other views' projected points onto them, and what is left.
    pub view_structure: ViewStructure,
    /// How long a landmark's own error lasts: its correlation with itself a lag later, per lag
    /// ([`PERSISTENCE_LAGS_S`], lags the recording is long enough for).
    #[serde(default)]
    pub persistence: Vec<LagRow>,
}

/// One lag of [`DetectorErrorReport::persistence`].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LagRow {
    /// The lag, seconds.
    pub lag_s: f64,
    /// Pairs of residuals this far apart (same camera and landmark).
    pub pairs: usize,
    /// Σ a·b / √(Σ|a|² Σ|b|²) over the pairs, of each landmark's residual less its view's mean in
    /// that frame (the shared shift taken out), relative to the image height, gross errors (beyond
    /// [`GROSS_ERROR_FRACTION`]) left out: 1 = the error stays, 0 = forgotten.
    pub correlation: f64,
}

/// The lags [`DetectorErrorReport::persistence`] measures, seconds.
pub const PERSISTENCE_LAGS_S: [f64; 9] = [0.05, 0.1, 0.2, 0.35, 0.5, 1.0, 2.0, 4.0, 8.0];

/// A lag is reported with at least this many pairs.
pub const MIN_LAG_PAIRS: usize = 200;

/// The persistent offsets of each view and frame (at least [`MIN_STRUCTURE_POINTS`] landmarks),
/// fitted by the 2-D similarity transform that best moves the projected points onto
/// projected + persistent (least squares, Umeyama's closed form): a shift is what the view's
/// calibration or timing would also cause, a scale a wrong depth, a rotation a tilted camera; none
/// of them bends the body's angles. The remainder does.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
pub struct ViewStructure {
    /// |shift| per view and frame, fraction of the image height.
    pub shift: Quantiles,
    /// |scale − 1| per view and frame.
    pub scale_error: Quantiles,
    /// |rotation| per view and frame, degrees.
    pub rotation_deg: Quantiles,
    /// Per landmark, the persistent offset left after its view's similarity, fraction of the image
    /// height.
    pub remainder: Quantiles,
}

/// The fewest landmarks a view-frame needs for [`ViewStructure`].
pub const MIN_STRUCTURE_POINTS: usize = 8;

/// [`ViewStructure`] of `residuals` with their persistent parts.
fn view_structure(residuals: &[Residual], persistent_px: &[Vector2<f64>]) -> ViewStructure {
    let mut views: std::collections::BTreeMap<(usize, usize), Vec<usize>> =
        std::collections::BTreeMap::new();
    for (i, r) in residuals.iter().enumerate() {
        views.entry((r.frame, r.camera)).or_default().push(i);
    }
    let (mut shift, mut scale, mut rotation, mut remainder) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for members in views.values() {
        if members.len() < MIN_STRUCTURE_POINTS {
            continue;
        }
        let n = members.len() as f64;
        let a: Vec<Vector2<f64>> = members.iter().map(|&i| residuals[i].predicted_px).collect();
        let b: Vec<Vector2<f64>> = members
            .iter()
            .map(|&i| residuals[i].predicted_px + persistent_px[i])
            .collect();
        let ca = a.iter().sum::<Vector2<f64>>() / n;
        let cb = b.iter().sum::<Vector2<f64>>() / n;
        // Umeyama in 2-D with complex numbers: s·e^{iθ} = Σ conj(a')·b' / Σ |a'|².
        let (mut re, mut im, mut aa) = (0.0, 0.0, 0.0);
        for (p, q) in a.iter().zip(&b) {
            let (p, q) = (p - ca, q - cb);
            re += p.x * q.x + p.y * q.y;
            im += p.x * q.y - p.y * q.x;
            aa += p.norm_squared();
        }
        if aa <= 0.0 {
            continue;
        }
        let (c, d) = (re / aa, im / aa);
        let height = residuals[members[0]].height_px;
        shift.push((cb - ca).norm() / height);
        scale.push(((c * c + d * d).sqrt() - 1.0).abs());
        rotation.push(d.atan2(c).abs().to_degrees());
        for (p, q) in a.iter().zip(&b) {
            let p = p - ca;
            let mapped = Vector2::new(c * p.x - d * p.y, d * p.x + c * p.y) + cb;
            remainder.push((q - mapped).norm() / height);
        }
    }
    ViewStructure {
        shift: Quantiles::of(shift),
        scale_error: Quantiles::of(scale),
        rotation_deg: Quantiles::of(rotation),
        remainder: Quantiles::of(remainder),
    }
}

/// A residual beyond this fraction of the person's image height is a gross error (a limb put on
/// the wrong place), not the detector's ordinary offset: the real single-person videos' face and
/// hips never reach it (p99 7–10 %), their wrists and feet sometimes do.
pub const GROSS_ERROR_FRACTION: f64 = 0.15;

/// The residuals, their persistent parts and the per-camera counts, before summarising.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Measured {
    pub residuals: Vec<Residual>,
    /// Per residual, its persistent part (pixels).
    pub persistent_px: Vec<Vector2<f64>>,
    /// Per residual, the mean persistent part of its view in its frame (pixels).
    pub shared_px: Vec<Vector2<f64>>,
    frames: usize,
    frames_seen: Vec<usize>,
    frames_missing: Vec<usize>,
    landmarks_missing: Vec<usize>,
    swapped_frames: Vec<usize>,
    identity_switches: Vec<usize>,
    frame_rate_hz: Option<f64>,
    /// Per frame whose torso was triangulated: mid-hip, facing, up.
    places: Vec<TorsoPlace>,
}

/// Measures every view of every frame against the other views (see the module docs).
pub fn measure(rig: &CameraRig, frames: &[Frame2], config: &MeasureConfig) -> Measured {
    let n = rig.len();
    let mut m = Measured {
        frames: frames.len(),
        frames_seen: vec![0; n],
        frames_missing: vec![0; n],
        landmarks_missing: vec![0; n],
        swapped_frames: vec![0; n],
        identity_switches: vec![0; n],
        ..Measured::default()
    };
    for (f, frame) in frames.iter().enumerate() {
        // Every view's observations in undistorted normalized coordinates, per landmark.
        let mut obs: Vec<Vec<(usize, NormalizedView, Vector2<f64>)>> =
            vec![Vec::new(); LANDMARK_COUNT];
        let mut heights = vec![None; n];
        for view in &frame.views {
            let Some(camera) = rig.camera(view.camera) else {
                continue;
            };
            if view.observed_count() < config.min_landmarks_in_view {
                continue;
            }
            let ys: Vec<f64> = view
                .keypoints()
                .iter()
                .flatten()
                .map(|k| k.pixel().y)
                .collect();
            let (lo, hi) = ys
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &y| {
                    (lo.min(y), hi.max(y))
                });
            // (also false for a NaN extent)
            if hi - lo <= 1.0 || (hi - lo).is_nan() {
                continue;
            }
            heights[view.camera] = Some(hi - lo);
            let r = camera.T_camera_world.rotation.to_rotation_matrix();
            for (l, k) in view.keypoints().iter().enumerate() {
                let Some(k) = k else { continue };
                let Ok(normalized) = camera.pixel_to_normalized(&k.pixel()) else {
                    continue;
                };
                obs[l].push((
                    view.camera,
                    NormalizedView {
                        R_camera_world: *r.matrix(),
                        t_camera_world: camera.T_camera_world.translation.vector,
                        normalized,
                        focal_px: Vector2::new(camera.intrinsics.fx, camera.intrinsics.fy),
                        confidence: k.confidence(),
                    },
                    k.pixel().coords,
                ));
            }
        }
        for c in 0..n {
            match heights[c] {
                Some(_) => {
                    m.frames_seen[c] += 1;
                    m.landmarks_missing[c] += (0..LANDMARK_COUNT)
                        .filter(|&l| !obs[l].iter().any(|o| o.0 == c))
                        .count();
                }
                None => m.frames_missing[c] += 1,
            }
        }
        // The point of landmark `l` from every view but `c`.
        let held_out = |l: usize, c: usize| -> Option<Point3<f64>> {
            let others: Vec<NormalizedView> =
                obs[l].iter().filter(|o| o.0 != c).map(|o| o.1).collect();
            (others.len() >= 2)
                .then(|| config.triangulator.triangulate(&others).ok())
                .flatten()
                .map(|t| t.point)
        };
        let all_views = |l: usize| -> Option<Point3<f64>> {
            let views: Vec<NormalizedView> = obs[l].iter().map(|o| o.1).collect();
            config
                .triangulator
                .triangulate(&views)
                .ok()
                .map(|t| t.point)
        };
        let facing = facing(
            all_views(Landmark::LeftShoulder.index()),
            all_views(Landmark::RightShoulder.index()),
            all_views(Landmark::LeftHip.index()),
            all_views(Landmark::RightHip.index()),
        );
        if let Some(place) = facing {
            m.places.push(place);
        }
        for (c, height) in heights.iter().enumerate() {
            let Some(height_px) = *height else { continue };
            let Some(camera) = rig.camera(c) else {
                continue;
            };
            let project = |p: Option<Point3<f64>>| p.and_then(|p| camera.project(&p).ok());
            let detection = |l: usize| obs[l].iter().find(|o| o.0 == c).map(|o| (o.1, o.2));
            let predicted: Vec<Option<Vector2<f64>>> = (0..LANDMARK_COUNT)
                .map(|l| project(held_out(l, c)).map(|p| p.coords))
                .collect();
            if swapped(&predicted, &|l| detection(l).map(|d| d.1)) {
                m.swapped_frames[c] += 1;
                continue;
            }
            let view_angle_deg = facing.map(|(centre, forward, up)| {
                let to_camera = camera.position_world() - centre;
                let flat = to_camera - up * up.dot(&to_camera);
                flat.angle(&forward).to_degrees()
            });
            let view: Vec<Residual> = predicted
                .iter()
                .enumerate()
                .filter_map(|(l, p)| {
                    let (Some(p), Some((view, pixel))) = (p, detection(l)) else {
                        return None;
                    };
                    Some(Residual {
                        frame: f,
                        stamp_nanos: frame.stamp_nanos,
                        camera: c,
                        landmark: l,
                        predicted_px: *p,
                        residual_px: pixel - p,
                        confidence: view.confidence,
                        height_px,
                        view_angle_deg,
                    })
                })
                .collect();
            let relative: Vec<f64> = view
                .iter()
                .map(|r| r.residual_px.norm() / r.height_px)
                .collect();
            if crate::metrics::median(&relative)
                .is_some_and(|m| m > config.identity_switch_fraction)
            {
                m.identity_switches[c] += 1;
                continue;
            }
            m.residuals.extend(view);
        }
    }
    m.persistent_px = persistent(&m.residuals, config.window_s);
    m.shared_px = shared(&m.residuals, &m.persistent_px);
    let mut periods: Vec<f64> = frames
        .windows(2)
        .map(|w| (w[1].stamp_nanos - w[0].stamp_nanos) as f64 * 1e-9)
        .filter(|dt| *dt > 0.0)
        .collect();
    m.frame_rate_hz = crate::metrics::median_in_place(&mut periods).map(|dt| 1.0 / dt);
    m
}

/// A torso's mid-hip, facing direction and up.
type TorsoPlace = (Point3<f64>, Vector3<f64>, Vector3<f64>);

/// The torso's centre, facing direction and up, from both shoulders and hips: up from mid-hip to
/// mid-shoulder, forward = (left − right) × up (the way the chest faces).
fn facing(
    ls: Option<Point3<f64>>,
    rs: Option<Point3<f64>>,
    lh: Option<Point3<f64>>,
    rh: Option<Point3<f64>>,
) -> Option<TorsoPlace> {
    let (ls, rs, lh, rh) = (ls?, rs?, lh?, rh?);
    let shoulders = nalgebra::center(&ls, &rs);
    let hips = nalgebra::center(&lh, &rh);
    let up = (shoulders - hips).try_normalize(1e-6)?;
    let across = (ls - rs) + (lh - rh);
    let forward = across.cross(&up).try_normalize(1e-6)?;
    Some((hips, forward, up))
}

/// Whether a view's left and right are swapped: over the left/right pairs it reports and the other
/// views place, the mirrored labels fit clearly better (at least 3 pairs, half the error or less).
fn swapped(
    predicted: &[Option<Vector2<f64>>],
    detection: &dyn Fn(usize) -> Option<Vector2<f64>>,
) -> bool {
    let (mut as_labelled, mut mirrored, mut pairs) = (0.0, 0.0, 0);
    for l in Landmark::ALL {
        if l.side() != Some(ergocell_skeleton::Side::Left) {
            continue;
        }
        let r = l.mirrored();
        let (Some(pl), Some(pr), Some(dl), Some(dr)) = (
            predicted[l.index()],
            predicted[r.index()],
            detection(l.index()),
            detection(r.index()),
        ) else {
            continue;
        };
        as_labelled += (dl - pl).norm() + (dr - pr).norm();
        mirrored += (dl - pr).norm() + (dr - pl).norm();
        pairs += 1;
    }
    pairs >= 3 && mirrored <= 0.5 * as_labelled
}

/// Per residual, the mean of `values` (one per residual: the persistent parts, the residuals) over
/// the residuals of its view in its frame.
fn shared(residuals: &[Residual], values: &[Vector2<f64>]) -> Vec<Vector2<f64>> {
    let mut sums: std::collections::HashMap<(usize, usize), (Vector2<f64>, usize)> =
        std::collections::HashMap::new();
    for (r, p) in residuals.iter().zip(values) {
        let e = sums
            .entry((r.frame, r.camera))
            .or_insert((Vector2::zeros(), 0));
        e.0 += p;
        e.1 += 1;
    }
    residuals
        .iter()
        .map(|r| {
            sums.get(&(r.frame, r.camera))
                .map_or_else(Vector2::zeros, |(sum, n)| sum / (*n).max(1) as f64)
        })
        .collect()
}

/// Per lag, the correlation of each landmark's own residual (less its view's mean in that frame)
/// with itself a lag later: pairs of the same camera and landmark whose stamps are the lag apart
/// within half the lag's shortest frame interval.
fn persistence(residuals: &[Residual]) -> Vec<LagRow> {
    let raw: Vec<Vector2<f64>> = residuals.iter().map(|r| r.residual_px).collect();
    let means = shared(residuals, &raw);
    // Relative to the image height, so that a near and a far view weigh alike.
    let own: Vec<Vector2<f64>> = residuals
        .iter()
        .zip(&means)
        .map(|(r, mean)| (r.residual_px - mean) / r.height_px.max(1.0))
        .collect();
    let mut order: Vec<usize> = (0..residuals.len()).collect();
    order.sort_by_key(|&i| {
        let r = &residuals[i];
        (r.camera, r.landmark, r.stamp_nanos)
    });
    let runs: Vec<&[usize]> = order
        .chunk_by(|&a, &b| {
            residuals[a].camera == residuals[b].camera
                && residuals[a].landmark == residuals[b].landmark
        })
        .collect();
    // Half the median frame interval: how close a stamp must be to the lag.
    let mut steps: Vec<f64> = runs
        .iter()
        .flat_map(|run| {
            run.windows(2)
                .map(|w| (residuals[w[1]].stamp_nanos - residuals[w[0]].stamp_nanos) as f64)
        })
        .filter(|d| *d > 0.0)
        .collect();
    let Some(step) = crate::metrics::median_in_place(&mut steps) else {
        return Vec::new();
    };
    let tolerance = (0.5 * step) as i64;
    PERSISTENCE_LAGS_S
        .iter()
        .filter(|lag| **lag * 1e9 >= 0.75 * step)
        .filter_map(|&lag_s| {
            let lag = (lag_s * 1e9) as i64;
            let (mut ab, mut aa, mut bb, mut pairs) = (0.0, 0.0, 0.0, 0usize);
            for run in &runs {
                let stamps: Vec<i64> = run.iter().map(|&i| residuals[i].stamp_nanos).collect();
                for (k, &i) in run.iter().enumerate() {
                    let want = stamps[k].saturating_add(lag);
                    let j = stamps.partition_point(|&s| s < want.saturating_sub(tolerance));
                    if j < stamps.len() && (stamps[j] - want).abs() <= tolerance {
                        let (a, b) = (own[i], own[run[j]]);
                        // Gross errors are rare, short and huge: left in, their squares would
                        // decide the correlation alone.
                        if a.norm() > GROSS_ERROR_FRACTION || b.norm() > GROSS_ERROR_FRACTION {
                            continue;
                        }
                        ab += a.dot(&b);
                        aa += a.norm_squared();
                        bb += b.norm_squared();
                        pairs += 1;
                    }
                }
            }
            (pairs >= MIN_LAG_PAIRS && aa > 0.0 && bb > 0.0).then(|| LagRow {
                lag_s,
                pairs,
                correlation: ab / (aa * bb).sqrt(),
            })
        })
        .collect()
}

/// Per residual, the mean residual of its camera and landmark over the centred window.
fn persistent(residuals: &[Residual], window_s: f64) -> Vec<Vector2<f64>> {
    let half = (window_s * 0.5e9) as i64;
    let mut out = vec![Vector2::zeros(); residuals.len()];
    let mut order: Vec<usize> = (0..residuals.len()).collect();
    order.sort_by_key(|&i| {
        let r = &residuals[i];
        (r.camera, r.landmark, r.stamp_nanos)
    });
    for run in order.chunk_by(|&a, &b| {
        residuals[a].camera == residuals[b].camera && residuals[a].landmark == residuals[b].landmark
    }) {
        // Sorted by time: each window is a contiguous range, its sum a difference of prefix sums.
        let stamps: Vec<i64> = run.iter().map(|&i| residuals[i].stamp_nanos).collect();
        let mut prefix = vec![Vector2::zeros(); run.len() + 1];
        for (k, &i) in run.iter().enumerate() {
            prefix[k + 1] = prefix[k] + residuals[i].residual_px;
        }
        for (k, &i) in run.iter().enumerate() {
            let t = stamps[k];
            let lo = stamps.partition_point(|&s| s < t.saturating_sub(half));
            let hi = stamps.partition_point(|&s| s <= t.saturating_add(half));
            out[i] = (prefix[hi] - prefix[lo]) / (hi - lo).max(1) as f64;
        }
    }
    out
}

impl Measured {
    fn stats(&self, keep: impl Fn(&Residual) -> bool) -> ErrorStats {
        let (mut total, mut persistent, mut jitter, mut px, mut height) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new(), 0.0);
        let (mut shared, mut own) = (Vec::new(), Vec::new());
        for ((r, p), c) in self
            .residuals
            .iter()
            .zip(&self.persistent_px)
            .zip(&self.shared_px)
        {
            if !keep(r) {
                continue;
            }
            total.push(r.residual_px.norm() / r.height_px);
            persistent.push(p.norm() / r.height_px);
            shared.push(c.norm() / r.height_px);
            own.push((p - c).norm() / r.height_px);
            jitter.push((r.residual_px - p).norm() / r.height_px);
            px.push(r.residual_px.norm());
            height += r.height_px;
        }
        let count = px.len().max(1) as f64;
        ErrorStats {
            total: Quantiles::of(total),
            persistent: Quantiles::of(persistent),
            jitter: Quantiles::of(jitter),
            persistent_shared: Quantiles::of(shared),
            persistent_own: Quantiles::of(own),
            total_px: Quantiles::of(px),
            mean_height_px: height / count,
        }
    }

    fn binned(
        &self,
        edges: &[f64],
        last: f64,
        value: impl Fn(&Residual) -> Option<f64>,
    ) -> Vec<BinRow> {
        edges
            .iter()
            .enumerate()
            .map(|(i, &from)| {
                let to = edges.get(i + 1).copied().unwrap_or(last);
                let total = Quantiles::of(
                    self.residuals
                        .iter()
                        .filter(|r| {
                            value(r)
                                .is_some_and(|v| v >= from && (v < to || (to == last && v <= to)))
                        })
                        .map(|r| r.residual_px.norm() / r.height_px)
                        .collect(),
                );
                BinRow { from, to, total }
            })
            .collect()
    }

    /// The summary tables.
    pub fn report(&self, rig: &CameraRig, window_s: f64) -> DetectorErrorReport {
        let groups = GROUPS
            .iter()
            .map(|(name, range)| {
                (
                    (*name).to_owned(),
                    self.stats(|r| range.contains(&r.landmark)),
                )
            })
            .collect();
        let landmarks = Landmark::ALL
            .iter()
            .map(|l| (l.name().to_owned(), self.stats(|r| r.landmark == l.index())))
            .filter(|(_, s)| s.total.count > 0)
            .collect();
        let cameras = rig
            .cameras()
            .iter()
            .enumerate()
            .map(|(c, camera)| CameraRow {
                camera: camera.id.as_str().to_owned(),
                error: self.stats(|r| r.camera == c),
                frames_seen: self.frames_seen[c],
                frames_missing: self.frames_missing[c],
                landmark_dropout: self.landmarks_missing[c] as f64
                    / (self.frames_seen[c] * LANDMARK_COUNT).max(1) as f64,
                swapped_frames: self.swapped_frames[c],
                identity_switches: self.identity_switches[c],
            })
            .collect();
        let median_of = |f: &dyn Fn(&TorsoPlace) -> [f64; 3]| {
            let values: Vec<[f64; 3]> = self.places.iter().map(f).collect();
            std::array::from_fn(|k| {
                crate::metrics::median(&values.iter().map(|v| v[k]).collect::<Vec<_>>())
                    .unwrap_or(0.0)
            })
        };
        let unit = |v: [f64; 3]| {
            let v = Vector3::from(v);
            let n = v.norm();
            if n > 0.0 {
                (v / n).into()
            } else {
                v.into()
            }
        };
        let person = (!self.places.is_empty()).then(|| PersonPlace {
            mid_hip_m: median_of(&|p| p.0.coords.into()),
            facing: unit(median_of(&|p| p.1.into())),
            up: unit(median_of(&|p| p.2.into())),
        });
        DetectorErrorReport {
            frames: self.frames,
            frame_rate_hz: self.frame_rate_hz,
            window_s,
            person,
            all: self.stats(|_| true),
            groups,
            landmarks,
            cameras,
            by_confidence: self.binned(&CONFIDENCE_EDGES, 1.0, |r| Some(r.confidence)),
            by_view_angle_deg: self.binned(&ANGLE_EDGES_DEG, 180.0, |r| r.view_angle_deg),
            view_structure: view_structure(&self.residuals, &self.persistent_px),
            persistence: persistence(&self.residuals),
            gross_error_share: self
                .residuals
                .iter()
                .filter(|r| r.residual_px.norm() / r.height_px > GROSS_ERROR_FRACTION)
                .count() as f64
                / self.residuals.len().max(1) as f64,
            confidence_error_spearman: spearman(
                &self
                    .residuals
                    .iter()
                    .map(|r| r.confidence)
                    .collect::<Vec<_>>(),
                &self
                    .residuals
                    .iter()
                    .map(|r| r.residual_px.norm() / r.height_px)
                    .collect::<Vec<_>>(),
            ),
        }
    }
}

/// Ranks with ties averaged.
fn ranks(values: &[f64]) -> Vec<f64> {
    let mut order: Vec<usize> = (0..values.len()).collect();
    order.sort_by(|&a, &b| values[a].total_cmp(&values[b]));
    let mut ranks = vec![0.0; values.len()];
    let mut i = 0;
    while i < order.len() {
        let mut j = i;
        while j + 1 < order.len() && values[order[j + 1]] == values[order[i]] {
            j += 1;
        }
        let rank = (i + j) as f64 / 2.0;
        for &k in &order[i..=j] {
            ranks[k] = rank;
        }
        i = j + 1;
    }
    ranks
}

/// Spearman's rank correlation (`None` when either list is constant or shorter than 3).
pub fn spearman(a: &[f64], b: &[f64]) -> Option<f64> {
    if a.len() != b.len() || a.len() < 3 {
        return None;
    }
    let (ra, rb) = (ranks(a), ranks(b));
    let mean = (a.len() - 1) as f64 / 2.0;
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (x, y) in ra.iter().zip(&rb) {
        sab += (x - mean) * (y - mean);
        saa += (x - mean) * (x - mean);
        sbb += (y - mean) * (y - mean);
    }
    (saa > 0.0 && sbb > 0.0).then(|| sab / (saa * sbb).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::detections::{Keypoint2, View2};
    use crate::fusion::tests::ring_rig;

    /// A standing body: left landmarks at +x, right at −x, heights by body part (metres).
    fn body() -> [Point3<f64>; LANDMARK_COUNT] {
        std::array::from_fn(|i| {
            let l = Landmark::ALL[i];
            let x = match l.side() {
                Some(ergocell_skeleton::Side::Left) => 0.18,
                Some(ergocell_skeleton::Side::Right) => -0.18,
                None => 0.0,
            };
            let z = match i {
                0..=10 => 1.6 + 0.01 * i as f64,
                11..=12 => 1.45,
                13..=14 => 1.2,
                15..=22 => 0.95 + 0.005 * i as f64,
                23..=24 => 0.95,
                25..=26 => 0.5,
                _ => 0.05 + 0.01 * (i - 27) as f64,
            };
            Point3::new(x, 0.03 * (i % 3) as f64, z)
        })
    }

    /// The body seen by every camera of `rig` at `stamp_nanos`, `edit` applied to each view's pixels.
    fn frame(
        rig: &CameraRig,
        stamp_nanos: i64,
        edit: &dyn Fn(usize, usize, Vector2<f64>) -> Vector2<f64>,
    ) -> Frame2 {
        let points = body();
        let views = rig
            .cameras()
            .iter()
            .enumerate()
            .map(|(c, cam)| {
                let mut v = View2::empty(c, stamp_nanos);
                for l in Landmark::ALL {
                    let px = edit(
                        c,
                        l.index(),
                        cam.project(&points[l.index()]).unwrap().coords,
                    );
                    v.set(l, Some(Keypoint2::new(px.x, px.y, 0.9).unwrap()));
                }
                v
            })
            .collect();
        Frame2 { stamp_nanos, views }
    }

    const WRIST: usize = 15;

    #[test]
    fn a_persistent_offset_and_frame_to_frame_jitter_are_told_apart() {
        // Camera 0 places the left wrist 12 px right of where it is in every frame, and jitters it
        // ±4 px vertically frame to frame; every other detection is exact. 2 s at 30 Hz.
        let rig = ring_rig(4);
        let frames: Vec<Frame2> = (0..60)
            .map(|k| {
                let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
                frame(&rig, k * 33_333_333, &|c, l, px| {
                    if c == 0 && l == WRIST {
                        px + Vector2::new(12.0, 4.0 * sign)
                    } else {
                        px
                    }
                })
            })
            .collect();
        let m = measure(&rig, &frames, &MeasureConfig::default());
        let mut seen = 0;
        for (r, p) in m.residuals.iter().zip(&m.persistent_px) {
            if r.camera == 0 && r.landmark == WRIST {
                seen += 1;
                assert!((p.x - 12.0).abs() < 0.2 && p.y.abs() < 0.5, "{p:?}");
                let jitter = r.residual_px - p;
                assert!((jitter.norm() - 4.0).abs() < 0.5, "{jitter:?}");
            } else if r.landmark == WRIST {
                // The other views' wrist: camera 0's error reaches them through their held-out
                // point (what the module docs call the conservative side): camera 1, 0.04 rad from
                // camera 0, sees nearly all of it; never more than its size, |(12, 4)| = 12.65 px.
                assert!(r.residual_px.norm() < 13.0, "{r:?}");
            } else {
                assert!(r.residual_px.norm() < 1e-3, "{r:?}");
            }
        }
        assert_eq!(seen, 60);
        let report = m.report(&rig, 1.0);
        assert_eq!(report.frames, 60);
        assert_eq!(report.cameras[0].swapped_frames, 0);
        assert!(report.cameras.iter().all(|c| c.landmark_dropout == 0.0));
        // The arms' group holds the wrist: its p99 is the offset relative to the image height.
        let (_, arms) = &report.groups[1];
        assert!(arms.total_px.p99 > 11.0, "{arms:?}");
    }

    #[test]
    fn a_swapped_view_and_a_view_of_someone_else_are_counted_not_measured() {
        let rig = ring_rig(4);
        let points = body();
        let frames = [
            // camera 3: left and right labels exchanged
            frame(&rig, 0, &|c, l, px| {
                if c == 3 {
                    let mirrored = Landmark::ALL[l].mirrored().index();
                    rig.cameras()[3].project(&points[mirrored]).unwrap().coords
                } else {
                    px
                }
            }),
            // camera 2: the whole body 150 px aside (someone else)
            frame(&rig, 33_333_333, &|c, _, px| {
                if c == 2 {
                    px + Vector2::new(150.0, 0.0)
                } else {
                    px
                }
            }),
        ];
        let m = measure(&rig, &frames, &MeasureConfig::default());
        let report = m.report(&rig, 1.0);
        assert_eq!(report.cameras[3].swapped_frames, 1);
        assert_eq!(report.cameras[2].identity_switches, 1);
        assert!(m
            .residuals
            .iter()
            .all(|r| !((r.camera == 3 && r.frame == 0) || (r.camera == 2 && r.frame == 1))));
        // The person faces −y or +y; the cameras at angle 0 see them side on (90°).
        let angle = m
            .residuals
            .iter()
            .find(|r| r.camera == 0)
            .unwrap()
            .view_angle_deg;
        assert!(angle.is_some_and(|a| (a - 90.0).abs() < 15.0), "{angle:?}");
    }

    #[test]
    fn a_views_shift_scale_and_rotation_are_told_from_its_landmarks_own_offsets() {
        // One view-frame: 12 points on a 200 px circle moved by a known similarity, one of them
        // also by its own 10 px.
        let (shift, scale, angle) = (Vector2::new(6.0, -8.0), 1.03, 2f64.to_radians());
        let (c, d) = (scale * angle.cos(), scale * angle.sin());
        let centre = Vector2::new(640.0, 360.0);
        let mut residuals = Vec::new();
        let mut persistent = Vec::new();
        for k in 0..12 {
            let t = k as f64 * std::f64::consts::TAU / 12.0;
            let p = centre + 200.0 * Vector2::new(t.cos(), t.sin());
            let q = p - centre;
            let mut moved = Vector2::new(c * q.x - d * q.y, d * q.x + c * q.y) + centre + shift;
            if k == 3 {
                moved += Vector2::new(0.0, 10.0);
            }
            residuals.push(Residual {
                frame: 0,
                stamp_nanos: 0,
                camera: 0,
                landmark: k,
                predicted_px: p,
                residual_px: moved - p,
                confidence: 1.0,
                height_px: 500.0,
                view_angle_deg: None,
            });
            persistent.push(moved - p);
        }
        let s = view_structure(&residuals, &persistent);
        assert_eq!(s.shift.count, 1);
        // The own 10 px moves the centroid by 10/12 px and leaks a little into the fit.
        assert!(
            (s.shift.p50 * 500.0 - (shift + Vector2::new(0.0, 10.0 / 12.0)).norm()).abs() < 0.5,
            "{s:?}"
        );
        assert!((s.scale_error.p50 - 0.03).abs() < 0.006, "{s:?}");
        assert!((s.rotation_deg.p50 - 2.0).abs() < 0.2, "{s:?}");
        // Left over: most of the 10 px at the landmark that had it (the fit absorbs a little),
        // about nothing elsewhere.
        assert!((s.remainder.p99 * 500.0 - 10.0).abs() < 2.0, "{s:?}");
        assert!(s.remainder.p50 * 500.0 < 1.5, "{s:?}");
    }

    #[test]
    fn quantiles_and_rank_correlation() {
        let q = Quantiles::of((1..=100).map(f64::from).collect());
        assert_eq!((q.count, q.p50, q.p90, q.p99), (100, 50.0, 90.0, 99.0));
        assert_eq!(Quantiles::of(vec![f64::NAN]).count, 0);
        let a = [1.0, 2.0, 3.0, 4.0];
        assert!((spearman(&a, &[10.0, 20.0, 30.0, 40.0]).unwrap() - 1.0).abs() < 1e-12);
        assert!((spearman(&a, &[4.0, 3.0, 2.0, 1.0]).unwrap() + 1.0).abs() < 1e-12);
        assert_eq!(spearman(&a, &[1.0, 1.0, 1.0, 1.0]), None);
    }
}
