//! The suite's summaries: `summary.md` (what a reviewer reads first), `summary.csv`
//! (machine-readable results, also the regression baseline format; the same bits for the same
//! revision) and `costs.csv` (each metric's run's wall time), from every case measured so far.

use super::known_misses;
use crate::suite::compare::{self, summary_csv, Baseline, Regression};
use crate::suite::{runner, Case, Fidelity, Metric};
use std::fmt::Write as _;
use std::path::Path;

/// Rewrites `OUT/summary.md`, `OUT/summary.csv` and `OUT/costs.csv` from every one of `cases` measured so far
/// under `out`; with a baseline, also compares and returns the regressions.
pub fn write_all(
    out: &Path,
    fidelity: Fidelity,
    cases: &[Box<dyn Case>],
    baseline: Option<Baseline>,
) -> anyhow::Result<Option<Vec<Regression>>> {
    let metrics = runner::saved_metrics(out, cases)?;
    let regressions = match baseline {
        Some(b) => Some(compare::compare(&metrics, b)?),
        None => None,
    };
    summary_csv::write(&out.join("summary.csv"), &metrics)?;
    summary_csv::write_costs(&out.join("costs.csv"), &metrics)?;
    write_markdown(
        &out.join("summary.md"),
        fidelity,
        cases,
        &metrics,
        regressions.as_deref(),
    )?;
    Ok(regressions)
}

/// A number with 4 significant digits (or a dash).
pub fn sig(v: f64) -> String {
    if !v.is_finite() {
        return if v.is_nan() {
            "—".into()
        } else {
            format!("{v}")
        };
    }
    if v == 0.0 {
        return "0".into();
    }
    let mag = v.abs().log10().floor() as i32;
    if (-3..5).contains(&mag) {
        let decimals = (3 - mag).max(0) as usize;
        format!("{v:.decimals$}")
    } else {
        format!("{v:.3e}")
    }
}

fn sig_opt(v: Option<f64>) -> String {
    v.map(sig).unwrap_or_else(|| "—".into())
}

/// Writes `summary.md`: the tally and regressions, then per case its source, effects,
/// resolution, a table of metrics, their notes and links to its plots.
fn write_markdown(
    path: &Path,
    fidelity: Fidelity,
    cases: &[Box<dyn Case>],
    metrics: &[Metric],
    regressions: Option<&[Regression]>,
) -> anyhow::Result<()> {
    let mut s = String::new();
    let out = path.parent().unwrap_or(Path::new("."));
    header(&mut s, fidelity, metrics, regressions);
    overview(&mut s, cases, metrics);
    provenance(&mut s, &run_revisions(out, fidelity, cases));
    for case in cases {
        let ms: Vec<&Metric> = metrics.iter().filter(|m| m.case == case.name()).collect();
        case_section(&mut s, case.as_ref(), fidelity, &ms, out);
    }
    crate::output::atomic_write(path, s.as_bytes())?;
    Ok(())
}

/// How many of `cases`' runs saved under `out` each revision of the code made (from their
/// `run_info.json`), in order of revision.
fn run_revisions(
    out: &Path,
    fidelity: Fidelity,
    cases: &[Box<dyn Case>],
) -> std::collections::BTreeMap<String, usize> {
    let mut revs = std::collections::BTreeMap::new();
    for case in cases {
        for spec in case.runs(fidelity) {
            let dir = out.join(case.name()).join(&spec.id);
            if let Ok(info) = crate::output::run_info::RunInfo::read(&dir) {
                *revs.entry(info.git_revision).or_insert(0) += 1;
            }
        }
    }
    revs
}

/// Which revisions made the runs reported, and whether that is one clean revision.
fn provenance(s: &mut String, revs: &std::collections::BTreeMap<String, usize>) {
    let list: Vec<String> = revs.iter().map(|(r, n)| format!("`{r}` ({n})")).collect();
    let clean = revs.len() == 1 && revs.keys().all(|r| !r.contains('-') && r != "unknown");
    let verdict = if revs.is_empty() {
        "no run records found".to_string()
    } else if clean {
        "all by one clean revision".to_string()
    } else {
        "**not one clean revision**: a dirty tree or several revisions; `verify all --force` \
         re-runs every run with one binary"
            .to_string()
    };
    let _ = writeln!(
        s,
        "Runs made by revision (count, from each `run_info.json`): {} — {verdict}.\n",
        list.join(", ")
    );
}

/// The title, how many metrics pass, and the regressions against a baseline if checked.
fn header(
    s: &mut String,
    fidelity: Fidelity,
    metrics: &[Metric],
    regressions: Option<&[Regression]>,
) {
    let judged: Vec<&Metric> = metrics.iter().filter(|m| m.pass().is_some()).collect();
    let passed = judged.iter().filter(|m| m.pass() == Some(true)).count();
    let _ = writeln!(s, "# Verification summary\n");
    let _ = writeln!(
        s,
        "Fidelity **{}**. {passed} of {} judged metrics within tolerance; {} \
         reported without a reference. Every reference value is computed by the code \
         (`verify/src/analytic`); \"paper\" is what the paper's own simulation reached \
         (`reference/paper_values.toml`). Error = value − reference.\n",
        fidelity.name(),
        judged.len(),
        metrics.len() - judged.len()
    );
    if let Some(r) = regressions {
        if r.is_empty() {
            let _ = writeln!(
                s,
                "Regression check against the baseline: no metric worse.\n"
            );
        } else {
            let _ = writeln!(s, "**Regressions against the baseline:**\n");
            for x in r {
                let _ = writeln!(s, "- {} / {}: {}", x.case, x.name, x.message);
            }
            s.push('\n');
        }
    }
}

/// One row per case — judged, passed, failed, of which known misses — then the known misses
/// with their reasons, so that a new failure stands out.
fn overview(s: &mut String, cases: &[Box<dyn Case>], metrics: &[Metric]) {
    let _ = writeln!(
        s,
        "| case | judged | pass | FAIL | known misses | **new FAIL** |\n|---|---|---|---|---|---|"
    );
    let (mut total_new, mut total_fail) = (0, 0);
    for case in cases {
        let ms: Vec<&Metric> = metrics.iter().filter(|m| m.case == case.name()).collect();
        if ms.is_empty() {
            continue;
        }
        let judged = ms.iter().filter(|m| m.pass().is_some()).count();
        let passed = ms.iter().filter(|m| m.pass() == Some(true)).count();
        let failed = ms.iter().filter(|m| m.pass() == Some(false)).count();
        let known = ms
            .iter()
            .filter(|m| known_misses::known(m).is_some())
            .count();
        total_new += failed - known;
        total_fail += failed;
        let new = if failed > known {
            format!("**{}**", failed - known)
        } else {
            "0".into()
        };
        let _ = writeln!(
            s,
            "| {0} | {judged} | {passed} | {failed} | {known} | {new} |",
            case.name()
        );
    }
    let _ = writeln!(
        s,
        "\n{total_fail} failing metrics, {} of them known misses of the model (below; `reference/known_misses.toml`), **{total_new} new**.\n",
        total_fail - total_new
    );
    let mut listed = Vec::new();
    for m in metrics {
        if let Some(k) = known_misses::known(m) {
            if !listed.contains(&k) {
                listed.push(k);
            }
        }
    }
    if !listed.is_empty() {
        let _ = writeln!(s, "Known misses:\n");
        for k in listed {
            let n = metrics
                .iter()
                .filter(|m| known_misses::known(m) == Some(k))
                .count();
            let noun = if n == 1 { "metric" } else { "metrics" };
            let _ = writeln!(
                s,
                "- **{}** ({n} {noun}): {} ({})",
                k.case, k.reason, k.r#where
            );
        }
        s.push('\n');
    }
}

/// The section of one case, with its metrics `ms` and the plots in `out/CASE`.
fn case_section(s: &mut String, case: &dyn Case, fidelity: Fidelity, ms: &[&Metric], out: &Path) {
    let _ = writeln!(s, "## {} — {}\n", case.name(), case.title());
    let _ = writeln!(s, "Source: {}.  ", case.source());
    let _ = writeln!(
        s,
        "Effects: {}.  ",
        crate::suite::DeclaredEffects::describe_declared(case.effects())
    );
    let _ = writeln!(s, "Resolution: {}\n", case.resolution(fidelity));
    if ms.is_empty() {
        let _ = writeln!(s, "_No results: the case was not run._\n");
        return;
    }
    metric_table(s, ms);
    let notes: Vec<String> = ms
        .iter()
        .filter(|m| !m.note.is_empty() || m.tolerance.is_some())
        .map(|m| {
            let tol = m
                .tolerance
                .as_ref()
                .map(|t| format!(" Tolerance: {}.", t.source))
                .unwrap_or_default();
            format!("- *{}*: {}{}", m.name, m.note, tol)
        })
        .collect();
    if !notes.is_empty() {
        let _ = writeln!(s, "\nNotes:\n");
        for n in notes {
            let _ = writeln!(s, "{n}");
        }
    }
    let plots = plots_of(out, case.name());
    if !plots.is_empty() {
        let _ = writeln!(s, "\nPlots: {}", plots.join(", "));
    }
    s.push('\n');
}

/// One row per metric: reference, paper, value, error, tolerance, verdict and cost.
fn metric_table(s: &mut String, ms: &[&Metric]) {
    let _ = writeln!(s, "| metric | unit | reference | paper | this project | error | tolerance | pass | particles | wall time [s] |");
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|");
    for m in ms {
        let pass = match (m.pass(), known_misses::known(m)) {
            (Some(true), _) => "pass",
            (Some(false), Some(_)) => "FAIL (known)",
            (Some(false), None) => "**FAIL**",
            (None, _) => "—",
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {:.0} |",
            m.name,
            m.unit,
            sig_opt(m.reference),
            sig_opt(m.paper),
            sig(m.value),
            sig_opt(m.error()),
            m.tolerance
                .as_ref()
                .map(|t| format!("±{}", sig(t.abs)))
                .unwrap_or_else(|| "—".into()),
            pass,
            m.particles,
            m.wall_time_s
        );
    }
}

/// Links to the case's PNG plots, relative to the summary.
fn plots_of(out: &Path, case: &str) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(out.join(case))
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().to_string())
                .filter(|n| n.ends_with(".png"))
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v.into_iter()
        .map(|n| format!("[{n}]({case}/{n})"))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn four_significant_digits() {
        assert_eq!(sig(1.21352), "1.214");
        assert_eq!(sig(0.00121352), "0.001214");
        assert_eq!(sig(48.7999), "48.80");
        assert_eq!(sig(12345.6), "12346");
        assert_eq!(sig(123456.0), "1.235e5");
        assert_eq!(sig(f64::NAN), "—");
        assert_eq!(sig(-0.5), "-0.5000");
    }
}
