//! Regenerates `anthropometry/data/ansur2_standing.csv` from ANSUR II's public release:
//!
//! ```text
//! cargo run -p ergocell_anthropometry --example ansur_extract -- ../shared/data/ansur2 > anthropometry/data/ansur2_standing.csv
//! ```

use std::path::PathBuf;

use ergocell_anthropometry::ansur::{read_public, write_extract, Sex};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(
        std::env::args()
            .nth(1)
            .ok_or("usage: ansur_extract <folder with ANSUR_II_{MALE,FEMALE}_Public.csv>")?,
    );
    let mut records = Vec::new();
    for (file, sex) in [
        ("ANSUR_II_MALE_Public.csv", Sex::Male),
        ("ANSUR_II_FEMALE_Public.csv", Sex::Female),
    ] {
        let path = dir.join(file);
        let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        records.extend(read_public(&bytes, sex).map_err(|e| format!("{}: {e}", path.display()))?);
    }
    print!("{}", write_extract(&records));
    Ok(())
}
