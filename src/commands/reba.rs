//! `ergocell reba`: REBA worksheets (Hignett & McAtamney 2000), the whole-body counterpart of
//! `ergocell rula score`.
//!
//! ```text
//! ergocell reba score --input cases.json   JSON array of single-side worksheets → JSON array of breakdowns
//! ```

use std::path::{Path, PathBuf};

use ergocell_ergonomics::reba::{parse_worksheets, score_worksheet, RebaScores};

use super::UsageError;

/// Arguments of `ergocell reba`.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub command: Sub,
}

#[derive(Debug, clap::Subcommand)]
pub enum Sub {
    /// Score single-side worksheets: reads a JSON array, prints a JSON array of breakdowns in order.
    Score {
        /// JSON array of worksheets (fields as in the REBA worksheet, angles in degrees, load in
        /// kilograms, coupling "good" | "fair" | "poor" | "unacceptable").
        #[arg(long)]
        input: PathBuf,
    },
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    match &args.command {
        Sub::Score { input } => score(input),
    }
}

fn score(input: &Path) -> anyhow::Result<()> {
    let text = ergocell::input::read_text(input, ergocell::input::Kind::Data)?;
    let worksheets =
        parse_worksheets(&text).map_err(|e| UsageError(format!("{}: {e}", input.display())))?;
    let out = worksheets
        .iter()
        .enumerate()
        .map(|(index, w)| {
            score_worksheet(w)
                .map_err(|e| UsageError(format!("{}: entry {index}: {e}", input.display())))
        })
        .collect::<Result<Vec<RebaScores>, _>>()?;
    println!("{}", serde_json::to_string_pretty(&out)?);
    Ok(())
}
