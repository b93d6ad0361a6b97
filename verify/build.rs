//! Records the git revision the binary was built from (for run_info.json and the reports).
//!
//! The revision is the commit `HEAD` names, 12 hex digits, with `-dirty` when the sources that
//! make the binary (the two crates, the workspace manifest and lock file) differ from that
//! commit, untracked source files included. Cargo re-runs this script when any of those sources
//! changes and when the commit changes (`HEAD`, the branch file it names, the packed refs), so a
//! binary never carries the revision of an older build. Not on a change of the index: `git
//! status` rewrites it without changing any source or commit, and staging does not change
//! whether the sources differ from the commit.
use std::path::{Path, PathBuf};
use std::process::Command;

/// The workspace's files that the `verify` binary is built from, relative to the workspace.
/// (`scenes/` and `reference/`: some scenes and the paper values are compiled in.)
const SOURCES: [&str; 10] = [
    "solver/src",
    "solver/Cargo.toml",
    "verify/src",
    "verify/assets",
    "verify/build.rs",
    "verify/Cargo.toml",
    "Cargo.toml",
    "Cargo.lock",
    "scenes",
    "reference",
];

fn git(args: &[&str]) -> Option<String> {
    Command::new("git")
        .args(args)
        .current_dir("..")
        .output()
        .ok()
        .filter(|o| o.status.success())
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map(|s| s.trim().to_string())
}

fn main() {
    let head = git(&["rev-parse", "--short=12", "HEAD"]);
    let rev = match &head {
        None => "unknown".to_string(),
        Some(h) => {
            let mut args = vec!["status", "--porcelain", "--untracked-files=normal", "--"];
            args.extend(SOURCES);
            match git(&args) {
                Some(s) if s.is_empty() => h.clone(),
                Some(_) => format!("{h}-dirty"),
                // status failed: say so rather than claim a clean tree
                None => format!("{h}-unknown-state"),
            }
        }
    };
    println!("cargo:rustc-env=GIT_REVISION={rev}");
    // the sources: any edit may change the dirty flag (directories are scanned recursively)
    for s in SOURCES {
        println!("cargo:rerun-if-changed=../{s}");
    }
    // the commit: HEAD, the branch file it names, packed refs
    if let Some(dir) = git(&["rev-parse", "--absolute-git-dir"]) {
        let dir = PathBuf::from(dir);
        let common = git(&["rev-parse", "--path-format=absolute", "--git-common-dir"])
            .map(PathBuf::from)
            .unwrap_or_else(|| dir.clone());
        let mut watch: Vec<PathBuf> = vec![dir.join("HEAD"), common.join("packed-refs")];
        if let Some(r) = git(&["symbolic-ref", "-q", "HEAD"]) {
            watch.push(common.join(&r));
        }
        for p in watch {
            if Path::new(&p).exists() {
                println!("cargo:rerun-if-changed={}", p.display());
            }
        }
    }
}
