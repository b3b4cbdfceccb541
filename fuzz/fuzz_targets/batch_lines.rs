//! Arbitrary bytes as `polydist batch` input: every non-blank line gets exactly one output line,
//! never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use polydist_scene::{BatchOptions, batch_pairs};

fuzz_target!(|data: &[u8]| {
    let mut out = Vec::new();
    let summary = batch_pairs(data, &mut out, &BatchOptions::default()).expect("writing to a Vec");
    let written = out.iter().filter(|&&b| b == b'\n').count() as u64;
    assert_eq!(written, summary.lines);
    assert_eq!(summary.lines, summary.answered + summary.errors);
});
