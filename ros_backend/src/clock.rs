//! The wall clock at the ROS boundary. The core and the simulator take time from their caller; this
//! is where the cell PC's clock is read.

/// Wall-clock time, nanoseconds since the Unix epoch (camera stamps are ROS time).
#[allow(clippy::disallowed_methods)]
pub fn now_nanos() -> i64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| i64::try_from(d.as_nanos()).unwrap_or(i64::MAX))
}

/// Monotonic instant for latency measurements.
#[allow(clippy::disallowed_methods)]
pub fn instant() -> std::time::Instant {
    std::time::Instant::now()
}

/// The session's clock: the wall clock read once at start, advanced by the monotonic clock.
/// Everything the session times — stale cameras, hold, resume and departure bounds, the height
/// timeout, `--max-secs`, the recording's log times and the stamps ergocell publishes — runs on it,
/// so a step of the system clock during a session (an NTP correction, someone setting the time) moves
/// none of them: the step is noticed on the next tick and reported once, and the session goes on as
/// if nothing happened. (The cameras' stamps are their own clock's: a camera whose clock steps is
/// handled by the staleness and fusion windows, which compare arrival times on this clock.)
#[derive(Debug, Clone)]
pub struct SessionClock {
    wall0_nanos: i64,
    mono0: std::time::Instant,
    /// The wall clock minus this clock when last reported (0 at start).
    reported_offset_nanos: i64,
}

/// A wall clock that departs from the session clock by more than this since the last report is a step.
pub const WALL_STEP_NANOS: i64 = 1_000_000_000;

impl SessionClock {
    pub fn start() -> Self {
        Self::anchored(now_nanos(), instant())
    }

    pub fn anchored(wall0_nanos: i64, mono0: std::time::Instant) -> Self {
        Self {
            wall0_nanos,
            mono0,
            reported_offset_nanos: 0,
        }
    }

    /// Nanoseconds since the Unix epoch, on the session's monotonic time line.
    pub fn now(&self) -> i64 {
        let elapsed = i64::try_from(self.mono0.elapsed().as_nanos()).unwrap_or(i64::MAX);
        self.wall0_nanos.saturating_add(elapsed)
    }

    /// The step of the wall clock (`wall_nanos`, read at session time `now`) since the last one
    /// reported, in nanoseconds, when it exceeds [`WALL_STEP_NANOS`]; then it is the new reference.
    pub fn wall_step(&mut self, wall_nanos: i64, now: i64) -> Option<i64> {
        let offset = wall_nanos.saturating_sub(now);
        let step = offset.saturating_sub(self.reported_offset_nanos);
        (step.abs() > WALL_STEP_NANOS).then(|| {
            self.reported_offset_nanos = offset;
            step
        })
    }
}
#[cfg(test)]
mod tests {
    use super::SessionClock;

    #[test]
    fn session_clock_reports_each_wall_clock_step_once_and_ignores_drift() {
        let mono0 = super::instant();
        let mut clock = SessionClock::anchored(1_000_000_000_000, mono0);
        let now = clock.now();
        assert!(now >= 1_000_000_000_000);
        // Drift under a second: not a step.
        assert_eq!(clock.wall_step(now + 400_000_000, now), None);
        // One hour forward: reported once, then the new reference.
        let hour = 3_600_000_000_000;
        assert_eq!(clock.wall_step(now + hour, now), Some(hour));
        assert_eq!(clock.wall_step(now + hour + 200_000_000, now), None);
        // Back by ten minutes from there.
        assert_eq!(
            clock.wall_step(now + hour - 600_000_000_000, now),
            Some(-600_000_000_000)
        );
        // The session clock never went back, whatever the wall clock did.
        assert!(clock.now() >= now);
    }
}
