//! Quality measures of a 3D reconstruction that need no ground truth.
//!
//! - **Bone-length variation**: bones are rigid, so the length of each bone over a recording should
//!   not change. For each bone of [`ergocell_skeleton::BONES`] the coefficient of variation
//!   (standard deviation / mean, over the frames where both ends are observed) is computed; the
//!   recording's figure is the mean over bones, in percent.
//! - **Reprojection error**: the median over all fused landmarks of their RMS pixel error.

use ergocell_skeleton::{Landmark, Skeleton3, BONES};

/// Per-bone length statistics over a recording.
#[derive(Debug, Clone, PartialEq)]
pub struct BoneStats {
    pub bone: (Landmark, Landmark),
    pub frames: usize,
    pub mean_m: f64,
    /// Coefficient of variation, percent.
    pub cv_percent: f64,
}

/// A bone: its two end landmarks.
pub type Bone = (Landmark, Landmark);

/// Length statistics of every bone (bones seen in fewer than 2 frames are left out).
pub fn bone_stats(frames: &[Skeleton3]) -> Vec<BoneStats> {
    BONES
        .iter()
        .filter_map(|&(a, b)| {
            let lengths: Vec<f64> = frames
                .iter()
                .filter_map(|s| s.bone_length_m(a, b))
                .collect();
            if lengths.len() < 2 {
                return None;
            }
            let n = lengths.len() as f64;
            let mean = lengths.iter().sum::<f64>() / n;
            let var = lengths.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / (n - 1.0);
            (mean > 0.0).then(|| BoneStats {
                bone: (a, b),
                frames: lengths.len(),
                mean_m: mean,
                cv_percent: 100.0 * var.sqrt() / mean,
            })
        })
        .collect()
}

/// Mean over bones of the bone-length coefficient of variation, percent (`None` when no bone was
/// seen in two frames).
pub fn bone_length_variation_percent(frames: &[Skeleton3]) -> Option<f64> {
    let stats = bone_stats(frames);
    (!stats.is_empty())
        .then(|| stats.iter().map(|s| s.cv_percent).sum::<f64>() / stats.len() as f64)
}

/// Bone-length variation of several reconstructions of the same recording, compared fairly: the
/// mean is taken over the bones that **every** reconstruction observed (a method that never sees
/// the lower legs must not look better for leaving out the hardest bones). Returns the bones used and
/// one mean per reconstruction (`None` when no bone is common to all).
pub fn common_bone_variation_percent(recordings: &[&[Skeleton3]]) -> Option<(Vec<Bone>, Vec<f64>)> {
    let stats: Vec<Vec<BoneStats>> = recordings.iter().map(|r| bone_stats(r)).collect();
    let common: Vec<Bone> = BONES
        .iter()
        .copied()
        .filter(|bone| stats.iter().all(|st| st.iter().any(|b| b.bone == *bone)))
        .collect();
    if common.is_empty() {
        return None;
    }
    let means = stats
        .iter()
        .map(|st| {
            let used: Vec<f64> = st
                .iter()
                .filter(|b| common.contains(&b.bone))
                .map(|b| b.cv_percent)
                .collect();
            used.iter().sum::<f64>() / used.len() as f64
        })
        .collect();
    Some((common, means))
}

/// Median of a list (`None` when empty); NaNs are ignored.
pub fn median(values: &[f64]) -> Option<f64> {
    let mut v: Vec<f64> = values.iter().copied().filter(|x| !x.is_nan()).collect();
    if v.is_empty() {
        return None;
    }
    v.sort_by(f64::total_cmp);
    let m = v.len() / 2;
    Some(if v.len().is_multiple_of(2) {
        0.5 * (v[m - 1] + v[m])
    } else {
        v[m]
    })
}

/// Median reprojection error (pixels) over every fused landmark of a recording.
pub fn median_reprojection_px(frames: &[Skeleton3]) -> Option<f64> {
    let errors: Vec<f64> = frames
        .iter()
        .flat_map(|s| {
            s.slots()
                .iter()
                .flatten()
                .filter_map(|e| e.reprojection_error_px)
        })
        .collect();
    median(&errors)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Point3;

    #[test]
    fn rigid_bones_have_zero_variation_and_stretching_shows() {
        let mut frames = Vec::new();
        for k in 0..10 {
            let pts = std::array::from_fn(|i| Point3::new(i as f64 * 0.1 + k as f64, 0.0, 0.0));
            frames.push(Skeleton3::from_points(k, &pts).unwrap());
        }
        assert!(bone_length_variation_percent(&frames).unwrap() < 1e-9);
        let mut stretched = Vec::new();
        for k in 0..10 {
            let s = 1.0 + 0.1 * (k % 2) as f64;
            let pts = std::array::from_fn(|i| Point3::new(i as f64 * 0.1 * s, 0.0, 0.0));
            stretched.push(Skeleton3::from_points(k, &pts).unwrap());
        }
        let cv = bone_length_variation_percent(&stretched).unwrap();
        // lengths alternate L and 1.1 L: CV = 0.05 / 1.05 · sqrt(10/9) ≈ 5.02 %
        assert!(
            (cv - 100.0 * 0.05 / 1.05 * (10.0_f64 / 9.0).sqrt()).abs() < 1e-9,
            "{cv}"
        );
        assert_eq!(bone_length_variation_percent(&[]), None);
    }

    #[test]
    fn median_of_even_and_odd_lists() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), Some(2.0));
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), Some(2.5));
        assert_eq!(median(&[f64::NAN]), None);
    }
}
