//! The front door's figures are the committed runs' own. The README and the user guide say how
//! many standard-fidelity runs `reports/` holds, what they cost (their own wall times, in all
//! and on one thread) and how many of the suite's runs are not made yet; this test computes the
//! same from the suite's plan and the runs' records, so a run added or re-made without updating
//! the text fails here instead of leaving a stale figure at the door.

use std::path::Path;
use verify::output::run_info::RunInfo;
use verify::plan::suite_tasks;
use verify::run::{saved, Saved};
use verify::suite::Fidelity;

/// The suite's standard runs as `reports/` holds them: (finished as `verify all` reuses them, their wall time [h], of it on
/// one thread [h], not finished).
fn committed() -> (usize, f64, f64, usize) {
    let reports = Path::new(env!("CARGO_MANIFEST_DIR")).join("../reports");
    let (_, tasks) = suite_tasks(Fidelity::Standard, &[], &[], false).unwrap();
    let (mut done, mut all_s, mut one_s, mut missing) = (0, 0.0, 0.0, 0);
    for t in &tasks {
        let dir = reports.join(&t.dir);
        // finished as `verify all` reuses it: this scene's run, completed or failed (a result)
        match (saved(&dir, &t.scene), RunInfo::read(&dir)) {
            (Saved::Finished, Ok(info)) => {
                done += 1;
                all_s += info.wall_time_s;
                if info.threads == 1 {
                    one_s += info.wall_time_s;
                }
            }
            _ => missing += 1,
        }
    }
    (done, all_s / 3600.0, one_s / 3600.0, missing)
}

/// The text of a document with its line breaks and runs of spaces made single spaces.
fn flat(doc: &str) -> String {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(doc)).unwrap();
    text.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The number written right before `after` in `text` (the first occurrence; one space between).
fn number_before(text: &str, after: &str) -> f64 {
    let at = text
        .find(after)
        .unwrap_or_else(|| panic!("the text no longer says {after:?}"));
    let head = text[..at].trim_end();
    let start = head
        .rfind(|c: char| !(c.is_ascii_digit() || c == '.'))
        .map_or(0, |i| i + 1);
    head[start..]
        .parse()
        .unwrap_or_else(|_| panic!("no number before {after:?}"))
}

/// The number written right after `before` in `text` (the first occurrence).
fn number_after(text: &str, before: &str) -> f64 {
    let at = text
        .find(before)
        .unwrap_or_else(|| panic!("the text no longer says {before:?}"));
    let rest = &text[at + before.len()..];
    let end = rest
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(rest.len());
    rest[..end]
        .parse()
        .unwrap_or_else(|_| panic!("no number after {before:?}"))
}

#[test]
fn the_readme_and_the_user_guide_state_the_committed_runs_and_their_cost() {
    let (done, hours, one_thread, missing) = committed();
    // the documents round hours to 0.1 h: half of it, and a little for the rounding of the sum
    let close = |stated: f64, measured: f64| (stated - measured).abs() <= 0.051;
    let readme = flat("../README.md");
    assert_eq!(
        number_before(&readme, "committed runs took") as usize,
        done,
        "README: the count of committed runs"
    );
    let tail = &readme[readme.find("committed runs took").unwrap()..];
    let (took, took_one) = (number_after(tail, "took "), number_after(tail, " h ("));
    assert!(
        close(took, hours) && close(took_one, one_thread),
        "README states {took} h ({took_one} h on one thread); reports/ holds {hours:.2} h \
         ({one_thread:.2} h)"
    );
    let not_run = number_after(&readme, "not run yet: ");
    assert_eq!(
        not_run as usize, missing,
        "README: the count of the suite's runs not made yet"
    );
    let guide = flat("../docs/user-guide.md");
    let count = number_before(&guide, "committed runs' own wall times");
    let tail = &guide[guide.find("committed runs' own wall times").unwrap()..];
    let (cost, cost_one) = (number_after(tail, "times, "), number_after(tail, " h, "));
    assert!(
        count as usize == done && close(cost, hours) && close(cost_one, one_thread),
        "user guide states {count} runs, {cost} h ({cost_one} h on one thread); reports/ \
         holds {done}, {hours:.2} h ({one_thread:.2} h)"
    );
}
