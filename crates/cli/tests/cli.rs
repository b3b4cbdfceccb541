//! End-to-end: the `polydist` binary on the default scene and the fixture scenes, its JSON checked
//! against answers computed here independently (brute force over vertex–edge pairs on poses
//! recomputed from the scene files, analytic contact times), and its exit statuses.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_polydist"))
}

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures")
}

fn run(args: &[&str]) -> (i32, String, String) {
    let out = bin().args(args).output().expect("the binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn run_json(args: &[&str]) -> (i32, Value) {
    let (code, stdout, stderr) = run(args);
    let v: Value = serde_json::from_str(&stdout)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {stdout}\nstderr: {stderr}"));
    (code, v)
}

// ---------------------------------------------------------------------------------------------
// Independent geometry (plain f64, brute force): poses, point–segment distances, intersection.

type P = [f64; 2];

fn sub(a: P, b: P) -> P {
    [a[0] - b[0], a[1] - b[1]]
}

fn dot(a: P, b: P) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

fn cross(a: P, b: P) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn norm(a: P) -> f64 {
    a[0].hypot(a[1])
}

/// Rotate by `angle` about the origin, then translate.
fn apply(v: P, x: f64, y: f64, angle: f64) -> P {
    let (s, c) = angle.sin_cos();
    [c * v[0] - s * v[1] + x, s * v[0] + c * v[1] + y]
}

fn point_segment(p: P, a: P, b: P) -> f64 {
    let ab = sub(b, a);
    let len2 = dot(ab, ab);
    let t = if len2 == 0.0 {
        0.0
    } else {
        (dot(sub(p, a), ab) / len2).clamp(0.0, 1.0)
    };
    norm(sub(p, [a[0] + t * ab[0], a[1] + t * ab[1]]))
}

fn ccw(poly: &[P]) -> Vec<P> {
    let area: f64 = (0..poly.len())
        .map(|i| cross(poly[i], poly[(i + 1) % poly.len()]))
        .sum();
    let mut v = poly.to_vec();
    if area < 0.0 {
        v.reverse();
    }
    v
}

/// Inside or on a convex polygon (any orientation).
fn inside_convex(p: P, poly: &[P]) -> bool {
    let v = ccw(poly);
    (0..v.len()).all(|i| cross(sub(v[(i + 1) % v.len()], v[i]), sub(p, v[i])) >= 0.0)
}

fn segments_cross(a: P, b: P, c: P, d: P) -> bool {
    let d1 = cross(sub(b, a), sub(c, a));
    let d2 = cross(sub(b, a), sub(d, a));
    let d3 = cross(sub(d, c), sub(a, c));
    let d4 = cross(sub(d, c), sub(b, c));
    if d1 == 0.0 && d2 == 0.0 {
        // Collinear: do the projections on the line overlap?
        let u = sub(b, a);
        let (s0, s1) = (dot(sub(c, a), u), dot(sub(d, a), u));
        return s0.min(s1) <= dot(u, u) && s0.max(s1) >= 0.0;
    }
    d1 * d2 <= 0.0 && d3 * d4 <= 0.0
}

/// The corners of a ring: its vertices without those collinear with their neighbours (the
/// vertices of the polygon as a convex polygon; vertex distances are between corners).
fn corners(poly: &[P]) -> Vec<P> {
    let n = poly.len();
    (0..n)
        .filter(|&i| {
            cross(
                sub(poly[i], poly[(i + n - 1) % n]),
                sub(poly[(i + 1) % n], poly[i]),
            ) != 0.0
        })
        .map(|i| poly[i])
        .collect()
}

fn convex_meet(a: &[P], b: &[P]) -> bool {
    a.iter().any(|&p| inside_convex(p, b))
        || b.iter().any(|&p| inside_convex(p, a))
        || (0..a.len()).any(|i| {
            (0..b.len())
                .any(|j| segments_cross(a[i], a[(i + 1) % a.len()], b[j], b[(j + 1) % b.len()]))
        })
}

/// The distance of two convex polygons by brute force over vertex–edge pairs (0 when they meet).
fn brute_distance(a: &[P], b: &[P]) -> f64 {
    if convex_meet(a, b) {
        return 0.0;
    }
    let mut best = f64::INFINITY;
    for (p, q) in [(a, b), (b, a)] {
        for &v in p {
            for j in 0..q.len() {
                best = best.min(point_segment(v, q[j], q[(j + 1) % q.len()]));
            }
        }
    }
    best
}

fn brute_vertex_distance(a: &[P], b: &[P]) -> f64 {
    a.iter()
        .flat_map(|&p| b.iter().map(move |&q| norm(sub(p, q))))
        .fold(f64::INFINITY, f64::min)
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + b.abs())
}

fn point(v: &Value) -> P {
    [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()]
}

/// A body's motion, read from the scene file with the `toml` crate (not with polydist-scene).
enum Motion {
    Linear {
        x: f64,
        y: f64,
        a: f64,
        vx: f64,
        vy: f64,
        w: f64,
    },
    Keys(Vec<[f64; 4]>),
}

impl Motion {
    fn pose(&self, t: f64) -> (f64, f64, f64) {
        match self {
            Motion::Linear { x, y, a, vx, vy, w } => (x + vx * t, y + vy * t, a + w * t),
            Motion::Keys(k) => {
                let i = k.partition_point(|key| key[0] <= t);
                if i == 0 {
                    return (k[0][1], k[0][2], k[0][3]);
                }
                if i == k.len() {
                    let l = k[i - 1];
                    return (l[1], l[2], l[3]);
                }
                let (p, q) = (k[i - 1], k[i]);
                let s = (t - p[0]) / (q[0] - p[0]);
                (
                    p[1] + (q[1] - p[1]) * s,
                    p[2] + (q[2] - p[2]) * s,
                    p[3] + (q[3] - p[3]) * s,
                )
            }
        }
    }
}

struct FileBody {
    vertices: Vec<P>,
    motion: Motion,
}

impl FileBody {
    fn at(&self, t: f64) -> Vec<P> {
        let (x, y, a) = self.motion.pose(t);
        self.vertices.iter().map(|&v| apply(v, x, y, a)).collect()
    }
}

fn num(v: Option<&toml::Value>) -> f64 {
    match v {
        Some(toml::Value::Float(f)) => *f,
        Some(toml::Value::Integer(i)) => *i as f64,
        None => 0.0,
        Some(other) => panic!("not a number: {other:?}"),
    }
}

fn read_bodies(scene: &Path) -> Vec<(String, FileBody)> {
    let text = std::fs::read_to_string(scene).unwrap();
    let table: toml::Table = text.parse().unwrap();
    let mut out = Vec::new();
    for b in table["body"].as_array().unwrap() {
        let id = b["id"].as_str().unwrap().to_owned();
        let vertices: Vec<P> = if let Some(g) = b.get("generator") {
            // The regular n-gon: vertex i at angle 2πi/n on the circle (the documented formula).
            // Other generators are not recomputed here (their pairs are checked for consistency).
            if g["type"].as_str() == Some("regular") {
                let n = g["n"].as_integer().unwrap();
                let r = num(g.get("radius"));
                (0..n)
                    .map(|i| {
                        let a = core::f64::consts::TAU * i as f64 / n as f64;
                        [r * a.cos(), r * a.sin()]
                    })
                    .collect()
            } else {
                Vec::new()
            }
        } else if let Some(v) = b.get("vertices") {
            v.as_array()
                .unwrap()
                .iter()
                .map(|p| [num(p.get(0)), num(p.get(1))])
                .collect()
        } else {
            let file = scene.parent().unwrap().join(b["file"].as_str().unwrap());
            std::fs::read_to_string(file)
                .unwrap()
                .lines()
                .map(|l| l.split('#').next().unwrap().trim())
                .filter(|l| !l.is_empty())
                .map(|l| {
                    let f: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
                    [f[0], f[1]]
                })
                .collect()
        };
        let pose = b.get("pose");
        let g = |k: &str| num(pose.and_then(|p| p.get(k)));
        let motion = match b.get("motion") {
            Some(m) if m["type"].as_str() == Some("keyframes") => Motion::Keys(
                m["keys"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|k| {
                        [
                            num(k.get("t")),
                            num(k.get("x")),
                            num(k.get("y")),
                            num(k.get("angle")),
                        ]
                    })
                    .collect(),
            ),
            Some(m) => {
                let v = m.get("velocity");
                Motion::Linear {
                    x: g("x"),
                    y: g("y"),
                    a: g("angle"),
                    vx: num(v.and_then(|v| v.get(0))),
                    vy: num(v.and_then(|v| v.get(1))),
                    w: num(m.get("angular")),
                }
            }
            None => Motion::Linear {
                x: g("x"),
                y: g("y"),
                a: g("angle"),
                vx: 0.0,
                vy: 0.0,
                w: 0.0,
            },
        };
        out.push((id, FileBody { vertices, motion }));
    }
    out
}

fn body<'a>(bodies: &'a [(String, FileBody)], id: &str) -> &'a FileBody {
    &bodies.iter().find(|(i, _)| i == id).unwrap().1
}

/// Every frame of every pair against brute force; every closest-point feature checked on the
/// body's own (caller) vertices; vertex distances against the brute-force minimum.
fn check_frames(report: &Value, bodies: &[(String, FileBody)]) {
    for pair in report["pairs"].as_array().unwrap() {
        let (a, b) = (
            body(bodies, pair["a"].as_str().unwrap()),
            body(bodies, pair["b"].as_str().unwrap()),
        );
        for f in pair["frames"].as_array().unwrap() {
            let t = f["t"].as_f64().unwrap();
            let (pa, pb) = (a.at(t), b.at(t));
            let expect = brute_distance(&pa, &pb);
            if let Some(d) = f["distance"].as_f64() {
                assert!(
                    close(d, expect, 1e-9),
                    "{} – {} at t = {t}: {d} vs brute force {expect}",
                    pair["a"],
                    pair["b"]
                );
                let status = f["status"].as_str().unwrap();
                assert_eq!(status == "disjoint", expect > 1e-9, "t = {t}: {status}");
            }
            if let Some(c) = f.get("closest_points").filter(|c| !c.is_null()) {
                let (qa, qb) = (point(&c["point_a"]), point(&c["point_b"]));
                assert!(close(norm(sub(qa, qb)), expect, 1e-9), "t = {t}");
                for (q, feat, poly) in [(qa, &c["feature_a"], &pa), (qb, &c["feature_b"], &pb)] {
                    let i = feat["index"].as_u64().unwrap() as usize;
                    let off = match feat["kind"].as_str().unwrap() {
                        "vertex" => norm(sub(q, poly[i])),
                        _ => point_segment(q, poly[i], poly[(i + 1) % poly.len()]),
                    };
                    assert!(off < 1e-9, "t = {t}: {feat} is {off} away from {q:?}");
                }
            }
            if let Some(v) = f.get("vertex_distance") {
                let d = v["distance"].as_f64().unwrap();
                // Corners found on the unposed ring, then posed (posing may round collinearity away).
                let ca: Vec<P> = {
                    let keep = corners(&a.vertices);
                    pa.iter()
                        .zip(&a.vertices)
                        .filter(|(_, v)| keep.contains(v))
                        .map(|(p, _)| *p)
                        .collect()
                };
                let cb: Vec<P> = {
                    let keep = corners(&b.vertices);
                    pb.iter()
                        .zip(&b.vertices)
                        .filter(|(_, v)| keep.contains(v))
                        .map(|(p, _)| *p)
                        .collect()
                };
                let expect = brute_vertex_distance(&ca, &cb);
                assert!(close(d, expect, 1e-9), "t = {t}: {d} vs {expect}");
                let (i, j) = (
                    v["vertex_a"].as_u64().unwrap() as usize,
                    v["vertex_b"].as_u64().unwrap() as usize,
                );
                assert!(close(norm(sub(pa[i], pb[j])), d, 1e-9));
            }
        }
    }
}

/// A contact bracket checked by brute force on recomputed poses, and an apart certificate checked
/// against a dense sampling (the certified bound must not exceed any sampled distance).
fn check_contact(report: &Value, bodies: &[(String, FileBody)], start: f64, end: f64) {
    for pair in report["pairs"].as_array().unwrap() {
        let Some(c) = pair.get("first_contact") else {
            continue;
        };
        let (a, b) = (
            body(bodies, pair["a"].as_str().unwrap()),
            body(bodies, pair["b"].as_str().unwrap()),
        );
        match c["outcome"].as_str().unwrap() {
            "contact" => {
                let (safe, hit) = (c["t_safe"].as_f64().unwrap(), c["t_hit"].as_f64().unwrap());
                assert!(safe < hit && hit - safe <= c["tolerance"].as_f64().unwrap());
                assert!(convex_meet(&a.at(hit), &b.at(hit)), "{pair}");
                assert!(brute_distance(&a.at(safe), &b.at(safe)) > 0.0, "{pair}");
                // Disjoint on a sampling of [start, t_safe].
                for k in 0..=200 {
                    let t = start + (safe - start) * f64::from(k) / 200.0;
                    assert!(brute_distance(&a.at(t), &b.at(t)) > 0.0, "t = {t}: {pair}");
                }
            }
            "apart" => {
                let lb = c["clearance_lower_bound"].as_f64().unwrap();
                assert!(lb > 0.0);
                for k in 0..=2000 {
                    let t = start + (end - start) * f64::from(k) / 2000.0;
                    let d = brute_distance(&a.at(t), &b.at(t));
                    assert!(lb <= d + 1e-12, "t = {t}: bound {lb} > distance {d}");
                }
            }
            other => panic!("unexpected outcome {other}: {pair}"),
        }
    }
}

fn pair<'a>(report: &'a Value, a: &str, b: &str) -> &'a Value {
    report["pairs"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["a"] == a && p["b"] == b)
        .unwrap_or_else(|| panic!("no pair {a} – {b}"))
}

// ---------------------------------------------------------------------------------------------

#[test]
fn default_scene_runs_without_arguments_and_as_run() {
    let (code, table, _) = run(&[]);
    assert_eq!(code, 0);
    for effect in [
        "distance",
        "closest_points",
        "vertex_distance",
        "first_contact",
    ] {
        assert!(table.contains(effect), "{effect} missing:\n{table}");
    }
    let (code2, table2, _) = run(&["run"]);
    assert_eq!(code2, 0);
    // The same scene (micro-second timings aside).
    assert_eq!(table.lines().next(), table2.lines().next());
}

#[test]
fn default_scene_json_against_independent_answers() {
    let (code, r) = run_json(&["run", "--json"]);
    assert_eq!(code, 0);
    assert_eq!(r["version"], 1);
    assert_eq!(r["scene"], "default");
    assert_eq!(r["failed"], false);
    assert_eq!(r["pairs"].as_array().unwrap().len(), 5);
    let bodies = read_bodies(&fixtures().join("scenes/default.toml"));
    // The robot over the U-shaped dock (a simple polygon): the separation by brute force.
    let (robot, dock) = (body(&bodies, "robot"), body(&bodies, "dock"));
    for f in pair(&r, "robot", "dock")["frames"].as_array().unwrap() {
        let t = f["t"].as_f64().unwrap();
        let expect = ring_distance(&robot.at(t), &dock.at(t));
        let d = f["separation"]["distance"].as_f64().unwrap();
        assert!(
            close(d, expect, 1e-12),
            "robot – dock at {t}: {d} vs {expect}"
        );
    }

    // The robot (hexagon of radius 1/2 about (−4 + t, 0), angle t/2) reaches the wall's face x = 1.5
    // when −4 + t + max_k cos(t/2 + kπ/3)/2 = 1.5: increasing in t (slope ≥ 1 − 1/4), bisected here.
    let f = |t: f64| {
        -4.0 + t
            + (0..6)
                .map(|k| 0.5 * (0.5 * t + f64::from(k) * core::f64::consts::FRAC_PI_3).cos())
                .fold(f64::MIN, f64::max)
            - 1.5
    };
    let (mut lo, mut hi) = (0.0, 6.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let rw = pair(&r, "robot", "wall");
    let c = &rw["first_contact"];
    assert_eq!(c["outcome"], "contact");
    let (safe, hit) = (c["t_safe"].as_f64().unwrap(), c["t_hit"].as_f64().unwrap());
    assert!(
        safe <= hi + 1e-12 && lo <= hit + 1e-12,
        "[{safe}, {hit}] vs {lo}"
    );

    // The static pair is evaluated once; its answer is exact: (−0.7, 1.2) to the wall's face.
    let pw = pair(&r, "pillar", "wall");
    assert_eq!(pw["moving"], false);
    assert_eq!(pw["frames"].as_array().unwrap().len(), 1);
    assert_eq!(pw["frames"][0]["distance"].as_f64(), Some(2.2));

    // Frames of every pair whose bodies the test can pose (the drone is generated: checked for
    // consistency only).
    let mut checkable = r.clone();
    checkable["pairs"]
        .as_array_mut()
        .unwrap()
        .retain(|p| p["a"] != "drone");
    check_frames(&checkable, &bodies);
    check_contact(&checkable, &bodies, 0.0, 6.0);
    for f in pair(&r, "drone", "robot")["frames"].as_array().unwrap() {
        let d = f["distance"].as_f64().unwrap();
        let v = f["vertex_distance"]["distance"].as_f64().unwrap();
        assert!(v >= d, "the vertex distance is never below the distance");
    }
}

#[test]
fn corridor_scene() {
    let path = fixtures().join("scenes/corridor.toml");
    let (code, r) = run_json(&["run", "--json", path.to_str().unwrap()]);
    assert_eq!(code, 0);
    let bodies = read_bodies(&path);
    check_frames(&r, &bodies);
    check_contact(&r, &bodies, 0.0, 14.0);
    for (obstacle, clearance) in [
        ("wall_south", 0.6),
        ("wall_north_1", 0.6),
        ("wall_north_2", 0.6),
        ("pillar", 0.3),
    ] {
        let c = &pair(&r, "robot", obstacle)["first_contact"];
        assert_eq!(c["outcome"], "apart", "{obstacle}");
        let lb = c["clearance_lower_bound"].as_f64().unwrap();
        assert!(lb > 0.0 && lb <= clearance + 1e-12, "{obstacle}: {lb}");
    }
    // The nose (x = 0.6 + t) reaches the block (x = 12) at t = 11.4.
    let c = &pair(&r, "robot", "block")["first_contact"];
    assert_eq!(c["outcome"], "contact");
    let (safe, hit) = (c["t_safe"].as_f64().unwrap(), c["t_hit"].as_f64().unwrap());
    assert!(safe <= 11.4 && 11.4 <= hit, "[{safe}, {hit}]");
    assert_eq!(
        pair(&r, "robot", "sweeper")["first_contact"]["outcome"],
        "contact"
    );
    // Only what was asked: no vertex distance anywhere.
    assert_eq!(r["costs"]["vertex_distance"]["calls"], 0);
}

#[test]
fn two_moving_bodies_against_brute_force() {
    let path = fixtures().join("scenes/two_bodies.toml");
    let (code, r) = run_json(&["run", "--json", path.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert_eq!(r["kernel"], "exact");
    let frames = r["pairs"][0]["frames"].as_array().unwrap();
    assert_eq!(frames.len(), 17);
    assert!(frames.iter().any(|f| f["status"] == "disjoint"));
    check_frames(&r, &read_bodies(&path));
    // Same answers under the other kernels and without temporal coherence.
    for extra in [
        &["--kernel", "robust"][..],
        &["--no-coherence"],
        &["--no-count"],
    ] {
        let mut args = vec!["run", "--json", path.to_str().unwrap()];
        args.extend_from_slice(extra);
        let (_, other) = run_json(&args);
        if extra == ["--kernel", "robust"] {
            assert_eq!(other["kernel"], "robust");
        }
        assert_eq!(other["pairs"], r["pairs"], "{extra:?}");
    }
}

/// The boundary distance of two closed rings by brute force over vertex–edge pairs.
fn ring_distance(a: &[P], b: &[P]) -> f64 {
    let mut best = f64::INFINITY;
    for (p, q) in [(a, b), (b, a)] {
        for &v in p {
            for j in 0..q.len() {
                best = best.min(point_segment(v, q[j], q[(j + 1) % q.len()]));
            }
        }
    }
    best
}

/// The GIS parcels scene: `separation` of simple parcels and a moving barge, every frame against a
/// brute force over the posed boundaries; the realizing points are that far apart; the route of the
/// pair whose hull edge is a lid is reported.
#[test]
fn parcels_scene_separation_against_brute_force() {
    let path = fixtures().join("scenes/parcels.toml");
    let (code, r) = run_json(&["run", "--json", path.to_str().unwrap()]);
    assert_eq!(code, 0);
    let bodies = read_bodies(&path);
    let (mut frames_checked, mut separators) = (0, 0);
    for pair in r["pairs"].as_array().unwrap() {
        let (a, b) = (
            body(&bodies, pair["a"].as_str().unwrap()),
            body(&bodies, pair["b"].as_str().unwrap()),
        );
        for f in pair["frames"].as_array().unwrap() {
            let t = f["t"].as_f64().unwrap();
            let expect = ring_distance(&a.at(t), &b.at(t));
            assert_eq!(
                f["status"], "disjoint",
                "{} – {} at {t}",
                pair["a"], pair["b"]
            );
            let s = &f["separation"];
            let d = s["distance"].as_f64().unwrap();
            assert!(
                close(d, expect, 1e-12),
                "{} – {} at {t}: {d} vs {expect}",
                pair["a"],
                pair["b"]
            );
            let (qa, qb) = (point(&s["point_a"]), point(&s["point_b"]));
            assert!(close(norm(sub(qa, qb)), expect, 1e-12));
            let route = s["route"].as_str().unwrap();
            assert!(
                [
                    "hull_features",
                    "monotone_sweep",
                    "envelope_sweep",
                    "separable_chains",
                    "separators"
                ]
                .contains(&route)
            );
            separators += usize::from(route == "separators");
            frames_checked += 1;
        }
    }
    // Ten static pairs once, five moving pairs (with the barge) at 11 frames.
    assert_eq!(frames_checked, 10 + 5 * 11);
    // The jetty reaches into the U lot's pocket (their hulls meet) and the kiosk stands in it (its
    // hull inside the U lot's): Amato's separator answers both.
    assert_eq!(separators, 2);
    // The same answers under the Exact kernel.
    let (_, exact) = run_json(&["run", "--json", "--kernel", "exact", path.to_str().unwrap()]);
    for (x, y) in r["pairs"]
        .as_array()
        .unwrap()
        .iter()
        .zip(exact["pairs"].as_array().unwrap())
    {
        for (f, g) in x["frames"].as_array().unwrap().iter().zip(g_frames(y)) {
            assert_eq!(f["separation"], g["separation"]);
        }
    }
}

fn g_frames(pair: &Value) -> &Vec<Value> {
    pair["frames"].as_array().unwrap()
}

#[test]
fn check_explains_every_problem() {
    let dir = std::env::temp_dir().join(format!("polydist-cli-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        "[[body]]\nid = \"a\"\nvertices = [[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]]\nkind = \"convex\"\n[[query]]\npairs = [[\"a\", \"ghost\"]]\neffects = [\"separation\", \"first_contact\"]\nmax_steps = 0\n",
    )
    .unwrap();
    let (code, _, err) = run(&["check", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("3 problems"), "{err}");
    assert!(
        err.contains("body 'a'") && err.contains("vertex 2"),
        "{err}"
    );
    assert!(err.contains("ghost") && err.contains("max_steps"), "{err}");
    let syntax = dir.join("syntax.toml");
    std::fs::write(
        &syntax,
        "[[body]]\nid = \"a\"\nvertices = [[0, 0], [1, 0]] x\n",
    )
    .unwrap();
    let (code, _, err) = run(&["check", syntax.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("syntax.toml:3:"), "{err}");
    let (code, out, _) = run(&[
        "check",
        fixtures().join("scenes/corridor.toml").to_str().unwrap(),
    ]);
    assert_eq!(code, 0);
    assert!(out.contains("ok") && out.contains("6 pairs"), "{out}");
    let (code, _, err) = run(&["run", dir.join("missing.toml").to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("cannot read"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_failing_pair_sets_the_exit_status_and_keeps_the_others() {
    let dir = std::env::temp_dir().join(format!("polydist-cli-fail-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("runaway.json");
    std::fs::write(
        &scene,
        r#"{
          "time": {"end": 6.0, "step": 1.0},
          "bodies": [
            {"id": "runaway", "vertices": [[0, 0], [1, 0], [0, 1]],
             "motion": {"type": "linear", "velocity": [1e150, 0.0]}},
            {"id": "b", "vertices": [[0, 5], [1, 5], [0, 6]]},
            {"id": "c", "vertices": [[5, 5], [6, 5], [5, 6]]}
          ],
          "queries": [{"pairs": "all", "effects": ["distance"]}]
        }"#,
    )
    .unwrap();
    let (code, r) = run_json(&["run", "--json", scene.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert_eq!(r["failed"], true);
    let pairs = r["pairs"].as_array().unwrap();
    assert_eq!(pairs.len(), 3);
    assert_eq!(pairs[0]["failed"], true);
    assert_eq!(pairs[0]["frames"][6]["status"], "invalid");
    assert_eq!(pairs[2]["failed"], false);
    assert_eq!(pairs[2]["frames"][0]["distance"].as_f64(), Some(4.0));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The complete example of docs/scene-format.md is fixtures/scenes/example.toml, and it runs.
#[test]
fn the_documented_example_is_a_fixture_and_runs() {
    let doc = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/scene-format.md"),
    )
    .unwrap();
    let start = doc.find("```toml\n").unwrap() + "```toml\n".len();
    let end = start + doc[start..].find("```").unwrap();
    let path = fixtures().join("scenes/example.toml");
    assert_eq!(&doc[start..end], std::fs::read_to_string(&path).unwrap());
    let (code, r) = run_json(&["run", "--json", path.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert_eq!(r["pairs"].as_array().unwrap().len(), 3);
    let bodies = read_bodies(&path);
    check_frames(&r, &bodies);
    check_contact(&r, &bodies, 0.0, 6.0);
    // Every fixture scene passes `check`.
    for entry in std::fs::read_dir(fixtures().join("scenes")).unwrap() {
        let p = entry.unwrap().path();
        let (code, out, err) = run(&["check", p.to_str().unwrap()]);
        assert_eq!(code, 0, "{}: {out}{err}", p.display());
    }
}

/// Runs the binary with `stdin` as its input.
fn run_stdin(args: &[&str], stdin: &str) -> (i32, String, String) {
    use std::io::Write as _;
    use std::process::Stdio;
    let mut child = bin()
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(stdin.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// `polydist batch` on stdin: answers in input order, brute-force distances, an error line that
/// does not stop the batch, exit status 1 for it; the same output on 1 and 2 threads.
#[test]
fn batch_streams_answers_and_error_lines() {
    let mut input = String::new();
    let mut want = Vec::new();
    for k in 0..50 {
        let x = 2.0 + f64::from(k) * 0.25;
        // A unit square at the origin and a triangle at x: distance x - 1 (its left vertex faces
        // the square's right edge).
        input += &format!(
            "{{\"id\": {k}, \"a\": [[0, 0], [1, 0], [1, 1], [0, 1]], \"b\": [[{x}, 0.5], [{}, 0], [{}, 1]]}}\n",
            x + 1.0,
            x + 1.0
        );
        want.push(x - 1.0);
    }
    input += "not json\n";
    let (code, out, err) = run_stdin(&["batch", "--effects", "distance,closest_points"], &input);
    assert_eq!(code, 1, "{err}");
    let lines: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 51);
    for (k, w) in want.iter().enumerate() {
        assert_eq!(lines[k]["id"], k);
        assert_eq!(lines[k]["distance"].as_f64().unwrap(), *w);
        assert_eq!(lines[k]["closest_points"]["feature_b"]["kind"], "vertex");
    }
    assert!(lines[50]["error"].as_str().unwrap().contains("line 51"));
    let (code1, out1, _) = run_stdin(
        &[
            "batch",
            "--threads",
            "1",
            "--effects",
            "distance,closest_points",
        ],
        &input,
    );
    assert_eq!((code1, out1), (1, out));
    // Unknown effects are refused before reading.
    let (code, _, err) = run_stdin(&["batch", "--effects", "speed"], "");
    assert_eq!(code, 2);
    assert!(err.contains("unknown effect 'speed'"));
}

/// `polydist batch --within R A B`: every pair of the two layers within R, against brute force.
#[test]
fn batch_within_two_layers() {
    let dir = std::env::temp_dir().join(format!("polydist-cli-within-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let square = |x: f64, y: f64| {
        format!(
            "[[{x}, {y}], [{}, {y}], [{}, {}], [{x}, {}]]",
            x + 1.0,
            x + 1.0,
            y + 1.0,
            y + 1.0
        )
    };
    let mut a = String::new();
    let mut b = String::new();
    let mut want = Vec::new();
    for i in 0..10 {
        for j in 0..10 {
            let (ax, ay) = (f64::from(i) * 3.0, f64::from(j) * 3.0);
            a += &format!(
                "{{\"id\": \"a{i}_{j}\", \"vertices\": {}}}\n",
                square(ax, ay)
            );
            // b squares: shifted by 1.25 in x from a, so the nearest a square is 0.25 away, the
            // next 0.75, the others farther.
            let bx = ax + 1.25;
            b += &format!(
                "{{\"id\": \"b{i}_{j}\", \"vertices\": {}}}\n",
                square(bx, ay)
            );
            want.push((format!("a{i}_{j}"), format!("b{i}_{j}")));
        }
    }
    b += "{\"vertices\": []}\n";
    std::fs::write(dir.join("a.jsonl"), &a).unwrap();
    std::fs::write(dir.join("b.jsonl"), &b).unwrap();
    let (code, out, err) = run(&[
        "batch",
        "--within",
        "0.5",
        dir.join("a.jsonl").to_str().unwrap(),
        dir.join("b.jsonl").to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{err}");
    let lines: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines[0]["layer"], "b");
    assert_eq!(lines[0]["line"], 101);
    let mut got: Vec<(String, String)> = lines[1..]
        .iter()
        .map(|v| {
            assert_eq!(v["distance"], 0.25);
            (
                v["a"].as_str().unwrap().to_owned(),
                v["b"].as_str().unwrap().to_owned(),
            )
        })
        .collect();
    got.sort();
    want.sort();
    assert_eq!(got, want);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `run --svg FILE` writes an SVG document with the bodies, next to the usual table.
#[test]
fn run_writes_svg() {
    let file = std::env::temp_dir().join(format!("polydist-cli-{}.svg", std::process::id()));
    let scene = fixtures().join("scenes/corridor.toml");
    let (code, out, err) = run(&[
        "run",
        scene.to_str().unwrap(),
        "--svg",
        file.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("first_contact"));
    let svg = std::fs::read_to_string(&file).unwrap();
    assert!(svg.starts_with("<?xml"));
    assert!(svg.trim_end().ends_with("</svg>"));
    assert!(svg.matches("class=\"body\"").count() >= 2);
    assert!(svg.contains("class=\"trajectory\""));
    assert!(svg.contains("class=\"distance-plot\""));
    std::fs::remove_file(&file).unwrap();
    // An unwritable path is an error (status 2).
    let (code, _, err) = run(&[
        "run",
        scene.to_str().unwrap(),
        "--svg",
        "/nonexistent-dir/x.svg",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("cannot write"));
}
