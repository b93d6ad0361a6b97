//! The `verify` binary's command-line layer (declared by `main.rs`; not part of the library):
//! the arguments ([`args`]) and what each command does ([`commands`]).

pub(crate) mod args;
pub(crate) mod commands;

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use verify::plan;
use verify::suite::runner;

/// A flag set by Ctrl-C, SIGTERM or SIGHUP (the handler is installed once per process).
pub(crate) fn interrupt_flag() -> Arc<AtomicBool> {
    static FLAG: std::sync::OnceLock<Arc<AtomicBool>> = std::sync::OnceLock::new();
    FLAG.get_or_init(|| {
        let flag = Arc::new(AtomicBool::new(false));
        let f = flag.clone();
        let _ = ctrlc::set_handler(move || f.store(true, Ordering::SeqCst));
        flag
    })
    .clone()
}

/// The process's exit code for a command's result: its own code, 2 for an input error, 130 when
/// interrupted, 3 for any other error (docs/user-guide.md lists them).
pub(crate) fn exit_of(r: anyhow::Result<i32>) -> i32 {
    match r {
        Ok(code) => code,
        Err(e) if e.downcast_ref::<plan::InputError>().is_some() => {
            eprintln!("error: {e}");
            2
        }
        Err(e) if e.downcast_ref::<runner::Interrupted>().is_some() => {
            eprintln!("{e}");
            130
        }
        Err(e) => {
            eprintln!("error: {e:#}");
            3
        }
    }
}
