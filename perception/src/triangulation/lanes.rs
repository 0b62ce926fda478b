//! [`RobustTriangulator::triangulate`] for several landmarks at once, one per SIMD lane.
//!
//! The default fusion triangulates 33 landmarks a frame from the same cameras. One landmark's
//! triangulation is a chain of dependent divisions and square roots per view (the Gauss–Newton
//! steps), which leaves the processor waiting; [`LANES`] landmarks in lockstep fill those waits
//! and let the arithmetic run 4 wide (AVX2 where the processor has it, detected at run time).
//!
//! Every lane does exactly the scalar triangulator's operations in the same order, so a lane's
//! answer is the scalar answer bit for bit (a test holds the two equal). Only the common path runs
//! in lanes — the linear estimate, the refinement, and the check that no view is behind its
//! camera or an outlier. A lane that leaves it (a view to drop, a singular system) is marked
//! [`LaneResult::Fallback`] and the caller runs the scalar triangulator on that landmark.
//!
//! Views are indexed by camera slot: every lane of a group sees the same cameras' constants
//! (rotation, translation, focal lengths), and each lane has its own observations, absent where
//! its landmark was not seen.

// The kernel and its helpers must be inlined into the AVX2 function to be compiled with AVX2 at
// all: `inline(always)` is the point here.
#![allow(clippy::inline_always)]

use nalgebra::{Matrix3, Point3};

#[cfg(test)]
use super::iter_mask;
use super::{RobustTriangulator, Triangulated, MAX_VIEWS};
use crate::simd::{LaneMask, LaneSym3, Lanes, S3Parts};

/// Landmarks triangulated together.
pub(crate) const LANES: usize = 8;

/// One value per lane.
type V = Lanes<LANES>;
/// One flag per lane.
type M = LaneMask<LANES>;
/// A symmetric 3×3 matrix per lane.
type S3 = LaneSym3<LANES>;

/// One camera's constants, the same for every lane.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LaneCamera {
    /// `R_camera_world`, row-major.
    pub r: [f64; 9],
    /// `t_camera_world`.
    pub t: [f64; 3],
    /// Focal lengths, pixels.
    pub focal: [f64; 2],
}

/// One camera slot's observations, a value per lane.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LaneObs {
    /// Undistorted normalized image coordinates.
    pub x: [f64; LANES],
    pub y: [f64; LANES],
    pub confidence: [f64; LANES],
    /// Lane `l` has a view from this camera.
    pub present: [bool; LANES],
}

impl Default for LaneObs {
    fn default() -> Self {
        Self {
            x: [0.0; LANES],
            y: [0.0; LANES],
            confidence: [0.0; LANES],
            present: [false; LANES],
        }
    }
}

/// What one lane's triangulation came to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum LaneResult {
    /// The scalar triangulator's answer; `used_mask` has a bit per camera slot.
    Done(Triangulated),
    /// Fewer than two usable views (the scalar triangulator's `TooFewViews`).
    TooFewViews(usize),
    /// Off the common path: run the scalar triangulator on this landmark (its answer or error).
    Fallback,
    /// No landmark in this lane.
    Unused,
}

impl RobustTriangulator {
    /// Triangulates the landmarks of lanes `0..lanes` from the observations of each camera slot
    /// (`obs[k]` seen by `cameras[k]`, at most [`MAX_VIEWS`] slots).
    pub(crate) fn triangulate_lanes(
        &self,
        cameras: &[LaneCamera],
        obs: &[LaneObs],
        lanes: usize,
    ) -> [LaneResult; LANES] {
        #[cfg(target_arch = "x86_64")]
        {
            if std::arch::is_x86_feature_detected!("avx2") {
                #[allow(unsafe_code)]
                // SAFETY: the processor has AVX2 (checked just above), the only requirement of
                // a `target_feature(enable = "avx2")` function.
                return unsafe { self.triangulate_lanes_avx2(cameras, obs, lanes) };
            }
        }
        self.triangulate_lanes_body(cameras, obs, lanes)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn triangulate_lanes_avx2(
        &self,
        cameras: &[LaneCamera],
        obs: &[LaneObs],
        lanes: usize,
    ) -> [LaneResult; LANES] {
        self.triangulate_lanes_body(cameras, obs, lanes)
    }

    #[inline(always)]
    #[allow(clippy::too_many_lines)]
    fn triangulate_lanes_body(
        &self,
        cameras: &[LaneCamera],
        obs: &[LaneObs],
        lanes: usize,
    ) -> [LaneResult; LANES] {
        let m = cameras.len().min(obs.len()).min(MAX_VIEWS);
        let (cameras, obs) = (&cameras[..m], &obs[..m]);
        let mut out = [LaneResult::Unused; LANES];
        // The views each lane uses: a bit per slot, and per slot a flag per lane.
        let mut mask = [0u64; LANES];
        let mut uses = [M::NONE; MAX_VIEWS];
        for (k, o) in obs.iter().enumerate() {
            for l in 0..lanes.min(LANES) {
                let c = o.confidence[l];
                if o.present[l]
                    && c >= self.min_confidence
                    && c > 0.0
                    && o.x[l].is_finite()
                    && o.y[l].is_finite()
                {
                    mask[l] |= 1 << k;
                    uses[k].set(l, true);
                }
            }
        }
        // Lanes still on the common path.
        let mut live = M::NONE;
        for l in 0..lanes.min(LANES) {
            let n = mask[l].count_ones() as usize;
            if n < 2 {
                out[l] = LaneResult::TooFewViews(n);
                for u in uses.iter_mut().take(m) {
                    u.set(l, false);
                }
            } else {
                live.set(l, true);
            }
        }
        if !live.any() {
            return out;
        }
        let pixel_terms: [[f64; 2]; MAX_VIEWS] = std::array::from_fn(|k| {
            cameras.get(k).map_or([0.0; 2], |c| {
                let (a, b) = (
                    self.pixel_noise_px / c.focal[0],
                    self.pixel_noise_px / c.focal[1],
                );
                [a * a, b * b]
            })
        });
        let zero = V::splat(0.0);

        // The linear estimate (`linear_estimate`): two rounds.
        let body2 = self.body_noise_m * self.body_noise_m;
        let first_sigma = V::splat(self.body_noise_m.max(1e-3));
        let mut p = [zero; 3];
        for round in 0..2 {
            let mut ata = S3::zero();
            let mut atb = [zero; 3];
            for k in 0..m {
                let use_k = uses[k];
                if !use_k.any() {
                    continue;
                }
                let (cam, o) = (&cameras[k], &obs[k]);
                let r = &cam.r;
                let t = &cam.t;
                let f = 0.5 * (cam.focal[0] + cam.focal[1]);
                let sigma_m = if round == 0 {
                    first_sigma
                } else {
                    let z = V::splat(r[6]) * p[0]
                        + V::splat(r[7]) * p[1]
                        + V::splat(r[8]) * p[2]
                        + V::splat(t[2]);
                    let a = V::splat(self.pixel_noise_px) * z / V::splat(f);
                    z.gt(V::splat(1e-6))
                        .select((a * a + V::splat(body2)).sqrt(), first_sigma)
                };
                let w = Lanes(o.confidence).sqrt() / sigma_m;
                let mut new_ata = ata;
                let mut new_atb = atb;
                for (c, axis) in [(Lanes(o.x), 0usize), (Lanes(o.y), 1usize)] {
                    let row = [
                        (V::splat(r[6]) * c - V::splat(r[axis * 3])) * w,
                        (V::splat(r[7]) * c - V::splat(r[axis * 3 + 1])) * w,
                        (V::splat(r[8]) * c - V::splat(r[axis * 3 + 2])) * w,
                    ];
                    let rhs = -(c * V::splat(t[2]) - V::splat(t[axis])) * w;
                    new_ata.add_outer_unit(row);
                    new_atb = [
                        new_atb[0] + row[0] * rhs,
                        new_atb[1] + row[1] * rhs,
                        new_atb[2] + row[2] * rhs,
                    ];
                }
                ata = S3::select(use_k, &new_ata, &ata);
                for a in 0..3 {
                    atb[a] = use_k.select(new_atb[a], atb[a]);
                }
            }
            let (q, ok) = ata.solve(atb);
            let ok = ok.and(q[0].finite()).and(q[1].finite()).and(q[2].finite());
            live = drop_lanes(live, ok, &mut out, &mut uses[..m]);
            if !live.any() {
                return out;
            }
            p = q;
        }

        // The refinement (`refine`) from the linear estimate. `1/σ` of each view at the start's
        // depth is computed in the first iteration, from the same `z` and `1/z` (`refine`
        // computes them apart, with the same operations).
        let mut inv_sigma = [[zero; 2]; MAX_VIEWS];
        let huber2 = V::splat(self.huber_sigmas * self.huber_sigmas);
        let mut information = S3::zero();
        // Lanes still iterating (a lane stops at its own small step, as the scalar loop breaks).
        let mut active = live;
        for iteration in 0..self.iterations {
            let mut h = S3::zero();
            let mut g = [zero; 3];
            for k in 0..m {
                let use_k = uses[k].and(active);
                if !use_k.any() {
                    continue;
                }
                let (cam, o) = (&cameras[k], &obs[k]);
                let r = cam.r.map(V::splat);
                let pc = project(&cam.r, &cam.t, &p);
                // the scalar loop skips a view with `pc.z <= 1e-9` (and keeps a NaN)
                let take = use_k.and(pc[2].le(V::splat(1e-9)).not());
                let inv_z = V::splat(1.0) / pc[2];
                if iteration == 0 {
                    let at_start = pc[2].gt(V::splat(1e-9)).select(inv_z, V::splat(1.0));
                    let body = V::splat(self.body_noise_m) * at_start;
                    let body2 = body * body;
                    let s2x = V::splat(pixel_terms[k][0]) + body2;
                    let s2y = V::splat(pixel_terms[k][1]) + body2;
                    inv_sigma[k] = [V::splat(1.0) / s2x.sqrt(), V::splat(1.0) / s2y.sqrt()];
                }
                let (u, w) = (pc[0] * inv_z, pc[1] * inv_z);
                let [sx, sy] = inv_sigma[k];
                let (r0, r1) = ((u - Lanes(o.x)) * sx, (w - Lanes(o.y)) * sy);
                let norm2 = r0 * r0 + r1 * r1;
                // Huber's weight where a lane's error is beyond it (most views are not: their
                // square root and division are then skipped; the weight is 1 either way)
                let robust = norm2.gt(huber2);
                let huber = if robust.any() {
                    robust.select(V::splat(self.huber_sigmas) / norm2.sqrt(), V::splat(1.0))
                } else {
                    V::splat(1.0)
                };
                let weight = Lanes(o.confidence) * huber;
                let (ax, ay) = (inv_z * sx, inv_z * sy);
                let j0 = [
                    (r[0] - u * r[6]) * ax,
                    (r[1] - u * r[7]) * ax,
                    (r[2] - u * r[8]) * ax,
                ];
                let j1 = [
                    (r[3] - w * r[6]) * ay,
                    (r[4] - w * r[7]) * ay,
                    (r[5] - w * r[8]) * ay,
                ];
                let mut new_h = h;
                new_h.add_outer(j0, weight);
                new_h.add_outer(j1, weight);
                let (wr0, wr1) = (weight * r0, weight * r1);
                h = S3::select(take, &new_h, &h);
                for a in 0..3 {
                    g[a] = take.select(g[a] + (j0[a] * wr0 + j1[a] * wr1), g[a]);
                }
            }
            let (step, ok) = h.solve(g);
            information = S3::select(active, &h, &information);
            let q = [p[0] - step[0], p[1] - step[1], p[2] - step[2]];
            let ok = ok.and(q[0].finite()).and(q[1].finite()).and(q[2].finite());
            let failed = active.and(ok.not());
            live = drop_lanes(live, failed.not(), &mut out, &mut uses[..m]);
            active = active.and(ok);
            for a in 0..3 {
                p[a] = active.select(q[a], p[a]);
            }
            let small =
                (step[0] * step[0] + step[1] * step[1] + step[2] * step[2]).lt(V::splat(1e-12));
            active = active.and(small.not());
            if !active.any() {
                break;
            }
        }
        if !live.any() {
            return out;
        }

        // No view behind its camera (the scalar cheirality loop drops a view with depth ≤ 0 and
        // starts again; `behind` below, depth ≤ 1e-9 or NaN, covers it) …
        // … and no outlier view (the scalar loop drops the worst and refines again): the first
        // round of the scalar outlier loop, with the pixel error of the views.
        let judge = M::from_fn(|l| mask[l].count_ones() > 2);
        let mut worst = V::splat(-1.0);
        let (mut sq, mut conf) = (zero, zero);
        let mut behind = M::NONE;
        for k in 0..m {
            let use_k = uses[k];
            if !use_k.any() {
                continue;
            }
            let (cam, o) = (&cameras[k], &obs[k]);
            let pc = project(&cam.r, &cam.t, &p);
            let front = pc[2].gt(V::splat(1e-9));
            let ex = pc[0] / pc[2] - Lanes(o.x);
            let ey = pc[1] / pc[2] - Lanes(o.y);
            let (px, py) = (ex * V::splat(cam.focal[0]), ey * V::splat(cam.focal[1]));
            let seen = use_k.and(front);
            sq = seen.select(sq + (px * px + py * py), sq);
            conf = seen.select(conf + Lanes(o.confidence), conf);
            let body = V::splat(self.body_noise_m) * (V::splat(1.0) / pc[2]);
            let body2 = body * body;
            let s2x = V::splat(pixel_terms[k][0]) + body2;
            let s2y = V::splat(pixel_terms[k][1]) + body2;
            let err = judge.select((ex * ex / s2x + ey * ey / s2y).sqrt(), zero);
            let err = front.select(err, V::splat(f64::INFINITY));
            behind = behind.or(use_k.and(front.not()));
            worst = use_k.and(err.gt(worst)).select(err, worst);
        }
        let outlier = judge.and(worst.gt(V::splat(self.outlier_sigmas)));
        let off = outlier.or(behind);
        live = drop_lanes(live, off.not(), &mut out, &mut uses[..m]);

        // The covariance, by nalgebra's 3×3 inverse (`finish`'s `try_inverse`) written out.
        let S3Parts {
            xx,
            xy,
            xz,
            yy,
            yz,
            zz,
        } = information.parts();
        let (m11, m12, m13, m21, m22, m23, m31, m32, m33) = (xx, xy, xz, xy, yy, yz, xz, yz, zz);
        let minor_m12_m23 = m22 * m33 - m32 * m23;
        let minor_m11_m23 = m21 * m33 - m31 * m23;
        let minor_m11_m22 = m21 * m32 - m31 * m22;
        let det = m11 * minor_m12_m23 - m12 * minor_m11_m23 + m13 * minor_m11_m22;
        let cov = [
            minor_m12_m23 / det,
            (m13 * m32 - m33 * m12) / det,
            (m12 * m23 - m22 * m13) / det,
            -minor_m11_m23 / det,
            (m11 * m33 - m31 * m13) / det,
            (m13 * m21 - m23 * m11) / det,
            minor_m11_m22 / det,
            (m12 * m31 - m32 * m11) / det,
            (m11 * m22 - m21 * m12) / det,
        ];
        let trace = cov[0] + cov[4] + cov[8];
        // `trace.max(0.0).sqrt() <= limit` (a NaN trace counts as 0 there, as `f64::max` has it)
        let sigma = trace.gt(zero).select(trace, zero).sqrt();
        let invertible = det.gt(zero).or(det.lt(zero));
        let constrained = invertible.and(sigma.le(V::splat(self.max_position_sigma_m)));
        for l in 0..LANES {
            if !live.get(l) {
                continue;
            }
            if !constrained.get(l) {
                // the scalar triangulator's `Unconstrained` (or `Degenerate`) for this landmark
                out[l] = LaneResult::Fallback;
                continue;
            }
            let n = f64::from(mask[l].count_ones());
            out[l] = LaneResult::Done(Triangulated {
                point: Point3::new(p[0].0[l], p[1].0[l], p[2].0[l]),
                rms_px: (sq.0[l] / n).sqrt(),
                used_mask: mask[l],
                mean_confidence: conf.0[l] / n,
                information: information.lane(l),
                covariance: Matrix3::from_fn(|r, c| cov[3 * r + c].0[l]),
            });
        }
        out
    }
}

/// `R·p + t` per lane, in [`super::camera_coordinates`]' order.
#[inline(always)]
fn project(r: &[f64; 9], t: &[f64; 3], p: &[V; 3]) -> [V; 3] {
    let row = |i: usize| {
        V::splat(r[3 * i]) * p[0]
            + V::splat(r[3 * i + 1]) * p[1]
            + V::splat(r[3 * i + 2]) * p[2]
            + V::splat(t[i])
    };
    [row(0), row(1), row(2)]
}

/// Lanes of `live` where `keep` is false leave the common path: marked [`LaneResult::Fallback`],
/// their views taken out of `uses`. Returns the lanes still live.
#[inline(always)]
fn drop_lanes(live: M, keep: M, out: &mut [LaneResult; LANES], uses: &mut [M]) -> M {
    let mut still = live;
    for l in 0..LANES {
        if live.get(l) && !keep.get(l) {
            out[l] = LaneResult::Fallback;
            still.set(l, false);
            for u in uses.iter_mut() {
                u.set(l, false);
            }
        }
    }
    still
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::PerceptionError;
    use crate::triangulation::NormalizedView;
    use nalgebra::{Vector2, Vector3};
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Eight cameras on a ring 3 m around the origin, looking at (0, 0, 1), focal lengths that differ.
    fn cameras() -> Vec<LaneCamera> {
        (0..8)
            .map(|k| {
                let a = f64::from(k) * 0.8;
                let eye = Vector3::new(3.0 * a.cos(), 3.0 * a.sin(), 1.2 + 0.1 * f64::from(k % 3));
                let z = (Vector3::new(0.0, 0.0, 1.0) - eye).normalize();
                let x = z.cross(&Vector3::z()).normalize();
                let y = z.cross(&x);
                let r = Matrix3::from_rows(&[x.transpose(), y.transpose(), z.transpose()]);
                let t = -(r * eye);
                LaneCamera {
                    r: std::array::from_fn(|i| r[(i / 3, i % 3)]),
                    t: [t.x, t.y, t.z],
                    focal: [700.0 + 40.0 * f64::from(k), 705.0 + 40.0 * f64::from(k)],
                }
            })
            .collect()
    }

    fn view(c: &LaneCamera, x: f64, y: f64, confidence: f64) -> NormalizedView {
        NormalizedView {
            R_camera_world: Matrix3::from_row_slice(&c.r),
            t_camera_world: Vector3::from_row_slice(&c.t),
            normalized: Vector2::new(x, y),
            focal_px: Vector2::new(c.focal[0], c.focal[1]),
            confidence,
        }
    }

    fn same(a: &Triangulated, b: &Triangulated) -> bool {
        let bits = |t: &Triangulated| {
            let mut v: Vec<u64> = t.point.coords.iter().map(|x| x.to_bits()).collect();
            v.extend(t.information.iter().map(|x| x.to_bits()));
            v.extend(t.covariance.iter().map(|x| x.to_bits()));
            v.push(t.rms_px.to_bits());
            v.push(t.mean_confidence.to_bits());
            v
        };
        bits(a) == bits(b)
    }

    /// Every lane's answer is the scalar triangulator's, bit for bit, over landmarks seen by random
    /// subsets of cameras with pixel noise, gross errors, low and invalid confidences, NaNs and
    /// points behind cameras; and most of them stay on the lanes' path.
    #[test]
    fn every_lane_answers_as_the_scalar_triangulator_bit_for_bit() {
        let cams = cameras();
        let tri = RobustTriangulator::default();
        let mut rng = ChaCha8Rng::seed_from_u64(19);
        let (mut done, mut fallback, mut too_few) = (0, 0, 0);
        for _ in 0..400 {
            let lanes = rng.random_range(1..=LANES);
            let mut obs = vec![LaneObs::default(); cams.len()];
            for l in 0..lanes {
                let p = Vector3::new(
                    rng.random_range(-0.5..0.5),
                    rng.random_range(-0.5..0.5),
                    rng.random_range(0.0..2.0),
                );
                // now and then a point far off, behind some cameras
                let p = if rng.random::<f64>() < 0.03 {
                    p * 4.0
                } else {
                    p
                };
                for (k, c) in cams.iter().enumerate() {
                    if rng.random::<f64>() < 0.3 {
                        continue;
                    }
                    let r = Matrix3::from_row_slice(&c.r);
                    let pc = r * p + Vector3::from_row_slice(&c.t);
                    let noise = |rng: &mut ChaCha8Rng, f: f64| {
                        let gross = if rng.random::<f64>() < 0.04 {
                            80.0
                        } else {
                            0.0
                        };
                        (rng.random_range(-3.0..3.0) + rng.random_range(-gross..=gross)) / f
                    };
                    let mut x = pc.x / pc.z + noise(&mut rng, c.focal[0]);
                    let y = pc.y / pc.z + noise(&mut rng, c.focal[1]);
                    if rng.random::<f64>() < 0.01 {
                        x = f64::NAN;
                    }
                    let confidence = match rng.random_range(0..20) {
                        0 => 0.0,
                        1 => 0.01,
                        _ => rng.random_range(0.05..1.0),
                    };
                    obs[k].x[l] = x;
                    obs[k].y[l] = y;
                    obs[k].confidence[l] = confidence;
                    obs[k].present[l] = true;
                }
            }
            let got = tri.triangulate_lanes(&cams, &obs, lanes);
            // the portable build of the lanes (no AVX2) answers alike
            assert_eq!(got, tri.triangulate_lanes_body(&cams, &obs, lanes));
            for (l, result) in got.iter().enumerate() {
                let slots: Vec<usize> = (0..cams.len()).filter(|&k| obs[k].present[l]).collect();
                let views: Vec<NormalizedView> = slots
                    .iter()
                    .map(|&k| view(&cams[k], obs[k].x[l], obs[k].y[l], obs[k].confidence[l]))
                    .collect();
                let want = tri.triangulate(&views);
                match (result, &want) {
                    (LaneResult::Unused, _) => assert!(l >= lanes),
                    (LaneResult::Fallback, _) => fallback += 1,
                    (LaneResult::TooFewViews(n), Err(PerceptionError::TooFewViews { views })) => {
                        assert_eq!(n, views);
                        too_few += 1;
                    }
                    (LaneResult::Done(t), Ok(w)) => {
                        let positions = iter_mask(t.used_mask)
                            .map(|k| 1u64 << slots.iter().position(|&s| s == k).unwrap())
                            .fold(0, |m, b| m | b);
                        assert_eq!(positions, w.used_mask);
                        assert!(same(t, w), "lane {l}: {t:?} vs scalar {w:?}");
                        done += 1;
                    }
                    (r, w) => panic!("lane {l}: {r:?} vs scalar {w:?}"),
                }
            }
        }
        assert!(
            too_few > 0 && fallback > 0,
            "{too_few} too few, {fallback} fallbacks"
        );
        assert!(
            done > 4 * fallback,
            "{done} done on the lanes, {fallback} fallbacks"
        );
    }
}
