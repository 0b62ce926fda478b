//! How RULA agreement depends on the detector: the sessions of a `rula-agreement` run again at other
//! pixel-noise levels ([`NOISE_SWEEP_PX`]), everything else (rig, seed, operators, the detector's
//! other noise) unchanged.
//!
//! `ergocell sim rula-agreement` adds the sweep to its result: a row per level in its JSON
//! ([`rows`]), a line per level in its text ([`crate::report::noise_sweep_text`]) and a figure
//! ([`crate::report::noise_sweep_figure`]). It lives here, beside [`super::rula_agreement_with`],
//! so that the binary only prints and writes what it returns. Pure: values in, values out.

use serde::Serialize;

use super::{rula_agreement_with, Handovers, RulaAgreement, Setup};
use crate::detector::DetectorNoise;
use crate::SimError;

/// Pixel-noise levels of the RULA-agreement sweep, pixels.
pub const NOISE_SWEEP_PX: [f64; 6] = [0.5, 1.0, 2.0, 3.0, 4.0, 6.0];

/// `setup` with the detector's pixel noise σ set to `noise_px` and nothing else changed.
fn at_noise(setup: &Setup, noise_px: f64) -> Setup {
    Setup {
        noise: DetectorNoise {
            pixel_sigma_px: noise_px,
            ..setup.noise
        },
        ..setup.clone()
    }
}

/// RULA agreement ([`rula_agreement_with`], the same operators, cycles and fixed lag) at each level
/// of [`NOISE_SWEEP_PX`], in that order: `(σ px, agreement)`.
pub fn sweep(
    setup: &Setup,
    handovers: &Handovers,
    statures_m: &[f64],
    cycles: usize,
    fixed_lag_s: Option<f64>,
) -> Result<Vec<(f64, RulaAgreement)>, SimError> {
    NOISE_SWEEP_PX
        .iter()
        .map(|&noise_px| {
            let a = rula_agreement_with(
                &at_noise(setup, noise_px),
                handovers,
                statures_m,
                cycles,
                fixed_lag_s,
                &mut |_, _| {},
            )?;
            Ok((noise_px, a))
        })
        .collect()
}

/// One score's exact agreement and Cohen's κ.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ExactKappa {
    pub exact: f64,
    pub kappa: f64,
}

/// One level of the sweep as the result's JSON holds it (`noise_sweep`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SweepRow {
    pub noise_px: f64,
    pub grand_score: ExactKappa,
    pub action_level: ExactKappa,
}

/// The sweep's rows, one per level in the sweep's order.
pub fn rows(sweep: &[(f64, RulaAgreement)]) -> Vec<SweepRow> {
    sweep
        .iter()
        .map(|(noise_px, a)| SweepRow {
            noise_px: *noise_px,
            grand_score: ExactKappa {
                exact: a.grand_score.exact,
                kappa: a.grand_score.kappa,
            },
            action_level: ExactKappa {
                exact: a.action_level.exact,
                kappa: a.action_level.kappa,
            },
        })
        .collect()
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::experiments::Agreement;
    use crate::{ring_rig, RingRigConfig};

    /// A RULA agreement with these grand-score and action-level figures (the rest empty).
    pub(crate) fn agreement(grand: [f64; 2], level: [f64; 2]) -> RulaAgreement {
        let score = |[exact, kappa]: [f64; 2]| Agreement {
            exact,
            kappa,
            confusion: Vec::new(),
        };
        RulaAgreement {
            fixed_lag_s: None,
            grand_score: score(grand),
            action_level: score(level),
            region_names: Vec::new(),
            region_exact: Vec::new(),
            region_mean_difference: Vec::new(),
            region_confusion: Vec::new(),
            grand_differs_with_regions_equal: 0,
            frames: 0,
            uncertain_frames: 0,
            grand_exact_uncertain: f64::NAN,
            grand_exact_certain: f64::NAN,
            warnings_per_min: 0.0,
            true_warnings_per_min: 0.0,
            warnings_raised: 0,
            true_warnings_raised: 0,
            minutes: 0.0,
            true_warnings_caught: 0,
            warnings_confirmed: 0,
            statures_m: Vec::new(),
        }
    }

    #[test]
    fn a_level_changes_the_pixel_noise_only() {
        let setup = Setup {
            rig: ring_rig(2, &RingRigConfig::default()).unwrap(),
            noise: DetectorNoise {
                pixel_sigma_px: 3.0,
                ear_offset_m: 0.02,
                ..DetectorNoise::default()
            },
            seed: 9,
        };
        let s = at_noise(&setup, 0.5);
        assert_eq!(s.noise.pixel_sigma_px, 0.5);
        assert_eq!(
            DetectorNoise {
                pixel_sigma_px: 3.0,
                ..s.noise
            },
            setup.noise
        );
        assert_eq!((s.seed, s.rig.len()), (9, 2));
    }

    #[test]
    fn each_level_is_a_row_with_its_own_figures_in_order() {
        let sweep = [
            (0.5, agreement([0.9, 0.8], [0.95, 0.85])),
            (6.0, agreement([0.5, 0.4], [0.7, 0.6])),
        ];
        let r = rows(&sweep);
        assert_eq!(r.len(), 2);
        assert_eq!(r[1].noise_px, 6.0);
        assert_eq!((r[0].grand_score.exact, r[0].grand_score.kappa), (0.9, 0.8));
        assert_eq!(
            (r[1].action_level.exact, r[1].action_level.kappa),
            (0.7, 0.6)
        );
        // the JSON's keys, as the result has always held them
        let v = serde_json::to_value(r[0]).unwrap();
        assert_eq!(
            v,
            serde_json::json!({
                "noise_px": 0.5,
                "grand_score": {"exact": 0.9, "kappa": 0.8},
                "action_level": {"exact": 0.95, "kappa": 0.85},
            })
        );
    }

    #[test]
    fn the_levels_rise_from_half_a_pixel_and_hold_the_default() {
        assert!(NOISE_SWEEP_PX.windows(2).all(|w| w[0] < w[1]));
        assert!(NOISE_SWEEP_PX.contains(&DetectorNoise::default().pixel_sigma_px));
    }
}
