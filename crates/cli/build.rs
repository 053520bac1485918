//! Records the git commit the command is built from (`FRICTRACK_BUILT_FROM`, read by `frictrack_cli::COMMIT`): the
//! environment's `FRICTRACK_COMMIT` when set (a CI build in a container where git cannot read the checkout), else
//! `git rev-parse --short=12 HEAD` of the source tree; nothing outside a repository.

use std::process::Command;

fn git(args: &[&str]) -> Option<String> {
    let out = Command::new("git").args(args).output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_string()).filter(|s| !s.is_empty())
}

fn main() {
    println!("cargo:rerun-if-env-changed=FRICTRACK_COMMIT");
    let commit = std::env::var("FRICTRACK_COMMIT").ok().filter(|c| !c.is_empty()).or_else(|| {
        // A new commit moves HEAD or the branch it names: rebuild then (and only then).
        // (A path that does not exist would rerun this script on every build: only those that do.)
        if let Some(dir) = git(&["rev-parse", "--absolute-git-dir"]) {
            let branch = git(&["symbolic-ref", "-q", "HEAD"]);
            let watched = ["HEAD", "packed-refs"].into_iter().map(String::from).chain(branch);
            for path in watched.map(|p| format!("{dir}/{p}")).filter(|p| std::path::Path::new(p).exists()) {
                println!("cargo:rerun-if-changed={path}");
            }
        }
        git(&["rev-parse", "--short=12", "HEAD"])
    });
    if let Some(commit) = commit {
        println!("cargo:rustc-env=FRICTRACK_BUILT_FROM={commit}");
    }
}
