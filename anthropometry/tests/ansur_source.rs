//! The embedded ANSUR II extract is what the public release in `../shared/data/ansur2` gives.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;

use ergocell_anthropometry::ansur::{read_public, write_extract, Sex, EXTRACT_CSV};

#[test]
fn the_extract_is_regenerated_from_the_public_release() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../shared/data/ansur2");
    if !dir.is_dir() {
        assert!(
            std::env::var_os("CI").is_none(),
            "{}: missing in CI (the shared data must sit beside the repo)",
            dir.display()
        );
        eprintln!("SKIPPED: {} is missing", dir.display());
        return;
    }
    let mut records = Vec::new();
    for (file, sex) in [
        ("ANSUR_II_MALE_Public.csv", Sex::Male),
        ("ANSUR_II_FEMALE_Public.csv", Sex::Female),
    ] {
        let bytes = std::fs::read(dir.join(file)).unwrap();
        records.extend(read_public(&bytes, sex).unwrap());
    }
    assert_eq!(records.len(), 6068);
    assert!(
        write_extract(&records) == EXTRACT_CSV,
        "anthropometry/data/ansur2_standing.csv differs from the public release: regenerate it \
         (cargo run -p ergocell_anthropometry --example ansur_extract -- ../shared/data/ansur2)"
    );
}
