//! Batch queries: pairs of polygons as JSON lines in, one JSON line of answers per pair out,
//! streamed in chunks evaluated in parallel; and all pairs of two layers within a distance. The
//! format is docs/batch.md.
//!
//! Every line is answered by the same code as a scene frame (the runner's per-frame evaluation on
//! bodies at the identity pose), so a batch answer equals the scene answer for the same polygons.
//! A bad line (malformed JSON, an invalid polygon, an effect a batch cannot compute) gets an error
//! line naming the line, the field and what was expected, and the batch goes on.

use std::io::{self, BufRead, Write};

use glam::DVec2;
use polydist_convex::Pose;
use polydist_polygon::ConvexPolygon;
use polydist_polygon::predicates::{Exact, Fast, Kernel, Robust};
use rayon::prelude::*;
use serde::Deserialize;
use serde_json::{Map, Value};

use crate::broad::{Aabb, sweep_classes};
use crate::generate::MAX_VERTICES;
use crate::load::{Body, Shape};
use crate::motion::Motion;
use crate::report::{Costs, FrameResult, Status};
use crate::run::{Ask, Meter, Posed, eval_frame, pose_body};
use crate::spec::{Effect, EffectSet, KernelChoice};

/// The longest input line, in bytes (a longer line gets an error line and is skipped).
pub const MAX_LINE_BYTES: usize = 16 << 20;
/// The most polygons read from one layer file by [`read_layer`].
pub const MAX_LAYER_POLYGONS: usize = 10_000_000;

/// How to answer a batch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BatchOptions {
    /// The precision kernel of every decision.
    pub kernel: KernelChoice,
    /// The effects of lines that give none (default: `distance`).
    pub effects: EffectSet,
    /// Lines read and answered per parallel chunk (the output is written in input order after each
    /// chunk; default 1024).
    pub chunk: usize,
}

impl Default for BatchOptions {
    fn default() -> Self {
        BatchOptions {
            kernel: KernelChoice::Robust,
            effects: [Effect::Distance].into_iter().collect(),
            chunk: 1024,
        }
    }
}

/// What a batch did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BatchSummary {
    /// Non-blank input lines (pairs), or, for [`batch_within`], candidate pairs from the broad phase.
    pub lines: u64,
    /// Lines answered (for [`batch_within`]: pairs within the distance, written).
    pub answered: u64,
    /// Error lines written.
    pub errors: u64,
}

/// One input line of [`batch_pairs`].
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PairLine {
    #[serde(default)]
    id: Option<Value>,
    a: Vec<[f64; 2]>,
    b: Vec<[f64; 2]>,
    #[serde(default)]
    effects: Option<Vec<Effect>>,
    #[serde(default)]
    within: Option<f64>,
}

/// One polygon of a layer file.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LayerLine {
    #[serde(default)]
    id: Option<Value>,
    vertices: Vec<[f64; 2]>,
}

/// A validated polygon of a layer: its id (the line number when the line gives none), its line and
/// the convex polygon.
#[derive(Clone, Debug, PartialEq)]
pub struct LayerPolygon {
    /// The `id` field of the line, or the line number.
    pub id: Value,
    /// The line (1-based).
    pub line: u64,
    /// The polygon.
    pub poly: ConvexPolygon,
}

/// Reads one line of at most [`MAX_LINE_BYTES`] into `buf` (without the line break). `Ok(None)` at
/// the end of the input; `Ok(Some(false))` when the line was longer (the rest is skipped).
fn read_line_bounded<R: BufRead>(r: &mut R, buf: &mut Vec<u8>) -> io::Result<Option<bool>> {
    buf.clear();
    let n = io::Read::take(&mut *r, MAX_LINE_BYTES as u64 + 1).read_until(b'\n', buf)?;
    if n == 0 {
        return Ok(None);
    }
    if buf.last() == Some(&b'\n') {
        buf.pop();
        if buf.last() == Some(&b'\r') {
            buf.pop();
        }
        return Ok(Some(true));
    }
    if buf.len() <= MAX_LINE_BYTES {
        // The last line, without a line break.
        return Ok(Some(true));
    }
    // Too long: skip to the end of the line in bounded pieces.
    let mut skip = Vec::new();
    loop {
        skip.clear();
        let n = io::Read::take(&mut *r, 1 << 16).read_until(b'\n', &mut skip)?;
        if n == 0 || skip.last() == Some(&b'\n') {
            return Ok(Some(false));
        }
    }
}

/// A line as text, or the error for a line that is too long or not UTF-8.
fn line_text(buf: &[u8], fits: bool) -> Result<&str, String> {
    if !fits {
        return Err(format!("the line is longer than {MAX_LINE_BYTES} bytes"));
    }
    std::str::from_utf8(buf).map_err(|e| format!("the line is not UTF-8: {e}"))
}

/// A polygon of a line, validated as convex, or an error naming the field and the vertex.
fn polygon(field: &str, v: &[[f64; 2]]) -> Result<ConvexPolygon, String> {
    if v.len() as u64 > MAX_VERTICES {
        return Err(format!(
            "'{field}' has {} vertices; at most {MAX_VERTICES} are allowed",
            v.len()
        ));
    }
    let pts: Vec<DVec2> = v.iter().map(|&p| DVec2::from_array(p)).collect();
    ConvexPolygon::try_new(&pts)
        .map_err(|e| format!("'{field}' is not a valid convex polygon: {e}"))
}

/// A body at the identity pose, and its posed form (posed exactly as the runner poses a body, so
/// feature indices map back to the caller's indices the same way).
fn at_rest(id: &str, poly: ConvexPolygon) -> Result<(Body, Posed), String> {
    let identity = Pose {
        translation: DVec2::ZERO,
        rotation: 0.0,
    };
    let radius = poly
        .vertices()
        .iter()
        .map(|v| v.length())
        .fold(0.0, f64::max);
    let body = Body {
        id: id.to_owned(),
        shape: Shape::Convex(poly),
        motion: Motion::Static(identity),
        radius,
    };
    let posed = pose_body(&body, 0.0)?;
    Ok((body, posed))
}

/// Evaluates the frame effects of one pair (the runner's code path) at the identity pose.
fn evaluate<K: Kernel>(
    a: ConvexPolygon,
    b: ConvexPolygon,
    effects: EffectSet,
    within: Option<f64>,
) -> Result<FrameResult, String> {
    let ask = Ask { effects, within };
    let (ba, pa) = at_rest("a", a)?;
    let (bb, pb) = at_rest("b", b)?;
    let meter = Meter { count: false };
    let mut costs = Costs::default();
    Ok(eval_frame::<K>(
        ask,
        0.0,
        (&ba, &pa),
        (&bb, &pb),
        None,
        &meter,
        &mut costs,
    ))
}

/// The answer object of a frame: its fields without `t`.
fn answer_fields(frame: &FrameResult) -> Map<String, Value> {
    match serde_json::to_value(frame) {
        Ok(Value::Object(mut m)) => {
            m.remove("t");
            m
        }
        // A FrameResult always serialises to an object.
        _ => Map::new(),
    }
}

/// The output line of an error.
fn error_line(line: u64, id: Option<Value>, error: String) -> String {
    let mut m = Map::new();
    m.insert("line".to_owned(), Value::from(line));
    if let Some(id) = id {
        m.insert("id".to_owned(), id);
    }
    m.insert("error".to_owned(), Value::String(error));
    Value::Object(m).to_string()
}

/// Answers one input line of [`batch_pairs`]: `Ok(answer line)` or `Err(error line)`.
fn answer_line<K: Kernel>(line: u64, text: &str, options: &BatchOptions) -> Result<String, String> {
    let parsed: PairLine = serde_json::from_str(text).map_err(|e| {
        error_line(
            line,
            None,
            format!(
                "line {line}, column {}: {e} (expected {{\"a\": [[x, y], ...], \"b\": [[x, y], ...]}} with optional \"id\", \"effects\", \"within\")",
                e.column()
            ),
        )
    })?;
    let id = parsed.id;
    let fail = |msg: String| error_line(line, id.clone(), msg);
    let effects: EffectSet = match &parsed.effects {
        Some(list) => list.iter().copied().collect(),
        None => options.effects,
    };
    if effects.is_empty() {
        return Err(fail("no effects asked".to_owned()));
    }
    for e in effects.iter() {
        match e {
            Effect::FirstContact => {
                return Err(fail(
                    "first_contact needs motions over a time span: use a scene file (polydist run)"
                        .to_owned(),
                ));
            }
            Effect::Separation => {
                return Err(fail(
                    "separation is not available in batch mode (convex pairs only): use a scene"
                        .to_owned(),
                ));
            }
            _ => {}
        }
    }
    if let Some(r) = parsed.within {
        if r.is_nan() || r < 0.0 {
            return Err(fail(format!("within must be >= 0 (got {r})")));
        }
    }
    let a = polygon("a", &parsed.a).map_err(&fail)?;
    let b = polygon("b", &parsed.b).map_err(&fail)?;
    let frame =
        evaluate::<K>(a, b, effects, parsed.within.filter(|r| r.is_finite())).map_err(&fail)?;
    let mut m = Map::new();
    m.insert("line".to_owned(), Value::from(line));
    if let Some(id) = id {
        m.insert("id".to_owned(), id);
    }
    m.extend(answer_fields(&frame));
    Ok(Value::Object(m).to_string())
}

/// Reads pairs of polygons as JSON lines from `input` and writes one JSON line per pair to `output`,
/// in input order: `{"line": n, "id": ..., "status": ..., "distance": ..., ...}` (the fields of a
/// scene frame for the asked effects) or `{"line": n, "id": ..., "error": "..."}`. Blank lines are
/// skipped (they still count in the line numbers). Lines are read in chunks of
/// [`BatchOptions::chunk`], answered in parallel on the current rayon pool, and written after each
/// chunk, so memory stays bounded by a chunk and output starts before the input ends.
///
/// Each pair is answered by the scene runner's per-frame evaluation: Yang et al. 2006 (`O(log n +
/// log m)`) for `distance`/`closest_points` (`distance_within` with `within`), McKenna–Toussaint 1985
/// (`O(n + m)`) for `vertex_distance`, Atallah–Ribeiro–Lifschitz 1991 (`O(n + m)`) for `hausdorff`
/// and `cmmr`; plus `O(n + m)` to validate the polygons (Melkman 1987 via `ConvexPolygon::try_new`).
///
/// # Errors
/// Only I/O errors of `input` or `output`; every problem of a line is an error line.
///
/// # Complexity
/// Per line, the effects' costs above; lines in parallel.
pub fn batch_pairs<R: BufRead, W: Write>(
    mut input: R,
    mut output: W,
    options: &BatchOptions,
) -> io::Result<BatchSummary> {
    let mut summary = BatchSummary::default();
    let chunk = options.chunk.max(1);
    let mut line_no = 0u64;
    let mut buf = Vec::new();
    let mut done = false;
    while !done {
        let mut lines: Vec<(u64, Result<String, String>)> = Vec::with_capacity(chunk);
        while lines.len() < chunk {
            let Some(fits) = read_line_bounded(&mut input, &mut buf)? else {
                done = true;
                break;
            };
            line_no += 1;
            match line_text(&buf, fits) {
                Ok(t) if t.trim().is_empty() => {}
                Ok(t) => lines.push((line_no, Ok(t.to_owned()))),
                Err(e) => lines.push((line_no, Err(e))),
            }
        }
        let answers: Vec<Result<String, String>> = lines
            .par_iter()
            .map(|(n, text)| match text {
                Ok(t) => match options.kernel {
                    KernelChoice::Fast => answer_line::<Fast>(*n, t, options),
                    KernelChoice::Robust => answer_line::<Robust>(*n, t, options),
                    KernelChoice::Exact => answer_line::<Exact>(*n, t, options),
                },
                Err(e) => Err(error_line(*n, None, format!("line {n}: {e}"))),
            })
            .collect();
        for a in answers {
            summary.lines += 1;
            let text = match a {
                Ok(t) => {
                    summary.answered += 1;
                    t
                }
                Err(t) => {
                    summary.errors += 1;
                    t
                }
            };
            output.write_all(text.as_bytes())?;
            output.write_all(b"\n")?;
        }
        output.flush()?;
    }
    Ok(summary)
}

/// Reads a layer: one polygon per JSON line, `{"id": ..., "vertices": [[x, y], ...]}` (`id`
/// optional: the line number). Returns the valid convex polygons and, for each bad line, an error
/// line `{"layer": name, "line": n, "error": ...}`.
///
/// # Errors
/// I/O errors of `input`, and more than [`MAX_LAYER_POLYGONS`] lines (`InvalidData`).
///
/// # Complexity
/// `O(total vertices)` (validation, Melkman 1987).
pub fn read_layer<R: BufRead>(
    mut input: R,
    name: &str,
) -> io::Result<(Vec<LayerPolygon>, Vec<String>)> {
    let mut polys = Vec::new();
    let mut errors = Vec::new();
    let mut buf = Vec::new();
    let mut line = 0u64;
    while let Some(fits) = read_line_bounded(&mut input, &mut buf)? {
        line += 1;
        if polys.len() + errors.len() >= MAX_LAYER_POLYGONS {
            return Err(io::Error::new(
                io::ErrorKind::InvalidData,
                format!("layer {name}: more than {MAX_LAYER_POLYGONS} polygons"),
            ));
        }
        let result = line_text(&buf, fits).and_then(|t| {
            if t.trim().is_empty() {
                return Ok(None);
            }
            let l: LayerLine = serde_json::from_str(t).map_err(|e| {
                format!(
                    "column {}: {e} (expected {{\"id\": ..., \"vertices\": [[x, y], ...]}})",
                    e.column()
                )
            })?;
            let poly = polygon("vertices", &l.vertices)?;
            Ok(Some(LayerPolygon {
                id: l.id.unwrap_or(Value::from(line)),
                line,
                poly,
            }))
        });
        match result {
            Ok(Some(p)) => polys.push(p),
            Ok(None) => {}
            Err(e) => {
                let mut m = Map::new();
                m.insert("layer".to_owned(), Value::String(name.to_owned()));
                m.insert("line".to_owned(), Value::from(line));
                m.insert("error".to_owned(), Value::String(e));
                errors.push(Value::Object(m).to_string());
            }
        }
    }
    Ok((polys, errors))
}

/// Every pair `(p, q)` with `p` in `a`, `q` in `b` and `dist(p, q) ≤ r` (exactly), written as JSON
/// lines in the order of `a` then `b`: `{"a": id, "b": id, "a_line": n, "b_line": m, "status": ...,
/// "distance": ..., "squared_distance": ..., "closest_points": {...}}`.
///
/// The broad phase (bounding boxes, sweep-and-prune with the certified box gap of
/// [`sweep_and_prune`](crate::sweep_and_prune)) proposes the candidates; each is decided by
/// `distance_within` (Yang et al. 2006 with an exact threshold, `O(log n + log m)`), in parallel, in
/// chunks of [`BatchOptions::chunk`]. A pair whose boxes are certainly farther than `r` is never
/// within `r`, so no pair within `r` is missed. `r` must be `≥ 0` (a negative or NaN `r` has no
/// pair).
///
/// # Errors
/// I/O errors of `output`.
///
/// # Complexity
/// `O(N log N + k)` for the broad phase (`N = |a| + |b|`, `k` pairs of one polygon of each layer
/// whose intervals on the sweep axis come within `r`; same-layer pairs are never walked), plus
/// `O(log n + log m)` per candidate pair.
pub fn batch_within<W: Write>(
    a: &[LayerPolygon],
    b: &[LayerPolygon],
    r: f64,
    options: &BatchOptions,
    mut output: W,
) -> io::Result<BatchSummary> {
    let mut summary = BatchSummary::default();
    if r.is_nan() || r < 0.0 {
        return Ok(summary);
    }
    let boxes: Vec<Option<Aabb>> = a
        .iter()
        .chain(b)
        .map(|p| Aabb::of(p.poly.vertices()))
        .collect();
    let na = a.len();
    let mut candidates = Vec::new();
    // Two classes, the layers: only pairs across them are walked.
    let _ = sweep_classes(
        &boxes,
        |i| usize::from(i >= na),
        [false, false],
        r,
        |i, j| {
            candidates.push((i, j));
            true
        },
    );
    candidates.sort_unstable();
    let mut effects = EffectSet::EMPTY;
    effects.insert(Effect::Distance);
    effects.insert(Effect::ClosestPoints);
    let within = r.is_finite().then_some(r);
    for chunk in candidates.chunks(options.chunk.max(1)) {
        let answers: Vec<Option<String>> = chunk
            .par_iter()
            .map(|&(i, j)| {
                let (p, q) = (&a[i], &b[j - na]);
                let frame = match options.kernel {
                    KernelChoice::Fast => {
                        evaluate::<Fast>(p.poly.clone(), q.poly.clone(), effects, within)
                    }
                    KernelChoice::Robust => {
                        evaluate::<Robust>(p.poly.clone(), q.poly.clone(), effects, within)
                    }
                    KernelChoice::Exact => {
                        evaluate::<Exact>(p.poly.clone(), q.poly.clone(), effects, within)
                    }
                };
                let frame = match frame {
                    Ok(f) if f.status == Some(Status::Beyond) => return None,
                    Ok(f) => f,
                    // Re-validating a valid convex ring at the identity pose cannot fail; were it
                    // to, the pair is reported rather than lost.
                    Err(e) => FrameResult {
                        error: Some(e),
                        ..FrameResult::empty(0.0, Status::Invalid)
                    },
                };
                let mut m = Map::new();
                m.insert("a".to_owned(), p.id.clone());
                m.insert("b".to_owned(), q.id.clone());
                m.insert("a_line".to_owned(), Value::from(p.line));
                m.insert("b_line".to_owned(), Value::from(q.line));
                m.extend(answer_fields(&frame));
                Some(Value::Object(m).to_string())
            })
            .collect();
        for text in answers {
            summary.lines += 1;
            if let Some(t) = text {
                summary.answered += 1;
                output.write_all(t.as_bytes())?;
                output.write_all(b"\n")?;
            }
        }
        output.flush()?;
    }
    Ok(summary)
}
