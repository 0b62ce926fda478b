//! What the robot can serve, said at start-up before anyone is measured: the classes whose locked
//! trajectory verifies now (with who approved it), and those that do not, grouped by why.

use super::TrajectoryProvider;

/// At start-up: the classes whose locked trajectory verifies now (with who approved it), and those
/// that do not, whose operators the robot will not serve.
#[derive(Debug, PartialEq)]
pub struct ApprovalSummary {
    /// The classes that run, with who approved each.
    pub approved: Vec<(ergocell_robot::TrajectoryClass, Vec<String>)>,
    /// The classes that cannot run, and why in a few words.
    pub refused: Vec<(ergocell_robot::TrajectoryClass, ergocell_approvals::Refusal)>,
}

impl ApprovalSummary {
    /// Every class asked of `provider`, in order.
    pub fn of(provider: &mut dyn TrajectoryProvider) -> Self {
        let mut out = Self {
            approved: Vec::new(),
            refused: Vec::new(),
        };
        for class in ergocell_robot::TrajectoryClass::ALL {
            match provider.verify(class) {
                Ok(a) => out.approved.push((
                    class,
                    a.approvals()
                        .iter()
                        .map(|x| x.approved_by.clone())
                        .collect(),
                )),
                Err(e) => out.refused.push((class, e.refusal())),
            }
        }
        out
    }
}

impl std::fmt::Display for ApprovalSummary {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let approved: Vec<String> = self
            .approved
            .iter()
            .map(|(class, by)| format!("{class} (approved by {})", by.join(", ")))
            .collect();
        // The refused classes grouped by why: "c1, c2, c3: not approved (…)".
        let mut why: Vec<(ergocell_approvals::Refusal, Vec<String>)> = Vec::new();
        for (class, refusal) in &self.refused {
            match why.iter_mut().find(|(r, _)| r == refusal) {
                Some((_, classes)) => classes.push(class.to_string()),
                None => why.push((*refusal, vec![class.to_string()])),
            }
        }
        let why = why
            .iter()
            .map(|(r, classes)| format!("{}: {r}", classes.join(", ")))
            .collect::<Vec<_>>()
            .join("; ");
        match (approved.is_empty(), self.refused.is_empty()) {
            (_, true) => write!(f, "robot: every class is approved: {}", approved.join(", ")),
            (true, false) => write!(
                f,
                "robot: no class can run, the robot will not move for any operator: {why} \
                 (`ergocell trajectories verify` says more)"
            ),
            (false, false) => write!(
                f,
                "robot: {}; the robot will not move for an operator of {why} \
                 (`ergocell trajectories verify` says more)",
                approved.join(", "),
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::session::ProviderError;
    use ergocell_robot::{ApprovedTrajectory, TrajectoryClass};

    /// A cell whose approvals are all missing.
    struct Unapproved(Vec<TrajectoryClass>);

    impl TrajectoryProvider for Unapproved {
        fn verify(&mut self, class: TrajectoryClass) -> Result<ApprovedTrajectory, ProviderError> {
            self.0.push(class);
            Err(ProviderError::NotVerified {
                failure: ergocell_robot::lock::VerifyFailure {
                    class,
                    problems: vec![ergocell_robot::RobotError::NotApproved {
                        class: class.to_string(),
                        lock_sha256: String::new(),
                        detail: "no approvals file".to_owned(),
                    }],
                },
                witness: None,
            })
        }
        fn stature_bounds_m(&mut self, _: TrajectoryClass) -> Result<(f64, f64), ProviderError> {
            Ok((1.5, 2.0))
        }
    }

    #[test]
    fn refused_classes_are_grouped_by_their_reason() {
        use ergocell_approvals::Refusal;
        let summary = ApprovalSummary {
            approved: vec![(TrajectoryClass::C2, vec!["alice@plant.example".to_owned()])],
            refused: vec![
                (TrajectoryClass::C1, Refusal::NotApproved),
                (TrajectoryClass::C3, Refusal::NotApproved),
            ],
        };
        assert_eq!(
            summary.to_string(),
            format!(
                "robot: c2 (approved by alice@plant.example); the robot will not move for an \
                 operator of c1, c3: {} (`ergocell trajectories verify` says more)",
                Refusal::NotApproved
            )
        );
        let none = ApprovalSummary {
            approved: Vec::new(),
            refused: vec![
                (TrajectoryClass::C1, Refusal::NotApproved),
                (TrajectoryClass::C2, Refusal::RolledBack),
                (TrajectoryClass::C3, Refusal::NotApproved),
            ],
        };
        assert_eq!(
            none.to_string(),
            format!(
                "robot: no class can run, the robot will not move for any operator: c1, c3: {}; \
                 c2: {} (`ergocell trajectories verify` says more)",
                Refusal::NotApproved,
                Refusal::RolledBack
            )
        );
    }

    #[test]
    fn every_class_is_asked_and_the_unapproved_are_named() {
        let mut cell = Unapproved(Vec::new());
        let summary = ApprovalSummary::of(&mut cell);
        assert_eq!(cell.0, TrajectoryClass::ALL.to_vec());
        assert_eq!(
            summary,
            ApprovalSummary {
                approved: Vec::new(),
                refused: TrajectoryClass::ALL
                    .iter()
                    .map(|&c| (c, ergocell_approvals::Refusal::NotApproved))
                    .collect(),
            }
        );
    }
}
