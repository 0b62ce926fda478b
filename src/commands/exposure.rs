//! `ergocell exposure`: many recordings → exposure per operator, day and week, task segment and
//! robot class ([`ergocell_review::exposure`]), and the sessions as Parquet
//! ([`ergocell_review::store`]). Each recording is streamed from its file, one at a
//! time, so a month of shifts needs no more memory than one.

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use anyhow::Context as _;
use ergocell_ergonomics::export::csv_text;
use ergocell_review::exposure::{stream_sessions, ExposureTable, SegmentRow};

use super::{output, UsageError};

#[derive(Debug, clap::Args)]
#[command(
    after_help = "Writes <out>/exposure.csv (one row per operator, day or week, class and \
    task segment; shares of scored time; the same as a page, <out>/exposure.html) and <out>/sessions.csv (one row per session and segment, \
    in seconds, for any engine to add up) and the same rows as <out>/sessions.parquet (for SQL in \
    DuckDB, Spark or Trino). Operators are the recordings' pseudonymous ids; no \
    landmark or angle is written. Exit codes: 0 done (unreadable recordings are named and left out); \
    2 bad input (no recording readable, an existing --out without --force)."
)]
pub struct Args {
    /// Recordings (`.mcap`) or folders searched for them (recursively).
    #[arg(required = true, value_name = "RECORDING_OR_FOLDER")]
    pub inputs: Vec<PathBuf>,
    /// The folder to write into (created; an existing one is refused unless --force).
    #[arg(long, default_value = "exposure")]
    pub out: PathBuf,
    /// Write into an existing --out folder, replacing its files of the same names.
    #[arg(long)]
    pub force: bool,
}

/// The recordings named: files as given, folders searched for `*.mcap`, each sorted by path.
fn recordings(inputs: &[PathBuf]) -> anyhow::Result<Vec<PathBuf>> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> anyhow::Result<()> {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
            .with_context(|| format!("reading the folder {}", dir.display()))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .collect();
        entries.sort();
        for path in entries {
            if path.is_dir() {
                walk(&path, out)?;
            } else if path.extension().is_some_and(|e| e == "mcap") {
                out.push(path);
            }
        }
        Ok(())
    }
    let mut out = Vec::new();
    for input in inputs {
        match std::fs::metadata(input) {
            Ok(m) if m.is_dir() => walk(input, &mut out)?,
            Ok(_) => out.push(input.clone()),
            Err(e) => {
                return Err(UsageError(format!("{}: {e}", input.display())).into());
            }
        }
    }
    if out.is_empty() {
        return Err(UsageError("no .mcap recording in the folders given".to_owned()).into());
    }
    // A recording named twice (a folder and a file in it) counts once.
    let mut seen = std::collections::BTreeSet::new();
    out.retain(|p| seen.insert(std::fs::canonicalize(p).unwrap_or_else(|_| p.clone())));
    Ok(out)
}

fn csv_bytes<T: serde::Serialize>(rows: impl IntoIterator<Item = T>) -> anyhow::Result<Vec<u8>> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for row in rows {
        w.serialize(row)?;
    }
    w.into_inner().context("writing CSV")
}

/// One `exposure.csv` row (shares of scored time, hours).
#[derive(serde::Serialize)]
struct GroupCsv<'a> {
    operator: Cow<'a, str>,
    period: Cow<'a, str>,
    period_start: Cow<'a, str>,
    class: Cow<'a, str>,
    segment: Cow<'a, str>,
    sessions: u32,
    hours: f64,
    rula_scored_hours: f64,
    rula_al1_share: Option<f64>,
    rula_al2_share: Option<f64>,
    rula_al3_share: Option<f64>,
    rula_al4_share: Option<f64>,
    rula_al3plus_share: Option<f64>,
    reba_scored_hours: f64,
    reba_al3plus_share: Option<f64>,
    rula_al3_longest_s: f64,
    peak_grand_score: u8,
    mean_posture_cost: Option<f64>,
    static_holds: u32,
    static_holds_exceeded: u32,
    parts_taken: u32,
}

/// One `sessions.csv` row (seconds).
#[derive(serde::Serialize)]
struct SessionCsv<'a> {
    operator: Cow<'a, str>,
    file: Cow<'a, str>,
    session: u32,
    start_unix_s: f64,
    day: Cow<'a, str>,
    week: Cow<'a, str>,
    class: Cow<'a, str>,
    segment: Cow<'a, str>,
    duration_s: f64,
    rula_scored_s: f64,
    rula_al1_s: f64,
    rula_al2_s: f64,
    rula_al3_s: f64,
    rula_al4_s: f64,
    reba_scored_s: f64,
    reba_al0_s: f64,
    reba_al1_s: f64,
    reba_al2_s: f64,
    reba_al3_s: f64,
    reba_al4_s: f64,
    rula_al3_longest_s: f64,
    peak_grand_score: u8,
    static_holds: u32,
    static_holds_exceeded: u32,
    parts_taken: u32,
    // last, as in the Parquet store
    posture_cost_s: f64,
    posture_cost_point_s: f64,
}

impl<'a> From<&'a SegmentRow> for SessionCsv<'a> {
    fn from(r: &'a SegmentRow) -> Self {
        Self {
            operator: csv_text(r.operator.as_deref().unwrap_or("-")),
            file: csv_text(&r.file),
            session: r.session,
            start_unix_s: r.start_unix_nanos as f64 * 1e-9,
            day: csv_text(&r.day),
            week: csv_text(&r.week),
            class: csv_text(r.class.as_deref().unwrap_or("-")),
            segment: csv_text(&r.segment),
            duration_s: r.duration_s,
            rula_scored_s: r.rula_scored_s,
            rula_al1_s: r.rula_al_s[0],
            rula_al2_s: r.rula_al_s[1],
            rula_al3_s: r.rula_al_s[2],
            rula_al4_s: r.rula_al_s[3],
            reba_scored_s: r.reba_scored_s,
            reba_al0_s: r.reba_al_s[0],
            reba_al1_s: r.reba_al_s[1],
            reba_al2_s: r.reba_al_s[2],
            reba_al3_s: r.reba_al_s[3],
            reba_al4_s: r.reba_al_s[4],
            rula_al3_longest_s: r.rula_al3_longest_s,
            peak_grand_score: r.peak_grand_score,
            posture_cost_s: r.posture_cost_s,
            posture_cost_point_s: r.posture_cost_point_s,
            static_holds: r.static_holds,
            static_holds_exceeded: r.static_holds_exceeded,
            parts_taken: r.parts_taken,
        }
    }
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    let files = recordings(&args.inputs)?;
    match std::fs::metadata(&args.out) {
        Ok(m) if !m.is_dir() => {
            return Err(UsageError(format!(
                "--out {} is a file, not a folder",
                args.out.display()
            ))
            .into())
        }
        Ok(_) if !args.force => {
            return Err(UsageError(format!(
                "--out {}: the folder already exists; pass --force to replace its exposure files, or choose another folder",
                args.out.display()
            ))
            .into())
        }
        _ => {}
    }
    let outputs = [
        "exposure.csv",
        "sessions.csv",
        "sessions.parquet",
        "exposure.html",
    ]
    .map(|name| args.out.join(name));
    let inputs: Vec<(&str, &Path)> = files.iter().map(|f| ("recording", f.as_path())).collect();
    for out in &outputs {
        output::check_in_new_folder("--out", out, true, &inputs)?;
    }

    let mut table = ExposureTable::default();
    let mut rows: Vec<SegmentRow> = Vec::new();
    let (mut read, mut sessions, mut failed) = (0usize, 0u32, 0usize);
    for path in &files {
        let label = path.display().to_string();
        let file = match ergocell::input::open(path) {
            Ok((f, _)) => f,
            Err(e) => {
                eprintln!("  {label}: left out: {e}");
                failed += 1;
                continue;
            }
        };
        let mut each = |row: SegmentRow| {
            table.add(&row);
            rows.push(row);
        };
        match stream_sessions(
            std::io::BufReader::with_capacity(1 << 20, file),
            &label,
            &mut each,
        ) {
            Ok(r) => {
                read += 1;
                sessions += r.sessions;
                println!(
                    "  {label}: {} session(s), {} messages{}",
                    r.sessions,
                    r.stats.messages,
                    if r.stats.complete {
                        ""
                    } else {
                        " (incomplete)"
                    }
                );
                for p in &r.stats.problems {
                    eprintln!("    {p}");
                }
                if r.late_poses > 0 {
                    eprintln!(
                        "    {} operator pose(s) arrived more than {} messages out of capture order and were not read for the task segments",
                        r.late_poses,
                        ergocell_review::exposure::REORDER_WINDOW
                    );
                }
            }
            Err(e) => {
                eprintln!("  {label}: left out: {e}");
                failed += 1;
            }
        }
    }
    if read == 0 {
        return Err(UsageError(format!(
            "none of the {} recording(s) could be read",
            files.len()
        ))
        .into());
    }
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    let groups = csv_bytes(table.groups.iter().map(|(k, g)| GroupCsv {
        operator: csv_text(&k.operator),
        period: csv_text(k.period),
        period_start: csv_text(&k.period_start),
        class: csv_text(&k.class),
        segment: csv_text(&k.segment),
        sessions: g.sessions,
        hours: g.duration_s / 3600.0,
        rula_scored_hours: g.rula_scored_s / 3600.0,
        rula_al1_share: g.rula_level_share(1),
        rula_al2_share: g.rula_level_share(2),
        rula_al3_share: g.rula_level_share(3),
        rula_al4_share: g.rula_level_share(4),
        rula_al3plus_share: g.rula_share(3),
        reba_scored_hours: g.reba_scored_s / 3600.0,
        reba_al3plus_share: g.reba_share(3),
        rula_al3_longest_s: g.rula_al3_longest_s,
        peak_grand_score: g.peak_grand_score,
        mean_posture_cost: g.mean_posture_cost(),
        static_holds: g.static_holds,
        static_holds_exceeded: g.static_holds_exceeded,
        parts_taken: g.parts_taken,
    }))?;
    output::write("--out", &outputs[0], true, &groups)?;
    output::write(
        "--out",
        &outputs[1],
        true,
        &csv_bytes(rows.iter().map(SessionCsv::from))?,
    )?;
    let mut parquet = Vec::new();
    ergocell_review::store::write_parquet(&rows, &mut parquet)?;
    output::write("--out", &outputs[2], true, &parquet)?;
    let html = ergocell_review::exposure::page(&table, read, sessions);
    output::write("--out", &outputs[3], true, html.as_bytes())?;
    println!(
        "exposure: {read} recording(s), {sessions} session(s){}; {} groups → {} (and {}), {} session rows → {} and {}",
        if failed > 0 {
            format!(", {failed} left out")
        } else {
            String::new()
        },
        table.groups.len(),
        outputs[0].display(),
        outputs[3].display(),
        rows.len(),
        outputs[1].display(),
        outputs[2].display()
    );
    Ok(())
}
