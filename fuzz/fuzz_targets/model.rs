//! Fuzz target: the model reader (body in `src/lib.rs`, shared with tests/fuzz_corpus.rs).
#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| torsim_fuzz::model(data));
