//! Writing files so that an output can never destroy an input (issue 13, "Data loss"):
//!
//! - [`atomic`]: every file is written to a temporary file in the same directory
//!   (`.<name>.<pid>.tmp`), synced, and renamed over its target once complete; on failure
//!   the temporary file is removed and the target is left as it was.
//! - [`temps`]: the temporary files in progress, so that a front end's signal handler can
//!   remove them ([`remove_temporaries`]); the library installs no handler.
//! - [`guard`]: refuses an output path that resolves to an input of the same command, or
//!   to the other half of a recording's CSV + sidecar pair.
//! - [`pair`]: writes a CSV and its sidecar in stages (both temporaries first, then the
//!   CSV renamed, then the sidecar).

pub mod atomic;
pub mod guard;
pub mod pair;
pub mod temps;

pub use atomic::{TempFile, write_atomic};
pub use guard::{OutputError, OutputGuard, same_file};
pub use pair::PreparedPair;
pub use temps::remove_temporaries;
