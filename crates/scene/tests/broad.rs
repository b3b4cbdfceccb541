//! The broad phase and the parallel runner: results identical with and without the broad phase and
//! on any number of threads (costs included, wall times aside); the broad phase skips exactly the
//! pair-frames whose bounding boxes are certainly farther apart than `within`, counted against an
//! independent recomputation of the posed boxes.

use std::path::Path;

use glam::DVec2;
use polydist_scene::{
    Aabb, FrameResult, Origin, Report, RunOptions, Scene, Status, all_pairs_not_farther, load_file,
    load_str, run,
};
use proptest::prelude::*;

fn fixture(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures/scenes")
        .join(name);
    match load_file(&path) {
        Ok(s) => s,
        Err(e) => panic!("{e}"),
    }
}

/// `n` random convex bodies on a jittered grid with seeded motions, all pairs, the given effects and
/// threshold.
fn many(n: usize, seed: u64, effects: &str, within: Option<f64>) -> Scene {
    let mut s = String::from("time = { end = 1.0, step = 0.5 }\n");
    let mut x = seed;
    let mut next = || {
        // SplitMix64.
        x = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = x;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    };
    let cols = (n as f64).sqrt().ceil() as usize;
    for k in 0..n {
        let (c, r) = ((k % cols) as f64, (k / cols) as f64);
        s += &format!(
            "[[body]]\nid = \"b{k}\"\ngenerator = {{ type = \"random_convex\", n = {}, radius = {}, seed = {} }}\n\
             pose = {{ x = {}, y = {}, angle = {} }}\n\
             motion = {{ type = \"linear\", velocity = [{}, {}], angular = {} }}\n",
            3 + (k % 6),
            0.5 + next(),
            k as u64 + seed,
            2.5 * c + next(),
            2.5 * r + next(),
            6.0 * next(),
            next() - 0.5,
            next() - 0.5,
            next() - 0.5,
        );
    }
    s += &format!("[[query]]\npairs = \"all\"\neffects = [{effects}]\n");
    if let Some(r) = within {
        s += &format!("within = {r}\n");
    }
    match load_str(&s, &Origin::text("many.toml")) {
        Ok(s) => s,
        Err(e) => panic!("{e}"),
    }
}

fn opts(broad_phase: bool, threads: usize) -> RunOptions {
    RunOptions {
        broad_phase,
        threads: Some(threads),
        ..RunOptions::default()
    }
}

/// Equal reports, wall times aside.
fn assert_same(a: &Report, b: &Report) {
    assert_eq!(a.pairs, b.pairs);
    assert_eq!(a.costs.without_times(), b.costs.without_times());
    assert_eq!(a.failed, b.failed);
}

/// The pair-frames (over all frames) whose posed boxes are certainly farther than `r`, computed
/// here from the bodies' vertices and motions, and the number of pairs per frame.
fn certainly_far_pair_frames(scene: &Scene, r: f64) -> (u64, u64) {
    let n = scene.bodies.len() as u64;
    let mut far = 0;
    for k in 0..scene.time.frames {
        let t = scene.time.frame(k);
        let boxes: Vec<Option<Aabb>> = scene
            .bodies
            .iter()
            .map(|b| {
                let pose = b.motion.pose_at(t);
                let moved: Vec<DVec2> = b.shape.vertices().iter().map(|&v| pose.apply(v)).collect();
                Aabb::of(&moved)
            })
            .collect();
        far += n * (n - 1) / 2 - all_pairs_not_farther(&boxes, r).len() as u64;
    }
    (far, n * (n - 1) / 2 * scene.time.frames as u64)
}

#[test]
fn thousand_bodies_skip_exactly_the_certainly_far_pairs() {
    let scene = fixture("thousand.toml");
    assert_eq!(scene.bodies.len(), 1000);
    let report = run(&scene, &RunOptions::default());
    assert!(!report.failed);
    let (far, total) = certainly_far_pair_frames(&scene, 1.5);
    let c = &report.costs;
    assert_eq!(c.broad_phase_skipped, far);
    // Everything else went to the narrow phase, once per pair-frame.
    assert_eq!(c.distance.calls, total - far);
    assert!(
        c.distance.calls < total / 100,
        "{} narrow-phase queries",
        c.distance.calls
    );
    assert_eq!(c.broad_phase.calls, scene.time.frames as u64);
    // Beyond frames are not listed; the listed ones carry the distance, at most 1.5.
    let mut listed = 0;
    for p in &report.pairs {
        assert!(!p.frames.is_empty());
        for f in &p.frames {
            listed += 1;
            assert_ne!(f.status, Some(Status::Beyond));
            assert!(f.distance.is_some_and(|d| d <= 1.5), "{f:?}");
        }
    }
    assert_eq!(listed + c.within_beyond, total);
    assert!(c.within_beyond >= far);
    assert_eq!(report.pairs.len() as u64 + report.pairs_beyond, 499_500);
    assert!(
        report.pairs.len() < 5_000,
        "{} pairs listed",
        report.pairs.len()
    );
    // Two threads: the same report.
    assert_same(&report, &run(&scene, &opts(true, 2)));
}

#[test]
fn broad_phase_and_threads_do_not_change_results() {
    for seed in [1, 7, 1234] {
        let scene = many(
            60,
            seed,
            r#""distance", "closest_points", "vertex_distance", "hausdorff", "cmmr""#,
            Some(1.0),
        );
        let base = run(&scene, &opts(true, 1));
        assert_same(&base, &run(&scene, &opts(true, 3)));
        let off = run(&scene, &opts(false, 1));
        assert_eq!(base.pairs, off.pairs);
        assert_same(&off, &run(&scene, &opts(false, 2)));
        assert_eq!(off.costs.broad_phase_skipped, 0);
        assert_eq!(off.costs.broad_phase.calls, 0);
        // Without the broad phase every pair-frame is a narrow-phase threshold query.
        let (far, total) = certainly_far_pair_frames(&scene, 1.0);
        assert_eq!(off.costs.distance.calls, total);
        assert_eq!(base.costs.distance.calls, total - far);
        assert_eq!(base.costs.broad_phase_skipped, far);
        // Hausdorff and CMMR only where the pair is within the threshold.
        let within = base.pairs.iter().flat_map(|p| &p.frames).count() as u64;
        assert_eq!(within + base.costs.within_beyond, total);
        assert_eq!(base.costs.hausdorff.calls, within);
        assert_eq!(base.costs.cmmr.calls, within);

        // Against the same scene without a threshold: equal values where within, and the full
        // distance is at least the threshold (up to its rounding) where beyond.
        let mut full_scene = scene.clone();
        full_scene.queries[0].within = None;
        let full = run(&full_scene, &opts(true, 2));
        assert_eq!(full.costs.broad_phase.calls, 0);
        let listed: std::collections::HashMap<(&str, &str), &Vec<FrameResult>> = base
            .pairs
            .iter()
            .map(|p| ((p.a.as_str(), p.b.as_str()), &p.frames))
            .collect();
        let mut found = 0;
        for q in &full.pairs {
            let frames = listed.get(&(q.a.as_str(), q.b.as_str()));
            for g in &q.frames {
                match frames.and_then(|fs| fs.iter().find(|f| f.t == g.t)) {
                    Some(f) => {
                        found += 1;
                        assert_eq!(f, g);
                    }
                    None => assert!(g.distance.unwrap() >= 1.0 * (1.0 - 8.0 * f64::EPSILON)),
                }
            }
        }
        assert_eq!(found, within);
    }
}

#[test]
fn fixture_scenes_are_identical_on_any_number_of_threads() {
    for name in [
        "default.toml",
        "corridor.toml",
        "two_bodies.toml",
        "example.toml",
    ] {
        let scene = fixture(name);
        let one = run(&scene, &opts(true, 1));
        for threads in [2, 4] {
            assert_same(&one, &run(&scene, &opts(true, threads)));
        }
        // The global pool too.
        assert_same(&one, &run(&scene, &RunOptions::default()));
    }
}

#[test]
fn a_pair_named_twice_takes_the_loosest_threshold() {
    let text = r#"
        [[body]]
        id = "a"
        vertices = [[0, 0], [1, 0], [0, 1]]
        [[body]]
        id = "b"
        vertices = [[5, 0], [6, 0], [5, 1]]
        [[query]]
        pairs = "all"
        effects = ["distance"]
        within = 1.0
        [[query]]
        pairs = [["a", "b"]]
        effects = ["distance"]
    "#;
    let scene = load_str(text, &Origin::text("t.toml")).unwrap();
    let report = run(&scene, &RunOptions::default());
    assert_eq!(report.pairs[0].frames[0].distance, Some(4.0));
    let text = format!("{text}\n        within = 2.0\n");
    let scene = load_str(&text, &Origin::text("t.toml")).unwrap();
    let report = run(&scene, &RunOptions::default());
    assert!(report.pairs.is_empty());
    assert_eq!(report.pairs_beyond, 1);
    assert_eq!(report.costs.within_beyond, 1);
    assert_eq!(report.costs.broad_phase_skipped, 1);
    assert_eq!(report.costs.distance.calls, 0);
}

#[test]
fn a_negative_threshold_is_refused() {
    let text = r#"
        [[body]]
        id = "a"
        vertices = [[0, 0], [1, 0], [0, 1]]
        [[body]]
        id = "b"
        vertices = [[5, 0], [6, 0], [5, 1]]
        [[query]]
        pairs = "all"
        effects = ["distance"]
        within = -1.0
    "#;
    let err = load_str(text, &Origin::text("t.toml")).unwrap_err();
    assert!(err.to_string().contains("within must be >= 0"), "{err}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]
    #[test]
    fn parallel_equals_sequential(seed in 0u64..1_000_000, n in 2usize..30, r in 0.0f64..3.0) {
        let scene = many(n, seed, r#""distance", "closest_points", "first_contact""#, Some(r));
        let one = run(&scene, &opts(true, 1));
        let two = run(&scene, &opts(true, 2));
        prop_assert_eq!(&one.pairs, &two.pairs);
        prop_assert_eq!(one.costs.without_times(), two.costs.without_times());
        let off = run(&scene, &opts(false, 2));
        prop_assert_eq!(&one.pairs, &off.pairs);
    }
}
