//! Fuzz target: the recording reader (body in `src/lib.rs`, shared with tests/fuzz_corpus.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| torsim_fuzz::recording(data));
