//! Issue row "panic in `k` on a URDF limit of NaN or lower > upper": every URDF value `k` 0.32's
//! conversion panics on (or silently turns into a NaN frame) is refused by
//! `RobotModel::from_urdf_str` with an error naming the joint and the value, before `k` sees it.

// Test helpers panic on purpose: a panic is the failure report.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use ergocell_robot::{RobotError, RobotModel};

const JOINT_1_LIMIT: &str =
    r#"<limit lower="-2.9670597" upper="2.9670597" velocity="1.4835299" effort="320"/>"#;

fn shipped_urdf() -> String {
    let urdf = common::shipped().urdf;
    assert!(urdf.contains(JOINT_1_LIMIT), "the fixture line moved");
    urdf
}

/// Loads the shipped URDF with joint_1's `<limit>` replaced (the call must return, not panic).
fn with_joint_1_limit(limit: &str) -> Result<RobotModel, RobotError> {
    let urdf = shipped_urdf().replacen(JOINT_1_LIMIT, limit, 1);
    RobotModel::from_urdf_str(&urdf, "link_0", "flange")
}

fn assert_names(err: &RobotError, joint: &str, value: &str) {
    let text = err.to_string();
    assert!(
        text.contains(&format!("`{joint}`")) && text.contains(value),
        "expected joint `{joint}` and value {value} in: {text}"
    );
}

#[test]
fn panic_in_k_on_a_urdf_limit_of_nan_or_lower_above_upper() {
    for (limit, value) in [
        (
            r#"<limit lower="-2.9670597" upper="NaN" velocity="1.4835299" effort="320"/>"#,
            "upper = NaN",
        ),
        (
            r#"<limit lower="nan" upper="2.9670597" velocity="1.4835299" effort="320"/>"#,
            "lower = NaN",
        ),
        (
            r#"<limit lower="2.9670597" upper="-2.9670597" velocity="1.4835299" effort="320"/>"#,
            "lower = 2.9670597",
        ),
        (
            r#"<limit lower="-inf" upper="inf" velocity="1.4835299" effort="320"/>"#,
            "lower = -inf",
        ),
        (
            r#"<limit lower="-2.9670597" upper="2.9670597" velocity="NaN" effort="320"/>"#,
            "velocity limit = NaN",
        ),
        (
            r#"<limit lower="-2.9670597" upper="2.9670597" velocity="1.4835299" effort="-1"/>"#,
            "effort limit = -1",
        ),
        (
            r#"<limit lower="-2.9670597" upper="2.9670597" velocity="inf" effort="320"/>"#,
            "velocity limit = inf",
        ),
    ] {
        let err = with_joint_1_limit(limit).unwrap_err();
        assert!(
            matches!(err, RobotError::InvalidLimit { ref joint, .. } if joint == "joint_1"),
            "{limit}: {err}"
        );
        assert_names(&err, "joint_1", value);
    }
}

#[test]
fn panic_in_k_on_a_bad_limit_of_a_joint_off_the_arm_chain() {
    // `k` converts every joint of the file, so a fixed joint's (or a side branch's) limit panics too.
    let urdf = shipped_urdf().replacen(
        r#"<origin xyz="0 0 0.045" rpy="0 0 0"/>
  </joint>"#,
        r#"<origin xyz="0 0 0.045" rpy="0 0 0"/>
    <limit lower="1" upper="0" velocity="0" effort="0"/>
  </joint>"#,
        1,
    );
    assert!(urdf.contains(r#"<limit lower="1" upper="0""#));
    let err = RobotModel::from_urdf_str(&urdf, "link_0", "flange").unwrap_err();
    assert!(
        matches!(err, RobotError::InvalidLimit { ref joint, .. } if joint == "joint_flange"),
        "{err}"
    );
    // And a side branch that is not between base and flange.
    let urdf = shipped_urdf().replacen(
        "</robot>",
        r#"<link name="camera_mount"/>
  <joint name="mount" type="revolute"><parent link="link_0"/><child link="camera_mount"/>
    <limit lower="NaN" upper="1" velocity="1" effort="1"/></joint>
</robot>"#,
        1,
    );
    let err = RobotModel::from_urdf_str(&urdf, "link_0", "flange").unwrap_err();
    assert_names(&err, "mount", "lower = NaN");
}

#[test]
fn panic_in_k_guards_nan_origins_and_zero_or_nan_axes() {
    let urdf = shipped_urdf();
    let origin = r#"<origin xyz="0 0 0.1575" rpy="0 0 0"/>"#;
    assert!(urdf.contains(origin));
    for (replacement, value) in [
        (r#"<origin xyz="0 NaN 0.1575" rpy="0 0 0"/>"#, "origin xyz"),
        (r#"<origin xyz="0 0 0.1575" rpy="0 inf 0"/>"#, "origin rpy"),
    ] {
        let err =
            RobotModel::from_urdf_str(&urdf.replacen(origin, replacement, 1), "link_0", "flange")
                .unwrap_err();
        assert!(matches!(err, RobotError::UnsupportedUrdf { .. }), "{err}");
        assert_names(&err, "joint_1", value);
    }
    let axis = r#"<axis xyz="0 0 1"/>"#;
    for (replacement, value) in [
        (r#"<axis xyz="0 0 0"/>"#, "not a direction"),
        (r#"<axis xyz="0 NaN 1"/>"#, "non-finite value NaN"),
    ] {
        let err =
            RobotModel::from_urdf_str(&urdf.replacen(axis, replacement, 1), "link_0", "flange")
                .unwrap_err();
        assert_names(&err, "joint_1", value);
    }
}

#[test]
fn panic_in_k_guards_ambiguous_names_and_missing_mimic_leaders() {
    let urdf = shipped_urdf();
    // Two joints called joint_2: our limit lookup and `k` would pick different ones.
    let twice = urdf.replacen(r#"<joint name="joint_3""#, r#"<joint name="joint_2""#, 1);
    let err = RobotModel::from_urdf_str(&twice, "link_0", "flange").unwrap_err();
    assert_names(&err, "joint_2", "more than once");
    // link_2 the child of two joints.
    let two_parents = urdf.replacen(
        "</robot>",
        r#"<joint name="extra" type="fixed"><parent link="link_0"/><child link="link_2"/></joint>
</robot>"#,
        1,
    );
    let err = RobotModel::from_urdf_str(&two_parents, "link_0", "flange").unwrap_err();
    assert_names(&err, "extra", "link `link_2`");
    let mimic = urdf.replacen(
        JOINT_1_LIMIT,
        &format!(r#"{JOINT_1_LIMIT}<mimic joint="nowhere"/>"#),
        1,
    );
    let err = RobotModel::from_urdf_str(&mimic, "link_0", "flange").unwrap_err();
    assert_names(&err, "joint_1", "nowhere");
}

#[test]
fn panic_in_k_guards_leave_the_shipped_urdf_and_equal_limits_alone() {
    // The committed URDF still loads unchanged (its bytes, and so the locks, are untouched).
    let s = common::shipped();
    assert_eq!(s.model.dof(), 7);
    // lower == upper is legal URDF (k drops the range); the arm itself still refuses it by name.
    let err =
        with_joint_1_limit(r#"<limit lower="0.5" upper="0.5" velocity="1.4835299" effort="320"/>"#)
            .unwrap_err();
    assert_names(&err, "joint_1", "lower 0.5 / upper 0.5");
}

/// A chain of links `depth` deep, each the child of the one before.
fn chain_urdf(depth: usize) -> String {
    use std::fmt::Write as _;
    let mut urdf = String::from("<robot name=\"deep\">\n<link name=\"l0\"/>\n");
    for i in 1..=depth {
        writeln!(
            urdf,
            "<link name=\"l{i}\"/>\n<joint name=\"j{i}\" type=\"fixed\"><parent link=\"l{}\"/><child link=\"l{i}\"/></joint>",
            i - 1
        )
        .unwrap();
    }
    urdf.push_str("</robot>\n");
    urdf
}

/// A URDF whose chain is 50,000 links deep used to overflow the stack in `k`'s recursive tree
/// building (SIGABRT): now it is refused with the count, and one at the limit still loads.
#[test]
fn a_urdf_chain_fifty_thousand_links_deep_is_refused_not_a_stack_overflow() {
    let err = RobotModel::from_urdf_str(&chain_urdf(50_000), "l0", "l50000").unwrap_err();
    assert!(matches!(err, RobotError::UnsupportedUrdf { .. }), "{err}");
    assert!(err.to_string().contains("at most 1000"), "{err}");
    // At the limit it parses (and fails only for want of a moving joint, not by crashing).
    let at_limit = RobotModel::from_urdf_str(&chain_urdf(999), "l0", "l999");
    if let Err(e) = at_limit {
        assert!(!e.to_string().contains("at most 1000"), "{e}");
    }
}

/// 50,000 nested unknown elements (350 KB) used to overflow the stack inside urdf-rs's recursive
/// reader (exit 134) before any check ran: the nesting is now bounded before it reads.
#[test]
fn a_urdf_nested_fifty_thousand_elements_deep_is_refused_not_a_stack_overflow() {
    let n = 50_000;
    let urdf = format!(
        "<robot name=\"deep\"><link name=\"l0\"/>{}{}</robot>",
        "<unknown>".repeat(n),
        "</unknown>".repeat(n)
    );
    let err = RobotModel::from_urdf_str(&urdf, "l0", "l0").unwrap_err();
    assert!(matches!(err, RobotError::UnsupportedUrdf { .. }), "{err}");
    // The shipped arm nests well within the bound.
    let shipped = include_str!("../../config/robots/iiwa14_r820.urdf");
    assert!(ergocell_nesting::check(shipped, ergocell_nesting::MAX_XML_DEPTH).is_ok());
}
