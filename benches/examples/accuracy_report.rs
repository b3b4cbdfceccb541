//! Generates `docs/accuracy.md` and `docs/accuracy.svg`: for every algorithm × kernel (the convex
//! algorithms and the separation of simple polygons), the time per
//! query on random inputs and on the hard-case suite, beside the accuracy on the hard-case suite (the
//! worst error in ulps against the exact answers stored with each case, the share of wrong features,
//! and the failures). Issue 8's report; never edit the output by hand.
//!
//! Run from anywhere: `cargo run --release -p polydist-benches --example accuracy_report`.
//!
//! Timing harness: each (algorithm, kernel, input set) is run once to warm up, then `REPS` times over
//! the whole set; the median of the repetitions, divided by the number of queries, is reported. The
//! machine and its load are printed in the report: figures from a shared machine are ratios, not
//! absolutes.

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

use glam::DVec2;
use polydist_convex::{
    Separation, cmmr_with, distance_brute, distance_schwartz_with, distance_with,
    distance_yang_with, hausdorff_with, min_vertex_distance_with,
};
use polydist_fixtures::hard_cases;
use polydist_oracle::{
    Feature as OFeature, HardAnswers, Relation, SimpleHardAnswers, SplitMix64, convex_pair,
    ulps_error_sqrt,
};
use polydist_polygon::{ConvexPolygon, Feature, SimplePolygon};
use polydist_predicates::{Exact, Fast, Kernel, Robust};
use polydist_separation::{PolygonSeparation, polygon_separation_brute, separation};

/// Repetitions of each timed set (the median is reported).
const REPS: usize = 5;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Alg {
    Dispatch,
    Yang,
    Schwartz,
    Brute,
    VertexDistance,
    Hausdorff,
    Cmmr,
}

impl Alg {
    const ALL: [Alg; 7] = [
        Alg::Dispatch,
        Alg::Yang,
        Alg::Schwartz,
        Alg::Brute,
        Alg::VertexDistance,
        Alg::Hausdorff,
        Alg::Cmmr,
    ];

    fn name(self) -> &'static str {
        match self {
            Alg::Dispatch => "distance (default)",
            Alg::Yang => "distance, Yang O(log)",
            Alg::Schwartz => "distance, Schwartz O(log²)",
            Alg::Brute => "distance, brute force",
            Alg::VertexDistance => "vertex distance (McKenna–Toussaint)",
            Alg::Hausdorff => "Hausdorff (ARL)",
            Alg::Cmmr => "CMMR (ARL)",
        }
    }
}

/// The answer of one algorithm, reduced to what is checked: the error in ulps of its value (against
/// the exact value of the same quantity), and whether its combinatorial part (features, argmax,
/// outcome) is exactly right.
struct Verdict {
    ulps: f64,
    right: bool,
}

fn ours(f: OFeature) -> Feature {
    match f {
        OFeature::Vertex(i) => Feature::Vertex(i),
        OFeature::Edge(i) => Feature::Edge(i),
    }
}

/// Runs `alg` under `K` once; with answers, judges it.
fn eval<K: Kernel>(
    alg: Alg,
    p: &ConvexPolygon,
    q: &ConvexPolygon,
    a: Option<&HardAnswers>,
) -> Option<Verdict> {
    let distance_verdict = |s: Separation, a: &HardAnswers| match (s, a.contact.as_str()) {
        (Separation::Disjoint(c), "disjoint") => Verdict {
            ulps: ulps_error_sqrt(c.distance, &a.dist),
            right: a
                .pairs
                .iter()
                .any(|&(f, g)| (ours(f), ours(g)) == (c.feature_p, c.feature_q)),
        },
        (
            Separation::Touching {
                feature_p,
                feature_q,
                ..
            },
            "touching",
        ) => Verdict {
            ulps: 0.0,
            right: a
                .pairs
                .iter()
                .any(|&(f, g)| (ours(f), ours(g)) == (feature_p, feature_q)),
        },
        (Separation::Overlapping, "overlapping") => Verdict {
            ulps: 0.0,
            right: true,
        },
        _ => Verdict {
            ulps: 0.0,
            right: false,
        },
    };
    match alg {
        Alg::Dispatch | Alg::Yang | Alg::Schwartz | Alg::Brute => {
            let s = match alg {
                Alg::Dispatch => distance_with::<K>(p, q),
                Alg::Yang => distance_yang_with::<K>(p, q),
                Alg::Schwartz => distance_schwartz_with::<K>(p, q),
                _ => distance_brute::<K>(p, q),
            };
            a.map(|a| distance_verdict(black_box(s), a))
        }
        Alg::VertexDistance => {
            let v = black_box(min_vertex_distance_with::<K>(p, q));
            a.map(|a| Verdict {
                ulps: ulps_error_sqrt(v.distance, &a.vdist),
                right: a.vpairs.contains(&(v.vertex_p, v.vertex_q)),
            })
        }
        Alg::Hausdorff => {
            let h = black_box(hausdorff_with::<K>(p, q));
            a.map(|a| Verdict {
                ulps: ulps_error_sqrt(h.distance, if a.hpq >= a.hqp { &a.hpq } else { &a.hqp }),
                right: a.apq.contains(&h.p_to_q.vertex) && a.aqp.contains(&h.q_to_p.vertex),
            })
        }
        Alg::Cmmr => {
            let c = black_box(cmmr_with::<K>(p, q));
            // The exact CMMR, or for the large cases a certified enclosure of it
            // (`polydist_oracle::cmmr_enclosure`): the error is bounded against every point of the
            // interval, so it is an upper bound of the error against the exact value.
            a.and_then(HardAnswers::cmmr_bounds).map(|b| Verdict {
                ulps: b.ulps_error(c.value),
                right: true,
            })
        }
    }
}

/// Repetitions of each timed set of large polygons (10⁴–10⁵ vertices; the median is reported).
const LARGE_REPS: usize = 3;

/// Median time per query over the set, in nanoseconds: one warm-up pass, then the median of `REPS`.
fn time_set<T>(set: &[T], one: impl Fn(&T)) -> f64 {
    time_set_reps(set, REPS, one)
}

/// [`time_set`] with `reps` repetitions (0 for an empty set).
fn time_set_reps<T>(set: &[T], reps: usize, one: impl Fn(&T)) -> f64 {
    if set.is_empty() {
        return 0.0;
    }
    let run = || {
        let clock = Instant::now();
        for x in set {
            one(x);
        }
        clock.elapsed().as_secs_f64() * 1e9 / set.len() as f64
    };
    run();
    let mut t: Vec<f64> = (0..reps).map(|_| run()).collect();
    t.sort_by(f64::total_cmp);
    t[reps / 2]
}

/// One line of a table: two timings (per query) and the accuracy on the judged cases.
struct Row {
    name: &'static str,
    kernel: &'static str,
    random_ns: f64,
    hard_ns: f64,
    max_ulps: f64,
    wrong: usize,
    /// The cases with an exact answer (or, for CMMR on the large cases, a certified enclosure).
    judged: usize,
}

/// The accuracy of `eval` over `cases` (with their answers): worst error, wrong answers, judged.
fn accuracy<T, A>(
    cases: &[T],
    answers: &[A],
    eval: impl Fn(&T, Option<&A>) -> Option<Verdict>,
) -> (f64, usize, usize) {
    let (mut max_ulps, mut wrong, mut judged) = (0.0f64, 0, 0);
    for (x, a) in cases.iter().zip(answers) {
        if let Some(v) = eval(x, Some(a)) {
            max_ulps = max_ulps.max(v.ulps);
            wrong += usize::from(!v.right);
            judged += 1;
        }
    }
    (max_ulps, wrong, judged)
}

/// One row of the report: the accuracy of `eval` on the hard cases (with their answers) and its time
/// on both sets.
fn make_row<T, A>(
    name: &'static str,
    kernel: &'static str,
    (random, hard, answers): (&[T], &[T], &[A]),
    eval: impl Fn(&T, Option<&A>) -> Option<Verdict>,
) -> Row {
    let (max_ulps, wrong, judged) = accuracy(hard, answers, &eval);
    Row {
        name,
        kernel,
        random_ns: time_set(random, |x| {
            let _ = eval(x, None);
        }),
        hard_ns: time_set(hard, |x| {
            let _ = eval(x, None);
        }),
        max_ulps,
        wrong,
        judged,
    }
}

/// One row of the large tables: the accuracy of `eval` on every large case, its time on the cases
/// below and at or above 50 000 vertices (`LARGE_REPS` passes each).
fn large_row<T, A>(
    name: &'static str,
    kernel: &'static str,
    (small, big, answers): (&[T], &[T], &[A]),
    eval: impl Fn(&T, Option<&A>) -> Option<Verdict>,
) -> Row {
    // The accuracy pass, timed per set: a query slower than `SLOW_NS` is not repeated (its time
    // is this pass's mean), the others get `LARGE_REPS` timed passes after this one.
    let pass = |set: &[T], answers: &[A]| {
        let clock = Instant::now();
        let acc = accuracy(set, answers, &eval);
        let per_query = clock.elapsed().as_secs_f64() * 1e9 / set.len().max(1) as f64;
        (acc, per_query)
    };
    let (acc_small, once_small) = pass(small, &answers[..small.len()]);
    let (acc_big, once_big) = pass(big, &answers[small.len()..]);
    let time = |set: &[T], once: f64| {
        if once > SLOW_NS {
            once
        } else {
            time_set_reps(set, LARGE_REPS, |x| {
                let _ = eval(x, None);
            })
        }
    };
    Row {
        name,
        kernel,
        random_ns: time(small, once_small),
        hard_ns: time(big, once_big),
        max_ulps: acc_small.0.max(acc_big.0),
        wrong: acc_small.1 + acc_big.1,
        judged: acc_small.2 + acc_big.2,
    }
}

/// Large queries slower than this (0.1 s) are timed once, in the accuracy pass.
const SLOW_NS: f64 = 1e8;

type Convex = (ConvexPolygon, ConvexPolygon);
type Simple = (SimplePolygon, SimplePolygon);

fn row<K: Kernel>(
    alg: Alg,
    kernel: &'static str,
    sets: (&[Convex], &[Convex], &[HardAnswers]),
) -> Row {
    make_row(alg.name(), kernel, sets, |(p, q), a| {
        eval::<K>(alg, p, q, a)
    })
}

fn simple_row<K: Kernel>(
    alg: SimpleAlg,
    kernel: &'static str,
    sets: (&[Simple], &[Simple], &[SimpleAnswer]),
) -> Row {
    make_row(alg.name(), kernel, sets, |(p, q), a| {
        eval_simple::<K>(alg, p, q, a)
    })
}

/// The simple-polygon part: `separation` (the default: the intersection check, then the hull
/// shortcut or the separable chains) and its brute-force twin.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum SimpleAlg {
    Separation,
    Brute,
}

impl SimpleAlg {
    fn name(self) -> &'static str {
        match self {
            SimpleAlg::Separation => "separation (Amato: hull route, section 3, separators)",
            SimpleAlg::Brute => "separation, brute force",
        }
    }
}

/// One simple case's exact answer, with the oracle's features as polydist's.
struct SimpleAnswer {
    exact: SimpleHardAnswers,
    pairs: Vec<(Feature, Feature)>,
}

fn simple_answer(c: &polydist_fixtures::HardCase) -> SimpleAnswer {
    let exact = SimpleHardAnswers::from_words(&c.answers).expect("answers");
    let pairs = exact
        .pairs
        .iter()
        .map(|&(f, g)| (ours(f), ours(g)))
        .collect();
    SimpleAnswer { exact, pairs }
}

fn eval_simple<K: Kernel>(
    alg: SimpleAlg,
    p: &SimplePolygon,
    q: &SimplePolygon,
    a: Option<&SimpleAnswer>,
) -> Option<Verdict> {
    let r = match alg {
        SimpleAlg::Separation => separation::<K>(p, q),
        SimpleAlg::Brute => polygon_separation_brute::<K>(p, q),
    };
    let a = a?;
    Some(match (black_box(r), a.exact.contact.as_str()) {
        (Ok(PolygonSeparation::Separated { pair, .. }), "disjoint") => Verdict {
            ulps: ulps_error_sqrt(pair.distance, &a.exact.dist),
            right: a.pairs.contains(&(pair.feature_p, pair.feature_q)),
        },
        (Ok(PolygonSeparation::Intersecting(_)), "touching" | "overlapping") => Verdict {
            ulps: 0.0,
            right: true,
        },
        _ => Verdict {
            ulps: 0.0,
            right: false,
        },
    })
}

fn fmt_ns(ns: f64) -> String {
    if ns >= 1e6 {
        format!("{:.2} ms", ns / 1e6)
    } else if ns >= 1e3 {
        format!("{:.2} µs", ns / 1e3)
    } else {
        format!("{ns:.0} ns")
    }
}

/// Writes one Markdown table of the report: a header, then one line per row (the failures column
/// says `not asserted` for Fast, whose wrong answers the suite only records).
/// The time columns are headed `times` (`time, random` and `time, hard` for the suite's tables);
/// an empty set's time (0) and an algorithm without exact answers print as `—`.
fn table(md: &mut String, rows: &[Row], times: (&str, &str)) {
    let _ = writeln!(
        md,
        "| algorithm | kernel | {} | {} | worst error (ulps) | wrong | failures |",
        times.0, times.1
    );
    md.push_str("|---|---|--:|--:|--:|--:|--:|\n");
    let time = |ns: f64| {
        if ns > 0.0 {
            fmt_ns(ns)
        } else {
            "—".to_owned()
        }
    };
    for r in rows {
        let (error, wrong) = if r.judged > 0 {
            (
                format!("{:.2}", r.max_ulps),
                format!("{} of {}", r.wrong, r.judged),
            )
        } else {
            ("—".to_owned(), "no exact value".to_owned())
        };
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {error} | {wrong} | {} |",
            r.name,
            r.kernel,
            time(r.random_ns),
            time(r.hard_ns),
            if r.kernel == "Fast" {
                "not asserted".to_owned()
            } else if r.judged == 0 {
                "—".to_owned()
            } else {
                r.wrong.to_string()
            }
        );
    }
}

/// The chart: time per query on the hard suite (log x) against the worst error in ulps (log y; 0 is
/// drawn on the bottom line), one point per algorithm × kernel, drawn by hand.
fn svg(rows: &[Row]) -> String {
    let (w, h, m) = (760.0, 460.0, 70.0);
    let tmin = rows
        .iter()
        .map(|r| r.hard_ns)
        .fold(f64::INFINITY, f64::min)
        .max(1.0);
    let tmax = rows
        .iter()
        .map(|r| r.hard_ns)
        .fold(0.0, f64::max)
        .max(tmin * 10.0);
    let (lx0, lx1) = (tmin.log10().floor(), tmax.log10().ceil());
    let emax = rows.iter().map(|r| r.max_ulps).fold(1.0, f64::max);
    let (ly0, ly1) = (-2.0, emax.log10().ceil().max(1.0));
    let x = |t: f64| m + (t.max(1.0).log10() - lx0) / (lx1 - lx0) * (w - 2.0 * m);
    let y = |e: f64| {
        let le = if e <= 0.0 { ly0 } else { e.log10().max(ly0) };
        h - m - (le - ly0) / (ly1 - ly0) * (h - 2.0 * m)
    };
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">"#
    );
    let _ = writeln!(s, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    let _ = writeln!(
        s,
        r#"<line x1="{m}" y1="{0}" x2="{1}" y2="{0}" stroke="black"/><line x1="{m}" y1="{m}" x2="{m}" y2="{0}" stroke="black"/>"#,
        h - m,
        w - m
    );
    let mut d = lx0;
    while d <= lx1 {
        let px = x(10f64.powf(d));
        let _ = writeln!(
            s,
            r##"<line x1="{px:.1}" y1="{0}" x2="{px:.1}" y2="{m}" stroke="#ddd"/><text x="{px:.1}" y="{1}" text-anchor="middle">{2}</text>"##,
            h - m,
            h - m + 16.0,
            fmt_ns(10f64.powf(d))
        );
        d += 1.0;
    }
    let mut d = ly0;
    while d <= ly1 {
        let py = y(10f64.powf(d));
        let _ = writeln!(
            s,
            r##"<line x1="{m}" y1="{py:.1}" x2="{0}" y2="{py:.1}" stroke="#ddd"/><text x="{1}" y="{2:.1}" text-anchor="end">{3}</text>"##,
            w - m,
            m - 6.0,
            py + 4.0,
            if d == ly0 {
                "≤ 0.01".to_owned()
            } else {
                format!("{}", 10f64.powf(d))
            }
        );
        d += 1.0;
    }
    let _ = writeln!(
        s,
        r#"<text x="{0}" y="{1}" text-anchor="middle">time per query on the hard-case suite</text><text x="16" y="{2}" transform="rotate(-90 16 {2})" text-anchor="middle">worst error (ulps)</text>"#,
        w / 2.0,
        h - 20.0,
        h / 2.0
    );
    for r in rows {
        let colour = match r.kernel {
            "Fast" => "#d62728",
            "Robust" => "#1f77b4",
            _ => "#2ca02c",
        };
        let (px, py) = (x(r.hard_ns), y(r.max_ulps));
        let mark = if r.wrong > 0 { "none" } else { colour };
        let _ = writeln!(
            s,
            r#"<circle cx="{px:.1}" cy="{py:.1}" r="5" fill="{mark}" stroke="{colour}" stroke-width="2"><title>{} / {}: {} per query, worst {:.2} ulps, {} wrong</title></circle>"#,
            r.name,
            r.kernel,
            fmt_ns(r.hard_ns),
            r.max_ulps,
            r.wrong
        );
    }
    let _ = writeln!(
        s,
        r##"<text x="{0}" y="20" text-anchor="end"><tspan fill="#d62728">● Fast</tspan>  <tspan fill="#1f77b4">● Robust</tspan>  <tspan fill="#2ca02c">● Exact</tspan>  (hollow: some answer wrong)</text>"##,
        w - m
    );
    s.push_str("</svg>\n");
    s
}

fn main() {
    let cases = hard_cases("hard/convex.txt").expect("fixtures/hard/convex.txt");
    let pts = |v: &[[f64; 2]]| -> Vec<DVec2> { v.iter().map(|&[x, y]| DVec2::new(x, y)).collect() };
    let hard: Vec<(ConvexPolygon, ConvexPolygon)> = cases
        .iter()
        .map(|c| {
            (
                ConvexPolygon::try_new(&pts(&c.p)).expect("convex"),
                ConvexPolygon::try_new(&pts(&c.q)).expect("convex"),
            )
        })
        .collect();
    let answers: Vec<HardAnswers> = cases
        .iter()
        .map(|c| HardAnswers::from_words(&c.answers).expect("answers"))
        .collect();
    let mut rng = SplitMix64::new(0xacc0);
    let random: Vec<(ConvexPolygon, ConvexPolygon)> = (0..40)
        .map(|_| {
            let pair = convex_pair(&mut rng, 64, 64, Relation::Far);
            (
                ConvexPolygon::try_new(&pair.p).expect("convex"),
                ConvexPolygon::try_new(&pair.q).expect("convex"),
            )
        })
        .collect();
    let mut rows = Vec::new();
    for alg in Alg::ALL {
        eprintln!("{} …", alg.name());
        let sets = (&random[..], &hard[..], &answers[..]);
        rows.push(row::<Fast>(alg, "Fast", sets));
        rows.push(row::<Robust>(alg, "Robust", sets));
        rows.push(row::<Exact>(alg, "Exact", sets));
    }

    // Simple polygons: the hard suite's disjoint-hull pairs, and random stars side by side.
    let scases = hard_cases("hard/simple.txt").expect("fixtures/hard/simple.txt");
    let shard: Vec<(SimplePolygon, SimplePolygon)> = scases
        .iter()
        .map(|c| {
            (
                SimplePolygon::try_new(&pts(&c.p)).expect("simple"),
                SimplePolygon::try_new(&pts(&c.q)).expect("simple"),
            )
        })
        .collect();
    let sanswers: Vec<SimpleAnswer> = scases.iter().map(simple_answer).collect();
    let srandom: Vec<(SimplePolygon, SimplePolygon)> = (0..20)
        .map(|_| {
            let a = polydist_oracle::star(&mut rng, 64, 16);
            let b = polydist_oracle::star(&mut rng, 64, 16);
            let max_x = a.iter().map(|v| v.x).fold(f64::NEG_INFINITY, f64::max);
            let min_x = b.iter().map(|v| v.x).fold(f64::INFINITY, f64::min);
            let b: Vec<DVec2> = b
                .iter()
                .map(|&v| v + DVec2::new(max_x - min_x + 0.125, 0.0))
                .collect();
            (
                SimplePolygon::try_new(&a).expect("simple"),
                SimplePolygon::try_new(&b).expect("simple"),
            )
        })
        .collect();
    let mut srows = Vec::new();
    for alg in [SimpleAlg::Separation, SimpleAlg::Brute] {
        eprintln!("{} …", alg.name());
        let sets = (&srandom[..], &shard[..], &sanswers[..]);
        srows.push(simple_row::<Fast>(alg, "Fast", sets));
        srows.push(simple_row::<Robust>(alg, "Robust", sets));
        srows.push(simple_row::<Exact>(alg, "Exact", sets));
    }

    // Large polygons: rebuilt from their `gen` lines, split at 50 000 vertices for the timings.
    let rebuild = |c: &polydist_fixtures::HardCase| {
        polydist_oracle::large_pair(c.answer("gen").expect("a `gen` line"))
            .unwrap_or_else(|e| panic!("{}/{}: {e}", c.family, c.name))
    };
    let split = |n: usize| n >= 50_000;
    let lcases = hard_cases("hard/large_convex.txt").expect("fixtures/hard/large_convex.txt");
    let mut large: (Vec<Convex>, Vec<Convex>) = (Vec::new(), Vec::new());
    let mut lanswers: (Vec<HardAnswers>, Vec<HardAnswers>) = (Vec::new(), Vec::new());
    let mut arcs: Vec<usize> = Vec::new();
    for c in &lcases {
        let (p, q) = rebuild(c);
        if c.family == "large_cocircular" {
            arcs.push(p.len());
        }
        let (set, answers) = if split(p.len().max(q.len())) {
            (&mut large.1, &mut lanswers.1)
        } else {
            (&mut large.0, &mut lanswers.0)
        };
        set.push((
            ConvexPolygon::try_new(&p).expect("convex"),
            ConvexPolygon::try_new(&q).expect("convex"),
        ));
        answers.push(HardAnswers::from_words(&c.answers).expect("answers"));
    }
    let lsizes = (
        arcs.iter().copied().min().unwrap_or(0),
        arcs.iter().copied().max().unwrap_or(0),
    );
    let lanswers: Vec<HardAnswers> = lanswers.0.into_iter().chain(lanswers.1).collect();
    // The CMMR enclosures of the large pairs: how many are exact, and the widest of the others.
    let enclosures: Vec<_> = lanswers
        .iter()
        .filter_map(|a| a.cmmr_enclosure.as_ref())
        .collect();
    let exact_enclosures = enclosures.iter().filter(|e| e.lo == e.hi).count();
    let widest = enclosures
        .iter()
        .map(|e| e.width_ulps())
        .fold(0.0, f64::max);
    let mut lrows = Vec::new();
    for alg in Alg::ALL.into_iter().filter(|&a| a != Alg::Brute) {
        eprintln!("{} (large) …", alg.name());
        let sets = (&large.0[..], &large.1[..], &lanswers[..]);
        let name = alg.name();
        lrows.push(large_row(name, "Fast", sets, |(p, q), a| {
            eval::<Fast>(alg, p, q, a)
        }));
        lrows.push(large_row(name, "Robust", sets, |(p, q), a| {
            eval::<Robust>(alg, p, q, a)
        }));
        lrows.push(large_row(name, "Exact", sets, |(p, q), a| {
            eval::<Exact>(alg, p, q, a)
        }));
    }
    let lscases = hard_cases("hard/large_simple.txt").expect("fixtures/hard/large_simple.txt");
    let mut lsimple: (Vec<Simple>, Vec<Simple>) = (Vec::new(), Vec::new());
    let mut lsanswers: (Vec<SimpleAnswer>, Vec<SimpleAnswer>) = (Vec::new(), Vec::new());
    for c in &lscases {
        let (p, q) = rebuild(c);
        let (set, answers) = if split(p.len().max(q.len())) {
            (&mut lsimple.1, &mut lsanswers.1)
        } else {
            (&mut lsimple.0, &mut lsanswers.0)
        };
        set.push((
            SimplePolygon::try_new(&p).expect("simple"),
            SimplePolygon::try_new(&q).expect("simple"),
        ));
        answers.push(simple_answer(c));
    }
    let lsanswers: Vec<SimpleAnswer> = lsanswers.0.into_iter().chain(lsanswers.1).collect();
    let mut lsrows = Vec::new();
    for alg in [SimpleAlg::Separation, SimpleAlg::Brute] {
        eprintln!("{} (large) …", alg.name());
        let sets = (&lsimple.0[..], &lsimple.1[..], &lsanswers[..]);
        let name = alg.name();
        lsrows.push(large_row(name, "Fast", sets, |(p, q), a| {
            eval_simple::<Fast>(alg, p, q, a)
        }));
        lsrows.push(large_row(name, "Robust", sets, |(p, q), a| {
            eval_simple::<Robust>(alg, p, q, a)
        }));
        if alg != SimpleAlg::Brute {
            lsrows.push(large_row(name, "Exact", sets, |(p, q), a| {
                eval_simple::<Exact>(alg, p, q, a)
            }));
        }
    }

    // Where Fast goes wrong: the default distance's wrong answers by family.
    let mut fast_wrong: std::collections::BTreeMap<&str, usize> = Default::default();
    for ((p, q), (c, a)) in hard.iter().zip(cases.iter().zip(&answers)) {
        if eval::<Fast>(Alg::Dispatch, p, q, Some(a)).is_some_and(|v| !v.right) {
            *fast_wrong.entry(c.family.as_str()).or_default() += 1;
        }
    }
    let mut sfast_wrong: std::collections::BTreeMap<&str, usize> = Default::default();
    for ((p, q), (c, a)) in shard.iter().zip(scases.iter().zip(&sanswers)) {
        if eval_simple::<Fast>(SimpleAlg::Separation, p, q, Some(a)).is_some_and(|v| !v.right) {
            *sfast_wrong.entry(c.family.as_str()).or_default() += 1;
        }
    }

    let mut md = String::new();
    md.push_str("# What accuracy costs in time\n\n");
    md.push_str(
        "Generated by `cargo run --release -p polydist-benches --example accuracy_report` \
         (`benches/examples/accuracy_report.rs`); do not edit by hand.\n\n",
    );
    let _ = writeln!(
        md,
        "Inputs: **random** = 40 pairs of disjoint random convex 64-gons (the oracle's `convex_pair`, \
         `Relation::Far`); **hard** = the {} cases of the hard-case suite (`fixtures/hard/convex.txt`: \
         nearly touching pairs 1–1000 ulps apart, exact contacts, offsets up to 1e15, parallel and \
         one-ulp-off-parallel edges, near ties moved to 2^27 and 2^40 then tilted by 1–3 ulps there, \
         co-circular vertex sets (also far from the origin), collinear inputs, slivers, overlapping, \
         nested and identical polygons, and three families built against plain `f64`: a vertex at \
         orientation exactly −3…3 grid units against a 2^47-long edge near (1e15, 1e15), i.e. \
         2^−43 off its line (`orient_1_far`), nearly parallel facing edges whose nearer end differs \
         by as little (`near_parallel_far`), co-circular sets scaled by 10^12 with one vertex moved \
         one ulp (`cocircular_1e12`)), each stored with its exact answers from the oracle. Time: \
         median of {REPS} passes over the set after one warm-up pass, per query. Error: the worst, \
         over the hard cases, of the reported distance (or Hausdorff distance, or CMMR value) \
         against the exact value, in ulps. Wrong: answers whose combinatorial part (features, \
         argmax vertices, outcome) is not an exact optimum. The machine: {} cores, shared with \
         other work while this ran: read times as ratios.\n",
        hard.len(),
        std::thread::available_parallelism().map_or(1, usize::from),
    );
    table(&mut md, &rows, ("time, random", "time, hard"));
    let _ = writeln!(
        md,
        "\nSimple polygons: **random** = 20 pairs of random 64-vertex stars side by side; \
         **hard** = the {} cases of `fixtures/hard/simple.txt` (shapes 1–1000 ulps apart, the \
         same at 1e12, saw-teeth facing tip to notch, interlocked combs 1–1000 ulps and 1e-9 \
         apart whose hulls meet (Amato's separator route), the same at 1e12, the convex \
         `orient_1_far` and `near_parallel_far` pairs above, disjoint, touching or overlapping, \
         and {} cases of a polygon in a pocket of the other, one hull inside the other (the \
         separator's containing case): a convex polygon, a star or a comb in a block's deep \
         pocket 1, 4 and 1000 ulps, 2^−30 and 2^−40 relative, or 0 from its walls (`pocket`), \
         pinched at one vertex or along edges on the pocket's lid line (`pocket_lid`), a star or \
         a small comb dropped into a notch of a comb, 0–4 ulps from a wall or the floor or on the \
         lid line (`comb_notch`), the same built at 1e8 and 1e12 with gaps of 1–4 ulps there \
         (`pocket_far`, `comb_notch_far`), and a triangle in a tilted pocket near (1e15, 1e15) \
         whose vertex is at orientation exactly −3…1 grid units against the pocket's 2^47-long \
         wall, 2^−43 off its line (`pocket_orient_far`, as `orient_1_far`), each pair in both \
         argument orders). The time includes \
         the intersection check.\n",
        shard.len(),
        scases
            .iter()
            .filter(|c| c.family.starts_with("pocket") || c.family.starts_with("comb_notch"))
            .count(),
    );
    table(&mut md, &srows, ("time, random", "time, hard"));
    let _ = writeln!(
        md,
        "\nLarge polygons (`fixtures/hard/large_convex.txt`, `large_simple.txt`; each pair rebuilt \
         from its `gen` line, its answers certified by the oracle's pruned exact search, its \
         CMMR by a certified enclosure): {} \
         convex pairs — dense rational circles of 10⁴ and 10⁵ vertices 1–3 ulps apart (their \
         facing edges parallel) and McKenna–Toussaint co-circular lattice arcs of {} and {} \
         vertices against a vertex at the centre (every vertex tied, or one moved one ulp) — and {} \
         simple pairs (stars and facing combs of 10⁴ vertices, hulls disjoint). Time: median of \
         {LARGE_REPS} passes after a warm-up (one pass for queries over 0.1 s), per query, on \
         the cases below and above 50 000 vertices. Not run: the `O(nm)` convex brute force (10⁸–10¹⁰ feature pairs per query) \
         and the simple brute force under Exact. CMMR: its exact value, a sum of 10⁵ rationals \
         with distinct denominators, is out of reach; the oracle stores an enclosure `[lo, hi]` of \
         it instead (`polydist_oracle::cmmr_enclosure`: each exact term rounded down and up, both \
         sums exact), exact on {} of the {} pairs and at most {:.1e} ulp wide on the others, and \
         the error reported is bounded against every point of the interval.\n",
        large.0.len() + large.1.len(),
        lsizes.0,
        lsizes.1,
        lsimple.0.len() + lsimple.1.len(),
        exact_enclosures,
        enclosures.len(),
        widest,
    );
    table(&mut md, &lrows, ("time, 10⁴", "time, 10⁵"));
    md.push('\n');
    table(&mut md, &lsrows, ("time, 10⁴", "time, 10⁵"));
    md.push_str(
        "\n![time against worst error, one point per algorithm and kernel](accuracy.svg)\n\n",
    );
    md.push_str("## Which kernel to choose\n\n");
    // Robust's time over Fast's: the range on the random convex pairs, the worst on the large ones
    // (rows come in Fast, Robust, Exact triples per algorithm).
    let ratios = |rows: &[Row], time: fn(&Row) -> f64| -> Vec<(f64, &'static str)> {
        rows.chunks(3)
            .filter(|t| t.len() >= 2 && time(&t[0]) > 0.0 && time(&t[1]) > 0.0)
            .map(|t| (time(&t[1]) / time(&t[0]), t[0].name))
            .collect()
    };
    let random = ratios(&rows, |r| r.random_ns);
    let random_ratio = (
        random.iter().map(|r| r.0).fold(f64::INFINITY, f64::min),
        random.iter().map(|r| r.0).fold(0.0, f64::max),
    );
    let large_ratio = ratios(&lrows, |r| r.random_ns)
        .into_iter()
        .chain(ratios(&lrows, |r| r.hard_ns))
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap_or((1.0, "none"));
    let _ = write!(
        md,
        "**Robust is the default and the right choice almost always.** It makes every decision \
         exactly — the features, the argmax vertices and the outcome (disjoint, touching, \
         overlapping) are an exact optimum on every hard case above — and its cost over Fast is \
         small on ordinary inputs ({:.1}–{:.1}× on the random convex pairs: compare the two rows \
         of each algorithm) because the searches are guided in plain `f64` and only certified \
         exactly. Where many decisions are exact ties the filter cannot settle them and the exact \
         fallback runs: on the large pairs, full of exact and near ties (co-circular arcs whose \
         vertices are all equidistant from Q's, dense circles with parallel facing edges), the \
         factor reaches {:.0}× ({}). The reported distances are constructed once from the \
         exact features and stay within the documented bounds (distance 3.5 ulps, squared distance \
         5, Hausdorff 3.5, CMMR 6), even 1 ulp from contact or 1e15 from the origin.\n\n",
        random_ratio.0, random_ratio.1, large_ratio.0, large_ratio.1,
    );
    let _ = writeln!(
        md,
        "**Fast** evaluates the same predicates in plain `f64`: it always terminates, but near \
         ties it may choose a wrong feature or outcome (the `wrong` column); use it only when \
         inputs are known to be far from degenerate and every nanosecond counts. Its predicates \
         take differences of nearby coordinates first, which are exact in `f64`, so large offsets \
         alone rarely defeat it; what does is a decision whose exact value lies below the rounding \
         of products of long differences. The default distance under Fast was wrong on {} of {} \
         hard cases, by family: {}; `separation` of simple polygons under Fast, on {} of \
         {}, by family: {}. **Exact** \
         evaluates every predicate in exact arithmetic without a filter; its answers are the same \
         as Robust's, at a much higher cost, and it adds exact rational results \
         (`distance_exact`, `hausdorff_squared_exact`): use it as a reference, or when an exact \
         rational squared distance is the output you need.",
        fast_wrong.values().sum::<usize>(),
        hard.len(),
        fast_wrong
            .iter()
            .map(|(f, k)| format!("`{f}` {k}"))
            .collect::<Vec<_>>()
            .join(", "),
        srows.first().map_or(0, |r| r.wrong),
        shard.len(),
        sfast_wrong
            .iter()
            .map(|(f, k)| format!("`{f}` {k}"))
            .collect::<Vec<_>>()
            .join(", "),
    );
    let docs = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs");
    std::fs::write(docs.join("accuracy.md"), md).expect("write docs/accuracy.md");
    rows.extend(srows);
    std::fs::write(docs.join("accuracy.svg"), svg(&rows)).expect("write docs/accuracy.svg");
    println!("wrote docs/accuracy.md and docs/accuracy.svg");
}
