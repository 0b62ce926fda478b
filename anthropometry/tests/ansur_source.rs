//! The embedded ANSUR II extract is what the public release in `../shared/data/ansur2` gives.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use ergocell_anthropometry::ansur::{read_public, write_extract, Sex, EXTRACT_CSV};

#[test]
fn the_extract_is_regenerated_from_the_public_release() {
    if ergocell_testdata::skip_without("data/ansur2") {
        return;
    }
    let dir = ergocell_testdata::shared("data/ansur2");
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
