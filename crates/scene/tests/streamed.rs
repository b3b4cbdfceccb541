//! Streamed queries (all pairs with `within`): no per-pair job is planned, each frame evaluates
//! only the broad phase's candidates, and the results equal both a brute force over every pair and
//! frame and the same query with its pairs listed (the materialized path). The sweep picks its
//! axis by the spread of the boxes (bodies along a vertical line stay linear). Limits: 100,000
//! bodies are accepted and cost no `n²` memory; the run-time candidate limit stops a query with an
//! error.

use std::collections::HashMap;
use std::path::Path;

use glam::DVec2;
use polydist_convex::{Within, distance_within};
use polydist_polygon::ConvexPolygon;
use polydist_polygon::predicates::Robust;
use polydist_scene::{
    Costs, MAX_PAIRS, Origin, PairSet, Report, RunOptions, Scene, SceneError, Status, load_file,
    load_str, plan, run,
};

fn fixture(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures/scenes")
        .join(name);
    load_file(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// SplitMix64 in `[0, 1)`.
fn rng(seed: u64) -> impl FnMut() -> f64 {
    let mut x = seed;
    move || {
        x = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = x;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `n` random convex bodies on a jittered grid, one in three static, the others drifting and
/// turning; one all-pairs query with the given effects and threshold.
fn mixed(n: usize, seed: u64, effects: &str, within: f64) -> Scene {
    let mut s = String::from("time = { end = 1.0, step = 0.25 }\n");
    let mut next = rng(seed);
    let cols = (n as f64).sqrt().ceil() as usize;
    for k in 0..n {
        let (c, r) = ((k % cols) as f64, (k / cols) as f64);
        s += &format!(
            "[[body]]\nid = \"b{k}\"\ngenerator = {{ type = \"random_convex\", n = {}, radius = {}, seed = {} }}\n\
             pose = {{ x = {}, y = {}, angle = {} }}\n",
            3 + (k % 6),
            0.5 + 0.5 * next(),
            k as u64 + seed,
            2.2 * c + next(),
            2.2 * r + next(),
            6.0 * next(),
        );
        if k % 3 != 0 {
            s += &format!(
                "motion = {{ type = \"linear\", velocity = [{}, {}], angular = {} }}\n",
                next() - 0.5,
                next() - 0.5,
                next() - 0.5,
            );
        }
    }
    s += &format!(
        "[[query]]\nname = \"near\"\npairs = \"all\"\neffects = [{effects}]\nwithin = {within}\n"
    );
    load_str(&s, &Origin::text("mixed.toml")).unwrap_or_else(|e| panic!("{e}"))
}

fn opts(broad_phase: bool, threads: usize) -> RunOptions {
    RunOptions {
        broad_phase,
        threads: Some(threads),
        ..RunOptions::default()
    }
}

/// The costs without wall times and without the fields that say how the pairs were planned.
fn comparable(c: &Costs) -> Costs {
    Costs {
        pair_jobs: 0,
        streamed_candidates: 0,
        max_frame_candidates: 0,
        ..c.without_times()
    }
}

/// The scene with its all-pairs query turned into the list of every pair (materialized jobs).
fn listed(scene: &Scene) -> Scene {
    let n = scene.bodies.len();
    let mut s = scene.clone();
    s.queries[0].pairs = PairSet::List(PairSet::All.iter(n).collect());
    assert!(!s.queries[0].is_streamed());
    s
}

/// Per pair (ids), the frames within the threshold: time, status, distance.
type PairFrames = HashMap<(String, String), Vec<(f64, Status, f64)>>;

/// Brute force: every pair at every frame it is evaluated (static pairs once), posed here and
/// decided by `distance_within`; the pair-frames within `r` with their status and distance.
fn brute_force(scene: &Scene, r: f64) -> PairFrames {
    let mut out: PairFrames = HashMap::new();
    for k in 0..scene.time.frames {
        let t = scene.time.frame(k);
        let posed: Vec<ConvexPolygon> = scene
            .bodies
            .iter()
            .map(|b| {
                let pose = b.motion.pose_at(t);
                let moved: Vec<DVec2> = b.shape.vertices().iter().map(|&v| pose.apply(v)).collect();
                ConvexPolygon::try_new(&moved).unwrap()
            })
            .collect();
        for (a, ba) in scene.bodies.iter().enumerate() {
            for (b, bb) in scene.bodies.iter().enumerate().skip(a + 1) {
                if k > 0 && ba.motion.is_static() && bb.motion.is_static() {
                    continue;
                }
                if let Within::Inside(sep) = distance_within::<Robust>(&posed[a], &posed[b], r) {
                    let status = match sep {
                        polydist_convex::Separation::Disjoint(_) => Status::Disjoint,
                        polydist_convex::Separation::Touching { .. } => Status::Touching,
                        polydist_convex::Separation::Overlapping => Status::Overlapping,
                    };
                    let d = sep.closest().map_or(0.0, |c| c.distance);
                    out.entry((ba.id.clone(), bb.id.clone()))
                        .or_default()
                        .push((t, status, d));
                }
            }
        }
    }
    out
}

fn reported(report: &Report) -> PairFrames {
    report
        .pairs
        .iter()
        .map(|p| {
            let frames = p
                .frames
                .iter()
                .map(|f| (f.t, f.status.unwrap(), f.distance.unwrap()))
                .collect();
            ((p.a.clone(), p.b.clone()), frames)
        })
        .collect()
}

#[test]
fn a_thousand_bodies_plan_no_pair_job() {
    let scene = fixture("thousand.toml");
    let n = scene.bodies.len() as u64;
    assert_eq!(n, 1000);
    let p = plan(&scene);
    assert!(p.jobs.is_empty(), "{} jobs planned", p.jobs.len());
    let s = p.streamed.as_ref().unwrap();
    assert_eq!((s.queries.as_slice(), s.within), (&[0][..], 1.5));

    let report = run(&scene, &RunOptions::default());
    let c = &report.costs;
    assert_eq!(c.pair_jobs, 0);
    // Every narrow-phase query is a candidate of the broad phase; the most held at once is a few
    // per body, not 499,500.
    assert_eq!(c.streamed_candidates, c.distance.calls);
    assert!(
        c.max_frame_candidates < 5 * n,
        "{} candidates in one frame",
        c.max_frame_candidates
    );
    let ns = scene.bodies.iter().filter(|b| b.motion.is_static()).count() as u64;
    let later = n * (n - 1) / 2 - ns * ns.saturating_sub(1) / 2;
    assert_eq!(
        c.streamed_candidates + c.broad_phase_skipped,
        n * (n - 1) / 2 + later * (scene.time.frames as u64 - 1)
    );
    // Without the broad phase every pair is a candidate (generated, never stored).
    let off = run(&scene, &opts(false, 2));
    assert_eq!(off.pairs, report.pairs);
    assert_eq!(off.costs.max_frame_candidates, n * (n - 1) / 2);
    assert_eq!(off.costs.pair_jobs, 0);
}

#[test]
fn streamed_equals_brute_force_and_the_listed_pairs() {
    for (seed, r) in [(3, 0.6), (11, 1.2), (40, 0.0)] {
        let scene = mixed(70, seed, r#""distance", "closest_points""#, r);
        assert!(plan(&scene).jobs.is_empty());
        let base = run(&scene, &opts(true, 1));
        assert!(!base.failed && base.errors.is_empty());

        // Brute force over every pair and frame.
        let want = brute_force(&scene, r);
        assert_eq!(reported(&base), want, "seed {seed}");
        let n = scene.bodies.len() as u64;
        assert_eq!(base.pairs.len() as u64 + base.pairs_beyond, n * (n - 1) / 2);
        // Static pairs once, at the first frame.
        for p in base.pairs.iter().filter(|p| !p.moving) {
            assert_eq!(p.frames.len(), 1);
            assert_eq!(p.frames[0].t, 0.0);
        }
        if r > 1.0 {
            assert!(base.pairs.iter().any(|p| !p.moving), "seed {seed}");
            assert!(base.pairs.iter().any(|p| p.moving), "seed {seed}");
        }

        // The same query with its pairs listed: the old path, one job per pair.
        let list = listed(&scene);
        assert_eq!(plan(&list).jobs.len() as u64, n * (n - 1) / 2);
        for (broad, threads) in [(true, 1), (true, 3), (false, 2)] {
            let a = run(&scene, &opts(broad, threads));
            let b = run(&list, &opts(broad, threads));
            assert_eq!(a.pairs, base.pairs);
            assert_eq!(b.pairs, base.pairs);
            assert_eq!(
                comparable(&a.costs),
                comparable(&b.costs),
                "{broad} {threads}"
            );
            assert_eq!(a.pairs_beyond, b.pairs_beyond);
            assert_eq!(b.costs.streamed_candidates, 0);
        }
    }
}

#[test]
fn listed_pairs_and_streamed_queries_merge_as_before() {
    // A listed query before and after the streamed one: the pairs it names keep their jobs, take
    // the streamed query's effects and threshold, and the report order is the naming order.
    let text_pairs = |q: &str, pairs: &str, extra: &str| {
        format!(
            "[[query]]\nname = \"{q}\"\npairs = {pairs}\neffects = [\"vertex_distance\"]\n{extra}"
        )
    };
    let mut spec_text = String::from("time = { end = 1.0, step = 0.25 }\n");
    let mut next = rng(5);
    let cols = 6;
    for k in 0..30usize {
        let (c, r) = ((k % cols) as f64, (k / cols) as f64);
        spec_text += &format!(
            "[[body]]\nid = \"b{k}\"\ngenerator = {{ type = \"regular\", n = {}, radius = 0.8 }}\n\
             pose = {{ x = {}, y = {} }}\n",
            3 + k % 5,
            2.0 * c + 0.3 * next(),
            2.0 * r + 0.3 * next(),
        );
        if k % 2 == 0 {
            spec_text += "motion = { type = \"linear\", velocity = [0.3, -0.2], angular = 0.5 }\n";
        }
    }
    let mut s = spec_text;
    s += &text_pairs("late", r#"[["b9", "b1"]]"#, "");
    s += "[[query]]\nname = \"near\"\npairs = \"all\"\neffects = [\"distance\"]\nwithin = 0.5\n";
    s += &text_pairs(
        "after",
        r#"[["b7", "b2"], ["b20", "b3"]]"#,
        "within = 0.25\n",
    );
    let scene = load_str(&s, &Origin::text("merge.toml")).unwrap();
    let p = plan(&scene);
    assert_eq!(p.jobs.len(), 3);
    // (b9, b1) is first named by "late" (query 0); the others by "near" (query 1), in order.
    assert_eq!((p.jobs[0].a, p.jobs[0].b), (9, 1));
    assert_eq!((p.jobs[1].a, p.jobs[1].b), (2, 7));
    assert_eq!(p.jobs[0].within, None);
    assert_eq!(p.jobs[1].within, Some(0.5));
    assert_eq!(p.jobs[1].queries, vec![1, 2]);

    // Against every pair listed in the streamed query's place.
    let mut list = scene.clone();
    list.queries[1].pairs = PairSet::List(PairSet::All.iter(30).collect());
    for broad in [true, false] {
        let a = run(&scene, &opts(broad, 2));
        let b = run(&list, &opts(broad, 1));
        assert_eq!(a.pairs, b.pairs, "broad phase {broad}");
        assert_eq!(a.pairs_beyond, b.pairs_beyond);
        assert_eq!(comparable(&a.costs), comparable(&b.costs));
        assert_eq!(a.costs.pair_jobs, 3);
        let first = &a.pairs[0];
        assert_eq!((first.a.as_str(), first.b.as_str()), ("b9", "b1"));
        assert_eq!(first.queries, vec!["late", "near"]);
    }
}

/// `n` unit squares along a line (vertical or horizontal), 2.2 apart, static.
fn line(n: usize, vertical: bool) -> Scene {
    let mut s = String::new();
    for k in 0..n {
        let (x, y) = if vertical {
            (0.0, 2.2 * k as f64)
        } else {
            (2.2 * k as f64, 0.0)
        };
        s += &format!(
            "[[body]]\nid = \"s{k}\"\nvertices = [[-1, -1], [1, -1], [1, 1], [-1, 1]]\npose = {{ x = {x}, y = {y} }}\n"
        );
    }
    s += "[[query]]\npairs = \"all\"\neffects = [\"distance\"]\nwithin = 0.5\n";
    load_str(&s, &Origin::text("line.toml")).unwrap()
}

#[test]
fn bodies_along_a_vertical_line_sweep_in_linear_time() {
    let n = 400u64;
    for vertical in [true, false] {
        let report = run(&line(n as usize, vertical), &RunOptions::default());
        let c = &report.costs;
        // Neighbours are 0.2 apart, all others at least 2.4: n − 1 pairs within 0.5.
        assert_eq!(report.pairs.len() as u64, n - 1);
        assert!(report.pairs.iter().all(|p| {
            let d = p.frames[0].distance.unwrap();
            (d - 0.2).abs() < 1e-12
        }));
        assert_eq!(c.streamed_candidates, n - 1);
        // The sweep runs along the line: each box meets its next neighbour only (an `x` sweep of
        // the vertical line would examine all n(n − 1)/2 = 79,800 pairs).
        assert_eq!(c.broad_phase_examined, n - 1, "vertical {vertical}");
    }
}

#[test]
fn a_hundred_thousand_bodies_are_accepted_without_quadratic_memory() {
    const N: usize = 100_000;
    // 316 x 317 grid of small squares 1 apart, side 0.5 (gaps 0.5), every other row moving
    // slowly; within 0.1: no pair is near.
    let mut bodies = Vec::with_capacity(N);
    for k in 0..N {
        let (x, y) = ((k % 316) as f64, (k / 316) as f64);
        let motion = if (k / 316) % 2 == 1 {
            r#","motion":{"type":"linear","velocity":[0.01,0.0]}"#
        } else {
            ""
        };
        bodies.push(format!(
            r#"{{"id":"q{k}","vertices":[[0,0],[0.5,0],[0.5,0.5],[0,0.5]],"pose":{{"x":{x},"y":{y}}}{motion}}}"#
        ));
    }
    let queries = r#"[{"pairs":"all","effects":["distance"],"within":0.1}]"#;
    let text = format!(
        r#"{{"time":{{"end":1.0,"step":1.0}},"bodies":[{}],"queries":{queries}}}"#,
        bodies.join(",")
    );
    let scene = load_str(&text, &Origin::text("big.json")).unwrap_or_else(|e| panic!("{e}"));
    let p = plan(&scene);
    assert!(p.jobs.is_empty());
    let report = run(&scene, &RunOptions::default());
    assert!(!report.failed, "{:?}", report.errors);
    let c = &report.costs;
    let n = N as u64;
    assert_eq!(c.pair_jobs, 0);
    assert_eq!(c.max_frame_candidates, 0);
    assert_eq!(c.distance.calls, 0);
    assert!(report.pairs.is_empty());
    assert_eq!(report.pairs_beyond, n * (n - 1) / 2);
    // A one-axis sweep of a square grid examines each box against its row (or column): about
    // n·√n box tests per frame (23.6 million here), not n²/2 = 5·10⁹; a known limit of
    // sweep-and-prune (docs/scene-format.md).
    let frames = scene.time.frames as u64;
    assert!(
        c.broad_phase_examined < frames * n * 320,
        "{}",
        c.broad_phase_examined
    );
    // Every body posed at the first frame, the moving ones again at the second.
    let moving = (0..N).filter(|k| (k / 316) % 2 == 1).count() as u64;
    assert_eq!(c.pose.calls, n + moving);

    // The same bodies asking every pair's distance (no `within`): refused by the pair limit.
    let text = text.replace(r#","within":0.1"#, "");
    let err = load_str(&text, &Origin::text("big.json")).unwrap_err();
    assert!(
        err.0.iter().any(|e| matches!(
            e,
            SceneError::TooMuchWork { what: "pairs", count, limit }
                if *count == u128::from(n * (n - 1) / 2) && *limit == MAX_PAIRS
        )),
        "{err}"
    );
}

#[test]
fn the_candidate_limit_stops_a_streamed_query_with_an_error() {
    let scene = mixed(60, 9, r#""distance""#, 1.5);
    let full = run(&scene, &opts(true, 2));
    assert!(full.errors.is_empty());
    let per_frame = full.costs.max_frame_candidates;
    assert!(per_frame > 20);
    for broad in [true, false] {
        let limited = run(
            &scene,
            &RunOptions {
                max_frame_candidates: 20,
                ..opts(broad, 2)
            },
        );
        assert!(limited.failed);
        assert_eq!(limited.errors.len(), 1);
        let e = &limited.errors[0];
        assert!(
            e.contains("near (all pairs within 1.5): stopped at frame 0 (t = 0)")
                && e.contains("MAX_FRAME_CANDIDATES"),
            "{e}"
        );
        // Stopped before any candidate was evaluated.
        assert_eq!(limited.costs.distance.calls, 0);
        assert!(limited.pairs.is_empty());
        // The JSON report carries the error; the table too.
        let json = serde_json::to_value(&limited).unwrap();
        assert_eq!(json["errors"][0].as_str(), Some(e.as_str()));
        assert!(limited.to_table().contains(&format!("error: {e}")));
    }
    // A report without errors has no "errors" field.
    let json = serde_json::to_value(&full).unwrap();
    assert!(json.get("errors").is_none());
}

#[test]
fn an_all_pairs_query_without_within_plans_the_same_jobs_as_its_list() {
    // The dense pair table of a materialized all-pairs query against the hash map of a list.
    let mut s = String::new();
    for k in 0..25 {
        s += &format!(
            "[[body]]\nid = \"b{k}\"\ngenerator = {{ type = \"regular\", n = 4, radius = 0.5 }}\npose = {{ x = {}, y = {} }}\n",
            2 * (k % 5),
            2 * (k / 5)
        );
    }
    s += "[[query]]\nname = \"first\"\npairs = [[\"b9\", \"b1\"], [\"b3\", \"b4\"], [\"b9\", \"b1\"]]\neffects = [\"vertex_distance\"]\n";
    s += "[[query]]\nname = \"all\"\npairs = \"all\"\neffects = [\"distance\"]\n";
    s += "[[query]]\nname = \"near\"\npairs = \"all\"\neffects = [\"closest_points\"]\nwithin = 1.0\n";
    let scene = load_str(&s, &Origin::text("dense.toml")).unwrap();
    let mut list = scene.clone();
    list.queries[1].pairs = PairSet::List(PairSet::All.iter(25).collect());
    let (p, q) = (plan(&scene), plan(&list));
    // The non-streamed all-pairs query materializes every pair: "near" is merged into the jobs
    // (with the list, "near" is streamed but every pair has a job, so it merges the same way).
    assert!(p.streamed.is_none() && q.streamed.is_some());
    assert_eq!(p.jobs.len(), 300);
    let view = |p: &polydist_scene::Plan| {
        p.jobs
            .iter()
            .map(|j| (j.a, j.b, j.queries.clone(), j.effects, j.within))
            .collect::<Vec<_>>()
    };
    assert_eq!(view(&p), view(&q));
    assert_eq!((p.jobs[0].a, p.jobs[0].b), (9, 1));
    assert_eq!(p.jobs[0].queries, vec![0, 1, 2]);
    assert_eq!((p.jobs[1].a, p.jobs[1].b), (3, 4));
    assert_eq!((p.jobs[2].a, p.jobs[2].b), (0, 1));
    assert_eq!(p.jobs[2].within, None);
    let a = run(&scene, &opts(true, 2));
    let b = run(&list, &opts(true, 1));
    assert_eq!(a.pairs, b.pairs);
    assert_eq!(a.pairs.len(), 300);
}

#[test]
fn bodies_that_cannot_be_posed_give_invalid_frames_once_per_pair() {
    // x = 1e150·t leaves the coordinate range ±2^500 ≈ 3.3e150 after t = 3: both runaways have no
    // box at t = 4, 5, 6, so their pairs are added to the candidates (the pair of the two once).
    let sq = |x: f64, y: f64| {
        format!(
            "[[{x}, {y}], [{}, {y}], [{}, {}], [{x}, {}]]",
            x + 1.0,
            x + 1.0,
            y + 1.0,
            y + 1.0
        )
    };
    let text = format!(
        r#"
        time = {{ end = 6.0, step = 1.0 }}
        [[body]]
        id = "runaway"
        vertices = {}
        motion = {{ type = "linear", velocity = [1e150, 0.0] }}
        [[body]]
        id = "b"
        vertices = {}
        [[body]]
        id = "c"
        vertices = {}
        [[body]]
        id = "other"
        vertices = {}
        motion = {{ type = "linear", velocity = [0.0, 1e150] }}
        [[query]]
        name = "near"
        pairs = "all"
        effects = ["distance"]
        within = 4.5
        "#,
        sq(0.0, 0.0),
        sq(0.0, 5.0),
        sq(5.0, 5.0),
        sq(9.0, 9.0),
    );
    let scene = load_str(&text, &Origin::text("runaway.toml")).unwrap();
    assert!(plan(&scene).jobs.is_empty());
    let list = listed(&scene);
    for broad in [true, false] {
        let report = run(&scene, &opts(broad, 2));
        let twin = run(&list, &opts(broad, 1));
        assert_eq!(report.pairs, twin.pairs, "broad phase {broad}");
        assert_eq!(comparable(&report.costs), comparable(&twin.costs));
        assert!(report.failed && report.errors.is_empty());
        let pair = |a: &str, b: &str| {
            report
                .pairs
                .iter()
                .find(|p| p.a == a && p.b == b)
                .unwrap_or_else(|| panic!("{a} – {b}"))
        };
        for (a, b) in [("runaway", "b"), ("runaway", "other"), ("b", "other")] {
            let p = pair(a, b);
            assert!(p.failed);
            let invalid: Vec<f64> = p
                .frames
                .iter()
                .filter(|f| f.status == Some(Status::Invalid))
                .map(|f| f.t)
                .collect();
            assert_eq!(invalid, vec![4.0, 5.0, 6.0], "{a} – {b}");
        }
        // b and c are static and 4 apart: within, once.
        let bc = pair("b", "c");
        assert!(!bc.failed && !bc.moving);
        assert_eq!(bc.frames.len(), 1);
        assert_eq!(bc.frames[0].distance, Some(4.0));
    }
}
