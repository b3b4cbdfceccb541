//! Arbitrary bytes as a scene file (TOML, or JSON when it starts with `{`): loading must return a
//! scene or typed errors, never panic; a scene that loads and is small enough is run.
#![no_main]

use libfuzzer_sys::fuzz_target;
use polydist_scene::{Origin, RunOptions, load_str, plan, run};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let origin = Origin::text("fuzz.toml");
    let Ok(scene) = load_str(text, &origin) else {
        return;
    };
    // Run only what finishes quickly (the limits refuse the enormous; this keeps each input fast).
    let jobs = plan(&scene).jobs.len();
    let vertices: usize = scene.bodies.iter().map(|b| b.shape.vertices().len()).sum();
    if jobs <= 64 && scene.time.frames <= 64 && vertices <= 4096 {
        let report = run(&scene, &RunOptions::default());
        let _ = report.to_table();
    }
});
