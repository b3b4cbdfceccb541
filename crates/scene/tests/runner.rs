//! The runner: first_contact against analytic contact times, certified clearances, the plan computing
//! only what is asked (counted), static pairs once, temporal coherence (identical results, fewer
//! predicates), invalid bodies at some frames.

use polydist_convex::{
    reset_search_stats, reset_vertex_distance_case_counts, search_stats,
    vertex_distance_case_counts,
};
use polydist_scene::{ContactOutcome, Origin, Report, RunOptions, Scene, Status, load_str, run};

fn scene(text: &str) -> Scene {
    match load_str(text, &Origin::text("test.toml")) {
        Ok(s) => s,
        Err(e) => panic!("{e}"),
    }
}

fn run_default(s: &Scene) -> Report {
    run(s, &RunOptions::default())
}

fn square(x: f64, y: f64, side: f64) -> String {
    format!(
        "[[{x}, {y}], [{}, {y}], [{}, {}], [{x}, {}]]",
        x + side,
        x + side,
        y + side,
        y + side
    )
}

/// Two unit squares approaching at constant speed: contact when the gap closes.
#[test]
fn first_contact_squares_at_constant_speed() {
    // Gap 4 between x = 1 and x = 5; relative speed 2 + 0.5 = 2.5: contact at t = 1.6.
    let text = format!(
        r#"
        time = {{ end = 10.0, step = 1.0 }}
        [[body]]
        id = "a"
        vertices = {}
        motion = {{ type = "linear", velocity = [2.0, 0.0] }}
        [[body]]
        id = "b"
        vertices = {}
        motion = {{ type = "linear", velocity = [-0.5, 0.0] }}
        [[query]]
        pairs = [["a", "b"]]
        effects = ["first_contact"]
        tolerance = 1e-9
        "#,
        square(0.0, 0.0, 1.0),
        square(5.0, 0.3, 1.0)
    );
    let report = run_default(&scene(&text));
    let c = report.pairs[0].first_contact.clone().unwrap();
    assert_eq!(c.outcome, ContactOutcome::Contact, "{c:?}");
    let (safe, hit) = (c.t_safe.unwrap(), c.t_hit.unwrap());
    assert!(safe <= 1.6 && 1.6 <= hit, "[{safe}, {hit}]");
    assert!(hit - safe <= 1e-9 * (1.0 + 1e-12), "width {}", hit - safe);
    // The speed bound is exact here (pure translation): advancement lands next to the contact in
    // a handful of steps.
    assert!(c.steps <= 5, "{} steps", c.steps);
    assert!(!report.failed);
}

/// A diagonal approach: the bound uses the relative velocity, whose norm exceeds the closing speed
/// along x, and the answer is still bracketed.
#[test]
fn first_contact_diagonal_approach() {
    // a moves with (1, 1) from [0,1]², b is [3,4] × [0, 10]: a's right side reaches x = 3 at t = 2.
    let text = format!(
        r#"
        time = {{ end = 5.0, step = 0.5 }}
        [[body]]
        id = "a"
        vertices = {}
        motion = {{ type = "linear", velocity = [1.0, 1.0] }}
        [[body]]
        id = "b"
        vertices = [[3, 0], [4, 0], [4, 10], [3, 10]]
        [[query]]
        pairs = [["a", "b"]]
        effects = ["first_contact"]
        tolerance = 1e-7
        "#,
        square(0.0, 0.0, 1.0)
    );
    let c = run_default(&scene(&text)).pairs[0]
        .first_contact
        .clone()
        .unwrap();
    assert_eq!(c.outcome, ContactOutcome::Contact, "{c:?}");
    let (safe, hit) = (c.t_safe.unwrap(), c.t_hit.unwrap());
    assert!(
        safe <= 2.0 && 2.0 <= hit && hit - safe <= 1.0000001e-7,
        "[{safe}, {hit}]"
    );
}

/// A bar spinning about its centre reaches a wall: the contact time is analytic.
#[test]
fn first_contact_rotating_bar_reaches_a_wall() {
    // Bar [-L, L] × [-w, w], starting vertical (angle π/2), turning clockwise at ω. Its extent along
    // x at angle θ ∈ [0, π/2] is L cos θ + w sin θ = R cos(θ − φ), R = √(L² + w²), φ = atan(w / L).
    // The wall's face is at x = c: contact when θ = φ + acos(c / R), at t = (π/2 − θ) / ω.
    let (l, w, c, omega) = (2.0f64, 0.1f64, 1.5f64, 0.8f64);
    let r = l.hypot(w);
    let theta = (w / l).atan() + (c / r).acos();
    let t_star = (core::f64::consts::FRAC_PI_2 - theta) / omega;
    let text = format!(
        r#"
        time = {{ end = 3.0, step = 0.25 }}
        [[body]]
        id = "bar"
        vertices = [[{ml}, {mw}], [{l}, {mw}], [{l}, {w}], [{ml}, {w}]]
        pose = {{ angle = {a} }}
        motion = {{ type = "linear", angular = {om} }}
        [[body]]
        id = "wall"
        vertices = [[{c}, -5], [{c2}, -5], [{c2}, 5], [{c}, 5]]
        [[query]]
        pairs = [["bar", "wall"]]
        effects = ["first_contact"]
        tolerance = 1e-8
        "#,
        ml = -l,
        mw = -w,
        a = core::f64::consts::FRAC_PI_2,
        om = -omega,
        c2 = c + 1.0,
    );
    let report = run_default(&scene(&text));
    let fc = report.pairs[0].first_contact.clone().unwrap();
    assert_eq!(fc.outcome, ContactOutcome::Contact, "{fc:?}");
    let (safe, hit) = (fc.t_safe.unwrap(), fc.t_hit.unwrap());
    // The analytic time is computed in f64 (a few ulps); the posed polygons are rounded (an ulp of
    // their coordinates): allow 1e-12 around the bracket.
    assert!(
        safe <= t_star + 1e-12 && t_star <= hit + 1e-12,
        "[{safe}, {hit}] vs {t_star}"
    );
    assert!(hit - safe <= 1.0000001e-8);
    // Rotation makes the bound loose (|ω|·r ≥ the closing speed): more steps, still bounded.
    assert!(fc.steps < 200, "{} steps", fc.steps);
}

/// Bodies that never meet: a certificate over the whole span with a clearance bound that is a true
/// lower bound (here the distance is constant, so the bound is exactly half of it: each step of
/// length d/V contributes (d + d − V·d/V)/2 = d/2).
#[test]
fn first_contact_apart_with_certified_clearance() {
    let text = format!(
        r#"
        time = {{ end = 12.0, step = 1.0 }}
        [[body]]
        id = "robot"
        vertices = {}
        motion = {{ type = "linear", velocity = [1.0, 0.0] }}
        [[body]]
        id = "wall"
        vertices = [[-5, 2], [30, 2], [30, 3], [-5, 3]]
        [[query]]
        pairs = [["robot", "wall"]]
        effects = ["first_contact"]
        "#,
        square(0.0, -0.5, 1.0)
    );
    let c = run_default(&scene(&text)).pairs[0]
        .first_contact
        .clone()
        .unwrap();
    assert_eq!(c.outcome, ContactOutcome::Apart, "{c:?}");
    let lb = c.clearance_lower_bound.unwrap();
    assert!(lb <= 1.5, "{lb}");
    assert!(lb >= 0.75 * (1.0 - 1e-9), "{lb}");
    assert_eq!(c.t_safe, Some(12.0));
}

/// A fly-by whose distance varies: the certified bound never exceeds the true minimum over the span
/// (computed analytically: a point passing a vertex), and it is positive.
#[test]
fn first_contact_flyby_clearance_is_below_the_true_minimum() {
    // A unit square moving along y = 2.5 .. 3.5 over a triangle with apex (0, 1): the nearest approach
    // is from the apex to the square's bottom edge, 1.5, when the square is above the apex.
    let text = format!(
        r#"
        time = {{ end = 8.0, step = 1.0 }}
        [[body]]
        id = "sq"
        vertices = {}
        motion = {{ type = "linear", velocity = [1.0, 0.0], angular = 0.0 }}
        [[body]]
        id = "tri"
        vertices = [[-1, 0], [1, 0], [0, 1]]
        [[query]]
        pairs = [["sq", "tri"]]
        effects = ["first_contact", "distance"]
        "#,
        square(-4.5, 2.5, 1.0)
    );
    let report = run_default(&scene(&text));
    let p = &report.pairs[0];
    let c = p.first_contact.clone().unwrap();
    assert_eq!(c.outcome, ContactOutcome::Apart);
    let lb = c.clearance_lower_bound.unwrap();
    assert!(lb > 0.0 && lb <= 1.5, "{lb}");
    // The sampled frames are all at least the certified bound.
    for f in &p.frames {
        assert!(f.distance.unwrap() >= lb);
    }
}

#[test]
fn contact_at_start_and_keyframes() {
    // Overlapping at t = 0.
    let text = format!(
        r#"
        [[body]]
        id = "a"
        vertices = {}
        [[body]]
        id = "b"
        vertices = {}
        [[query]]
        pairs = "all"
        effects = ["first_contact", "distance"]
        "#,
        square(0.0, 0.0, 1.0),
        square(0.5, 0.5, 1.0)
    );
    let report = run_default(&scene(&text));
    let c = report.pairs[0].first_contact.clone().unwrap();
    assert_eq!(c.outcome, ContactOutcome::ContactAtStart);
    assert_eq!(c.t_hit, Some(0.0));
    assert_eq!(report.pairs[0].frames[0].status, Some(Status::Overlapping));

    // Keyframes: b waits at x = 10 until t = 2, then moves left at speed 4 (x = 10 − 4(t − 2)),
    // reaching a's right side (x = 1) at t = 2 + 9/4 = 4.25.
    let text = format!(
        r#"
        time = {{ end = 6.0, step = 0.5 }}
        [[body]]
        id = "a"
        vertices = {}
        [[body]]
        id = "b"
        vertices = {}
        motion = {{ type = "keyframes", keys = [{{ t = 0, x = 10 }}, {{ t = 2, x = 10 }}, {{ t = 5, x = -2 }}] }}
        [[query]]
        pairs = [["a", "b"]]
        effects = ["first_contact"]
        tolerance = 1e-9
        "#,
        square(0.0, 0.0, 1.0),
        square(0.0, 0.0, 1.0)
    );
    let c = run_default(&scene(&text)).pairs[0]
        .first_contact
        .clone()
        .unwrap();
    assert_eq!(c.outcome, ContactOutcome::Contact, "{c:?}");
    let (safe, hit) = (c.t_safe.unwrap(), c.t_hit.unwrap());
    assert!(safe <= 4.25 && 4.25 <= hit, "[{safe}, {hit}]");
}

#[test]
fn max_steps_gives_undecided_and_fails_the_pair() {
    let text = format!(
        r#"
        time = {{ end = 10.0, step = 1.0 }}
        [[body]]
        id = "a"
        vertices = {}
        motion = {{ type = "linear", velocity = [1.0, 0.0], angular = 3.0 }}
        [[body]]
        id = "b"
        vertices = {}
        [[query]]
        pairs = [["a", "b"]]
        effects = ["first_contact"]
        max_steps = 3
        "#,
        square(0.0, 0.0, 1.0),
        square(8.0, 0.0, 1.0)
    );
    let report = run_default(&scene(&text));
    let c = report.pairs[0].first_contact.clone().unwrap();
    assert_eq!(c.outcome, ContactOutcome::Undecided);
    assert_eq!(c.steps, 3);
    assert!(c.t_safe.unwrap() > 0.0);
    assert!(report.failed && report.pairs[0].failed);
}

/// A scene asking only first_contact performs no vertex-distance work and no per-frame distance
/// query: the runner's counters and the convex crate's own counters agree.
#[test]
fn only_first_contact_does_no_other_work() {
    let text = format!(
        r#"
        time = {{ end = 10.0, step = 0.1 }}
        [[body]]
        id = "a"
        generator = {{ type = "regular", n = 64, radius = 1.0 }}
        motion = {{ type = "linear", velocity = [1.0, 0.0] }}
        [[body]]
        id = "b"
        vertices = {}
        [[query]]
        pairs = [["a", "b"]]
        effects = ["first_contact"]
        "#,
        square(6.0, -1.0, 2.0)
    );
    let s = scene(&text);
    reset_vertex_distance_case_counts();
    reset_search_stats();
    let report = run_default(&s);
    let c = report.costs;
    assert_eq!(c.vertex_distance.calls, 0);
    assert_eq!((c.hausdorff.calls, c.cmmr.calls), (0, 0));
    assert_eq!(c.distance.calls, 0);
    assert_eq!(
        c.pose.calls, 0,
        "no frame posing: first_contact poses at its own times"
    );
    assert_eq!(c.first_contact.calls, 1);
    assert!(c.first_contact_steps >= 1);
    assert_eq!(vertex_distance_case_counts().calls, 0);
    assert!(report.pairs[0].frames.is_empty());
    // And the same scene with vertex_distance asked does that work, per frame.
    let text2 = text.replace(
        r#"effects = ["first_contact"]"#,
        r#"effects = ["vertex_distance"]"#,
    );
    reset_vertex_distance_case_counts();
    let report = run_default(&scene(&text2));
    assert_eq!(report.costs.vertex_distance.calls, 101);
    assert_eq!(vertex_distance_case_counts().calls, 101);
    assert_eq!(report.costs.distance.calls, 0);
    assert_eq!(report.costs.first_contact.calls, 0);
    let _ = search_stats();
}

/// `hausdorff` and `cmmr` at every frame of a moving pair equal the brute-force twins on the posed
/// polygons the runner used (recomputed here from the pose), and cost exactly one query each per frame.
#[test]
fn hausdorff_and_cmmr_match_the_brute_force_per_frame() {
    use glam::DVec2;
    use polydist_convex::polygon::ConvexPolygon;
    use polydist_convex::polygon::predicates::Robust;
    use polydist_convex::{cmmr_brute, hausdorff_brute};
    let text = format!(
        r#"
        time = {{ end = 2.0, step = 0.25 }}
        [[body]]
        id = "a"
        vertices = {}
        motion = {{ type = "linear", velocity = [1.5, 0.25] }}
        [[body]]
        id = "b"
        vertices = [[1.0, -1.0], [4.0, 0.0], [3.0, 2.5], [0.5, 1.5]]
        [[query]]
        pairs = [["a", "b"]]
        effects = ["hausdorff", "cmmr"]
        "#,
        square(-2.0, 0.0, 1.0)
    );
    let report = run_default(&scene(&text));
    assert_eq!(report.costs.hausdorff.calls, 9);
    assert_eq!(report.costs.cmmr.calls, 9);
    assert_eq!(report.costs.distance.calls, 0);
    let b = ConvexPolygon::try_new(&[
        DVec2::new(1.0, -1.0),
        DVec2::new(4.0, 0.0),
        DVec2::new(3.0, 2.5),
        DVec2::new(0.5, 1.5),
    ])
    .expect("valid");
    let frames = &report.pairs[0].frames;
    assert_eq!(frames.len(), 9);
    let mut overlapping = 0;
    for f in frames {
        // The runner's pose: a translation by t·v, rounded per coordinate.
        let (dx, dy) = (1.5 * f.t, 0.25 * f.t);
        let a: Vec<DVec2> = [(-2.0, 0.0), (-1.0, 0.0), (-1.0, 1.0), (-2.0, 1.0)]
            .iter()
            .map(|&(x, y)| DVec2::new(x + dx, y + dy))
            .collect();
        let a = ConvexPolygon::try_new(&a).expect("valid");
        let h = f.hausdorff.as_deref().expect("hausdorff asked");
        let want = hausdorff_brute::<Robust>(&a, &b);
        assert_eq!(h.distance, want.distance, "t = {}", f.t);
        assert_eq!(h.squared_distance, want.squared_distance);
        assert_eq!(h.a_to_b.distance, want.p_to_q.distance);
        assert_eq!(h.b_to_a.distance, want.q_to_p.distance);
        let c = f.cmmr.expect("cmmr asked");
        assert_eq!(c, cmmr_brute::<Robust>(&a, &b).value, "t = {}", f.t);
        overlapping += usize::from(h.a_to_b.feature.is_none());
    }
    // The square moves into b: some frames have a vertex of a inside b.
    assert!(overlapping > 0);
}

/// distance and closest_points share one query per pair and frame; a static pair is evaluated once.
#[test]
fn shared_queries_and_static_pairs_once() {
    let text = format!(
        r#"
        time = {{ end = 99.0, step = 1.0 }}
        [[body]]
        id = "a"
        vertices = {}
        [[body]]
        id = "b"
        vertices = {}
        pose = {{ x = 1.0, y = 0.0, angle = 0.3 }}
        [[body]]
        id = "m"
        vertices = {}
        motion = {{ type = "linear", velocity = [0.0, 0.01] }}
        [[query]]
        pairs = [["a", "b"]]
        effects = ["distance"]
        [[query]]
        name = "both"
        pairs = [["b", "a"], ["a", "m"]]
        effects = ["closest_points", "distance"]
        "#,
        square(0.0, 0.0, 1.0),
        square(3.0, 0.0, 1.0),
        square(0.0, 5.0, 1.0)
    );
    let report = run_default(&scene(&text));
    assert_eq!(report.time.frames, 100);
    assert_eq!(report.pairs.len(), 2, "a–b named twice is one job");
    let ab = &report.pairs[0];
    assert_eq!(ab.queries, vec!["query #1".to_owned(), "both".to_owned()]);
    assert!(!ab.moving);
    assert_eq!(ab.frames.len(), 1);
    assert!(ab.frames[0].closest_points.is_some() && ab.frames[0].distance.is_some());
    let am = &report.pairs[1];
    assert!(am.moving);
    assert_eq!(am.frames.len(), 100);
    // 1 query for the static pair, 100 for the moving one: both effects from one query each.
    assert_eq!(report.costs.distance.calls, 101);
    // Poses: a and b once each (static), m once per frame.
    assert_eq!(report.costs.pose.calls, 2 + 100);
    // The moving pair's distance: the square m rises from y = 5 (gap 4) at 0.01 per frame.
    for f in &am.frames {
        let expect = 4.0 + 0.01 * f.t;
        assert!((f.distance.unwrap() - expect).abs() < 1e-12);
    }
}

/// Temporal coherence: identical results with and without, and fewer predicates with it.
#[test]
fn coherence_gives_identical_results_and_saves_predicates() {
    let text = r#"
        time = { end = 20.0, step = 0.05 }
        [[body]]
        id = "a"
        generator = { type = "random_convex", n = 500, radius = 2.0, seed = 11 }
        motion = { type = "linear", velocity = [0.0, 0.0], angular = 0.3 }
        [[body]]
        id = "b"
        generator = { type = "regular", n = 300, radius = 1.0 }
        pose = { x = 6.0, y = 0.0 }
        motion = { type = "keyframes", keys = [{ t = 0, x = 6 }, { t = 10, x = 4, y = 3, angle = 2 }, { t = 20, x = 6, y = -3, angle = -1 }] }
        [[query]]
        pairs = "all"
        effects = ["distance", "closest_points"]
        "#;
    // `pose` with keyframes is an error; drop it.
    let text = text.replace("pose = { x = 6.0, y = 0.0 }\n", "");
    let s = scene(&text);
    let on = run(&s, &RunOptions::default());
    let off = run(
        &s,
        &RunOptions {
            coherence: Some(false),
            ..RunOptions::default()
        },
    );
    assert_eq!(on.pairs, off.pairs, "identical results");
    assert!(on.coherence && !off.coherence);
    assert_eq!(on.costs.distance_hinted, 400);
    assert_eq!(off.costs.distance_hinted, 0);
    let (p_on, p_off) = (
        on.costs.distance.predicates.unwrap(),
        off.costs.distance.predicates.unwrap(),
    );
    assert!(p_on < p_off, "with hints {p_on}, without {p_off}");
    // Without counting, no predicate figures.
    let quiet = run(
        &s,
        &RunOptions {
            count_predicates: false,
            ..RunOptions::default()
        },
    );
    assert_eq!(quiet.costs.distance.predicates, None);
    assert_eq!(quiet.pairs, on.pairs);
}

/// The three kernels agree on well-separated input, and the report names the kernel.
#[test]
fn kernels_agree_on_easy_input() {
    let text = format!(
        r#"
        time = {{ end = 2.0, step = 0.5 }}
        [[body]]
        id = "a"
        generator = {{ type = "regular", n = 12, radius = 1.0 }}
        motion = {{ type = "linear", velocity = [0.5, 0.25], angular = 0.1 }}
        [[body]]
        id = "b"
        vertices = {}
        [[query]]
        pairs = "all"
        effects = ["distance", "closest_points", "vertex_distance"]
        "#,
        square(5.0, 0.0, 1.0)
    );
    let s = scene(&text);
    let reports: Vec<Report> = [
        polydist_scene::KernelChoice::Fast,
        polydist_scene::KernelChoice::Robust,
        polydist_scene::KernelChoice::Exact,
    ]
    .into_iter()
    .map(|k| {
        run(
            &s,
            &RunOptions {
                kernel: Some(k),
                ..RunOptions::default()
            },
        )
    })
    .collect();
    assert_eq!(reports[0].kernel, "fast");
    assert_eq!(reports[2].kernel, "exact");
    assert_eq!(reports[1].pairs, reports[2].pairs);
    assert_eq!(reports[0].pairs, reports[1].pairs);
}

/// A body that becomes invalid at some frames is reported for those frames; the run goes on.
#[test]
fn invalid_body_at_some_frames_is_reported_and_the_run_goes_on() {
    // x = 1e150·t leaves the coordinate range ±2^500 ≈ 3.3e150 after t = 3.
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
        [[query]]
        pairs = "all"
        effects = ["distance"]
        "#,
        square(0.0, 0.0, 1.0),
        square(0.0, 5.0, 1.0),
        square(5.0, 5.0, 1.0)
    );
    let report = run_default(&scene(&text));
    assert!(report.failed);
    let rb = &report.pairs[0];
    assert_eq!((rb.a.as_str(), rb.b.as_str()), ("runaway", "b"));
    assert!(rb.failed);
    assert_eq!(rb.frames.len(), 7);
    for f in &rb.frames {
        if f.t <= 3.0 {
            assert_eq!(f.status, Some(Status::Disjoint));
        } else {
            assert_eq!(f.status, Some(Status::Invalid));
            let e = f.error.as_deref().unwrap();
            assert!(e.contains("runaway") && e.contains("vertex"), "{e}");
        }
    }
    let bc = &report.pairs[2];
    assert_eq!((bc.a.as_str(), bc.b.as_str()), ("b", "c"));
    assert!(!bc.failed);
    assert_eq!(bc.frames[0].distance, Some(4.0));
}

/// A keyframed body that waits, then rushes: windowed speed bounds let the advancement take long
/// steps while it waits (the bound over the whole span would force steps of distance / 100).
#[test]
fn first_contact_windows_skip_the_wait() {
    // b sits at x = 11 until t = 100, then moves left at speed 100: it reaches a (x ≤ 1) at t = 100.1.
    let text = format!(
        r#"
        time = {{ end = 101.0, step = 1.0 }}
        [[body]]
        id = "a"
        vertices = {}
        [[body]]
        id = "b"
        vertices = {}
        motion = {{ type = "keyframes", keys = [{{ t = 0, x = 11 }}, {{ t = 100, x = 11 }}, {{ t = 101, x = -89 }}] }}
        [[query]]
        pairs = [["a", "b"]]
        effects = ["first_contact"]
        tolerance = 1e-9
        "#,
        square(0.0, 0.0, 1.0),
        square(0.0, 0.0, 1.0)
    );
    let c = run_default(&scene(&text)).pairs[0]
        .first_contact
        .clone()
        .unwrap();
    assert_eq!(c.outcome, ContactOutcome::Contact, "{c:?}");
    let (safe, hit) = (c.t_safe.unwrap(), c.t_hit.unwrap());
    assert!(safe <= 100.1 && 100.1 <= hit, "[{safe}, {hit}]");
    assert!(c.steps < 30, "{} steps", c.steps);
}
