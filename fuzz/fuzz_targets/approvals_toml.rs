#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| ergocell_fuzzing::approvals_toml(data));
