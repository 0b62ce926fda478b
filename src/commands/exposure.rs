//! `ergocell exposure`: many recordings → exposure per operator, day and week, task segment and
//! robot class ([`ergocell_review::exposure`]), and the sessions as Parquet
//! ([`ergocell_review::store`]). Each recording is streamed from its file, one at a
//! time, so a month of shifts needs no more memory than one.

use std::path::{Path, PathBuf};

use anyhow::Context as _;
use ergocell_review::exposure::{ExposureSet, FILES};
use ergocell_review::{exposure_csv, text};

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

/// The files to write into `--out`, checked before any work: `--out` a folder that does not exist yet
/// (or, with `--force`, does), and none of its files a recording.
fn check_outputs(args: &Args, files: &[PathBuf]) -> anyhow::Result<[PathBuf; 4]> {
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
    let outputs = FILES.map(|name| args.out.join(name));
    let inputs: Vec<(&str, &Path)> = files.iter().map(|f| ("recording", f.as_path())).collect();
    for out in &outputs {
        output::check_in_new_folder("--out", out, true, &inputs)?;
    }
    Ok(outputs)
}

/// Reads every recording, one at a time, saying what each held; one that cannot be read is named and
/// left out.
fn read_all(files: &[PathBuf]) -> ExposureSet {
    let mut set = ExposureSet::default();
    for path in files {
        let label = path.display().to_string();
        let read = ergocell::input::open(path)
            .map_err(|e| e.to_string())
            .and_then(|(file, _)| {
                set.read(std::io::BufReader::with_capacity(1 << 20, file), &label)
                    .map_err(|e| e.to_string())
            });
        match read {
            Ok(r) => {
                println!("{}", text::recording_read_line(&label, &r));
                for note in text::recording_notes(&r) {
                    eprintln!("{note}");
                }
            }
            Err(e) => {
                eprintln!("  {label}: left out: {e}");
                set.left_out();
            }
        }
    }
    set
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    let files = recordings(&args.inputs)?;
    let outputs = check_outputs(args, &files)?;
    let set = read_all(&files);
    if set.recordings == 0 {
        return Err(UsageError(format!(
            "none of the {} recording(s) could be read",
            files.len()
        ))
        .into());
    }
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("creating {}", args.out.display()))?;
    output::write(
        "--out",
        &outputs[0],
        true,
        &exposure_csv::groups_csv(&set.table)?,
    )?;
    output::write(
        "--out",
        &outputs[1],
        true,
        &exposure_csv::sessions_csv(&set.rows)?,
    )?;
    let mut parquet = Vec::new();
    ergocell_review::store::write_parquet(&set.rows, &mut parquet)?;
    output::write("--out", &outputs[2], true, &parquet)?;
    output::write("--out", &outputs[3], true, set.page().as_bytes())?;
    let shown = outputs.each_ref().map(|p| p.display().to_string());
    println!("{}", text::exposure_done_line(&set, &shown));
    Ok(())
}
