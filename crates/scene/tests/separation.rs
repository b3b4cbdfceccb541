//! The `separation` effect on simple bodies: answers against the separation crate's brute-force twin
//! on the posed bodies (the separator route for interlocked combs and for a polygon in a pocket of
//! the other), the `intersecting` outcome, the counters (only the asked work is done), and the
//! `NeedsConvex` rule for the other effects.

use glam::DVec2;
use polydist_polygon::SimplePolygon;
use polydist_polygon::predicates::Robust;
use polydist_scene::{Origin, RunOptions, SceneError, Status, load_str, run};
use polydist_separation::{PolygonSeparation, polygon_separation_brute};

const SCENE: &str = r#"
time = { start = 0.0, end = 4.0, step = 0.5 }

[[body]]
id = "u"
kind = "simple"
vertices = [[0, 0], [10, 0], [10, 10], [0, 10], [0, 7], [6, 7], [6, 3], [0, 3]]

[[body]]
id = "l"
kind = "simple"
vertices = [[-20, 0], [-12, 0], [-12, 2], [-18, 2], [-18, 8], [-20, 8]]
motion = { type = "linear", velocity = [2.0, 0.0] }

[[body]]
id = "comb_a"
kind = "simple"
vertices = [[0, 20], [9, 20], [9, 24], [8, 24], [8, 21], [5, 21], [5, 24], [4, 24], [4, 21], [1, 21], [1, 24], [0, 24]]

[[body]]
id = "comb_b"
kind = "simple"
# Teeth pointing down into comb_a's gaps, without touching: the hulls meet.
vertices = [[2, 22], [3, 22], [3, 25], [6, 25], [6, 22], [7, 22], [7, 26], [2, 26]]

[[body]]
id = "pebble"
kind = "simple"
# Inside u's pocket: CH(pebble) lies inside CH(u), the separator's containing case.
vertices = [[1, 4], [2, 4], [2, 6], [1, 6]]

[[query]]
name = "clearance"
pairs = [["u", "l"], ["comb_a", "comb_b"], ["u", "pebble"]]
effects = ["separation"]
"#;

#[test]
fn separation_frames_match_the_brute_force_and_the_run_goes_on() {
    let scene = match load_str(SCENE, &Origin::text("sep.toml")) {
        Ok(s) => s,
        Err(e) => panic!("{e}"),
    };
    let report = run(&scene, &RunOptions::default());
    let ul = report.pairs.iter().find(|p| p.a == "u").expect("pair u–l");
    let combs = report
        .pairs
        .iter()
        .find(|p| p.a == "comb_a")
        .expect("pair of combs");
    // u – l: l's right end slides from x = -12 to x = -4 at 2 per unit of time; u starts at x = 0.
    assert_eq!(ul.frames.len(), 9);
    let u: Vec<DVec2> = [
        [0, 0],
        [10, 0],
        [10, 10],
        [0, 10],
        [0, 7],
        [6, 7],
        [6, 3],
        [0, 3],
    ]
    .iter()
    .map(|&[x, y]| DVec2::new(f64::from(x), f64::from(y)))
    .collect();
    let su = SimplePolygon::try_new(&u).unwrap();
    for f in &ul.frames {
        // l moved by 2t along x (exact: t is a multiple of 1/2).
        let l: Vec<DVec2> = [[-20, 0], [-12, 0], [-12, 2], [-18, 2], [-18, 8], [-20, 8]]
            .iter()
            .map(|&[x, y]| DVec2::new(f64::from(x) + 2.0 * f.t, f64::from(y)))
            .collect();
        let sl = SimplePolygon::try_new(&l).unwrap();
        let Ok(PolygonSeparation::Separated { pair, .. }) =
            polygon_separation_brute::<Robust>(&su, &sl)
        else {
            panic!("disjoint at {}", f.t);
        };
        assert_eq!(f.status, Some(Status::Disjoint), "t = {}", f.t);
        let s = f.separation.expect("separation");
        assert_eq!(s.distance, pair.distance, "t = {}", f.t);
        assert_eq!(s.distance, 12.0 - 2.0 * f.t);
    }
    // The combs interlock: disjoint, but their hulls meet: Amato's separator answers.
    let poly = |v: &[[i32; 2]]| {
        let v: Vec<DVec2> = v
            .iter()
            .map(|&[x, y]| DVec2::new(f64::from(x), f64::from(y)))
            .collect();
        SimplePolygon::try_new(&v).unwrap()
    };
    let ca = poly(&[
        [0, 20],
        [9, 20],
        [9, 24],
        [8, 24],
        [8, 21],
        [5, 21],
        [5, 24],
        [4, 24],
        [4, 21],
        [1, 21],
        [1, 24],
        [0, 24],
    ]);
    let cb = poly(&[
        [2, 22],
        [3, 22],
        [3, 25],
        [6, 25],
        [6, 22],
        [7, 22],
        [7, 26],
        [2, 26],
    ]);
    // Static pairs answered by the separators: every frame disjoint at the brute force's distance.
    let static_separators =
        |frames: &[polydist_scene::FrameResult], a: &SimplePolygon, b: &SimplePolygon| {
            let Ok(PolygonSeparation::Separated { pair, .. }) =
                polygon_separation_brute::<Robust>(a, b)
            else {
                panic!("the bodies are disjoint");
            };
            assert!(!frames.is_empty());
            for f in frames {
                assert_eq!(f.status, Some(Status::Disjoint));
                let s = f.separation.expect("separation");
                assert_eq!(s.distance, pair.distance);
                assert_eq!(s.route, "separators");
            }
        };
    static_separators(&combs.frames, &ca, &cb);
    // The pebble in u's pocket (the containing case).
    let pebble = report
        .pairs
        .iter()
        .find(|p| p.b == "pebble")
        .expect("pair u–pebble");
    static_separators(
        &pebble.frames,
        &su,
        &poly(&[[1, 4], [2, 4], [2, 6], [1, 6]]),
    );
    assert!(!pebble.failed && !combs.failed && !ul.failed && !report.failed);
    // Only the asked work: separation, no convex distance of any kind.
    let c = report.costs;
    assert!(c.separation.calls >= 9);
    assert_eq!(
        c.distance.calls + c.vertex_distance.calls + c.hausdorff.calls + c.cmmr.calls,
        0
    );
}

#[test]
fn meeting_bodies_are_intersecting_and_convex_effects_need_convex_bodies() {
    let text = r#"
[[body]]
id = "l"
kind = "simple"
vertices = [[0, 0], [4, 0], [4, 1], [1, 1], [1, 4], [0, 4]]
[[body]]
id = "sq"
vertices = [[0.5, 0.5], [3, 0.5], [3, 3], [0.5, 3]]
[[query]]
pairs = [["l", "sq"]]
effects = ["separation"]
"#;
    let scene = load_str(text, &Origin::text("meet.toml")).unwrap_or_else(|e| panic!("{e}"));
    let report = run(&scene, &RunOptions::default());
    assert_eq!(report.pairs[0].frames[0].status, Some(Status::Intersecting));
    assert!(report.pairs[0].frames[0].separation.is_none());
    // `distance` on a simple body is refused at load, naming `separation` as the way.
    let refused = text.replace("effects = [\"separation\"]", "effects = [\"distance\"]");
    let errors = load_str(&refused, &Origin::text("refused.toml"))
        .unwrap_err()
        .0;
    assert!(errors.iter().any(|e| matches!(
        e,
        SceneError::NeedsConvex {
            effect: "distance",
            ..
        }
    )));
}
