//! Stereo and multi-camera calibration: each camera is calibrated alone ([`crate::intrinsics`]),
//! cameras are chained into one world frame through the board views they share, and a joint
//! Levenberg–Marquardt refinement minimises every camera's reprojection error at once.
//!
//! The world frame is the first camera's, as in the seed paper (Sec. II.A.2: `R1 = I`, `T1 = 0`,
//! `R2 = R`, `T2 = T`). For a stereo pair `T_right_left` is OpenCV's `stereoCalibrate` `(R, T)`:
//! `p_right = R p_left + T`. Chaining: a camera joins the rig through the already-placed camera it
//! shares the most frames with, `T_m_world = T_m_k · T_k_world`, `T_m_k` the average over the shared
//! frames of `T_m_board · T_k_boardⁱ⁻¹` (quaternion mean); with `joint_refinement` all extrinsics,
//! board poses (and, with `refine_intrinsics`, intrinsics) are then refined together, as OpenCV's
//! `stereoCalibrate` does for two cameras; without it each chained link is refined on its own pair.

use ergocell_perception::{Camera, CameraId, CameraRig};
use nalgebra::{Isometry3, Point2, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};

use crate::board::BoardSpec;
use crate::error::{CalibrationError, Result};
use crate::intrinsics::{
    calibrate_camera, check_camera, check_determined, CameraCalibration, SolveOptions,
};
use crate::lm::{solve, BlockProblem, LmReport};
use crate::model::{
    camera_of, params_of, pose_from_params, pose_to_params, rms_per_point, view_residuals,
    N_INTRINSICS, N_POSE,
};

/// Fewest frames two cameras must share to be chained.
pub const MIN_SHARED_VIEWS: usize = 3;

/// Rig calibration settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigOptions {
    /// Refine every camera's intrinsics in the joint refinement (otherwise they stay as calibrated
    /// alone, OpenCV's `CALIB_FIX_INTRINSIC`).
    pub refine_intrinsics: bool,
    /// Refine all cameras and board poses together after chaining.
    pub joint_refinement: bool,
    pub solve: SolveOptions,
}

impl Default for RigOptions {
    fn default() -> Self {
        Self {
            refine_intrinsics: false,
            joint_refinement: true,
            solve: SolveOptions::default(),
        }
    }
}

/// The views of one camera: one entry per frame (the same frames for every camera), `None` where
/// the board was not found. Corners come from
/// [`Detection::into_rig_corners`](crate::detect::Detection::into_rig_corners), so every camera lists
/// the same physical corner first.
#[derive(Debug, Clone, PartialEq)]
pub struct CameraViews {
    pub id: CameraId,
    pub image_size_px: (u32, u32),
    pub frames: Vec<Option<Vec<Point2<f64>>>>,
}

/// A calibrated rig.
#[derive(Debug, Clone, PartialEq)]
pub struct RigCalibration {
    /// The cameras in the first camera's frame, ready for `rig_file::to_ergocell_toml`.
    pub rig: CameraRig,
    /// Each camera calibrated alone (before the joint refinement).
    pub single: Vec<CameraCalibration>,
    /// RMS reprojection error over every corner of every camera in the rig solve, pixels.
    pub rms_px: f64,
    /// `[camera][frame]`: RMS of that view in the rig solve, pixels; `None` if not used.
    pub view_rms_px: Vec<Vec<Option<f64>>>,
    /// How the final refinement ended.
    pub report: Option<LmReport>,
}

impl RigCalibration {
    /// Distance between two cameras' centres, metres.
    pub fn baseline_m(&self, a: usize, b: usize) -> Option<f64> {
        let (ca, cb) = (self.rig.camera(a)?, self.rig.camera(b)?);
        Some((ca.position_world() - cb.position_world()).norm())
    }

    /// `T_b_a`: maps camera `a`'s frame into camera `b`'s (OpenCV's stereo `(R, T)` for a = left).
    pub fn T_between(&self, a: usize, b: usize) -> Option<Isometry3<f64>> {
        let (ca, cb) = (self.rig.camera(a)?, self.rig.camera(b)?);
        Some(cb.T_camera_world * ca.T_camera_world.inverse())
    }
}

/// Calibrates a stereo pair: `left` becomes the world frame.
pub fn calibrate_stereo(
    left: CameraViews,
    right: CameraViews,
    board: &BoardSpec,
    options: RigOptions,
) -> Result<RigCalibration> {
    let pair = [("S1".to_owned(), left.id.to_string(), right.id.to_string())];
    calibrate_rig(&[left, right], board, &pair, options)
}

/// Calibrates a rig of cameras that see the same board frames. `pairs` are `(name, left id, right
/// id)` stereo pairs written to the rig (empty: consecutive cameras are paired).
pub fn calibrate_rig(
    cameras: &[CameraViews],
    board: &BoardSpec,
    pairs: &[(String, String, String)],
    options: RigOptions,
) -> Result<RigCalibration> {
    let n_frames = cameras.first().map_or(0, |c| c.frames.len());
    if cameras.len() < 2 {
        return Err(CalibrationError::TooFewViews {
            what: "rig calibration (cameras)".into(),
            usable: cameras.len(),
            needed: 2,
        });
    }
    if let Some(c) = cameras.iter().find(|c| c.frames.len() != n_frames) {
        return Err(CalibrationError::TooFewViews {
            what: format!(
                "camera `{}` has {} frames, `{}` has {n_frames}; frames must correspond",
                c.id,
                c.frames.len(),
                cameras[0].id
            ),
            usable: c.frames.len(),
            needed: n_frames,
        });
    }
    // 1. each camera alone
    let mut single = Vec::with_capacity(cameras.len());
    // T_camera_board per [camera][frame]
    let mut board_poses: Vec<Vec<Option<Isometry3<f64>>>> = Vec::new();
    for cam in cameras {
        let (frames, views): (Vec<usize>, Vec<Vec<Point2<f64>>>) = cam
            .frames
            .iter()
            .enumerate()
            .filter_map(|(f, v)| v.clone().map(|v| (f, v)))
            .unzip();
        let calib = calibrate_camera(&views, board, cam.image_size_px, options.solve).map_err(
            |e| match e {
                CalibrationError::TooFewViews { usable, needed, .. } => {
                    CalibrationError::TooFewViews {
                        what: format!("camera `{}`", cam.id),
                        usable,
                        needed,
                    }
                }
                other => other,
            },
        )?;
        let mut poses = vec![None; n_frames];
        for (f, pose) in frames.iter().zip(&calib.T_camera_board) {
            poses[*f] = Some(*pose);
        }
        board_poses.push(poses);
        single.push(calib);
    }
    // 2. chain into camera 0's frame
    let n_cams = cameras.len();
    let mut T_cam_world: Vec<Option<Isometry3<f64>>> = vec![None; n_cams];
    T_cam_world[0] = Some(Isometry3::identity());
    let mut intrinsics: Vec<[f64; N_INTRINSICS]> = single
        .iter()
        .map(|c| params_of(&c.intrinsics, &c.distortion))
        .collect();
    let mut links = Vec::new();
    for _ in 1..n_cams {
        let mut best: Option<(usize, usize, Vec<usize>)> = None;
        for k in (0..n_cams).filter(|&k| T_cam_world[k].is_some()) {
            for m in (0..n_cams).filter(|&m| T_cam_world[m].is_none()) {
                let shared: Vec<usize> = (0..n_frames)
                    .filter(|&f| board_poses[k][f].is_some() && board_poses[m][f].is_some())
                    .collect();
                if best.as_ref().is_none_or(|b| shared.len() > b.2.len()) {
                    best = Some((k, m, shared));
                }
            }
        }
        let Some((k, m, shared)) = best else { break };
        if shared.len() < MIN_SHARED_VIEWS {
            let lonely = (0..n_cams)
                .find(|&c| T_cam_world[c].is_none())
                .map_or_else(String::new, |c| cameras[c].id.to_string());
            return Err(CalibrationError::TooFewViews {
                what: format!("frames camera `{lonely}` shares with the rig"),
                usable: shared.len(),
                needed: MIN_SHARED_VIEWS,
            });
        }
        let estimates: Vec<Isometry3<f64>> = shared
            .iter()
            .filter_map(|&f| Some(board_poses[m][f]? * board_poses[k][f]?.inverse()))
            .collect();
        let T_m_k = average_pose(&estimates)
            .ok_or_else(|| CalibrationError::Disconnected(cameras[m].id.to_string()))?;
        let T_k_world = T_cam_world[k].unwrap_or_else(Isometry3::identity);
        T_cam_world[m] = Some(T_m_k * T_k_world);
        links.push((k, m));
    }
    let mut extrinsics: Vec<Isometry3<f64>> = Vec::with_capacity(n_cams);
    for (c, t) in T_cam_world.iter().enumerate() {
        extrinsics
            .push(t.ok_or_else(|| CalibrationError::Disconnected(cameras[c].id.to_string()))?);
    }

    // 3. refinement
    let mut report = None;
    let mut view_rms_px = vec![vec![None; n_frames]; n_cams];
    let mut all = Vec::new();
    let object = board.object_points();
    let refine = |members: &[usize],
                  intrinsics: &mut Vec<[f64; N_INTRINSICS]>,
                  extrinsics: &mut Vec<Isometry3<f64>>,
                  refine_k: bool,
                  min_seen: usize|
     -> (LmReport, RigProblem) {
        let mut problem = RigProblem::new(members, cameras, &object, min_seen);
        let mut x = problem.initial(intrinsics, extrinsics, &board_poses);
        let fixed = problem.fixed(refine_k);
        let rep = solve(&problem, &mut x, &fixed, options.solve.max_iterations);
        problem.read_back(&x, intrinsics, extrinsics);
        problem.x = x;
        (rep, problem)
    };
    let members: Vec<usize> = (0..n_cams).collect();
    if options.joint_refinement {
        let min_seen = if options.refine_intrinsics { 1 } else { 2 };
        let (rep, problem) = refine(
            &members,
            &mut intrinsics,
            &mut extrinsics,
            options.refine_intrinsics,
            min_seen,
        );
        report = Some(rep);
        problem.errors(&mut view_rms_px, &mut all);
    } else {
        for &(k, m) in &links {
            // refine camera m relative to the (already refined) camera k: k's pose held fixed
            let (rep, _) = refine(&[k, m], &mut intrinsics, &mut extrinsics, false, 2);
            report = Some(rep);
        }
        let mut problem = RigProblem::new(&members, cameras, &object, 2);
        let mut x = problem.initial(&intrinsics, &extrinsics, &board_poses);
        // only board poses free: the reported error is for the chained rig as it stands
        let mut fixed = problem.fixed(false);
        for f in fixed.iter_mut().take(problem.frames_offset) {
            *f = true;
        }
        solve(&problem, &mut x, &fixed, options.solve.max_iterations);
        problem.x = x;
        problem.errors(&mut view_rms_px, &mut all);
    }

    let mut rig_cameras = Vec::with_capacity(n_cams);
    for (c, cam) in cameras.iter().enumerate() {
        let (k, d) = camera_of(&intrinsics[c], cam.image_size_px);
        check_camera(&k, &d)?;
        check_determined(&k)?;
        let t = &extrinsics[c];
        rig_cameras.push(Camera::new(
            cam.id.clone(),
            k,
            d,
            t.rotation.to_rotation_matrix(),
            t.translation.vector,
        )?);
    }
    let rig = CameraRig::new(rig_cameras, pairs, None)?;
    Ok(RigCalibration {
        rig,
        single,
        rms_px: rms_per_point(&all),
        view_rms_px,
        report,
    })
}

/// Mean of poses: sign-aligned quaternion mean and mean translation.
fn average_pose(poses: &[Isometry3<f64>]) -> Option<Isometry3<f64>> {
    let first = poses.first()?;
    let q0 = first.rotation.into_inner();
    let mut q = Quaternion::new(0.0, 0.0, 0.0, 0.0);
    let mut t = Vector3::zeros();
    for p in poses {
        let qi = p.rotation.into_inner();
        q += if qi.dot(&q0) < 0.0 { -qi } else { qi };
        t += p.translation.vector;
    }
    let q = UnitQuaternion::try_new(q, 1e-12)?;
    Some(Isometry3::from_parts(
        Translation3::from(t / poses.len() as f64),
        q,
    ))
}

/// The joint problem over `members` cameras: parameters are their intrinsics, the extrinsics of all
/// members but the first (held at its current pose, the reference), and one board pose in the world
/// per frame seen by at least `min_seen` members.
struct RigProblem<'a> {
    members: Vec<usize>,
    cameras: &'a [CameraViews],
    object: &'a [Point3<f64>],
    /// frames used, in order
    frames: Vec<usize>,
    /// blocks: (member slot, frame slot)
    blocks: Vec<(usize, usize)>,
    params: Vec<Vec<usize>>,
    frames_offset: usize,
    reference: Isometry3<f64>,
    x: Vec<f64>,
}

impl<'a> RigProblem<'a> {
    fn new(
        members: &[usize],
        cameras: &'a [CameraViews],
        object: &'a [Point3<f64>],
        min_seen: usize,
    ) -> Self {
        let n_frames = cameras[members[0]].frames.len();
        let frames: Vec<usize> = (0..n_frames)
            .filter(|&f| {
                members
                    .iter()
                    .filter(|&&c| cameras[c].frames[f].is_some())
                    .count()
                    >= min_seen
            })
            .collect();
        let n = members.len();
        let frames_offset = N_INTRINSICS * n + N_POSE * (n - 1);
        let mut blocks = Vec::new();
        let mut params = Vec::new();
        for (fs, &f) in frames.iter().enumerate() {
            for (ms, &c) in members.iter().enumerate() {
                if cameras[c].frames[f].is_none() {
                    continue;
                }
                let mut p: Vec<usize> = (N_INTRINSICS * ms..N_INTRINSICS * (ms + 1)).collect();
                if ms > 0 {
                    let e = N_INTRINSICS * n + N_POSE * (ms - 1);
                    p.extend(e..e + N_POSE);
                }
                let o = frames_offset + N_POSE * fs;
                p.extend(o..o + N_POSE);
                blocks.push((ms, fs));
                params.push(p);
            }
        }
        Self {
            members: members.to_vec(),
            cameras,
            object,
            frames,
            blocks,
            params,
            frames_offset,
            reference: Isometry3::identity(),
            x: Vec::new(),
        }
    }

    fn initial(
        &mut self,
        intrinsics: &[[f64; N_INTRINSICS]],
        extrinsics: &[Isometry3<f64>],
        board_poses: &[Vec<Option<Isometry3<f64>>>],
    ) -> Vec<f64> {
        self.reference = extrinsics[self.members[0]];
        let mut x = Vec::with_capacity(self.frames_offset + N_POSE * self.frames.len());
        for &c in &self.members {
            x.extend_from_slice(&intrinsics[c]);
        }
        for &c in &self.members[1..] {
            // relative to the reference member
            x.extend_from_slice(&pose_to_params(&(extrinsics[c] * self.reference.inverse())));
        }
        for &f in &self.frames {
            // T_ref_board from the first member that sees it
            let pose = self
                .members
                .iter()
                .find_map(|&c| {
                    let T_c_board = board_poses[c][f]?;
                    let T_c_ref = extrinsics[c] * self.reference.inverse();
                    Some(T_c_ref.inverse() * T_c_board)
                })
                .unwrap_or_else(Isometry3::identity);
            x.extend_from_slice(&pose_to_params(&pose));
        }
        x
    }

    fn fixed(&self, refine_intrinsics: bool) -> Vec<bool> {
        let n = self.frames_offset + N_POSE * self.frames.len();
        (0..n)
            .map(|i| !refine_intrinsics && i < N_INTRINSICS * self.members.len())
            .collect()
    }

    fn read_back(
        &self,
        x: &[f64],
        intrinsics: &mut [[f64; N_INTRINSICS]],
        extrinsics: &mut [Isometry3<f64>],
    ) {
        let n = self.members.len();
        for (ms, &c) in self.members.iter().enumerate() {
            intrinsics[c].copy_from_slice(&x[N_INTRINSICS * ms..N_INTRINSICS * (ms + 1)]);
            if ms > 0 {
                let e = N_INTRINSICS * n + N_POSE * (ms - 1);
                extrinsics[c] = pose_from_params(&x[e..e + N_POSE]) * self.reference;
            }
        }
    }

    fn camera_from_ref(&self, ms: usize, x: &[f64]) -> Isometry3<f64> {
        if ms == 0 {
            Isometry3::identity()
        } else {
            let e = N_INTRINSICS * self.members.len() + N_POSE * (ms - 1);
            pose_from_params(&x[e..e + N_POSE])
        }
    }

    fn errors(&self, view_rms_px: &mut [Vec<Option<f64>>], all: &mut Vec<f64>) {
        let mut r = Vec::new();
        for (b, &(ms, fs)) in self.blocks.iter().enumerate() {
            self.block_residuals(b, &self.x, &mut r);
            view_rms_px[self.members[ms]][self.frames[fs]] = Some(rms_per_point(&r));
            all.extend_from_slice(&r);
        }
    }
}

impl BlockProblem for RigProblem<'_> {
    fn blocks(&self) -> usize {
        self.blocks.len()
    }
    fn block_params(&self, b: usize) -> &[usize] {
        &self.params[b]
    }
    fn block_residuals(&self, b: usize, x: &[f64], out: &mut Vec<f64>) {
        out.clear();
        let (ms, fs) = self.blocks[b];
        let c = self.members[ms];
        let Some(observed) = &self.cameras[c].frames[self.frames[fs]] else {
            return;
        };
        let o = self.frames_offset + N_POSE * fs;
        let T_ref_board = pose_from_params(&x[o..o + N_POSE]);
        let T_c_board = self.camera_from_ref(ms, x) * T_ref_board;
        view_residuals(
            &x[N_INTRINSICS * ms..N_INTRINSICS * (ms + 1)],
            &T_c_board,
            self.object,
            observed,
            out,
        );
    }
}
