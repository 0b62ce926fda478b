//! Multi-camera fusion: all cameras' 2D views of one instant → one 3D skeleton.
//!
//! Two methods, chosen by [`FusionMethod`]:
//!
//! - [`FusionMethod::Paper`] — the seed paper's scheme (Sec. II.B), kept as the baseline, exactly as
//!   written: each stereo pair `S_j` triangulates every landmark it sees by DLT; a graph is built with
//!   the `N` observed landmarks and the `M` cameras as nodes and an edge between landmark `i` and camera
//!   `k` when `k`'s pair estimated `i` (no camera–camera or landmark–landmark edges); `L` is the binary
//!   (unweighted) graph Laplacian in its normalized form `L = I − D⁻¹A`, so that row `i` of `L·p̂` is
//!   `p̂_i − (1/|Ψ_i|) Σ_{j∈Ψ_i} p̂_j` as in the paper's Eq. for `δ`. Anchors `a` are the mean of the
//!   per-pair estimates (landmark rows) and the known camera centres (camera rows). The differential
//!   coordinates `δ` are formed from the relative measurements along the edges — each camera's own
//!   pair estimate relative to that camera, `δ_i = mean_k (p_i^(k) − c_k)`, `δ_k = mean_i (c_k − p_i^(k))`
//!   — (computing `δ = L·a` from the anchors themselves would make the least squares return the anchors
//!   unchanged). The result is `p̂ = (L̃ᵀL̃)⁻¹L̃ᵀ b` with `L̃ = [L; I]`, `b = [δ; a]`; the constant
//!   `(L̃ᵀL̃)⁻¹L̃ᵀ` is computed once per graph topology and cached, as the paper prescribes.
//! - [`FusionMethod::Default`] — ours: every camera's view directly (no pairing), confidence-weighted,
//!   refined on pixel reprojection error with robust weights and outlier-view rejection
//!   ([`RobustTriangulator`]). It uses all the information the pairs see, weights each view by what its
//!   geometry and detector say it is worth, and throws out the gross detector errors that averaging would
//!   smear into every estimate.

use std::collections::HashMap;

use ergocell_skeleton::{Landmark, LandmarkEstimate, Skeleton3, LANDMARK_COUNT};
use nalgebra::{DMatrix, Matrix3, Matrix3x4, Point2, Point3, Vector2, Vector3};

use crate::body_prior::{BonePrior, BonePriorParams};
use crate::detections::Frame2;
use crate::error::{PerceptionError, Result};
use crate::rig::CameraRig;
use crate::triangulation::{
    iter_mask, DltAccumulator, LaneCamera, LaneObs, LaneResult, NormalizedView, RobustTriangulator,
    Triangulated, LANES, MAX_VIEWS,
};

/// Which fusion to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FusionMethod {
    /// The seed paper's per-pair DLT + graph-Laplacian fusion (baseline).
    Paper,
    /// ergocell's robust, confidence-weighted N-view fusion.
    #[default]
    Default,
}

impl FusionMethod {
    /// Parses `paper` / `default`.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "paper" => Some(Self::Paper),
            "default" => Some(Self::Default),
            _ => None,
        }
    }
}

/// The fused skeleton of one frame and what fusion had to leave out.
#[derive(Debug, Clone, PartialEq)]
pub struct FusedFrame {
    pub skeleton: Skeleton3,
    /// Views dropped as outliers or behind their camera, over all landmarks.
    pub rejected_views: usize,
    /// Keypoints that could not be undistorted (far outside the lens model) and were left out.
    pub undistortion_failures: usize,
    /// Bit `k` set: camera `k` contributed a view to this frame.
    pub cameras_present: u64,
    /// Bit `k` set: camera `k`'s view had the person's left and right swapped (the detector's
    /// mistake) and was used mirrored. Default fusion only.
    pub swapped_views: u64,
}

/// A view is judged swapped when mirroring its left and right explains it at most this fraction as
/// badly as its labels do.
pub const SWAP_RATIO: f64 = 0.5;
/// … over at least this many left/right landmark pairs that the view and the fusion both have …
pub const SWAP_MIN_PAIRS: u32 = 4;
/// … by at least this many pixels per pair (two keypoints): below it, noise.
pub const SWAP_MIN_GAIN_PX: f64 = 8.0;

/// The default fusion's per-landmark triangulations of one frame.
struct Triangulations {
    points: [Option<Point3<f64>>; LANDMARK_COUNT],
    information: [Matrix3<f64>; LANDMARK_COUNT],
    covariance: [Option<Matrix3<f64>>; LANDMARK_COUNT],
    masks: [u64; LANDMARK_COUNT],
    rejected: usize,
}

impl Triangulations {
    fn new() -> Self {
        Self {
            points: [None; LANDMARK_COUNT],
            information: [Matrix3::zeros(); LANDMARK_COUNT],
            covariance: [None; LANDMARK_COUNT],
            masks: [0u64; LANDMARK_COUNT],
            rejected: 0,
        }
    }

    /// Landmark `i`'s triangulation from `listed` observations.
    fn record(&mut self, i: usize, r: &Triangulated, listed: usize) {
        self.rejected += listed - r.views_used() as usize;
        self.points[i] = Some(r.point);
        self.information[i] = r.information;
        // what the prior's `covariance_of` computes, already inverted (information from a
        // triangulation is never all zeros)
        self.covariance[i] = Some(r.covariance).filter(|c| c.iter().all(|v| v.is_finite()));
        self.masks[i] = r.used_mask;
    }
}

/// Exchanges the left and right observations of the cameras in `cameras` (a bit per camera); each
/// list stays in camera order.
fn swap_sides(obs: &mut FrameObs, cameras: u64) {
    let moves = |o: &Obs| cameras & (1 << o.camera) != 0;
    for left in Landmark::ALL
        .into_iter()
        .filter(|l| l.side() == Some(ergocell_skeleton::Side::Left))
    {
        let (l, r) = (left.index(), left.mirrored().index());
        let (to_right, mut stay_left): (Vec<Obs>, Vec<Obs>) =
            std::mem::take(&mut obs[l]).into_iter().partition(moves);
        let (to_left, mut stay_right): (Vec<Obs>, Vec<Obs>) =
            std::mem::take(&mut obs[r]).into_iter().partition(moves);
        stay_left.extend(to_left);
        stay_right.extend(to_right);
        stay_left.sort_by_key(|o| o.camera);
        stay_right.sort_by_key(|o| o.camera);
        obs[l] = stay_left;
        obs[r] = stay_right;
    }
}

#[derive(Debug, Clone)]
struct CameraCache {
    R_camera_world: Matrix3<f64>,
    t_camera_world: Vector3<f64>,
    /// `[R|t]`: the projection matrix in normalized coordinates.
    pose: Matrix3x4<f64>,
    focal_px: Vector2<f64>,
    centre_world: Point3<f64>,
}

/// Observation of one landmark by one camera, undistorted.
#[derive(Debug, Clone, Copy)]
struct Obs {
    camera: usize,
    normalized: Vector2<f64>,
    confidence: f64,
}

/// Turns time-aligned multi-camera frames into fused skeletons. Holds the rig and per-rig caches;
/// one engine per session.
#[derive(Debug, Clone)]
pub struct FusionEngine {
    rig: CameraRig,
    cameras: Vec<CameraCache>,
    /// The cameras as the lane-parallel triangulator takes them (slot = camera index).
    lane_cameras: Vec<LaneCamera>,
    method: FusionMethod,
    triangulator: RobustTriangulator,
    paper_cache: HashMap<[u64; LANDMARK_COUNT], DMatrix<f64>>,
    /// Per-frame buffers reused across frames (no allocation on the hot path once warm).
    scratch_obs: FrameObs,
    scratch_views: Vec<NormalizedView>,
    scratch_lanes: Vec<LaneObs>,
    scratch_paper: PaperScratch,
    /// The learned-bone-length prior of the default fusion (`None`: per-frame geometry only).
    bone_prior: Option<BonePrior>,
}

/// Undistorted observations of every landmark in a frame.
type FrameObs = [Vec<Obs>; LANDMARK_COUNT];

/// Each stereo pair's estimate of every landmark.
type PerPair = Vec<[Option<Point3<f64>>; LANDMARK_COUNT]>;

/// The paper fusion's per-frame buffers, reused across frames.
#[derive(Debug, Clone)]
struct PaperScratch {
    /// `(pair, landmark, left camera, right camera)` of each DLT.
    jobs: Vec<(usize, usize, usize, usize)>,
    accs: Vec<DltAccumulator>,
    solved: Vec<Result<Point3<f64>>>,
    per_pair: PerPair,
    /// The right-hand side `[δ; a]` and the solution.
    b: DMatrix<f64>,
    p: DMatrix<f64>,
}

impl Default for PaperScratch {
    fn default() -> Self {
        Self {
            jobs: Vec::new(),
            accs: Vec::new(),
            solved: Vec::new(),
            per_pair: Vec::new(),
            b: DMatrix::zeros(0, 3),
            p: DMatrix::zeros(0, 3),
        }
    }
}

impl FusionEngine {
    /// An engine for this rig (2 to [`MAX_VIEWS`] cameras: one camera cannot triangulate anything,
    /// so a one-camera rig is an error here rather than a run of empty skeletons; coincident
    /// cameras are refused by [`CameraRig::new`]).
    pub fn new(rig: CameraRig, method: FusionMethod) -> Result<Self> {
        if rig.len() < 2 {
            return Err(PerceptionError::TooFewCameras { cameras: rig.len() });
        }
        if rig.len() > MAX_VIEWS {
            return Err(PerceptionError::Unsupported(format!(
                "{} cameras (at most {MAX_VIEWS})",
                rig.len()
            )));
        }
        let cameras = rig
            .cameras()
            .iter()
            .map(|c| {
                let r = *c.T_camera_world.rotation.to_rotation_matrix().matrix();
                CameraCache {
                    R_camera_world: r,
                    t_camera_world: c.T_camera_world.translation.vector,
                    pose: c.pose_matrix(),
                    focal_px: Vector2::new(c.intrinsics.fx, c.intrinsics.fy),
                    centre_world: c.position_world(),
                }
            })
            .collect::<Vec<CameraCache>>();
        let lane_cameras = cameras
            .iter()
            .map(|c| LaneCamera {
                r: std::array::from_fn(|i| c.R_camera_world[(i / 3, i % 3)]),
                t: [c.t_camera_world.x, c.t_camera_world.y, c.t_camera_world.z],
                focal: [c.focal_px.x, c.focal_px.y],
            })
            .collect();
        Ok(Self {
            rig,
            cameras,
            lane_cameras,
            method,
            triangulator: RobustTriangulator::default(),
            paper_cache: HashMap::new(),
            scratch_obs: std::array::from_fn(|_| Vec::new()),
            scratch_views: Vec::new(),
            scratch_lanes: Vec::new(),
            scratch_paper: PaperScratch::default(),
            bone_prior: Some(BonePrior::new(BonePriorParams::default())),
        })
    }

    /// Replaces the default triangulator settings.
    #[must_use]
    pub fn with_triangulator(mut self, triangulator: RobustTriangulator) -> Self {
        self.triangulator = triangulator;
        self
    }

    /// Sets (or with `None` removes) the default fusion's bone-length prior; starts it afresh.
    #[must_use]
    pub fn with_bone_prior(mut self, params: Option<BonePriorParams>) -> Self {
        self.bone_prior = params.map(BonePrior::new);
        self
    }

    /// Forgets what was learned about the current operator (a new session).
    pub fn reset_operator(&mut self) {
        if let Some(p) = self.bone_prior.as_mut() {
            p.reset();
        }
    }

    /// The rig.
    pub fn rig(&self) -> &CameraRig {
        &self.rig
    }

    /// The fusion method.
    pub fn method(&self) -> FusionMethod {
        self.method
    }

    /// Fuses one frame. Landmarks seen by fewer than two usable views are "not observed" (`None`);
    /// errors only for a frame that is malformed as a whole (unknown camera, a camera twice).
    pub fn fuse(&mut self, frame: &Frame2) -> Result<FusedFrame> {
        let mut obs = std::mem::replace(&mut self.scratch_obs, std::array::from_fn(|_| Vec::new()));
        let result = self.fuse_with(frame, &mut obs);
        self.scratch_obs = obs;
        result
    }

    fn fuse_with(&mut self, frame: &Frame2, obs: &mut FrameObs) -> Result<FusedFrame> {
        let (undistortion_failures, cameras_present) = self.observations_into(frame, obs)?;
        let mut skeleton = Skeleton3::empty(frame.stamp_nanos);
        let mut rejected_views = 0;
        let mut swapped_views = 0;
        match self.method {
            FusionMethod::Default => {
                let mut views = std::mem::take(&mut self.scratch_views);
                let mut lanes = std::mem::take(&mut self.scratch_lanes);
                let mut tri = self.triangulate_all(obs, &mut views, &mut lanes);
                // A view whose left and right the detector swapped: the fused points explain it
                // better mirrored. Correct it (swap its sides) and triangulate again.
                swapped_views = self.swapped_views(obs, &tri.points, cameras_present);
                if swapped_views != 0 {
                    swap_sides(obs, swapped_views);
                    tri = self.triangulate_all(obs, &mut views, &mut lanes);
                }
                let Triangulations {
                    mut points,
                    information,
                    covariance,
                    masks,
                    rejected,
                } = tri;
                rejected_views += rejected;
                rejected_views += drop_off_body(&mut points, &masks);
                if let Some(prior) = self.bone_prior.as_mut() {
                    prior.observe_with_covariance(&points, &covariance);
                    prior.refine(&mut points, &information);
                }
                for lm in Landmark::ALL {
                    let Some(p) = points[lm.index()] else {
                        continue;
                    };
                    let used = Used {
                        obs: &obs[lm.index()],
                        mask: masks[lm.index()],
                        covariance: covariance[lm.index()],
                    };
                    self.set(&mut skeleton, lm, p, &used)?;
                }
                self.scratch_views = views;
                self.scratch_lanes = lanes;
            }
            FusionMethod::Paper => {
                let mut scratch = std::mem::take(&mut self.scratch_paper);
                self.pair_estimates_into(obs, &mut scratch);
                let fused = self.paper_fuse(&mut scratch);
                self.scratch_paper = scratch;
                if let Some(points) = fused {
                    for lm in Landmark::ALL {
                        if let Some(p) = points[lm.index()] {
                            let o = &obs[lm.index()];
                            let mask = if o.len() >= 64 {
                                u64::MAX
                            } else {
                                (1u64 << o.len()) - 1
                            };
                            let used = Used {
                                obs: o,
                                mask,
                                covariance: None,
                            };
                            self.set(&mut skeleton, lm, p, &used)?;
                        }
                    }
                }
            }
        }
        Ok(FusedFrame {
            skeleton,
            rejected_views,
            undistortion_failures,
            cameras_present,
            swapped_views,
        })
    }

    /// The robust triangulation of every landmark from its observations (the default fusion's
    /// per-frame geometry, before the body checks and the bone prior).
    fn triangulate_all(
        &self,
        obs: &FrameObs,
        views: &mut Vec<NormalizedView>,
        lanes: &mut Vec<LaneObs>,
    ) -> Triangulations {
        let mut t = Triangulations::new();
        // [`LANES`] landmarks at a time; the scalar triangulator for a landmark off the lanes'
        // common path (a view dropped, a degenerate system), which gives the same answers.
        for first in (0..LANDMARK_COUNT).step_by(LANES) {
            let group = first..(first + LANES).min(LANDMARK_COUNT);
            lanes.clear();
            lanes.resize(self.cameras.len(), LaneObs::default());
            // bit k of `cameras[l]`: lane l's landmark has a view from camera k
            let mut cameras = [0u64; LANES];
            for (l, i) in group.clone().enumerate() {
                for ob in &obs[i] {
                    let slot = &mut lanes[ob.camera];
                    slot.x[l] = ob.normalized.x;
                    slot.y[l] = ob.normalized.y;
                    slot.confidence[l] = ob.confidence;
                    slot.present[l] = true;
                    cameras[l] |= 1 << ob.camera;
                }
            }
            // a group of one or two costs the lanes as much as a full one: those go scalar
            let results = if group.len() > 2 {
                self.triangulator
                    .triangulate_lanes(&self.lane_cameras, lanes, group.len())
            } else {
                [LaneResult::Fallback; LANES]
            };
            for (l, i) in group.enumerate() {
                let o = &obs[i];
                let r = match results[l] {
                    LaneResult::Done(mut r) => {
                        // camera slots → positions in the landmark's (camera-ordered) list
                        r.used_mask = iter_mask(r.used_mask)
                            .map(|k| 1u64 << (cameras[l] & ((1u64 << k) - 1)).count_ones())
                            .fold(0, |m, b| m | b);
                        r
                    }
                    LaneResult::TooFewViews(_) | LaneResult::Unused => continue,
                    LaneResult::Fallback => {
                        self.views_into(o, views);
                        let Ok(r) = self.triangulator.triangulate(views) else {
                            continue;
                        };
                        r
                    }
                };
                t.record(i, &r, o.len());
            }
        }
        t
    }

    /// One landmark's observations as the scalar triangulator takes them, into `views`.
    fn views_into(&self, o: &[Obs], views: &mut Vec<NormalizedView>) {
        views.clear();
        views.extend(o.iter().map(|ob| {
            let c = &self.cameras[ob.camera];
            NormalizedView {
                R_camera_world: c.R_camera_world,
                t_camera_world: c.t_camera_world,
                normalized: ob.normalized,
                focal_px: c.focal_px,
                confidence: ob.confidence,
            }
        }));
    }

    /// The cameras whose view has the person's left and right swapped, judged against the fused
    /// points: over every left/right landmark pair the view sees and the fusion placed, the pixel
    /// distance of the view's two keypoints to the pair's projections as labelled and mirrored. A
    /// view is swapped when mirrored explains it at most [`SWAP_RATIO`] as badly, over at least
    /// [`SWAP_MIN_PAIRS`] pairs, by at least [`SWAP_MIN_GAIN_PX`] per pair. Needs three cameras
    /// (with two, each view is as right as the other). The robust triangulation has usually
    /// rejected a lone swapped view already, so the fused points are the other views'.
    fn swapped_views(
        &self,
        obs: &FrameObs,
        points: &[Option<Point3<f64>>; LANDMARK_COUNT],
        present: u64,
    ) -> u64 {
        if present.count_ones() < 3 {
            return 0;
        }
        let m = self.cameras.len();
        let mut keep = [0.0f64; MAX_VIEWS];
        let mut mirrored = [0.0f64; MAX_VIEWS];
        let mut pairs = [0u32; MAX_VIEWS];
        for left in Landmark::ALL
            .into_iter()
            .filter(|l| l.side() == Some(ergocell_skeleton::Side::Left))
        {
            let right = left.mirrored();
            let (Some(pl), Some(pr)) = (points[left.index()], points[right.index()]) else {
                continue;
            };
            for ol in &obs[left.index()] {
                let Some(or) = obs[right.index()].iter().find(|o| o.camera == ol.camera) else {
                    continue;
                };
                let c = &self.cameras[ol.camera];
                let project = |p: Point3<f64>| {
                    let q = c.R_camera_world * p.coords + c.t_camera_world;
                    (q.z > 1e-9).then(|| Vector2::new(q.x / q.z, q.y / q.z))
                };
                let (Some(ql), Some(qr)) = (project(pl), project(pr)) else {
                    continue;
                };
                let px =
                    |a: Vector2<f64>, b: Vector2<f64>| (a - b).component_mul(&c.focal_px).norm();
                keep[ol.camera] += px(ql, ol.normalized) + px(qr, or.normalized);
                mirrored[ol.camera] += px(ql, or.normalized) + px(qr, ol.normalized);
                pairs[ol.camera] += 1;
            }
        }
        let mut swapped = 0u64;
        for k in 0..m {
            let n = pairs[k];
            if n >= SWAP_MIN_PAIRS
                && mirrored[k] <= SWAP_RATIO * keep[k]
                && (keep[k] - mirrored[k]) / f64::from(n) >= SWAP_MIN_GAIN_PX
            {
                swapped |= 1 << k;
            }
        }
        swapped
    }

    /// Each stereo pair's own DLT estimate of every landmark (the paper's `S_j` rows of Table 1).
    pub fn pair_estimates_of(
        &self,
        frame: &Frame2,
    ) -> Result<Vec<[Option<Point3<f64>>; LANDMARK_COUNT]>> {
        let (obs, _, _) = self.observations(frame)?;
        let mut scratch = PaperScratch::default();
        self.pair_estimates_into(&obs, &mut scratch);
        Ok(scratch.per_pair)
    }

    /// Plain N-view DLT over every camera that sees each landmark, with unit weights, on the raw
    /// (distorted) pixels with `P = K[R|t]` — caliscope's own triangulation, for comparison.
    pub fn raw_pixel_dlt(&self, frame: &Frame2) -> Result<[Option<Point3<f64>>; LANDMARK_COUNT]> {
        self.check_frame(frame)?;
        let projections: Vec<Matrix3x4<f64>> = self
            .rig
            .cameras()
            .iter()
            .map(crate::camera::Camera::projection_matrix)
            .collect();
        let mut out = [None; LANDMARK_COUNT];
        for lm in Landmark::ALL {
            let mut acc = DltAccumulator::default();
            for view in &frame.views {
                if let Some(k) = view.get(lm) {
                    acc.add_view(&projections[view.camera], &k.pixel(), 1.0);
                }
            }
            out[lm.index()] = acc.solve().ok();
        }
        Ok(out)
    }

    /// Confidence-weighted N-view DLT on undistorted normalized coordinates (no robust refinement).
    pub fn weighted_dlt(&self, frame: &Frame2) -> Result<[Option<Point3<f64>>; LANDMARK_COUNT]> {
        let (obs, _, _) = self.observations(frame)?;
        let mut out = [None; LANDMARK_COUNT];
        for lm in Landmark::ALL {
            let mut acc = DltAccumulator::default();
            for o in &obs[lm.index()] {
                acc.add_view(
                    &self.cameras[o.camera].pose,
                    &Point2::from(o.normalized),
                    o.confidence,
                );
            }
            out[lm.index()] = acc.solve().ok();
        }
        Ok(out)
    }

    fn check_frame(&self, frame: &Frame2) -> Result<u64> {
        let mut present: u64 = 0;
        for view in &frame.views {
            if view.camera >= self.cameras.len() {
                return Err(PerceptionError::UnknownCamera(format!(
                    "camera index {}",
                    view.camera
                )));
            }
            if present & (1 << view.camera) != 0 {
                return Err(PerceptionError::DuplicateCamera(
                    self.rig.cameras()[view.camera].id.clone(),
                ));
            }
            present |= 1 << view.camera;
        }
        Ok(present)
    }

    fn observations(&self, frame: &Frame2) -> Result<(FrameObs, usize, u64)> {
        let mut obs: FrameObs = std::array::from_fn(|_| Vec::new());
        let (failures, present) = self.observations_into(frame, &mut obs)?;
        Ok((obs, failures, present))
    }

    /// Undistorts every keypoint of the frame into `obs` (cleared first); returns the number of
    /// keypoints that could not be undistorted and the mask of cameras present.
    fn observations_into(&self, frame: &Frame2, obs: &mut FrameObs) -> Result<(usize, u64)> {
        let present = self.check_frame(frame)?;
        for o in obs.iter_mut() {
            o.clear();
        }
        let mut failures = 0;
        // in camera order, so every landmark's list is (the triangulation's lanes rely on it)
        let mut order = [0u8; MAX_VIEWS];
        let order = &mut order[..frame.views.len()];
        for (slot, k) in order.iter_mut().zip(0u8..) {
            *slot = k;
        }
        order.sort_unstable_by_key(|&k| frame.views[usize::from(k)].camera);
        for view in order.iter().map(|&k| &frame.views[usize::from(k)]) {
            let camera = &self.rig.cameras()[view.camera];
            let k = &camera.intrinsics;
            // distorted normalized coordinates of every keypoint, then all undistorted at once
            let mut points: [Option<Vector2<f64>>; LANDMARK_COUNT] = [None; LANDMARK_COUNT];
            for (slot, kp) in points.iter_mut().zip(view.keypoints()) {
                let Some(kp) = kp else { continue };
                let px = kp.pixel();
                if px.x.is_finite() && px.y.is_finite() {
                    let yd = (px.y - k.cy) / k.fy;
                    *slot = Some(Vector2::new((px.x - k.cx - k.skew * yd) / k.fx, yd));
                } else {
                    failures += 1;
                }
            }
            camera.distortion.undistort_many(&mut points);
            for (i, (kp, n)) in view.keypoints().iter().zip(points).enumerate() {
                let Some(kp) = kp else { continue };
                match n {
                    Some(n) => obs[i].push(Obs {
                        camera: view.camera,
                        normalized: n,
                        confidence: kp.confidence(),
                    }),
                    None if kp.pixel().x.is_finite() && kp.pixel().y.is_finite() => failures += 1,
                    None => {}
                }
            }
        }
        Ok((failures, present))
    }

    /// Each pair's DLT estimate of every landmark into `scratch.per_pair`.
    fn pair_estimates_into(&self, obs: &FrameObs, scratch: &mut PaperScratch) {
        // every (pair, landmark) both cameras see, accumulated, then all solved at once
        let PaperScratch {
            jobs,
            accs,
            solved,
            per_pair: out,
            ..
        } = scratch;
        jobs.clear();
        accs.clear();
        for (j, pair) in self.rig.pairs().iter().enumerate() {
            for (i, o) in obs.iter().enumerate() {
                let Some(l) = o.iter().find(|o| o.camera == pair.left) else {
                    continue;
                };
                let Some(r) = o.iter().find(|o| o.camera == pair.right) else {
                    continue;
                };
                let mut acc = DltAccumulator::default();
                acc.add_view(
                    &self.cameras[l.camera].pose,
                    &Point2::from(l.normalized),
                    1.0,
                );
                acc.add_view(
                    &self.cameras[r.camera].pose,
                    &Point2::from(r.normalized),
                    1.0,
                );
                jobs.push((j, i, l.camera, r.camera));
                accs.push(acc);
            }
        }
        solved.clear();
        solved.resize(accs.len(), Err(PerceptionError::Degenerate));
        DltAccumulator::solve_many(accs, solved);
        out.clear();
        out.resize(self.rig.pairs().len(), [None; LANDMARK_COUNT]);
        for (&(j, i, left, right), p) in jobs.iter().zip(solved.iter()) {
            let Ok(p) = *p else { continue };
            // a pair estimate behind either camera is no estimate
            let in_front = [left, right].iter().all(|&c| {
                let cam = &self.cameras[c];
                (cam.R_camera_world.row(2) * p.coords)[0] + cam.t_camera_world.z > 0.0
            });
            if in_front {
                out[j][i] = Some(p);
            }
        }
    }

    /// The paper's graph-Laplacian fusion of the per-pair estimates (`scratch.per_pair`).
    fn paper_fuse(
        &mut self,
        scratch: &mut PaperScratch,
    ) -> Option<[Option<Point3<f64>>; LANDMARK_COUNT]> {
        let m = self.cameras.len();
        let per_pair = &scratch.per_pair;
        let rig = &self.rig;
        // camera k's estimate of landmark i: its pair's estimate
        let camera_estimate =
            |k: usize, i: usize| -> Option<Point3<f64>> { per_pair[rig.pair_of(k)?][i] };
        // topology: for each landmark, the mask of connected cameras
        let edges: [u64; LANDMARK_COUNT] = std::array::from_fn(|i| {
            (0..m)
                .filter(|&k| camera_estimate(k, i).is_some())
                .fold(0u64, |acc, k| acc | (1 << k))
        });
        let mut landmarks = [0usize; LANDMARK_COUNT];
        let mut n = 0;
        for (i, _) in edges.iter().enumerate().filter(|(_, &e)| e != 0) {
            landmarks[n] = i;
            n += 1;
        }
        let landmarks = &landmarks[..n];
        if landmarks.is_empty() {
            return None;
        }
        let size = n + m;
        let solver = self
            .paper_cache
            .entry(edges)
            .or_insert_with(|| paper_solver(&edges, landmarks, m));
        // b = [δ; a]
        let b = &mut scratch.b;
        if b.shape() != (2 * size, 3) {
            *b = DMatrix::zeros(2 * size, 3);
        }
        for (row, &i) in landmarks.iter().enumerate() {
            let mut anchor = Vector3::zeros();
            let mut pairs_seen = 0.0;
            for est in per_pair.iter().filter_map(|pp| pp[i]) {
                anchor += est.coords;
                pairs_seen += 1.0;
            }
            anchor /= pairs_seen;
            let mut delta = Vector3::zeros();
            for k in iter_mask(edges[i]) {
                let est = camera_estimate(k, i)?;
                delta += est.coords - self.cameras[k].centre_world.coords;
            }
            delta /= f64::from(edges[i].count_ones());
            b.fixed_slice_mut::<1, 3>(row, 0)
                .copy_from(&delta.transpose());
            b.fixed_slice_mut::<1, 3>(size + row, 0)
                .copy_from(&anchor.transpose());
        }
        for k in 0..m {
            let c = self.cameras[k].centre_world.coords;
            let mut delta = Vector3::zeros();
            let mut connected = 0usize;
            for &i in landmarks.iter().filter(|&&i| edges[i] & (1 << k) != 0) {
                delta += c - camera_estimate(k, i)?.coords;
                connected += 1;
            }
            if connected != 0 {
                delta /= connected as f64;
            }
            b.fixed_slice_mut::<1, 3>(n + k, 0)
                .copy_from(&delta.transpose());
            b.fixed_slice_mut::<1, 3>(size + n + k, 0)
                .copy_from(&c.transpose());
        }
        let p = &mut scratch.p;
        if p.shape() != (size, 3) {
            *p = DMatrix::zeros(size, 3);
        }
        solver.mul_to(b, p);
        let mut out = [None; LANDMARK_COUNT];
        for (row, &i) in landmarks.iter().enumerate() {
            let q = Point3::new(p[(row, 0)], p[(row, 1)], p[(row, 2)]);
            if q.coords.iter().all(|x| x.is_finite()) {
                out[i] = Some(q);
            }
        }
        if self.paper_cache.len() > 256 {
            self.paper_cache.clear();
        }
        Some(out)
    }

    /// Stores a fused landmark with its RMS reprojection error over the observations that were used,
    /// in pixels of the undistorted image (the observation undistorted, the point projected by the
    /// pinhole model: no second pass through the lens model on the hot path).
    fn set(
        &self,
        skeleton: &mut Skeleton3,
        lm: Landmark,
        p: Point3<f64>,
        used: &Used<'_>,
    ) -> Result<()> {
        let mut sq = 0.0;
        let mut n = 0u32;
        let mut conf = 0.0;
        let mut conf2 = 0.0;
        for o in iter_mask(used.mask).filter_map(|i| used.obs.get(i)) {
            let c = &self.cameras[o.camera];
            let pc = c.R_camera_world * p.coords + c.t_camera_world;
            if pc.z <= 1e-9 {
                continue;
            }
            let r = Vector2::new(
                (pc.x / pc.z - o.normalized.x) * c.focal_px.x,
                (pc.y / pc.z - o.normalized.y) * c.focal_px.y,
            );
            sq += r.norm_squared();
            n += 1;
            conf += o.confidence;
            conf2 += o.confidence * o.confidence;
        }
        if n == 0 {
            return Ok(());
        }
        let estimate = LandmarkEstimate {
            position_m: p,
            // The views' confidences, each weighted by itself (the robust triangulator also weights each
            // view by its confidence): how sure the detector was of the views that place the point. A plain mean
            // lets occluded guesses the triangulator hardly listened to make a well-placed landmark
            // look unsure (twin, 3 px: 39 % of frames "uncertain", mostly the right ear, and those
            // frames scored as well as the rest).
            confidence: if conf > 0.0 { conf2 / conf } else { 0.0 }.clamp(0.0, 1.0),
            reprojection_error_px: Some((sq / f64::from(n)).sqrt()),
            views: n,
            // per axis: the covariance's mean variance (a finite covariance's trace is ≥ 0 up to
            // rounding; the clamp keeps a rounding-negative trace from becoming NaN)
            position_sd_m: used
                .covariance
                .map(|c| (c.trace() / 3.0).max(0.0).sqrt())
                .filter(|v| v.is_finite()),
        };
        skeleton
            .set(lm, Some(estimate))
            .map_err(|e| PerceptionError::Unsupported(format!("fused landmark rejected: {e}")))
    }
}

/// No landmark of a human body lies farther than this from the centre of its torso, metres. The
/// farthest are the feet, about 0.68 H from the torso's centre (hips at 0.53 H, shoulders at 0.82 H
/// of stature H, Drillis & Contini): 1.43 m for a 2.1 m person. A fingertip straight overhead is
/// nearer, about 0.55 H. From the median of all landmarks a standing person's farthest is ≈ 1.3 m
/// for 2.2 m.
pub const MAX_BODY_RADIUS_M: f64 = 1.5;

/// The torso's landmarks: one of the centres [`drop_off_body`] measures from.
const TORSO: [Landmark; 4] = [
    Landmark::LeftShoulder,
    Landmark::RightShoulder,
    Landmark::LeftHip,
    Landmark::RightHip,
];

/// Drops landmarks farther than [`MAX_BODY_RADIUS_M`] from the body's centre; returns the views
/// they had used.
///
/// The body's centre is judged two ways, and a landmark is off the body only when it is farther
/// than the radius from both: the per-axis median of every landmark (at least 5 are needed to
/// judge), and the per-axis median of the torso's landmarks when at least three of the four were
/// triangulated (one of them far off cannot move it outside the others). Either alone can sit off
/// the body's middle: 21 of the 33 landmarks are the face's and the hands', so with both arms raised
/// the median of all of them sits at the head and a tall operator's feet are more than the radius
/// below it; and the torso's own landmarks can be triangulated wrong together.
fn drop_off_body(
    points: &mut [Option<Point3<f64>>; LANDMARK_COUNT],
    masks: &[u64; LANDMARK_COUNT],
) -> usize {
    // on the stack: no allocation per frame
    let median = |pts: &mut dyn Iterator<Item = Point3<f64>>| {
        let mut v = [[0.0; LANDMARK_COUNT]; 3];
        let mut n = 0;
        for p in pts.take(LANDMARK_COUNT) {
            for axis in 0..3 {
                v[axis][n] = p[axis];
            }
            n += 1;
        }
        let mut mid = |axis: usize| {
            let v = &mut v[axis][..n];
            v.sort_unstable_by(f64::total_cmp);
            if n == 0 {
                f64::NAN
            } else if n % 2 == 0 {
                0.5 * (v[n / 2 - 1] + v[n / 2])
            } else {
                v[n / 2]
            }
        };
        (n, Point3::new(mid(0), mid(1), mid(2)))
    };
    let (n, all) = median(&mut points.iter().flatten().copied());
    if n < 5 {
        return 0;
    }
    let torso = median(&mut TORSO.iter().filter_map(|l| points[l.index()]));
    let torso = (torso.0 >= 3).then_some(torso.1);
    let off = |q: &Point3<f64>| {
        (q - all).norm() > MAX_BODY_RADIUS_M
            && torso.is_none_or(|t| (q - t).norm() > MAX_BODY_RADIUS_M)
    };
    let mut dropped = 0;
    for (p, mask) in points.iter_mut().zip(masks) {
        if p.as_ref().is_some_and(off) {
            *p = None;
            dropped += mask.count_ones() as usize;
        }
    }
    dropped
}

/// The observations of one landmark that a fused estimate used.
struct Used<'a> {
    obs: &'a [Obs],
    /// Bit `i`: `obs[i]` was used.
    mask: u64,
    /// The triangulation's covariance of the point, m² (none for the paper's fusion).
    covariance: Option<Matrix3<f64>>,
}

/// `(L̃ᵀL̃)⁻¹L̃ᵀ` for one topology: rows are the `n` observed landmarks then the `m` cameras.
fn paper_solver(edges: &[u64], landmarks: &[usize], m: usize) -> DMatrix<f64> {
    let n = landmarks.len();
    let size = n + m;
    let mut l = DMatrix::<f64>::identity(size, size);
    for (row, &i) in landmarks.iter().enumerate() {
        let cams: Vec<usize> = iter_mask(edges[i]).collect();
        let deg = cams.len() as f64;
        for k in cams {
            l[(row, n + k)] = -1.0 / deg;
        }
    }
    for k in 0..m {
        let rows: Vec<usize> = landmarks
            .iter()
            .enumerate()
            .filter(|(_, &i)| edges[i] & (1 << k) != 0)
            .map(|(r, _)| r)
            .collect();
        if rows.is_empty() {
            // an isolated camera has no neighbours: its differential coordinate is zero by definition
            l[(n + k, n + k)] = 0.0;
            continue;
        }
        let deg = rows.len() as f64;
        for r in rows {
            l[(n + k, r)] = -1.0 / deg;
        }
    }
    let mut lt = DMatrix::zeros(2 * size, size);
    lt.slice_mut((0, 0), (size, size)).copy_from(&l);
    lt.slice_mut((size, 0), (size, size)).fill_with_identity();
    let normal = lt.transpose() * &lt;
    // LᵀL + I is symmetric positive definite, so the inverse always exists.
    let inv = normal
        .clone()
        .cholesky()
        .map_or_else(|| DMatrix::identity(size, size), |c| c.inverse());
    inv * lt.transpose()
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::camera::{Camera, CameraId, Distortion, Intrinsics};
    use crate::detections::{Keypoint2, View2};
    use approx::assert_relative_eq;

    pub(crate) fn ring_rig(n: usize) -> CameraRig {
        let cams = (0..n)
            .map(|k| {
                let angle = (k / 2) as f64 * 2.1 + if k % 2 == 1 { 0.04 } else { 0.0 };
                let eye = Point3::new(
                    3.0 * angle.cos(),
                    3.0 * angle.sin(),
                    1.4 + 0.1 * (k % 3) as f64,
                );
                Camera::look_at(
                    CameraId::new(format!("cam_{k}")).unwrap(),
                    eye,
                    Point3::new(0.0, 0.0, 1.0),
                    Vector3::z(),
                    Intrinsics {
                        fx: 900.0,
                        fy: 900.0,
                        cx: 640.0,
                        cy: 360.0,
                        skew: 0.0,
                        width_px: 1280,
                        height_px: 720,
                    },
                    Distortion {
                        k1: -0.05,
                        k2: 0.01,
                        p1: 0.0005,
                        p2: -0.0003,
                        k3: 0.0,
                    },
                )
                .unwrap()
            })
            .collect();
        CameraRig::new(cams, &[], None).unwrap()
    }

    fn frame_of(rig: &CameraRig, points: &[Point3<f64>; LANDMARK_COUNT]) -> Frame2 {
        let views = rig
            .cameras()
            .iter()
            .enumerate()
            .map(|(k, cam)| {
                let mut v = View2::empty(k, 0);
                for lm in Landmark::ALL {
                    let px = cam.project(&points[lm.index()]).unwrap();
                    v.set(lm, Some(Keypoint2::new(px.x, px.y, 0.9).unwrap()));
                }
                v
            })
            .collect();
        Frame2 {
            stamp_nanos: 0,
            views,
        }
    }

    fn body() -> [Point3<f64>; LANDMARK_COUNT] {
        std::array::from_fn(|i| {
            Point3::new(
                0.1 * ((i * 7) % 5) as f64 - 0.2,
                0.05 * ((i * 3) % 4) as f64 - 0.1,
                0.2 + 1.6 * i as f64 / 33.0,
            )
        })
    }

    /// The default fusion's triangulation of a frame one landmark at a time with the scalar
    /// triangulator: what `triangulate_all` did before it ran in lanes.
    fn triangulate_all_scalar(engine: &FusionEngine, obs: &FrameObs) -> Triangulations {
        let mut t = Triangulations::new();
        let mut views = Vec::new();
        for (i, o) in obs.iter().enumerate() {
            engine.views_into(o, &mut views);
            if let Ok(r) = engine.triangulator.triangulate(&views) {
                t.record(i, &r, o.len());
            }
        }
        t
    }

    #[test]
    fn the_lanes_triangulate_every_landmark_as_the_scalar_triangulator_does() {
        // Noisy frames with gross errors, missing keypoints, low confidences and an absent
        // camera, views listed out of camera order: points, information, covariances, used views
        // and rejected counts are equal bit for bit.
        use rand::{Rng, SeedableRng};
        let rig = ring_rig(6);
        let truth = body();
        let engine = FusionEngine::new(rig.clone(), FusionMethod::Default).unwrap();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(19);
        let mut fallbacks_seen = false;
        for f in 0..60 {
            let mut frame = frame_of(&rig, &truth);
            for view in &mut frame.views {
                for lm in Landmark::ALL {
                    let Some(k) = view.get(lm).copied() else {
                        continue;
                    };
                    let gross = if rng.random::<f64>() < 0.03 {
                        70.0
                    } else {
                        0.0
                    };
                    let px = k.pixel();
                    let kp = Keypoint2::new(
                        px.x + rng.random_range(-3.0..3.0) + rng.random_range(-gross..=gross),
                        px.y + rng.random_range(-3.0..3.0),
                        rng.random_range(0.02..1.0),
                    )
                    .unwrap();
                    view.set(lm, (rng.random::<f64>() > 0.1).then_some(kp));
                }
            }
            frame.views.retain(|v| v.camera != f % 7);
            frame.views.reverse();
            let (obs, _, _) = engine.observations(&frame).unwrap();
            let mut views = Vec::new();
            let mut lanes = Vec::new();
            let got = engine.triangulate_all(&obs, &mut views, &mut lanes);
            let want = triangulate_all_scalar(&engine, &obs);
            let bits = |t: &Triangulations| {
                let mut v: Vec<u64> = Vec::new();
                for i in 0..LANDMARK_COUNT {
                    v.extend(
                        t.points[i]
                            .iter()
                            .flat_map(|p| p.iter().map(|x| x.to_bits())),
                    );
                    v.extend(t.information[i].iter().map(|x| x.to_bits()));
                    v.extend(
                        t.covariance[i]
                            .iter()
                            .flat_map(|c| c.iter().map(|x| x.to_bits())),
                    );
                    v.push(t.masks[i]);
                }
                v.push(t.rejected as u64);
                v
            };
            assert!(bits(&got) == bits(&want), "frame {f}");
            fallbacks_seen |= want.rejected > 0;
        }
        assert!(
            fallbacks_seen,
            "some views were rejected (the scalar fallback ran)"
        );
    }

    #[test]
    fn a_landmark_off_the_body_is_dropped_with_its_views() {
        let mut points = body().map(Some);
        let masks = [0b11u64; LANDMARK_COUNT];
        assert_eq!(drop_off_body(&mut points, &masks), 0, "a body stays whole");
        points[2] = Some(Point3::new(-40.0, 12.0, 1.1));
        assert_eq!(drop_off_body(&mut points, &masks), 2);
        assert!(points[2].is_none());
        assert_eq!(points.iter().flatten().count(), LANDMARK_COUNT - 1);
        // Too few landmarks to judge: nothing dropped.
        let mut few = [None; LANDMARK_COUNT];
        few[0] = Some(Point3::origin());
        few[1] = Some(Point3::new(30.0, 0.0, 0.0));
        assert_eq!(drop_off_body(&mut few, &masks), 0);
    }

    /// A 1.95 m operator placing a part on a high shelf: both arms straight overhead (Drillis &
    /// Contini proportions), feet on the floor.
    fn tall_operator_reaching_overhead() -> [Option<Point3<f64>>; LANDMARK_COUNT] {
        let h = 1.95;
        std::array::from_fn(|i| {
            let lm = Landmark::ALL[i];
            let x = match lm.side() {
                Some(ergocell_skeleton::Side::Left) => 1.0,
                Some(ergocell_skeleton::Side::Right) => -1.0,
                None => 0.0,
            };
            let (lateral, z) = match lm {
                Landmark::LeftShoulder | Landmark::RightShoulder => (0.13, 0.818),
                Landmark::LeftElbow | Landmark::RightElbow => (0.13, 0.818 + 0.186),
                Landmark::LeftWrist | Landmark::RightWrist => (0.13, 0.818 + 0.332),
                Landmark::LeftHip | Landmark::RightHip => (0.1, 0.53),
                Landmark::LeftKnee | Landmark::RightKnee => (0.1, 0.285),
                Landmark::LeftAnkle | Landmark::RightAnkle => (0.1, 0.039),
                Landmark::LeftHeel | Landmark::RightHeel => (0.1, 0.01),
                Landmark::LeftFootIndex | Landmark::RightFootIndex => (0.1, 0.005),
                // the hands' points above the wrist, the face's about the head
                l if l.index() >= Landmark::LeftPinky.index() => (0.13, 0.818 + 0.37),
                _ => (0.03, 0.93),
            };
            Some(Point3::new(x * lateral * h, 0.0, z * h))
        })
    }

    #[test]
    fn a_tall_operator_reaching_overhead_keeps_their_feet() {
        let mut points = tall_operator_reaching_overhead();
        let masks = [0b11u64; LANDMARK_COUNT];
        // The premise: the median of all 33 landmarks sits at the head, farther than the radius
        // from the feet (what dropped them before the centre was the torso's).
        let mut z: Vec<f64> = points.iter().flatten().map(|p| p.z).collect();
        z.sort_by(f64::total_cmp);
        let ankle = points[Landmark::LeftAnkle.index()].map_or(f64::NAN, |p| p.z);
        assert!(z[z.len() / 2] - ankle > MAX_BODY_RADIUS_M);
        assert_eq!(drop_off_body(&mut points, &masks), 0);
        assert_eq!(points.iter().flatten().count(), LANDMARK_COUNT);
    }

    #[test]
    fn a_torso_landmark_far_off_is_dropped_and_the_body_kept() {
        let mut points = tall_operator_reaching_overhead();
        let masks = [0b111u64; LANDMARK_COUNT];
        points[Landmark::RightHip.index()] = Some(Point3::new(40.0, -12.0, 1.0));
        assert_eq!(drop_off_body(&mut points, &masks), 3);
        assert!(points[Landmark::RightHip.index()].is_none());
        assert_eq!(points.iter().flatten().count(), LANDMARK_COUNT - 1);
    }

    #[test]
    fn both_fusions_are_exact_on_noise_free_data() {
        let rig = ring_rig(6);
        let pts = body();
        let frame = frame_of(&rig, &pts);
        for method in [FusionMethod::Default, FusionMethod::Paper] {
            let mut engine = FusionEngine::new(rig.clone(), method).unwrap();
            let fused = engine.fuse(&frame).unwrap();
            for lm in Landmark::ALL {
                let e = fused.skeleton.get(lm).unwrap();
                let tol = if method == FusionMethod::Default {
                    1e-9
                } else {
                    1e-6
                };
                assert_relative_eq!(e.position_m, pts[lm.index()], epsilon = tol);
                assert!(e.reprojection_error_px.unwrap() < 1e-4);
            }
        }
    }

    #[test]
    fn a_fused_landmark_is_as_confident_as_the_views_that_place_it() {
        // Two cameras sure of the nose (0.9), four reporting an occluded guess (0.2): the views'
        // confidences weighted by their confidence, (2·0.81 + 4·0.04) / (2·0.9 + 4·0.2) = 0.6846.
        let rig = ring_rig(6);
        let mut frame = frame_of(&rig, &body());
        for view in frame.views.iter_mut().skip(2) {
            let px = view.get(Landmark::Nose).unwrap().pixel();
            view.set(
                Landmark::Nose,
                Some(Keypoint2::new(px.x, px.y, 0.2).unwrap()),
            );
        }
        let mut engine = FusionEngine::new(rig, FusionMethod::Default).unwrap();
        let fused = engine.fuse(&frame).unwrap();
        let nose = fused.skeleton.get(Landmark::Nose).unwrap();
        assert_eq!(nose.views, 6);
        assert_relative_eq!(nose.confidence, 1.78 / 2.6, epsilon = 1e-12);
        // Every view alike: that confidence.
        let ear = fused.skeleton.get(Landmark::LeftEar).unwrap();
        assert_relative_eq!(ear.confidence, 0.9, epsilon = 1e-12);
    }

    #[test]
    fn paper_laplacian_has_zero_row_sums_and_the_cached_solver_is_reused() {
        let rig = ring_rig(6);
        let frame = frame_of(&rig, &body());
        let mut engine = FusionEngine::new(rig, FusionMethod::Paper).unwrap();
        engine.fuse(&frame).unwrap();
        engine.fuse(&frame).unwrap();
        assert_eq!(engine.paper_cache.len(), 1);
        // The solver reproduces any configuration that is consistent with its own anchors.
        let edges = vec![0b11u64, 0b1100, 0b11_0000];
        let s = paper_solver(&edges, &[0, 1, 2], 6);
        assert_eq!(s.shape(), (9, 18));
    }

    #[test]
    fn frames_with_unknown_or_repeated_cameras_are_errors() {
        let rig = ring_rig(4);
        let mut frame = frame_of(&rig, &body());
        let mut engine = FusionEngine::new(rig, FusionMethod::Default).unwrap();
        frame.views[1].camera = 0;
        assert!(matches!(
            engine.fuse(&frame),
            Err(PerceptionError::DuplicateCamera(_))
        ));
        frame.views[1].camera = 9;
        assert!(matches!(
            engine.fuse(&frame),
            Err(PerceptionError::UnknownCamera(_))
        ));
    }

    #[test]
    fn a_missing_camera_degrades_but_does_not_block() {
        let rig = ring_rig(6);
        let pts = body();
        let mut frame = frame_of(&rig, &pts);
        frame.views.retain(|v| v.camera != 3 && v.camera != 4);
        let mut engine = FusionEngine::new(rig, FusionMethod::Default).unwrap();
        let fused = engine.fuse(&frame).unwrap();
        assert_eq!(fused.cameras_present, 0b10_0111);
        assert_eq!(fused.skeleton.observed_count(), LANDMARK_COUNT);
        // one camera only: nothing can be triangulated, and nothing is made up
        frame.views.truncate(1);
        let fused = engine.fuse(&frame).unwrap();
        assert_eq!(fused.skeleton.observed_count(), 0);
    }

    /// [`body`] with the person's left 0.2 m to +y and right 0.2 m to −y, so mirroring a view moves
    /// its keypoints far.
    fn sided_body() -> [Point3<f64>; LANDMARK_COUNT] {
        let mut b = body();
        for lm in Landmark::ALL {
            match lm.side() {
                Some(ergocell_skeleton::Side::Left) => b[lm.index()].y += 0.2,
                Some(ergocell_skeleton::Side::Right) => b[lm.index()].y -= 0.2,
                None => {}
            }
        }
        b
    }

    fn mirror_view(v: &mut View2) {
        let original = v.clone();
        for lm in Landmark::ALL {
            v.set(lm, original.get(lm.mirrored()).copied());
        }
    }

    #[test]
    fn a_view_with_left_and_right_swapped_is_used_mirrored() {
        let rig = ring_rig(6);
        let truth = sided_body();
        let mut engine = FusionEngine::new(rig.clone(), FusionMethod::Default)
            .unwrap()
            .with_bone_prior(None);
        let clean = engine.fuse(&frame_of(&rig, &truth)).unwrap();
        assert_eq!(clean.swapped_views, 0);
        for swapped in [2usize, 5] {
            let mut frame = frame_of(&rig, &truth);
            mirror_view(&mut frame.views[swapped]);
            let fused = engine.fuse(&frame).unwrap();
            assert_eq!(fused.swapped_views, 1 << swapped);
            assert_eq!(
                fused.rejected_views, 0,
                "the corrected view is used, not rejected"
            );
            for lm in Landmark::ALL {
                let p = fused.skeleton.position(lm).unwrap();
                assert!((p - truth[lm.index()]).norm() < 1e-6, "{lm}: {p}");
            }
        }
        // two cameras cannot tell which of them is swapped: nothing is corrected
        let two = CameraRig::new(rig.cameras()[..2].to_vec(), &[], None).unwrap();
        let mut engine2 = FusionEngine::new(two.clone(), FusionMethod::Default).unwrap();
        let mut frame = frame_of(&two, &truth);
        mirror_view(&mut frame.views[1]);
        assert_eq!(engine2.fuse(&frame).unwrap().swapped_views, 0);
        // the paper's fusion is the baseline as written: it corrects nothing
        let mut paper = FusionEngine::new(rig.clone(), FusionMethod::Paper).unwrap();
        let mut frame = frame_of(&rig, &truth);
        mirror_view(&mut frame.views[2]);
        assert_eq!(paper.fuse(&frame).unwrap().swapped_views, 0);
    }
}
