//! What a suite command did with its runs: how many it reused (and which revisions made them),
//! how many it simulated, and what a real re-run would cost — so a main job that reused every
//! run says so instead of looking like a finished simulation.

use crate::output::run_info::RunInfo;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// The runs of a suite command, counted.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RunTally {
    /// Runs that were finished before the command and reused.
    pub reused: usize,
    /// Runs the command simulated (or resumed).
    pub simulated: usize,
    /// The simulated runs' wall time [s].
    pub simulated_s: f64,
    /// The reused runs' own wall times, as their records state them [s].
    pub reused_cost_s: f64,
    /// Revisions that made the reused runs, with their counts.
    pub reused_revisions: BTreeMap<String, usize>,
}

impl RunTally {
    /// Counts the run saved in `dir` (its `run_info.json`); `reused` if it was finished before
    /// the command. A run without a readable record counts with no wall time.
    pub fn add(&mut self, dir: &Path, reused: bool) {
        let info = RunInfo::read(dir).ok();
        let wall = info.as_ref().map_or(0.0, |i| i.wall_time_s);
        if reused {
            self.reused += 1;
            self.reused_cost_s += wall;
            let rev = info.map_or_else(|| "unknown".to_string(), |i| i.git_revision);
            *self.reused_revisions.entry(rev).or_insert(0) += 1;
        } else {
            self.simulated += 1;
            self.simulated_s += wall;
        }
    }

    /// One paragraph for the terminal.
    pub fn describe(&self) -> String {
        let mut s = format!(
            "runs: {} simulated ({}), {} reused",
            self.simulated,
            hours(self.simulated_s),
            self.reused
        );
        if self.reused > 0 {
            let revs: Vec<String> = self
                .reused_revisions
                .iter()
                .map(|(r, n)| format!("{n} by {r}"))
                .collect();
            let _ = write!(
                s,
                " (made by revision: {}; their own wall times add up to {} of one thread — \
                 `--force` simulates them again)",
                revs.join(", "),
                hours(self.reused_cost_s)
            );
        }
        s
    }
}

/// A duration in the largest unit that keeps it readable.
fn hours(seconds: f64) -> String {
    if seconds >= 3600.0 {
        format!("{:.1} h", seconds / 3600.0)
    } else if seconds >= 60.0 {
        format!("{:.0} min", seconds / 60.0)
    } else {
        format!("{seconds:.0} s")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_command_that_reused_everything_says_so_and_what_a_rerun_costs() {
        let t = RunTally {
            reused: 82,
            reused_cost_s: 5.8 * 3600.0,
            reused_revisions: [("8fba23b325b4".to_string(), 82)].into(),
            ..RunTally::default()
        };
        let s = t.describe();
        assert!(s.starts_with("runs: 0 simulated (0 s), 82 reused"), "{s}");
        assert!(
            s.contains("82 by 8fba23b325b4") && s.contains("5.8 h"),
            "{s}"
        );
        let fresh = RunTally {
            simulated: 3,
            simulated_s: 125.0,
            ..RunTally::default()
        };
        assert_eq!(fresh.describe(), "runs: 3 simulated (2 min), 0 reused");
    }

    #[test]
    fn a_missing_record_counts_without_cost() {
        let mut t = RunTally::default();
        t.add(Path::new("/nonexistent/run"), true);
        assert_eq!(t.reused, 1);
        assert_eq!(t.reused_cost_s, 0.0);
        assert_eq!(t.reused_revisions.get("unknown"), Some(&1));
    }
}
