#![no_main]

libfuzzer_sys::fuzz_target!(|data: &[u8]| ergocell_fuzzing::openpose_json(data));
