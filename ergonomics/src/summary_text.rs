//! The text of a session's summary, as `ergocell rula track` prints it under the frames: time per
//! action level, the posture cost beside RULA, REBA's levels, each body region's scores, exposure
//! stretches, ISO 11226's static postures, the task segments and the warnings raised. A layout of
//! [`SessionSummary`]'s facts, nothing computed here; no I/O (the caller prints it).

use std::fmt::Write as _;

use crate::assess::BodyRegion;
use crate::rula::action_level_meaning;
use crate::static_posture::STATIC_MIN_SECS;
use crate::summary::{Exposure, SessionSummary};
use crate::warnings::{WarningEvent, WarningKind};
use crate::Side;

/// The summary of `rula track` as text: time shares, regions, exposure, static postures, task
/// segments, warnings per region (`t0`: the first frame's stamp).
pub fn session_text(s: &SessionSummary, events: &[WarningEvent], t0: i64) -> String {
    let mut out = String::new();
    out.push('\n');
    let _ = writeln!(
        out,
        "summary: {} frames over {:.2} s, {} scored, {} uncertain, unscored {:.1}% of the time",
        s.frames,
        s.duration_secs,
        s.scored_frames,
        s.uncertain_frames,
        s.unscored_share * 100.0
    );
    let _ = writeln!(out, "time share per action level (worse side):");
    for (k, share) in s.action_level_share.iter().enumerate() {
        let level = k as u8 + 1;
        let _ = writeln!(
            out,
            "  level {level} ({:<34}) {:5.1}%",
            action_level_meaning(level),
            share * 100.0
        );
    }
    if let Some(cost) = s.posture_cost.mean() {
        let _ = writeln!(out,
            "posture cost beside RULA (worse side, the grand score plus how far the angles lie into \
             their bands): mean {cost:.3} over {:.1} s",
            s.posture_cost.secs
        );
    }
    if !s.reba_score.is_empty() {
        let _ = writeln!(
            out,
            "REBA beside RULA: time share per REBA action level (worse side):"
        );
        for (level, share) in s.reba_action_level_share.iter().enumerate() {
            let (risk, action) = crate::reba::risk(level as u8);
            let _ = writeln!(
                out,
                "  level {level} ({risk}, action {action:<20}) {:5.1}%",
                share * 100.0
            );
        }
    }
    let _ = writeln!(out, "time share per body region score:");
    for r in &s.regions {
        let name = match r.side {
            Some(Side::Left) => format!("left {}", r.region.name()),
            Some(Side::Right) => format!("right {}", r.region.name()),
            None => r.region.name().to_owned(),
        };
        let shares: Vec<String> = r
            .share_by_score
            .iter()
            .map(|(score, share)| format!("{score}: {:.1}%", share * 100.0))
            .collect();
        let _ = writeln!(out, "  {name:<16} {}", shares.join("  "));
    }
    let _ =
        writeln!(out,
        "exposure over time (stretches at or above a level; a gap or an unscored frame ends one):"
    );
    let mut line = |name: &str, e: &[Exposure]| {
        let parts: Vec<String> = e
            .iter()
            .filter(|x| x.episodes > 0)
            .map(|x| {
                format!(
                    ">={}: {} episode(s), longest {:.1} s, {:.1} s in all",
                    x.at_least, x.episodes, x.longest_secs, x.total_secs
                )
            })
            .collect();
        if !parts.is_empty() {
            let _ = writeln!(out, "  {name:<16} {}", parts.join("; "));
        }
    };
    line("action level", &s.action_level_exposure);
    line("REBA level", &s.reba_action_level_exposure);
    for r in &s.regions {
        let name = match r.side {
            Some(Side::Left) => format!("left {}", r.region.name()),
            Some(Side::Right) => format!("right {}", r.region.name()),
            None => r.region.name().to_owned(),
        };
        line(&name, &r.exposure);
    }
    if !s.static_postures.is_empty() {
        let _ = writeln!(out,
            "static postures (ISO 11226: held > {STATIC_MIN_SECS} s outside the acceptable zone; trunk 20°–60° for at most 4 min at 20° down to 1 min at 60°, beyond 60° or extended (unless the task's trunk is supported) not acceptable; neck beyond 25° or extended not acceptable; upper arm beyond 60° not acceptable, 20°–60° time-limited by a curve no readable source gives):"
        );
        for p in &s.static_postures {
            let worst = p
                .holds
                .iter()
                .filter(|h| h.exceeded)
                .max_by(|a, b| a.duration_secs.total_cmp(&b.duration_secs));
            let _ = writeln!(out,
                "  {:<15} {} static hold(s), {} not acceptable, {} with no known limit (for the ergonomist), longest {:.1} s{}",
                p.part.name(),
                p.static_holds,
                p.exceeded,
                p.limit_unknown,
                p.longest_secs,
                worst.map_or(String::new(), |h| {
                    let why = match h.limit_secs {
                        Some(l) if h.not_acceptable_secs <= STATIC_MIN_SECS => {
                            format!("longer than the {l:.0} s allowed at its largest angle")
                        }
                        _ => format!(
                            "{:.1} s of it in a zone not acceptable at any duration",
                            h.not_acceptable_secs
                        ),
                    };
                    format!(
                        "; worst: {:.1} s from {:.1} s, up to {:.0}°: {why}",
                        h.duration_secs,
                        h.start_nanos.saturating_sub(t0) as f64 * 1e-9,
                        h.peak_deg,
                    )
                })
            );
        }
    }
    if !s.phases.is_empty() {
        let _ = writeln!(
            out,
            "task segments (from the skeleton: walking, floor pick, in place):"
        );
        for p in &s.phases {
            let levels: Vec<String> = p
                .action_level_share
                .iter()
                .enumerate()
                .map(|(k, x)| format!("AL{} {:.0}%", k + 1, x * 100.0))
                .collect();
            let _ =
                writeln!(out,
                "  {:<10} {:6.1} s ({:4.1}% of the time, {} episode(s)); {}; peak grand score {}",
                p.phase,
                p.duration_secs,
                p.time_share * 100.0,
                p.episodes,
                levels.join(" "),
                p.peak_grand_score.map_or("-".to_owned(), |x| x.to_string())
            );
        }
    }
    let raised: Vec<String> = BodyRegion::ALL
        .iter()
        .map(|region| {
            let n = events
                .iter()
                .filter(|e| e.region == *region && e.kind == WarningKind::Raised)
                .count();
            format!("{} {n}", region.name())
        })
        .collect();
    let _ = writeln!(out, "warnings raised per region: {}", raised.join(", "));
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::summary::{SummaryBuilder, DEFAULT_MAX_FRAME_NANOS};

    fn event(kind: WarningKind, region: BodyRegion) -> WarningEvent {
        WarningEvent {
            stamp_nanos: 0,
            kind,
            region,
            side: None,
            region_score: 3,
            angle_deg: None,
            action_level: 2,
            uncertain: false,
            band_probability: None,
            near_limit: false,
            message: String::new(),
        }
    }

    #[test]
    fn only_raised_warnings_are_counted_per_region() {
        let s = SummaryBuilder::new(DEFAULT_MAX_FRAME_NANOS).finish();
        let events = [
            event(WarningKind::Raised, BodyRegion::Trunk),
            event(WarningKind::Changed, BodyRegion::Trunk),
            event(WarningKind::Raised, BodyRegion::Trunk),
            event(WarningKind::Cleared, BodyRegion::Neck),
            event(WarningKind::Raised, BodyRegion::Wrist),
        ];
        let text = session_text(&s, &events, 0);
        assert_eq!(
            text.lines().last(),
            Some("warnings raised per region: upper_arm 0, lower_arm 0, wrist 1, neck 0, trunk 2, legs 0")
        );
        // Nothing scored: no posture cost, REBA, static postures or task segments to lay out.
        assert_eq!(
            text.lines()
                .filter(|l| l.starts_with("posture cost"))
                .count(),
            0
        );
    }
}
