//! `render_svg`: the document is well-formed XML (checked by a minimal parser here: balanced tags,
//! quoted attributes, escaped text) and holds the expected elements for the fixture scenes.

use std::collections::HashMap;
use std::path::Path;

use polydist_scene::{Origin, RunOptions, Scene, load_file, load_str, render_svg, run};

/// A parsed element: its name and attributes.
type Element = (String, HashMap<String, String>);

/// Parses `s` as XML just enough to check it is well-formed; returns the elements in order.
fn parse_xml(s: &str) -> Vec<Element> {
    let mut out = Vec::new();
    let mut stack: Vec<String> = Vec::new();
    let mut rest = s.trim_start();
    if let Some(r) = rest.strip_prefix("<?xml") {
        let end = r.find("?>").expect("unterminated XML declaration");
        rest = &r[end + 2..];
    }
    let check_text = |t: &str| {
        assert!(!t.contains('>'), "raw '>' in text: {t:?}");
        for (i, _) in t.match_indices('&') {
            let ent = &t[i..t[i..].find(';').map_or(t.len(), |e| i + e + 1)];
            assert!(
                ["&amp;", "&lt;", "&gt;", "&quot;", "&apos;"].contains(&ent),
                "bad entity {ent:?}"
            );
        }
    };
    let mut roots = 0;
    while !rest.is_empty() {
        let lt = rest.find('<').unwrap_or(rest.len());
        check_text(&rest[..lt]);
        if lt == rest.len() {
            break;
        }
        rest = &rest[lt + 1..];
        let gt = rest.find('>').expect("unterminated tag");
        let tag = &rest[..gt];
        rest = &rest[gt + 1..];
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(
                stack.pop().as_deref(),
                Some(name.trim()),
                "mismatched </{name}>"
            );
            continue;
        }
        let self_closing = tag.ends_with('/');
        let tag = tag.trim_end_matches('/');
        let name_end = tag.find(char::is_whitespace).unwrap_or(tag.len());
        let name = tag[..name_end].to_owned();
        assert!(!name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '-'));
        let mut attrs = HashMap::new();
        let mut a = tag[name_end..].trim();
        while !a.is_empty() {
            let eq = a.find('=').expect("attribute without value");
            let key = a[..eq].trim().to_owned();
            let v = a[eq + 1..].strip_prefix('"').expect("unquoted attribute");
            let close = v.find('"').expect("unterminated attribute");
            let value = &v[..close];
            assert!(!value.contains('<'), "'<' in attribute {key}");
            check_text(value);
            assert!(
                attrs.insert(key.clone(), value.to_owned()).is_none(),
                "duplicate {key}"
            );
            a = v[close + 1..].trim_start();
        }
        if stack.is_empty() {
            roots += 1;
        }
        if !self_closing {
            stack.push(name.clone());
        }
        out.push((name, attrs));
    }
    assert!(stack.is_empty(), "unclosed {stack:?}");
    assert_eq!(roots, 1, "one root element");
    out
}

fn count(elements: &[Element], name: &str, class: &str) -> usize {
    elements
        .iter()
        .filter(|(n, a)| n == name && a.get("class").is_some_and(|c| c == class))
        .count()
}

fn fixture(name: &str) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures/scenes")
        .join(name);
    load_file(&path).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn default_scene_draws_bodies_closest_segments_and_hausdorff_witnesses() {
    let scene = fixture("default.toml");
    let report = run(&scene, &RunOptions::default());
    let svg = render_svg(&scene, &report);
    let el = parse_xml(&svg);
    assert_eq!(el[0].0, "svg");
    assert_eq!(count(&el, "polygon", "body"), scene.bodies.len());
    let moving = scene
        .bodies
        .iter()
        .filter(|b| !b.motion.is_static())
        .count();
    let frames = scene.time.frames;
    let expect_traj = if frames > 1 { moving } else { 0 };
    assert_eq!(count(&el, "polyline", "trajectory"), expect_traj);
    assert_eq!(count(&el, "polygon", "ghost"), expect_traj);
    // One closest segment per pair with closest points at the drawn frame; two witnesses per pair
    // with a Hausdorff result.
    let t: f64 = el
        .iter()
        .find(|(n, a)| n == "polygon" && a["class"] == "body")
        .map(|(_, a)| a["data-t"].parse().unwrap())
        .unwrap();
    let at = |p: &polydist_scene::PairReport| {
        if p.moving {
            p.frames.iter().find(|f| (f.t - t).abs() <= 1e-3).cloned()
        } else {
            p.frames.first().cloned()
        }
    };
    let closest = report
        .pairs
        .iter()
        .filter(|p| at(p).is_some_and(|f| f.closest_points.is_some()))
        .count();
    let hausdorff = report
        .pairs
        .iter()
        .filter(|p| at(p).is_some_and(|f| f.hausdorff.is_some()))
        .count();
    assert!(closest > 0 && hausdorff > 0, "the default scene shows both");
    assert_eq!(count(&el, "line", "closest"), closest);
    assert_eq!(count(&el, "line", "hausdorff"), 2 * hausdorff);
    assert_eq!(count(&el, "circle", "hausdorff-vertex"), 2 * hausdorff);
}

#[test]
fn moving_scene_has_trajectories_and_a_distance_plot() {
    let scene = fixture("corridor.toml");
    let report = run(&scene, &RunOptions::default());
    let el = parse_xml(&render_svg(&scene, &report));
    let moving = scene
        .bodies
        .iter()
        .filter(|b| !b.motion.is_static())
        .count();
    assert!(moving > 0 && scene.time.frames > 1);
    assert_eq!(count(&el, "polyline", "trajectory"), moving);
    let plotted = report
        .pairs
        .iter()
        .filter(|p| p.moving && p.frames.iter().any(|f| f.distance.is_some()))
        .count();
    assert_eq!(count(&el, "g", "distance-plot"), usize::from(plotted > 0));
    assert_eq!(count(&el, "polyline", "distance"), plotted);
    // Every distance polyline has one point per frame with a distance.
    for (n, a) in &el {
        if n == "polyline" && a["class"] == "distance" {
            assert_eq!(a["points"].split(' ').count(), scene.time.frames);
        }
    }
}

#[test]
fn ids_are_escaped() {
    let scene = load_str(
        r#"
        [[body]]
        id = "<a & 'b'>"
        vertices = [[0, 0], [1, 0], [0, 1]]
        [[body]]
        id = "\"c\""
        vertices = [[3, 0], [4, 0], [3, 1]]
        [[query]]
        pairs = "all"
        effects = ["distance", "closest_points", "hausdorff"]
        "#,
        &Origin::text("esc.toml"),
    )
    .unwrap();
    let report = run(&scene, &RunOptions::default());
    let el = parse_xml(&render_svg(&scene, &report));
    assert!(el.iter().any(|(_, a)| {
        a.get("data-body")
            .is_some_and(|v| v == "&lt;a &amp; &apos;b&apos;&gt;")
    }));
    assert_eq!(count(&el, "line", "closest"), 1);
}
