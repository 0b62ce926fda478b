#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| ergocell_fuzzing::cdr_messages(data));
