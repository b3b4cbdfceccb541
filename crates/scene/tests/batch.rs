//! `batch_pairs` and `batch_within` against the exact oracle: distances within 3 ulps of the exact
//! value, statuses equal to the exact contact status, the pairs within a distance equal to the exact
//! all-pairs answer; per-line errors that name the line and do not stop the batch; the same bytes
//! on any number of threads and any chunk size.

use std::collections::BTreeSet;

use glam::DVec2;
use polydist_oracle::{
    Contact, Relation, SplitMix64, contact_status_convex, convex_distance, convex_pair,
    min_vertex_distance, random_convex, rat, ulps_error_sqrt,
};
use polydist_scene::{BatchOptions, BatchSummary, batch_pairs, batch_within, read_layer};
use serde_json::Value;

fn ring(v: &[DVec2]) -> Value {
    Value::from(v.iter().map(|p| vec![p.x, p.y]).collect::<Vec<_>>())
}

fn run_batch(input: &str, options: &BatchOptions, threads: usize) -> (String, BatchSummary) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    let mut out = Vec::new();
    let summary = pool
        .install(|| batch_pairs(input.as_bytes(), &mut out, options))
        .unwrap();
    (String::from_utf8(out).unwrap(), summary)
}

fn parse_lines(out: &str) -> Vec<Value> {
    out.lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

#[test]
fn pairs_agree_with_the_exact_oracle() {
    let mut rng = SplitMix64::new(77);
    let mut input = String::new();
    let mut cases = Vec::new();
    for (k, rel) in Relation::EVERY.iter().cycle().take(120).enumerate() {
        let n = 3 + (k % 9);
        let m = 3 + (k * 7 % 13);
        let pair = convex_pair(&mut rng, n, m, *rel);
        let line = serde_json::json!({
            "id": format!("case{k}"),
            "a": ring(&pair.p),
            "b": ring(&pair.q),
            "effects": ["distance", "closest_points", "vertex_distance"],
        });
        input += &line.to_string();
        input.push('\n');
        cases.push((pair, *rel));
    }
    let (out, summary) = run_batch(&input, &BatchOptions::default(), 2);
    assert_eq!(summary.lines, 120);
    assert_eq!(summary.errors, 0, "{out}");
    let answers = parse_lines(&out);
    for (k, (a, (pair, rel))) in answers.iter().zip(&cases).enumerate() {
        assert_eq!(a["line"], k + 1);
        assert_eq!(a["id"], format!("case{k}"));
        let exact = convex_distance(&pair.p, &pair.q);
        let d = a["distance"].as_f64().unwrap();
        assert!(ulps_error_sqrt(d, &exact.sq) <= 3.0, "case {k}: {d}");
        let status = match contact_status_convex(&pair.p, &pair.q) {
            Contact::Disjoint => "disjoint",
            Contact::Touching => "touching",
            Contact::Overlapping => "overlapping",
        };
        assert_eq!(a["status"], status, "case {k}");
        // vertex_distance is between corners; collinear input vertices are not corners (the
        // oracle's brute force takes every input vertex), so that relation is checked by distance
        // only.
        if *rel != Relation::CollinearInput {
            let (vsq, _) = min_vertex_distance(&pair.p, &pair.q);
            let vd = a["vertex_distance"]["distance"].as_f64().unwrap();
            assert!(ulps_error_sqrt(vd, &vsq) <= 3.0, "case {k}: {vd}");
        }
        assert_eq!(a.get("closest_points").is_some(), status != "overlapping");
    }
}

#[test]
fn bad_lines_get_error_lines_and_the_batch_goes_on() {
    let good = r#"{"id": 1, "a": [[0, 0], [1, 0], [0, 1]], "b": [[3, 0], [4, 0], [3, 1]]}"#;
    let input = [
        good,
        r#"{"a": [[0, 0], [1, 0]"#,
        "",
        r#"{"id": "reflex", "a": [[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]], "b": [[5, 5]]}"#,
        r#"{"a": [[0, 0]], "b": [[1, 1]], "effects": ["first_contact"]}"#,
        r#"{"a": [[0, 0]], "b": [[1, 1]], "effects": ["teleport"]}"#,
        r#"{"a": [[0, 0]], "b": [[1, 1]], "colour": "red"}"#,
        r#"{"a": [[0, 0]], "b": [[1e300, 1]]}"#,
        r#"{"a": [[0, 0]], "b": [[1, 1]], "within": -2}"#,
        r#"{"a": [[0, 0]], "b": [[3, 4]], "within": 4.5, "effects": ["distance"]}"#,
        good,
    ]
    .join("\n");
    let (out, summary) = run_batch(&input, &BatchOptions::default(), 2);
    assert_eq!(
        summary,
        BatchSummary {
            lines: 10,
            answered: 3,
            errors: 7
        }
    );
    let a = parse_lines(&out);
    let lines: Vec<u64> = a.iter().map(|v| v["line"].as_u64().unwrap()).collect();
    assert_eq!(lines, [1, 2, 4, 5, 6, 7, 8, 9, 10, 11]);
    assert_eq!(a[0]["distance"], 2.0);
    let err = |i: usize| a[i]["error"].as_str().unwrap().to_owned();
    assert!(err(1).contains("line 2, column"), "{}", err(1));
    assert!(
        err(2).contains("'a' is not a valid convex polygon") && err(2).contains("vertex 2"),
        "{}",
        err(2)
    );
    assert_eq!(a[2]["id"], "reflex");
    assert!(err(3).contains("first_contact needs motions"), "{}", err(3));
    assert!(err(4).contains("teleport"), "{}", err(4));
    assert!(err(5).contains("colour"), "{}", err(5));
    assert!(err(6).contains("'b'"), "{}", err(6));
    assert!(err(7).contains("within must be >= 0"), "{}", err(7));
    assert_eq!(a[8]["status"], "beyond");
    assert!(a[8].get("distance").is_none());
    assert_eq!(a[9]["distance"], 2.0);
}

#[test]
fn same_output_on_any_thread_count_and_chunk_size() {
    let mut rng = SplitMix64::new(5);
    let mut input = String::new();
    for k in 0..200 {
        let rel = Relation::EVERY[k % Relation::EVERY.len()];
        let pair = convex_pair(&mut rng, 3 + k % 17, 3 + k % 5, rel);
        let line = serde_json::json!({
            "a": ring(&pair.p), "b": ring(&pair.q),
            "effects": ["distance", "closest_points", "hausdorff", "cmmr"],
        });
        input += &line.to_string();
        input += if k % 50 == 3 { "\n{oops\n" } else { "\n" };
    }
    let base = run_batch(&input, &BatchOptions::default(), 1);
    for (threads, chunk) in [(2, 1), (3, 7), (2, 1024), (1, 13)] {
        let options = BatchOptions {
            chunk,
            ..BatchOptions::default()
        };
        assert_eq!(run_batch(&input, &options, threads), base);
    }
    assert_eq!(base.1.errors, 4);
}

/// A layer of `n` random convex polygons in a `size × size` square, as JSON lines.
fn layer(rng: &mut SplitMix64, n: usize, size: f64) -> (String, Vec<Vec<DVec2>>) {
    let mut unit = || (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    let mut text = String::new();
    let mut polys = Vec::new();
    for k in 0..n {
        let center = DVec2::new(size * unit(), size * unit());
        let radius = 0.2 + 0.8 * unit();
        let sides = 3 + (k % 8);
        let seed = (unit() * 1e9) as u64;
        let p = random_convex(&mut SplitMix64::new(seed), sides, center, radius);
        text += &serde_json::json!({"id": format!("p{k}"), "vertices": ring(&p)}).to_string();
        text.push('\n');
        polys.push(p);
    }
    (text, polys)
}

#[test]
fn within_equals_the_exact_all_pairs_answer() {
    let mut rng = SplitMix64::new(2024);
    let (ta, pa) = layer(&mut rng, 45, 12.0);
    let (tb, pb) = layer(&mut rng, 40, 12.0);
    let (la, ea) = read_layer(ta.as_bytes(), "a").unwrap();
    let (lb, eb) = read_layer(
        format!("{tb}\n{{\"vertices\": [[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]]}}\n").as_bytes(),
        "b",
    )
    .unwrap();
    assert!(ea.is_empty());
    assert_eq!(eb.len(), 1, "{eb:?}");
    assert!(eb[0].contains("\"line\":42"), "{}", eb[0]);
    for r in [0.0, 0.3, 1.0] {
        let mut out = Vec::new();
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(2)
            .build()
            .unwrap();
        let summary = pool
            .install(|| batch_within(&la, &lb, r, &BatchOptions::default(), &mut out))
            .unwrap();
        let got: BTreeSet<(u64, u64)> = parse_lines(std::str::from_utf8(&out).unwrap())
            .iter()
            .map(|v| {
                assert!(v["distance"].as_f64().unwrap() <= r);
                (v["a_line"].as_u64().unwrap(), v["b_line"].as_u64().unwrap())
            })
            .collect();
        let r2 = rat(r).unwrap() * rat(r).unwrap();
        let mut want = BTreeSet::new();
        for (i, p) in pa.iter().enumerate() {
            for (j, q) in pb.iter().enumerate() {
                if convex_distance(p, q).sq <= r2 {
                    want.insert((i as u64 + 1, j as u64 + 1));
                }
            }
        }
        assert_eq!(got, want, "r = {r}");
        assert_eq!(summary.answered, want.len() as u64);
        // The broad phase proposed far fewer candidates than all pairs.
        assert!(
            summary.lines < (45 * 40) / 2,
            "{} candidates",
            summary.lines
        );
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(300))]
    /// Arbitrary input never panics and gets exactly one output line per non-blank line.
    #[test]
    fn arbitrary_input_one_line_out_per_line_in(lines in proptest::collection::vec(
        proptest::prop_oneof![
            ".{0,40}",
            r#"\{"a": \[\[-?[0-9]{1,3}(\.[0-9])?, -?[0-9]{1,3}\](, \[-?[0-9]{1,3}, -?[0-9e+]{1,4}\]){0,5}\], "b": \[\[[0-9], [0-9]\]\]( , "within": -?[0-9.]{1,4})?\}"#,
        ],
        0..20,
    )) {
        let input = lines.join("\n");
        let mut out = Vec::new();
        let s = batch_pairs(input.as_bytes(), &mut out, &BatchOptions { chunk: 3, ..BatchOptions::default() }).unwrap();
        let non_blank = input.lines().filter(|l| !l.trim().is_empty()).count() as u64;
        proptest::prop_assert_eq!(s.lines, non_blank);
        proptest::prop_assert_eq!(s.answered + s.errors, s.lines);
        let text = String::from_utf8(out).unwrap();
        proptest::prop_assert_eq!(text.lines().count() as u64, s.lines);
        for l in text.lines() {
            let v: Value = serde_json::from_str(l).unwrap();
            proptest::prop_assert!(v.get("line").is_some());
        }
    }
}
