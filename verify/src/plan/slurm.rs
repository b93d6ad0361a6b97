//! The SLURM scripts of a plan: `run.sbatch` (one array task per plan task) and `submit.sh`
//! (submits it, then `verify collect` once every task has ended).

use super::Plan;
use crate::output::atomic_write;
use std::path::{Path, PathBuf};

/// How the array job asks for resources.
#[derive(Clone, Debug)]
pub struct SlurmOptions {
    /// The `verify` binary the tasks run (absolute; by default this one).
    pub exe: PathBuf,
    /// Cores per task (`--cpus-per-task`), also the run's worker threads.
    pub cpus_per_task: usize,
    /// Time limit per task (`--time`, e.g. `04:00:00`). A task stopped at its limit writes a
    /// checkpoint (SIGTERM is asked for 120 s before it); submitting again resumes it.
    pub time: String,
    /// Partition (`--partition`), if not the cluster's default.
    pub partition: Option<String>,
}

/// `s` quoted for a POSIX shell.
fn quote(s: &str) -> String {
    format!("'{}'", s.replace('\'', r"'\''"))
}

fn abs(p: &Path) -> anyhow::Result<String> {
    Ok(std::fs::canonicalize(p)?.to_string_lossy().into_owned())
}

/// The text of `run.sbatch` for the plan in `dir`.
fn sbatch(dir: &str, plan: &Plan, o: &SlurmOptions, exe: &str) -> String {
    let mut s = String::new();
    s.push_str("#!/bin/bash\n");
    s.push_str("# One task of the plan per array index; written by `verify plan`.\n");
    s.push_str("# A task whose run is finished is skipped, a stopped one resumes from its\n");
    s.push_str("# checkpoint: submitting again after a time limit or a failure is safe.\n");
    s.push_str("#SBATCH --job-name=verify-plan\n");
    s.push_str(&format!("#SBATCH --array=0-{}\n", plan.tasks.len() - 1));
    s.push_str("#SBATCH --ntasks=1\n");
    s.push_str(&format!("#SBATCH --cpus-per-task={}\n", o.cpus_per_task));
    s.push_str(&format!("#SBATCH --time={}\n", o.time));
    if let Some(p) = &o.partition {
        s.push_str(&format!("#SBATCH --partition={p}\n"));
    }
    // the batch shell is `verify` itself (exec), so B: delivers SIGTERM to it 120 s before the
    // limit: it finishes its step, writes a checkpoint and exits 130
    s.push_str("#SBATCH --signal=B:TERM@120\n");
    s.push_str(&format!("#SBATCH --output={dir}/logs/task_%a.log\n"));
    s.push_str("#SBATCH --open-mode=append\n");
    s.push_str(&format!(
        "exec {} task {} --index \"$SLURM_ARRAY_TASK_ID\" --threads \"${{SLURM_CPUS_PER_TASK:-1}}\"\n",
        quote(exe),
        quote(dir)
    ));
    s
}

/// The text of `submit.sh`: prints the array job's id, then the collect job's.
fn submit(dir: &str, exe: &str) -> String {
    let collect = format!("exec {} collect {}", quote(exe), quote(dir));
    format!(
        r#"#!/usr/bin/env bash
# Submits the plan as a SLURM array job, then `verify collect` once every task has ended
# (afterany: a partial plan is collected too, naming its unfinished tasks). Written by
# `verify plan`. Prints the two job ids.
set -euo pipefail
array=$(sbatch --parsable {sbatch})
array=${{array%%;*}}
collect=$(sbatch --parsable --dependency=afterany:"$array" --job-name=verify-collect \
  --ntasks=1 --cpus-per-task=1 --output={log} --open-mode=append --wrap={wrap})
echo "$array ${{collect%%;*}}"
"#,
        sbatch = quote(&format!("{dir}/run.sbatch")),
        log = quote(&format!("{dir}/logs/collect.log")),
        wrap = quote(&collect),
    )
}

/// Writes `run.sbatch` and `submit.sh` (executable) into the plan's folder `dir`.
pub(super) fn write_scripts(dir: &Path, plan: &Plan, o: &SlurmOptions) -> anyhow::Result<()> {
    let d = abs(dir)?;
    anyhow::ensure!(
        !d.contains(char::is_whitespace),
        "{d}: SLURM's #SBATCH lines cannot hold a path with spaces; put the plan elsewhere"
    );
    let exe = abs(&o.exe)?;
    atomic_write(
        &dir.join("run.sbatch"),
        sbatch(&d, plan, o, &exe).as_bytes(),
    )?;
    let path = dir.join("submit.sh");
    atomic_write(&path, submit(&d, &exe).as_bytes())?;
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoting_survives_a_single_quote() {
        assert_eq!(quote("a'b"), r"'a'\''b'");
    }
}
