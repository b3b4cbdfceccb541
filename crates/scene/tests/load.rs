//! Loading and validation: errors for people, every problem reported, limits refused, and no panic
//! on any text.

use polydist_polygon::PolygonError;
use polydist_scene::{
    Effect, MAX_FRAMES, MAX_VERTICES, Origin, SceneError, SceneErrors, Shape, load_file, load_str,
};
use proptest::prelude::*;

fn errors(text: &str) -> Vec<SceneError> {
    match load_str(text, &Origin::text("scene.toml")) {
        Ok(_) => panic!("expected errors"),
        Err(SceneErrors(e)) => e,
    }
}

#[test]
fn toml_syntax_error_names_file_line_column() {
    let e = errors("name = \"x\"\n[[body]]\nid = \"a\" oops\nvertices = [[0, 0], [1, 0]]\n");
    assert_eq!(e.len(), 1);
    let SceneError::Syntax {
        file, line, column, ..
    } = &e[0]
    else {
        panic!("{e:?}")
    };
    assert_eq!(file, "scene.toml");
    assert_eq!((*line, *column), (3, 10), "{}", e[0]);
    // An unclosed array is reported where the text ends.
    let e = errors("[[body]]\nid = \"a\"\nvertices = [[0, 0], [1, 0]\n");
    assert!(
        matches!(e[0], SceneError::Syntax { line: 4, .. }),
        "{}",
        e[0]
    );
    // A type error in a field: the span points at the value.
    let e = errors("[[body]]\nid = \"a\"\nvertices = \"square\"\n");
    let SceneError::Syntax {
        line,
        column,
        message,
        ..
    } = &e[0]
    else {
        panic!("{e:?}")
    };
    assert_eq!((*line, *column), (3, 12), "{message}");
    // An unknown field is an error, not silently ignored.
    let e = errors("[[body]]\nid = \"a\"\nvertice = [[0, 0]]\n");
    let text = e[0].to_string();
    assert!(text.starts_with("scene.toml:3:1"), "{text}");
    assert!(text.contains("vertice"), "{text}");
    // An unknown effect lists the expected ones.
    let e = errors("[[query]]\npairs = \"all\"\neffects = [\"distanse\"]\n");
    let text = e[0].to_string();
    assert!(
        text.contains("distanse") && text.contains("first_contact"),
        "{text}"
    );
    // "all" or a list.
    let e = errors("[[query]]\npairs = \"some\"\neffects = [\"distance\"]\n");
    assert!(e[0].to_string().contains(r#""all" or a list"#), "{}", e[0]);
}

#[test]
fn json_syntax_error_names_line_column() {
    let text = "{\n  \"body\": [\n    {\"id\": \"a\", \"vertices\": [[0, 0], [1, 0]] ,}\n  ]\n}";
    let e = match load_str(text, &Origin::text("s.json")) {
        Err(SceneErrors(e)) => e,
        Ok(_) => panic!("expected an error"),
    };
    let SceneError::Syntax { file, line, .. } = &e[0] else {
        panic!("{e:?}")
    };
    assert_eq!((file.as_str(), *line), ("s.json", 3));
    // JSON is detected from the content too.
    let ok = load_str(
        r#"{"bodies": [{"id": "a", "vertices": [[0, 0], [1, 0], [0, 1]]}], "queries": []}"#,
        &Origin::text("<stdin>"),
    )
    .unwrap();
    assert_eq!(ok.bodies.len(), 1);
}

#[test]
fn every_problem_is_reported() {
    let e = errors(
        r#"
        time = { start = 2.0, end = 1.0, step = 0.5 }
        [[body]]
        id = "a"
        kind = "convex"
        vertices = [[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]]
        [[body]]
        id = "a"
        generator = { type = "regular", n = 1000000000000, radius = 1.0 }
        [[body]]
        id = ""
        vertices = [[0, 0], [1, 0], [0, 1]]
        file = "x.txt"
        [[body]]
        id = "k"
        vertices = [[0, 0], [1, 0], [0, 1]]
        pose = { x = 1.0 }
        motion = { type = "keyframes", keys = [{ t = 1.0 }, { t = 1.0 }] }
        [[body]]
        id = "star"
        generator = { type = "star", points = 5, outer = 2.0, inner = 1.0 }
        [[query]]
        pairs = [["a", "nobody"], ["k", "k"]]
        effects = ["hausdorff", "distance", "cmmr"]
        [[query]]
        name = "sep"
        pairs = [["k", "star"]]
        effects = ["separation", "first_contact"]
        max_steps = 0
        [[query]]
        pairs = "all"
        effects = []
        "#,
    );
    let text: Vec<String> = e.iter().map(ToString::to_string).collect();
    let has = |pred: &dyn Fn(&SceneError) -> bool| e.iter().any(pred);
    assert!(
        has(&|e| matches!(e, SceneError::BadTime { .. })),
        "{text:#?}"
    );
    // The reflex vertex of body a is named: vertex 2 (0-based), (1, 0.5).
    assert!(has(&|e| matches!(
        e,
        SceneError::InvalidPolygon { body, kind: "convex", source: PolygonError::NotConvex { index: 2 } } if body == "a"
    )));
    assert!(has(
        &|e| matches!(e, SceneError::DuplicateId { id, first: 1, second: 2 } if id == "a")
    ));
    assert!(has(&|e| matches!(
        e,
        SceneError::TooManyVertices { count: 1_000_000_000_000, limit, .. } if *limit == MAX_VERTICES
    )));
    assert!(has(&|e| matches!(e, SceneError::EmptyId { index: 3 })));
    assert!(has(&|e| matches!(
        e,
        SceneError::ShapeSource { found: 2, .. }
    )));
    assert!(has(
        &|e| matches!(e, SceneError::PoseWithKeyframes { body } if body == "k")
    ));
    assert!(has(&|e| matches!(
        e,
        SceneError::BadKeyframes { index: 1, .. }
    )));
    assert!(has(
        &|e| matches!(e, SceneError::UnknownBody { id, .. } if id == "nobody")
    ));
    assert!(has(
        &|e| matches!(e, SceneError::SelfPair { id, .. } if id == "k")
    ));
    // Every effect is available now; `separation` takes simple bodies, the others do not.
    assert!(!has(&|e| matches!(
        e,
        SceneError::EffectNotYetAvailable { .. }
    )));
    assert!(!has(&|e| matches!(
        e,
        SceneError::NeedsConvex {
            effect: "separation",
            ..
        }
    )));
    assert!(has(&|e| matches!(
        e,
        SceneError::NeedsConvex { effect: "first_contact", body, .. } if body == "star"
    )));
    assert!(has(&|e| matches!(e, SceneError::BadParameter { .. })));
    assert!(has(&|e| matches!(e, SceneError::NoEffects { .. })));
    // The message of a convex-only effect on a simple body names the query and says what to do.
    let msg = text.iter().find(|t| t.contains("`first_contact`")).unwrap();
    assert!(
        msg.contains("sep") && msg.contains("ask `separation`"),
        "{msg}"
    );
    // The whole list renders with a count.
    let all = SceneErrors(e.clone()).to_string();
    assert!(
        all.starts_with(&format!("{} problems in the scene:", e.len())),
        "{all}"
    );
}

#[test]
fn first_contact_parameters_are_checked() {
    let q = |extra: &str| {
        format!(
            "[[body]]\nid = \"a\"\nvertices = [[0, 0], [1, 0], [0, 1]]\n[[body]]\nid = \"b\"\nvertices = [[5, 0], [6, 0], [5, 1]]\n[[query]]\npairs = \"all\"\neffects = [\"first_contact\"]\n{extra}"
        )
    };
    for bad in [
        "tolerance = 0.0\n",
        "tolerance = -1.0\n",
        "tolerance = nan\n",
        "max_steps = 0\n",
    ] {
        let e = errors(&q(bad));
        assert!(
            matches!(e[0], SceneError::BadParameter { .. }),
            "{bad}: {e:?}"
        );
    }
    assert!(
        load_str(
            &q("tolerance = 1e-12\nmax_steps = 1\n"),
            &Origin::text("q.toml")
        )
        .is_ok()
    );
    // Two queries asking first_contact on one pair with different parameters.
    let text = format!(
        "{}[[query]]\npairs = [[\"b\", \"a\"]]\neffects = [\"first_contact\"]\ntolerance = 0.5\n",
        q("")
    );
    let e = errors(&text);
    assert!(
        matches!(e[0], SceneError::ConflictingParameters { .. }),
        "{e:?}"
    );
}

#[test]
fn limits_refuse_huge_spans_and_generators() {
    let e = errors("time = { end = 1e15, step = 1.0 }\n");
    assert!(matches!(
        e[0],
        SceneError::TooManyFrames { limit, .. } if limit == MAX_FRAMES
    ));
    let e = errors(
        "[[body]]\nid = \"a\"\ngenerator = { type = \"random_convex\", n = 1099511627776, radius = 1.0, seed = 1 }\n",
    );
    assert!(matches!(e[0], SceneError::TooManyVertices { .. }), "{e:?}");
    // Negative counts are a type error with a position, not a wrap-around.
    let e =
        errors("[[body]]\nid = \"a\"\ngenerator = { type = \"regular\", n = -5, radius = 1.0 }\n");
    assert!(matches!(e[0], SceneError::Syntax { line: 3, .. }), "{e:?}");
    // Pair-frame work: 200 bodies, all pairs, 10,000 frames.
    let mut text = String::from("time = { end = 9999.0, step = 1.0 }\n");
    for i in 0..200 {
        text.push_str(&format!(
            "[[body]]\nid = \"b{i}\"\nvertices = [[{i}, 0], [{i}.5, 0], [{i}, 0.5]]\n"
        ));
    }
    text.push_str("[[query]]\npairs = \"all\"\neffects = [\"distance\"]\n");
    let e = errors(&text);
    assert!(
        matches!(
            e[0],
            SceneError::TooMuchWork {
                what: "pair-frame evaluations",
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn kinds_are_detected_once_at_load() {
    let s = load_str(
        r#"
        [[body]]
        id = "tri"
        vertices = [[0, 0], [1, 0], [0, 1]]
        [[body]]
        id = "l"
        vertices = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]
        [[body]]
        id = "seg"
        vertices = [[5, 5], [6, 6]]
        [[body]]
        id = "declared"
        kind = "simple"
        vertices = [[0, 0], [1, 0], [0, 1]]
        [[body]]
        id = "comb"
        generator = { type = "comb", teeth = 3, width = 0.5, height = 1.0, spine = 0.5 }
        "#,
        &Origin::text("k.toml"),
    )
    .unwrap();
    let kinds: Vec<&str> = s.bodies.iter().map(|b| b.shape.kind()).collect();
    assert_eq!(kinds, ["convex", "simple", "convex", "simple", "simple"]);
    assert!(matches!(s.bodies[2].shape, Shape::Convex(ref p) if p.len() == 2));
    // A bow tie is neither: the error is the simple polygon's, naming the crossing edges.
    let e = errors("[[body]]\nid = \"bow\"\nvertices = [[0, 0], [1, 1], [1, 0], [0, 1]]\n");
    assert!(matches!(
        &e[0],
        SceneError::InvalidPolygon { body, kind: "simple", source: PolygonError::SelfIntersection { .. } } if body == "bow"
    ));
    assert!(e[0].to_string().contains("body 'bow'"));
}

#[test]
fn polygon_files_resolve_against_the_scene_directory() {
    let dir = std::env::temp_dir().join(format!("polydist-scene-test-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("polygons")).unwrap();
    std::fs::write(
        dir.join("polygons/tri.txt"),
        "# a triangle\n0 0\n3 0\n0 3\n",
    )
    .unwrap();
    std::fs::write(dir.join("polygons/bad.txt"), "0 0\n3 zero\n").unwrap();
    std::fs::write(
        dir.join("scene.toml"),
        "[[body]]\nid = \"t\"\nfile = \"polygons/tri.txt\"\n[[body]]\nid = \"b\"\nfile = \"polygons/bad.txt\"\n[[body]]\nid = \"m\"\nfile = \"polygons/missing.txt\"\n",
    )
    .unwrap();
    let e = load_file(&dir.join("scene.toml")).unwrap_err().0;
    assert_eq!(e.len(), 2, "{e:?}");
    assert!(e[0].to_string().contains("body 'b'") && e[0].to_string().contains("line 2"));
    assert!(e[1].to_string().contains("missing.txt"));
    std::fs::write(
        dir.join("ok.toml"),
        "[[body]]\nid = \"t\"\nfile = \"polygons/tri.txt\"\n",
    )
    .unwrap();
    let s = load_file(&dir.join("ok.toml")).unwrap();
    assert_eq!(s.bodies[0].shape.vertices().len(), 3);
    assert_eq!(s.name, "ok");
    // Text without a directory cannot name files.
    let e = errors("[[body]]\nid = \"t\"\nfile = \"polygons/tri.txt\"\n");
    assert!(matches!(e[0], SceneError::BadPolygonFile { .. }));
    assert!(matches!(
        load_file(&dir.join("nope.toml")).unwrap_err().0[0],
        SceneError::Io { .. }
    ));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn effect_names_round_trip() {
    for e in Effect::ALL {
        let text = format!("[[query]]\npairs = []\neffects = [\"{}\"]\n", e.name());
        let r = load_str(&text, &Origin::text("e.toml"));
        assert_eq!(r.is_ok(), e.is_available(), "{}", e.name());
    }
}

const SHAPES: &[&str] = &[
    "vertices = [[0, 0], [1, 0], [0, 1]]",
    "vertices = [[3, 3], [4, 3], [4, 4], [3, 4]]",
    "vertices = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]",
    "vertices = [[0, 0], [1, 1], [1, 0], [0, 1]]",
    "vertices = [[5, 5]]",
    "vertices = [[-2, 0], [-1, 1]]",
    "vertices = []",
    "generator = { type = \"regular\", n = 7, radius = 0.5 }",
    "generator = { type = \"random_convex\", n = 12, radius = 1.5, seed = 9 }",
    "generator = { type = \"star\", points = 4, outer = 1.0, inner = 0.4 }",
    "generator = { type = \"comb\", teeth = 2, width = 0.3, height = 1.0, spine = 0.2 }",
    "generator = { type = \"regular\", n = 2, radius = 1.0 }",
];
const POSES: &[&str] = &[
    "",
    "pose = { x = 2.0, y = -1.0, angle = 0.5 }\n",
    "pose = { x = 1e200 }\n",
];
const MOTIONS: &[&str] = &[
    "",
    "motion = { type = \"static\" }\n",
    "motion = { type = \"linear\", velocity = [1.0, 0.5], angular = 2.0 }\n",
    "motion = { type = \"linear\", velocity = [-3.0, 0.0] }\n",
    "motion = { type = \"keyframes\", keys = [{ t = 0 }, { t = 1, x = 3, angle = 9 }] }\n",
    "motion = { type = \"keyframes\", keys = [{ t = 1 }, { t = 0 }] }\n",
];
const KINDS: &[&str] = &["", "kind = \"convex\"\n", "kind = \"simple\"\n"];
const PAIRS: &[&str] = &[
    "\"all\"",
    "[[\"a\", \"b\"]]",
    "[[\"b\", \"c\"], [\"a\", \"c\"]]",
    "[[\"a\", \"a\"]]",
    "[]",
];
const TIMES: &[&str] = &[
    "",
    "time = { end = 2.0, step = 0.5 }\n",
    "time = { start = 1.0, end = 3.0, step = 0.25 }\n",
    "time = { end = -2.0, step = 0.0 }\n",
];

/// A scene text from structured choices: usually valid TOML, often a valid scene.
fn scene_text(
    time: usize,
    kernel: usize,
    bodies: &[(usize, usize, usize, usize)],
    queries: &[(usize, Vec<bool>, bool)],
) -> String {
    let mut s = String::from(TIMES[time]);
    s.push_str(["", "kernel = \"fast\"\n", "kernel = \"exact\"\n"][kernel]);
    for (i, &(shape, pose, motion, kind)) in bodies.iter().enumerate() {
        let id = ["a", "b", "c", "d"][i];
        s.push_str(&format!(
            "[[body]]\nid = \"{id}\"\n{}\n{}{}{}",
            SHAPES[shape], POSES[pose], MOTIONS[motion], KINDS[kind]
        ));
    }
    for (pairs, effects, params) in queries {
        let list: Vec<String> = Effect::ALL
            .iter()
            .zip(effects)
            .filter(|(_, on)| **on)
            .map(|(e, _)| format!("\"{}\"", e.name()))
            .collect();
        s.push_str(&format!(
            "[[query]]\npairs = {}\neffects = [{}]\n",
            PAIRS[*pairs],
            list.join(", ")
        ));
        if *params {
            s.push_str("tolerance = 0.001\nmax_steps = 40\n");
        }
    }
    s
}

fn body_strategy() -> impl Strategy<Value = (usize, usize, usize, usize)> {
    (
        0..SHAPES.len(),
        0..POSES.len(),
        0..MOTIONS.len(),
        0..KINDS.len(),
    )
}

fn query_strategy() -> impl Strategy<Value = (usize, Vec<bool>, bool)> {
    (
        0..PAIRS.len(),
        proptest::collection::vec(proptest::bool::weighted(0.3), 7),
        any::<bool>(),
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    /// Any text: a scene or typed errors, never a panic.
    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,300}") {
        let _ = load_str(&text, &Origin::text("fuzz.toml"));
        let _ = load_str(&text, &Origin::text("fuzz.json"));
    }

    /// Structured scenes: loading never panics, errors are never empty, and what loads also runs
    /// without panicking and reports one entry per planned pair.
    #[test]
    fn structured_scenes_load_and_run_without_panic(
        time in 0..TIMES.len(),
        kernel in 0..3usize,
        bodies in proptest::collection::vec(body_strategy(), 0..4),
        queries in proptest::collection::vec(query_strategy(), 0..3),
    ) {
        let text = scene_text(time, kernel, &bodies, &queries);
        match load_str(&text, &Origin::text("gen.toml")) {
            Ok(scene) => {
                let report = polydist_scene::run(&scene, &polydist_scene::RunOptions::default());
                prop_assert_eq!(report.pairs.len(), polydist_scene::plan(&scene).jobs.len());
                let _ = report.to_table();
            }
            Err(SceneErrors(e)) => prop_assert!(!e.is_empty()),
        }
    }
}

/// The structured generator reaches valid scenes often enough for the property above to run
/// scenes, not only to reject them.
#[test]
fn structured_scenes_are_often_valid() {
    let mut valid = 0;
    let mut ran_pairs = 0;
    for k in 0..500usize {
        let pick = |m: usize, salt: usize| (k.wrapping_mul(2_654_435_761) >> (salt * 3)) % m;
        let n = pick(4, 1);
        let bodies: Vec<_> = (0..n)
            .map(|i| {
                (
                    pick(SHAPES.len(), 2 + i) % 3 + usize::from(i % 2 == 1) * 7,
                    pick(2, 3 + i),
                    pick(MOTIONS.len() - 1, 4 + i),
                    0,
                )
            })
            .collect();
        let effects = vec![
            true,
            pick(2, 5) == 1,
            pick(2, 6) == 1,
            false,
            false,
            false,
            pick(2, 7) == 1,
        ];
        let queries = vec![(pick(2, 8), effects, true)];
        let text = scene_text(pick(3, 9), pick(3, 10), &bodies, &queries);
        if let Ok(scene) = load_str(&text, &Origin::text("gen.toml")) {
            valid += 1;
            ran_pairs += polydist_scene::run(&scene, &polydist_scene::RunOptions::default())
                .pairs
                .len();
        }
    }
    assert!(valid >= 100, "{valid} valid of 500");
    assert!(ran_pairs >= 100, "{ran_pairs} pairs run");
}
