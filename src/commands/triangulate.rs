//! `ergocell triangulate`: 2D detections + calibration → 3D landmarks file and a summary.

/// Arguments of `ergocell triangulate`.
#[derive(Debug, clap::Args)]
pub struct Args {}

pub fn run(_args: &Args) -> anyhow::Result<()> {
    anyhow::bail!("not yet wired")
}
