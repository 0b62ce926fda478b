//! ANSUR II: the measured body dimensions of 6,068 adults, the real spread of body proportions
//! between people.
//!
//! # Source
//! Gordon, C. C., Blackwell, C. L., Bradtmiller, B., et al. (2014). *2012 Anthropometric Survey of
//! U.S. Army Personnel: Methods and Summary Statistics*. Technical Report NATICK/TR-15/007, U.S.
//! Army Natick Soldier Research, Development and Engineering Center; the public release
//! (`ANSUR_II_MALE_Public.csv`, `ANSUR_II_FEMALE_Public.csv`), a work of the U.S. Government.
//!
//! # What is kept
//! The crate embeds an extract of the public release ([`EXTRACT_CSV`], `data/ansur2_standing.csv`):
//! per person the subject id, sex and the standing dimensions a camera can see, in millimetres as
//! published. `cargo run -p ergocell_anthropometry --example ansur_extract -- <ansur2 folder>`
//! regenerates it from the two public files, and a test checks that it still does.
//!
//! | field | ANSUR II column(s) | landmark |
//! |---|---|---|
//! | stature | `stature` | vertex |
//! | ear height | `stature − tragiontopofhead` | tragion (the ear canal's notch) |
//! | eye height | `stature − (sittingheight − eyeheightsitting)` | ectocanthus (the head's eye-to-vertex span, measured seated) |
//! | shoulder height | `acromialheight` | acromion |
//! | hip height | `trochanterionheight` | greater trochanter |
//! | knee height | `lateralfemoralepicondyleheight` | lateral femoral epicondyle |
//! | ankle height | `lateralmalleolusheight` | lateral malleolus |
//! | upper arm | `acromionradialelength` | acromion to radiale |
//! | forearm | `radialestylionlength` | radiale to stylion |
//! | hand, foot | `handlength`, `footlength` | |
//!
//! A military population (ages 17–58, fit): use it for the spread of proportions between people,
//! and say so when quoting a population share.
//!
//! # The split
//! Whoever fits a model on these people and reports on them splits by subject id
//! ([`Split::of`]): even ids fit, odd ids report.

use thiserror::Error;

/// The embedded extract (see the module docs), millimetres.
pub const EXTRACT_CSV: &str = include_str!("../data/ansur2_standing.csv");

/// The extract's header, in order.
pub const EXTRACT_HEADER: [&str; 14] = [
    "subjectid",
    "sex",
    "stature",
    "tragiontopofhead",
    "sittingheight",
    "eyeheightsitting",
    "acromialheight",
    "trochanterionheight",
    "lateralfemoralepicondyleheight",
    "lateralmalleolusheight",
    "acromionradialelength",
    "radialestylionlength",
    "handlength",
    "footlength",
];

/// A person's sex as recorded.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Sex {
    Female,
    Male,
}

impl Sex {
    fn code(self) -> &'static str {
        match self {
            Sex::Female => "F",
            Sex::Male => "M",
        }
    }
}

/// Which part of the people a person belongs to: fitting or reporting.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Split {
    /// Even subject ids: models are fitted and tuned on these.
    Fit,
    /// Odd subject ids: figures are reported on these, never used for fitting.
    Report,
}

impl Split {
    /// The split of a subject id.
    pub fn of(subject_id: u32) -> Self {
        if subject_id.is_multiple_of(2) {
            Split::Fit
        } else {
            Split::Report
        }
    }
}

/// One measured person, millimetres as published (see the module docs for the columns).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Record {
    pub subject_id: u32,
    pub sex: Sex,
    /// The 12 dimensions of [`EXTRACT_HEADER`] after `subjectid` and `sex`, in that order.
    pub mm: [u32; 12],
}

/// One person's standing dimensions, metres (derived from a [`Record`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Person {
    pub subject_id: u32,
    pub sex: Sex,
    pub stature_m: f64,
    pub ear_height_m: f64,
    pub eye_height_m: f64,
    pub shoulder_height_m: f64,
    pub hip_height_m: f64,
    pub knee_height_m: f64,
    pub ankle_height_m: f64,
    pub upper_arm_m: f64,
    pub forearm_m: f64,
    pub hand_m: f64,
    pub foot_m: f64,
}

impl Person {
    /// The split this person belongs to.
    pub fn split(&self) -> Split {
        Split::of(self.subject_id)
    }
}

/// Why a file could not be read as ANSUR II.
#[derive(Debug, Error)]
pub enum AnsurError {
    #[error("ANSUR II CSV: {0}")]
    Csv(#[from] csv::Error),
    #[error("ANSUR II CSV: no column `{0}` in the header")]
    MissingColumn(&'static str),
    #[error(
        "ANSUR II CSV, line {line}: `{column}` = {value:?} is not a whole number of millimetres"
    )]
    BadValue {
        line: u64,
        column: &'static str,
        value: String,
    },
    #[error("ANSUR II CSV, line {line}: sex {value:?} is neither M nor F")]
    BadSex { line: u64, value: String },
    #[error(
        "ANSUR II CSV, line {line} (subject {subject_id}): {what} — not a standing adult as measured"
    )]
    Implausible {
        line: u64,
        subject_id: u32,
        what: String,
    },
    #[error("ANSUR II CSV: subject id {0} appears twice")]
    DuplicateSubject(u32),
    #[error("ANSUR II CSV: no people")]
    Empty,
}

fn column(headers: &csv::ByteRecord, name: &'static str) -> Result<usize, AnsurError> {
    headers
        .iter()
        .position(|h| h.eq_ignore_ascii_case(name.as_bytes()))
        .ok_or(AnsurError::MissingColumn(name))
}

fn number(
    record: &csv::ByteRecord,
    index: usize,
    line: u64,
    column: &'static str,
) -> Result<u32, AnsurError> {
    let raw = record.get(index).unwrap_or_default();
    std::str::from_utf8(raw)
        .ok()
        .and_then(|s| s.trim().parse::<u32>().ok())
        .ok_or_else(|| AnsurError::BadValue {
            line,
            column,
            value: String::from_utf8_lossy(raw).into_owned(),
        })
}

/// Reads CSV bytes with the extract's columns (by name, in any order, among others). `sex`: the
/// sex of every row when the file has no `sex` column (the public release is one file per sex).
fn read(bytes: &[u8], sex: Option<Sex>) -> Result<Vec<Record>, AnsurError> {
    let mut reader = csv::ReaderBuilder::new().from_reader(bytes);
    let headers = reader.byte_headers()?.clone();
    let id = column(&headers, "subjectid")?;
    // Every row's sex: fixed for the file, or read from its column.
    let sex_of: Result<Sex, usize> = match sex {
        Some(s) => Ok(s),
        None => Err(column(&headers, "sex")?),
    };
    let mut cols = [0usize; 12];
    for (k, name) in EXTRACT_HEADER[2..].iter().enumerate() {
        cols[k] = column(&headers, name)?;
    }
    let mut out = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for row in reader.byte_records() {
        let row = row?;
        let line = row.position().map_or(0, csv::Position::line);
        let subject_id = number(&row, id, line, "subjectid")?;
        let sex = match sex_of {
            Ok(s) => s,
            Err(c) => match row.get(c).unwrap_or_default() {
                b"F" => Sex::Female,
                b"M" => Sex::Male,
                other => {
                    return Err(AnsurError::BadSex {
                        line,
                        value: String::from_utf8_lossy(other).into_owned(),
                    })
                }
            },
        };
        let mut mm = [0u32; 12];
        for (k, c) in cols.iter().enumerate() {
            mm[k] = number(&row, *c, line, EXTRACT_HEADER[k + 2])?;
        }
        if !seen.insert(subject_id) {
            return Err(AnsurError::DuplicateSubject(subject_id));
        }
        let record = Record {
            subject_id,
            sex,
            mm,
        };
        record.check(line)?;
        out.push(record);
    }
    if out.is_empty() {
        return Err(AnsurError::Empty);
    }
    Ok(out)
}

impl Record {
    /// Standing heights must fall from the vertex to the ankle, and every dimension be an adult's.
    fn check(&self, line: u64) -> Result<(), AnsurError> {
        let [stature, tragion_top, sitting, eye_sitting, shoulder, hip, knee, ankle, ..] = self.mm;
        let bad = |what: String| AnsurError::Implausible {
            line,
            subject_id: self.subject_id,
            what,
        };
        if !(1200..=2300).contains(&stature) {
            return Err(bad(format!("stature {stature} mm")));
        }
        if tragion_top == 0 || tragion_top >= 300 || eye_sitting >= sitting || sitting >= stature {
            return Err(bad(format!(
                "head spans tragion–vertex {tragion_top} mm, sitting height {sitting} mm, eye height sitting {eye_sitting} mm"
            )));
        }
        let ear = stature - tragion_top;
        let eye = stature - (sitting - eye_sitting);
        let falling = [ear.min(eye), shoulder, hip, knee, ankle];
        if !falling.windows(2).all(|w| w[0] > w[1]) || ankle == 0 {
            return Err(bad(format!(
                "standing heights do not fall from head to ankle (ear {ear}, eye {eye}, shoulder {shoulder}, hip {hip}, knee {knee}, ankle {ankle} mm)"
            )));
        }
        if self.mm[8..].contains(&0) {
            return Err(bad("a segment length of 0 mm".to_owned()));
        }
        Ok(())
    }

    /// The person's dimensions in metres.
    pub fn person(&self) -> Person {
        let m = |mm: u32| f64::from(mm) * 1e-3;
        let [stature, tragion_top, sitting, eye_sitting, shoulder, hip, knee, ankle, upper_arm, forearm, hand, foot] =
            self.mm;
        Person {
            subject_id: self.subject_id,
            sex: self.sex,
            stature_m: m(stature),
            ear_height_m: m(stature) - m(tragion_top),
            eye_height_m: m(stature) - (m(sitting) - m(eye_sitting)),
            shoulder_height_m: m(shoulder),
            hip_height_m: m(hip),
            knee_height_m: m(knee),
            ankle_height_m: m(ankle),
            upper_arm_m: m(upper_arm),
            forearm_m: m(forearm),
            hand_m: m(hand),
            foot_m: m(foot),
        }
    }
}

/// Reads one file of the public release (`ANSUR_II_MALE_Public.csv` or
/// `ANSUR_II_FEMALE_Public.csv`, Latin-1 bytes); every row is of `sex`.
pub fn read_public(bytes: &[u8], sex: Sex) -> Result<Vec<Record>, AnsurError> {
    read(bytes, Some(sex))
}

/// Reads the extract's format ([`EXTRACT_HEADER`]).
pub fn read_extract(text: &str) -> Result<Vec<Record>, AnsurError> {
    read(text.as_bytes(), None)
}

/// Writes records in the extract's format, sorted by subject id.
pub fn write_extract(records: &[Record]) -> String {
    let mut sorted = records.to_vec();
    sorted.sort_by_key(|r| r.subject_id);
    let mut out = EXTRACT_HEADER.join(",");
    out.push('\n');
    for r in &sorted {
        out.push_str(&r.subject_id.to_string());
        out.push(',');
        out.push_str(r.sex.code());
        for v in r.mm {
            out.push(',');
            out.push_str(&v.to_string());
        }
        out.push('\n');
    }
    out
}

/// The embedded people, metres, sorted by subject id.
pub fn people() -> Result<Vec<Person>, AnsurError> {
    Ok(read_extract(EXTRACT_CSV)?
        .iter()
        .map(Record::person)
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_embedded_extract_holds_the_survey() {
        let people = people().unwrap();
        assert_eq!(people.len(), 6068);
        let women = people.iter().filter(|p| p.sex == Sex::Female).count();
        assert_eq!(women, 1986);
        // SOURCE.md's pooled facts: stature 1714 ± 90 mm, tragion to vertex 129.6 ± 6.7 mm.
        let n = people.len() as f64;
        let mean = |f: &dyn Fn(&Person) -> f64| people.iter().map(f).sum::<f64>() / n;
        let sd = |f: &dyn Fn(&Person) -> f64| {
            let m = mean(f);
            (people.iter().map(|p| (f(p) - m).powi(2)).sum::<f64>() / (n - 1.0)).sqrt()
        };
        assert!((mean(&|p| p.stature_m) - 1.714).abs() < 0.001);
        assert!((sd(&|p| p.stature_m) - 0.090).abs() < 0.001);
        let head = |p: &Person| p.stature_m - p.ear_height_m;
        assert!((mean(&head) - 0.1296).abs() < 0.0001);
        assert!((sd(&head) - 0.0067).abs() < 0.0001);
        // Both parts of the split are large and of both sexes.
        for split in [Split::Fit, Split::Report] {
            let part: Vec<_> = people.iter().filter(|p| p.split() == split).collect();
            assert!(part.len() > 2500, "{split:?}: {}", part.len());
            assert!(part.iter().filter(|p| p.sex == Sex::Female).count() > 800);
        }
    }

    #[test]
    fn the_extract_round_trips() {
        let records = read_extract(EXTRACT_CSV).unwrap();
        assert_eq!(write_extract(&records), EXTRACT_CSV);
    }

    #[test]
    fn bad_files_are_refused_with_the_reason() {
        let header = EXTRACT_HEADER.join(",");
        let row = "10027,M,1776,131,936,822,1467,922,551,73,337,270,206,274";
        assert!(read_extract(&format!("{header}\n{row}\n")).is_ok());
        let e = read_extract(&format!("{header}\n{row}\n{row}\n")).unwrap_err();
        assert!(matches!(e, AnsurError::DuplicateSubject(10027)), "{e}");
        let e = read_extract(&format!("{header}\n")).unwrap_err();
        assert!(matches!(e, AnsurError::Empty), "{e}");
        let e = read_extract(&format!("{header}\n{}\n", row.replace(",M,", ",X,"))).unwrap_err();
        assert!(e.to_string().contains("neither M nor F"), "{e}");
        let e = read_extract(&format!("{header}\n{}\n", row.replace("1776", "17.76"))).unwrap_err();
        assert!(e.to_string().contains("`stature`"), "{e}");
        // Millimetres read as metres would be refused as a stature.
        let e = read_extract(&format!("{header}\n{}\n", row.replace("1776", "2"))).unwrap_err();
        assert!(e.to_string().contains("stature 2 mm"), "{e}");
        // A knee above the hip.
        let e =
            read_extract(&format!("{header}\n{}\n", row.replace(",551,", ",951,"))).unwrap_err();
        assert!(e.to_string().contains("do not fall"), "{e}");
        let e = read_extract("subjectid,sex\n1,M\n").unwrap_err();
        assert!(matches!(e, AnsurError::MissingColumn("stature")), "{e}");
    }
}
