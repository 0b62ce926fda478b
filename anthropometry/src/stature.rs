//! Stature from a standing landmark height, fitted on ANSUR II's measured people.
//!
//! A camera sees the ear (BlazePose's ear landmark, nearest the tragion of all its points on the
//! head), the ankles and the floor, never the top of the head. Each model here predicts stature
//! from one standing span with a straight line, `H = intercept + slope · span`, fitted by least
//! squares on the fitting half of [`crate::ansur`] (even subject ids) and judged on the other half
//! (odd ids, never used for fitting): [`StatureModel::residual_sigma_m`] is the standard deviation
//! of `H − prediction` on those people, the model's share of the uncertainty of any estimate it
//! makes (before any measurement error, and before the pose estimator's own offset between its
//! landmark and the anatomical point, which a cell calibrates: `ergocell height calibrate`).
//!
//! The shipped constants ([`FLOOR_TO_EAR`], [`ANKLE_TO_EAR`]) are what [`fit`] returns on the
//! embedded extract; a test refits and compares.

use crate::ansur::{Person, Split};

/// `H = intercept_m + slope · span_m`, with its residual spread on people never fitted.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StatureModel {
    /// What the span is (for reports).
    pub span: Span,
    pub intercept_m: f64,
    pub slope: f64,
    /// Standard deviation of the residual on the reporting half, metres.
    pub residual_sigma_m: f64,
    /// People fitted on and reported on.
    pub fitted_on: usize,
    pub reported_on: usize,
}

/// The standing span a model reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Span {
    /// Ear (tragion) height above the floor.
    FloorToEar,
    /// Ear height above the ankle (lateral malleolus): what a chain of segments measures.
    AnkleToEar,
}

impl Span {
    /// The span of a measured person, metres.
    pub fn of(self, p: &Person) -> f64 {
        match self {
            Span::FloorToEar => p.ear_height_m,
            Span::AnkleToEar => p.ear_height_m - p.ankle_height_m,
        }
    }

    pub const fn name(self) -> &'static str {
        match self {
            Span::FloorToEar => "floor_to_ear",
            Span::AnkleToEar => "ankle_to_ear",
        }
    }
}

impl StatureModel {
    /// The stature of a span, metres.
    pub fn stature_m(&self, span_m: f64) -> f64 {
        self.intercept_m + self.slope * span_m
    }

    /// The span of a stature (the model's inverse): where a body of stature `H` puts the landmark.
    pub fn span_m(&self, stature_m: f64) -> f64 {
        (stature_m - self.intercept_m) / self.slope
    }
}

/// Fits `span`'s model on the fitting half of `people` and measures its residual on the reporting
/// half. `None` when either half has fewer than three people or the spans do not vary.
pub fn fit(people: &[Person], span: Span) -> Option<StatureModel> {
    let (fit_part, report_part): (Vec<&Person>, Vec<&Person>) =
        people.iter().partition(|p| p.split() == Split::Fit);
    if fit_part.len() < 3 || report_part.len() < 3 {
        return None;
    }
    let n = fit_part.len() as f64;
    let mx = fit_part.iter().map(|p| span.of(p)).sum::<f64>() / n;
    let my = fit_part.iter().map(|p| p.stature_m).sum::<f64>() / n;
    let (mut sxy, mut sxx) = (0.0, 0.0);
    for p in &fit_part {
        let dx = span.of(p) - mx;
        sxy += dx * (p.stature_m - my);
        sxx += dx * dx;
    }
    if sxx <= 0.0 {
        return None;
    }
    let slope = sxy / sxx;
    let intercept_m = my - slope * mx;
    let residuals: Vec<f64> = report_part
        .iter()
        .map(|p| p.stature_m - (intercept_m + slope * span.of(p)))
        .collect();
    let m = residuals.iter().sum::<f64>() / residuals.len() as f64;
    let var =
        residuals.iter().map(|r| (r - m).powi(2)).sum::<f64>() / (residuals.len() as f64 - 1.0);
    // The residual's mean on unseen people counts against the model too: root mean square about 0.
    let residual_sigma_m = (var + m * m).sqrt();
    Some(StatureModel {
        span,
        intercept_m,
        slope,
        residual_sigma_m,
        fitted_on: fit_part.len(),
        reported_on: report_part.len(),
    })
}

/// Stature from the ear's height above the floor, ANSUR II (see the module docs).
pub const FLOOR_TO_EAR: StatureModel = StatureModel {
    span: Span::FloorToEar,
    intercept_m: FLOOR_TO_EAR_FIT[0],
    slope: FLOOR_TO_EAR_FIT[1],
    residual_sigma_m: FLOOR_TO_EAR_FIT[2],
    fitted_on: FIT_COUNTS[0],
    reported_on: FIT_COUNTS[1],
};

/// Stature from the ear's height above the ankle, ANSUR II (see the module docs).
pub const ANKLE_TO_EAR: StatureModel = StatureModel {
    span: Span::AnkleToEar,
    intercept_m: ANKLE_TO_EAR_FIT[0],
    slope: ANKLE_TO_EAR_FIT[1],
    residual_sigma_m: ANKLE_TO_EAR_FIT[2],
    fitted_on: FIT_COUNTS[0],
    reported_on: FIT_COUNTS[1],
};

// [intercept_m, slope, residual_sigma_m], as `cargo test -p ergocell_anthropometry -- --nocapture
// print_the_fits` prints them, digit for digit.
#[allow(clippy::unreadable_literal)]
const FLOOR_TO_EAR_FIT: [f64; 3] = [
    0.09391827984515766,
    1.0225945638668101,
    0.006473542204711487,
];
#[allow(clippy::unreadable_literal)]
const ANKLE_TO_EAR_FIT: [f64; 3] = [
    0.07612028138611393,
    1.0813120094705793,
    0.009000493627434897,
];
const FIT_COUNTS: [usize; 2] = [3030, 3038];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ansur::people;

    #[test]
    fn print_the_fits() {
        let people = people().unwrap();
        for span in [Span::FloorToEar, Span::AnkleToEar] {
            let m = fit(&people, span).unwrap();
            println!(
                "{}: [{:?}, {:?}, {:?}] counts [{}, {}]",
                span.name(),
                m.intercept_m,
                m.slope,
                m.residual_sigma_m,
                m.fitted_on,
                m.reported_on
            );
        }
    }

    #[test]
    fn the_shipped_models_are_the_fits() {
        let people = people().unwrap();
        for shipped in [FLOOR_TO_EAR, ANKLE_TO_EAR] {
            let m = fit(&people, shipped.span).unwrap();
            assert_eq!(m, shipped, "{}: refit differs", shipped.span.name());
        }
    }

    #[test]
    fn the_ear_predicts_stature_to_about_7_mm() {
        // SOURCE.md: ear height plus a constant predicts stature to about 6.7 mm (1 σ); a fitted
        // slope may do a little better, never worse; the ankle adds its own spread.
        let people = people().unwrap();
        let ear = fit(&people, Span::FloorToEar).unwrap();
        let chain = fit(&people, Span::AnkleToEar).unwrap();
        assert!(ear.residual_sigma_m < 0.0070, "{ear:?}");
        assert!(ear.residual_sigma_m > 0.0050, "{ear:?}");
        assert!(chain.residual_sigma_m >= ear.residual_sigma_m);
        // A 1.75 m person's ear sits about 13 cm below the vertex.
        let span = ear.span_m(1.75);
        assert!((1.75 - span - 0.130).abs() < 0.004, "{span}");
        assert!((ear.stature_m(span) - 1.75).abs() < 1e-12);
    }

    #[test]
    fn a_fit_needs_people_on_both_sides_of_the_split() {
        let people = people().unwrap();
        let fit_only: Vec<Person> = people
            .iter()
            .filter(|p| p.split() == Split::Fit)
            .copied()
            .collect();
        assert!(fit(&fit_only, Span::FloorToEar).is_none());
        assert!(fit(&[], Span::FloorToEar).is_none());
    }
}
