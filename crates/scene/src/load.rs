//! Loading and validating a scene: text → [`SceneSpec`] → [`Scene`], reporting every problem.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use glam::DVec2;
use polydist_convex::Pose;
use polydist_polygon::{ConvexPolygon, SimplePolygon};

use crate::error::{SceneError, SceneErrors};
use crate::generate::{GenError, MAX_VERTICES, generate, generator_name};
use crate::motion::{Keyframe, Motion, radius};
use crate::spec::{
    BodySpec, Effect, EffectSet, KernelChoice, KindSpec, MotionSpec, PairsSpec, SceneSpec,
};

/// The most bodies a scene may have.
pub const MAX_BODIES: usize = 100_000;
/// The most frames a time span may have.
pub const MAX_FRAMES: u64 = 1_000_000;
/// The most pairs named over all queries (a streamed query, [`Query::is_streamed`], names none:
/// its candidates are bounded at run time by [`MAX_FRAME_CANDIDATES`]).
pub const MAX_PAIRS: u128 = 10_000_000;
/// The most pair-frame evaluations (pairs with per-frame effects × frames; a streamed query counts
/// its bodies × frames at load, and its candidate pair-frames at run time).
pub const MAX_PAIR_FRAMES: u128 = 100_000_000;
/// The most candidate pairs of streamed queries in one frame (pairs the broad phase cannot
/// certify beyond `within`, or every pair without the broad phase). A run reaching it stops the
/// streamed queries there, with an error in the report ([`Report::errors`](crate::Report::errors)),
/// before storing the candidates; so does a run whose candidate pair-frames would exceed
/// [`MAX_PAIR_FRAMES`].
pub const MAX_FRAME_CANDIDATES: u64 = 10_000_000;
/// The largest polygon file read, in bytes (64 MiB).
pub const MAX_FILE_BYTES: u64 = 64 << 20;
/// `first_contact`'s default bracket width, relative to the span `end − start`.
pub const DEFAULT_RELATIVE_TOLERANCE: f64 = 1e-6;
/// `first_contact`'s default step limit per pair.
pub const DEFAULT_MAX_STEPS: u64 = 100_000;
/// Frames are `start + k·step` for `k = 0, 1, …` while `k·step ≤ (end − start) + FRAME_SLACK·step`
/// (so that `end = 0.3, step = 0.1` has its frame at `0.3` despite `0.3 / 0.1 < 3` in `f64`); the
/// last frame's time is clamped to `end`. It only places frames; no geometric decision uses it.
pub const FRAME_SLACK: f64 = 1e-9;

/// Where scene text came from: names the file in messages and resolves polygon files.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Origin {
    /// The name used in messages (`path/to/scene.toml`, `<embedded default scene>`, ...).
    pub name: String,
    /// The directory polygon files are relative to (`None`: polygon files are refused).
    pub dir: Option<PathBuf>,
    /// Whether the text is JSON (`None`: detected from the name's extension, then the first
    /// non-blank character: `{` means JSON).
    pub json: Option<bool>,
}

impl Origin {
    /// Text with a name and no directory.
    #[must_use]
    pub fn text(name: &str) -> Origin {
        Origin {
            name: name.to_owned(),
            dir: None,
            json: None,
        }
    }
}

/// The kind and the validated polygon of a body.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A convex polygon (points and segments included).
    Convex(ConvexPolygon),
    /// A simple polygon that is not convex (or was declared `simple`).
    Simple(SimplePolygon),
}

impl Shape {
    /// `convex` or `simple`.
    #[must_use]
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Convex(_) => "convex",
            Shape::Simple(_) => "simple",
        }
    }

    /// The vertices in the body's frame.
    #[must_use]
    pub fn vertices(&self) -> &[DVec2] {
        match self {
            Shape::Convex(p) => p.vertices(),
            Shape::Simple(p) => p.vertices(),
        }
    }
}

/// A validated body.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// The id.
    pub id: String,
    /// The polygon in the body's frame.
    pub shape: Shape,
    /// The motion.
    pub motion: Motion,
    /// The largest distance of a vertex from the body frame's origin, rounded up.
    pub radius: f64,
}

/// `first_contact`'s parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactParams {
    /// The largest width of the reported bracket, in time units.
    pub tolerance: f64,
    /// The most advancement steps.
    pub max_steps: u64,
}

/// A validated query.
#[derive(Clone, Debug, PartialEq)]
pub struct Query {
    /// The name.
    pub name: String,
    /// The pairs it names: every unordered pair of distinct bodies, or a list (never expanded for
    /// `all`: a scene of `n` bodies has `n(n − 1)/2` pairs).
    pub pairs: PairSet,
    /// The effects.
    pub effects: EffectSet,
    /// `first_contact`'s parameters.
    pub contact: ContactParams,
    /// The distance threshold of the per-frame effects (`None`: every pair; see
    /// [`QuerySpec::within`](crate::QuerySpec::within)).
    pub within: Option<f64>,
}

/// The pairs a query names.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PairSet {
    /// Every unordered pair `(a, b)`, `a < b`, of distinct bodies (`pairs = "all"`), in the order
    /// `(0, 1), (0, 2), …, (1, 2), …`.
    All,
    /// Listed pairs of body indices (distinct bodies; `a` as listed first), in the order listed.
    List(Vec<(usize, usize)>),
}

impl PairSet {
    /// The number of pairs named (with repetitions for a list) among `bodies` bodies.
    ///
    /// # Complexity
    /// `O(1)`.
    #[must_use]
    pub fn count(&self, bodies: usize) -> u128 {
        match self {
            PairSet::All => {
                let n = bodies as u128;
                n * n.saturating_sub(1) / 2
            }
            PairSet::List(list) => list.len() as u128,
        }
    }

    /// The pairs, in order: `O(1)` each (an `all` set is generated, never stored).
    ///
    /// # Complexity
    /// `O(1)` per pair.
    pub fn iter(&self, bodies: usize) -> impl Iterator<Item = (usize, usize)> + '_ {
        let list = match self {
            PairSet::All => None,
            PairSet::List(list) => Some(list.iter().copied()),
        };
        let all = list
            .is_none()
            .then(|| (0..bodies).flat_map(move |a| (a + 1..bodies).map(move |b| (a, b))));
        list.into_iter().flatten().chain(all.into_iter().flatten())
    }
}

impl Query {
    /// Whether the query is **streamed**: all pairs, with a `within` threshold, without
    /// `first_contact`. Its pairs are never materialized: the runner takes each frame's candidate
    /// pairs from the broad phase (docs/scene-format.md, "Many bodies").
    #[must_use]
    pub fn is_streamed(&self) -> bool {
        streamed(&self.pairs, self.within, self.effects)
    }
}

fn streamed(pairs: &PairSet, within: Option<f64>, effects: EffectSet) -> bool {
    matches!(pairs, PairSet::All) && within.is_some() && !effects.contains(Effect::FirstContact)
}

/// The validated time span.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TimeSpan {
    /// The first frame.
    pub start: f64,
    /// The end of the span.
    pub end: f64,
    /// The frame step.
    pub step: f64,
    /// The number of frames (at least 1).
    pub frames: usize,
}

impl TimeSpan {
    /// The time of frame `k`: `min(start + k·step, end)`.
    #[must_use]
    pub fn frame(&self, k: usize) -> f64 {
        (self.start + k as f64 * self.step).min(self.end)
    }
}

/// A validated scene, ready to run.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The scene's name.
    pub name: String,
    /// The time span.
    pub time: TimeSpan,
    /// The kernel.
    pub kernel: KernelChoice,
    /// Temporal coherence for moving convex pairs.
    pub coherence: bool,
    /// The bodies.
    pub bodies: Vec<Body>,
    /// The queries.
    pub queries: Vec<Query>,
}

/// Byte offset → 1-based (line, column in characters).
fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, col)
}

/// Parses scene text (TOML or JSON) into its [`SceneSpec`], with a [`SceneError::Syntax`] naming
/// the file, line and column on failure.
///
/// # Errors
/// [`SceneError::Syntax`].
///
/// # Complexity
/// Linear in the text.
pub fn parse_spec(text: &str, origin: &Origin) -> Result<SceneSpec, SceneError> {
    let json = origin.json.unwrap_or_else(|| {
        let lower = origin.name.to_ascii_lowercase();
        if lower.ends_with(".json") {
            true
        } else if lower.ends_with(".toml") {
            false
        } else {
            text.trim_start().starts_with('{')
        }
    });
    if json {
        serde_json::from_str(text).map_err(|e| SceneError::Syntax {
            file: origin.name.clone(),
            line: e.line(),
            column: e.column(),
            message: e.to_string(),
        })
    } else {
        toml::from_str(text).map_err(|e| {
            let (line, column) = e.span().map_or((1, 1), |s| line_col(text, s.start));
            SceneError::Syntax {
                file: origin.name.clone(),
                line,
                column,
                message: e.message().trim().to_owned(),
            }
        })
    }
}

/// Loads a scene file from disk (TOML, or JSON by extension or content).
///
/// # Errors
/// [`SceneError::Io`] when the file cannot be read, and every problem [`load_str`] finds.
///
/// # Complexity
/// That of [`load_str`].
pub fn load_file(path: &Path) -> Result<Scene, SceneErrors> {
    let text = std::fs::read_to_string(path).map_err(|e| SceneError::Io {
        path: path.display().to_string(),
        reason: e.to_string(),
    })?;
    let origin = Origin {
        name: path.display().to_string(),
        dir: Some(
            path.parent()
                .map_or_else(|| PathBuf::from("."), Path::to_path_buf),
        ),
        json: None,
    };
    load_str(&text, &origin)
}

/// Parses and validates scene text: every problem is reported, not just the first.
///
/// # Errors
/// A syntax error alone (nothing after it can be read), or every validation problem: bodies (ids,
/// shape sources, polygons with the offending vertex, generators, files, poses, motions, limits),
/// the time span, queries (unknown ids, self pairs, effects not yet available or needing convex
/// bodies, parameters), and the work limits.
///
/// # Complexity
/// Linear in the text and the bodies' vertices (`O(n log n)` for simple polygons), plus the pairs.
///
/// # Examples
/// ```
/// use polydist_scene::{Origin, load_str};
///
/// let scene = load_str(r#"
///     time = { end = 1.0, step = 0.5 }
///     [[body]]
///     id = "a"
///     generator = { type = "regular", n = 4, radius = 1.0 }
///     [[body]]
///     id = "b"
///     vertices = [[3, 0], [4, 0], [4, 1]]
///     [[query]]
///     pairs = [["a", "b"]]
///     effects = ["distance"]
/// "#, &Origin::text("example.toml")).unwrap();
/// assert_eq!(scene.time.frames, 3);
/// assert_eq!(scene.bodies[1].shape.kind(), "convex");
///
/// let errors = load_str("[[body]]\nid = 3\n", &Origin::text("bad.toml")).unwrap_err();
/// assert!(errors.to_string().contains("bad.toml:2:6"));
/// ```
pub fn load_str(text: &str, origin: &Origin) -> Result<Scene, SceneErrors> {
    let spec = parse_spec(text, origin)?;
    validate(&spec, origin)
}

/// Validates a parsed [`SceneSpec`] (see [`load_str`]).
///
/// # Errors
/// Every problem found (see [`load_str`]).
///
/// # Complexity
/// That of [`load_str`] without the parsing.
pub fn validate(spec: &SceneSpec, origin: &Origin) -> Result<Scene, SceneErrors> {
    let mut errors = Vec::new();
    let time = validate_time(spec, &mut errors);

    if spec.bodies.len() > MAX_BODIES {
        errors.push(SceneError::TooManyBodies {
            count: spec.bodies.len(),
            limit: MAX_BODIES,
        });
        return Err(SceneErrors(errors));
    }
    let mut ids: HashMap<&str, usize> = HashMap::new();
    let mut bodies: Vec<Option<Body>> = Vec::with_capacity(spec.bodies.len());
    for (i, b) in spec.bodies.iter().enumerate() {
        if b.id.is_empty() {
            errors.push(SceneError::EmptyId { index: i + 1 });
        } else if let Some(&first) = ids.get(b.id.as_str()) {
            errors.push(SceneError::DuplicateId {
                id: b.id.clone(),
                first: first + 1,
                second: i + 1,
            });
        } else {
            ids.insert(&b.id, i);
        }
        bodies.push(validate_body(b, origin, &mut errors));
    }

    let span = time.map_or(0.0, |t| t.end - t.start);
    let mut queries = Vec::with_capacity(spec.queries.len());
    let mut pair_count: u128 = 0;
    for (k, q) in spec.queries.iter().enumerate() {
        let name = q
            .name
            .clone()
            .unwrap_or_else(|| format!("query #{}", k + 1));
        let mut effects = EffectSet::EMPTY;
        if q.effects.is_empty() {
            errors.push(SceneError::NoEffects {
                query: name.clone(),
            });
        }
        for &e in &q.effects {
            if !e.is_available() && !effects.contains(e) {
                errors.push(SceneError::EffectNotYetAvailable {
                    query: name.clone(),
                    effect: e.name(),
                });
            }
            effects.insert(e);
        }
        // A given tolerance must be positive (with 0 the bracket could never be confirmed); the
        // default is 0 only for a span of length 0, where no step is ever taken.
        let tolerance = q
            .tolerance
            .unwrap_or(DEFAULT_RELATIVE_TOLERANCE * span.max(0.0));
        if q.tolerance.is_some() && !(tolerance.is_finite() && tolerance > 0.0) {
            errors.push(SceneError::BadParameter {
                query: name.clone(),
                reason: format!("tolerance must be finite and > 0 (got {tolerance})"),
            });
        }
        let max_steps = q.max_steps.unwrap_or(DEFAULT_MAX_STEPS);
        if max_steps == 0 {
            errors.push(SceneError::BadParameter {
                query: name.clone(),
                reason: "max_steps must be at least 1".to_owned(),
            });
        }
        if let Some(r) = q.within {
            if r.is_nan() || r < 0.0 {
                errors.push(SceneError::BadParameter {
                    query: name.clone(),
                    reason: format!("within must be >= 0 (got {r})"),
                });
            }
        }
        let is_convex = |i: usize| {
            !matches!(
                bodies.get(i),
                Some(Some(Body {
                    shape: Shape::Simple(_),
                    ..
                }))
            )
        };
        // Convex-only effects on pairs with a simple body: reported once per query and simple
        // body (at its first pair), not once per pair of an "all" query.
        let needs_convex = |errors: &mut Vec<SceneError>, a: usize, b: usize, s: usize| {
            for e in effects
                .iter()
                .filter(|e| e.is_available() && e.needs_convex())
            {
                errors.push(SceneError::NeedsConvex {
                    query: name.clone(),
                    effect: e.name(),
                    a: spec.bodies[a].id.clone(),
                    b: spec.bodies[b].id.clone(),
                    body: spec.bodies[s].id.clone(),
                });
            }
        };
        let pairs = match &q.pairs {
            PairsSpec::All => {
                let n = spec.bodies.len();
                // An all-pairs query with `within` (and without `first_contact`) is never expanded
                // into pairs: the runner takes its candidates from the broad phase, frame by frame
                // (its work is bounded at run time, `MAX_FRAME_CANDIDATES`).
                if !streamed(&PairSet::All, q.within.filter(|r| r.is_finite()), effects) {
                    pair_count += PairSet::All.count(n);
                }
                // The first pair of each simple body in the order (0, 1), (0, 2), …: body `a`
                // names its own pairs first when simple; the first convex `a` names every later
                // simple body.
                for a in 0..n.saturating_sub(1) {
                    if is_convex(a) {
                        for b in (a + 1..n).filter(|&b| !is_convex(b)) {
                            needs_convex(&mut errors, a, b, b);
                        }
                        break;
                    }
                    needs_convex(&mut errors, a, a + 1, a);
                }
                PairSet::All
            }
            PairsSpec::List(list) => {
                pair_count += list.len() as u128;
                let mut pairs = Vec::with_capacity(list.len());
                for [a, b] in list {
                    let ia = lookup(&ids, a, &name, &mut errors);
                    let ib = lookup(&ids, b, &name, &mut errors);
                    if a == b {
                        errors.push(SceneError::SelfPair {
                            query: name.clone(),
                            id: a.clone(),
                        });
                    } else if let (Some(ia), Some(ib)) = (ia, ib) {
                        pairs.push((ia, ib));
                    }
                }
                let mut reported = std::collections::HashSet::new();
                for &(a, b) in &pairs {
                    let simple = [a, b].into_iter().find(|&i| !is_convex(i));
                    if let Some(s) = simple.filter(|&s| reported.insert(s)) {
                        needs_convex(&mut errors, a, b, s);
                    }
                }
                PairSet::List(pairs)
            }
        };
        queries.push(Query {
            name,
            pairs,
            effects,
            contact: ContactParams {
                tolerance,
                max_steps,
            },
            within: q.within.filter(|r| r.is_finite()),
        });
    }
    if pair_count > MAX_PAIRS {
        errors.push(SceneError::TooMuchWork {
            what: "pairs",
            count: pair_count,
            limit: MAX_PAIRS,
        });
    } else if let Some(t) = time {
        // A streamed query poses every body at every frame; its pair-frames are bounded at run time.
        let n = bodies.len() as u128;
        let per_frame = queries
            .iter()
            .filter(|q| q.effects.has_per_frame())
            .map(|q| {
                if q.is_streamed() {
                    n
                } else {
                    q.pairs.count(bodies.len())
                }
            })
            .sum::<u128>();
        let work = per_frame * t.frames as u128;
        if work > MAX_PAIR_FRAMES {
            errors.push(SceneError::TooMuchWork {
                what: "pair-frame evaluations",
                count: work,
                limit: MAX_PAIR_FRAMES,
            });
        }
    }
    if pair_count <= MAX_PAIRS {
        // Bounded: a query with `first_contact` is never streamed, so its pairs are counted.
        check_conflicts(&queries, &spec.bodies, &mut errors);
    }

    match (errors.is_empty(), time) {
        (true, Some(time)) => Ok(Scene {
            name: spec.name.clone().unwrap_or_else(|| default_name(origin)),
            time,
            kernel: spec.kernel,
            coherence: spec.coherence.unwrap_or(true),
            bodies: bodies.into_iter().flatten().collect(),
            queries,
        }),
        _ => Err(SceneErrors(errors)),
    }
}

fn default_name(origin: &Origin) -> String {
    Path::new(&origin.name)
        .file_stem()
        .and_then(|s| s.to_str())
        .filter(|s| !s.is_empty() && !s.starts_with('<'))
        .unwrap_or("scene")
        .to_owned()
}

fn lookup(
    ids: &HashMap<&str, usize>,
    id: &str,
    query: &str,
    errors: &mut Vec<SceneError>,
) -> Option<usize> {
    let found = ids.get(id).copied();
    if found.is_none() {
        errors.push(SceneError::UnknownBody {
            query: query.to_owned(),
            id: id.to_owned(),
        });
    }
    found
}

/// Two queries asking `first_contact` for the same pair with different parameters.
fn check_conflicts(queries: &[Query], bodies: &[BodySpec], errors: &mut Vec<SceneError>) {
    let mut seen: HashMap<(usize, usize), usize> = HashMap::new();
    for (k, q) in queries.iter().enumerate() {
        if !q.effects.contains(Effect::FirstContact) {
            continue;
        }
        for (a, b) in q.pairs.iter(bodies.len()) {
            let key = (a.min(b), a.max(b));
            match seen.get(&key) {
                Some(&j) if j != k && queries[j].contact != q.contact => {
                    errors.push(SceneError::ConflictingParameters {
                        query: q.name.clone(),
                        other: queries[j].name.clone(),
                        a: bodies[a].id.clone(),
                        b: bodies[b].id.clone(),
                    });
                }
                Some(_) => {}
                None => {
                    seen.insert(key, k);
                }
            }
        }
    }
}

fn validate_time(spec: &SceneSpec, errors: &mut Vec<SceneError>) -> Option<TimeSpan> {
    let Some(t) = spec.time else {
        return Some(TimeSpan {
            start: 0.0,
            end: 0.0,
            step: 1.0,
            frames: 1,
        });
    };
    let bad = |reason: String| SceneError::BadTime { reason };
    if !(t.start.is_finite() && t.end.is_finite() && t.step.is_finite()) {
        errors.push(bad(format!(
            "start, end and step must be finite (got {}, {}, {})",
            t.start, t.end, t.step
        )));
        return None;
    }
    if t.end < t.start {
        errors.push(bad(format!(
            "end ({}) is before start ({})",
            t.end, t.start
        )));
        return None;
    }
    if t.step <= 0.0 {
        errors.push(bad(format!("step must be > 0 (got {})", t.step)));
        return None;
    }
    let q = ((t.end - t.start) / t.step + FRAME_SLACK).floor();
    if !q.is_finite() || q >= MAX_FRAMES as f64 {
        errors.push(SceneError::TooManyFrames {
            frames: q + 1.0,
            limit: MAX_FRAMES,
        });
        return None;
    }
    Some(TimeSpan {
        start: t.start,
        end: t.end,
        step: t.step,
        // `q < MAX_FRAMES`, a small non-negative integer: the cast is exact.
        frames: q as usize + 1,
    })
}

fn finite(body: &str, field: &str, x: f64, errors: &mut Vec<SceneError>) -> bool {
    if x.is_finite() {
        true
    } else {
        errors.push(SceneError::NonFinite {
            body: body.to_owned(),
            field: field.to_owned(),
        });
        false
    }
}

fn validate_body(b: &BodySpec, origin: &Origin, errors: &mut Vec<SceneError>) -> Option<Body> {
    let before = errors.len();
    let vertices = body_vertices(b, origin, errors);
    let shape = vertices.and_then(|v| {
        let r = match b.kind {
            KindSpec::Convex => ConvexPolygon::try_new(&v)
                .map(Shape::Convex)
                .map_err(|e| ("convex", e)),
            KindSpec::Simple => SimplePolygon::try_new(&v)
                .map(Shape::Simple)
                .map_err(|e| ("simple", e)),
            KindSpec::Auto => ConvexPolygon::try_new(&v).map(Shape::Convex).or_else(|_| {
                SimplePolygon::try_new(&v)
                    .map(Shape::Simple)
                    .map_err(|e| ("simple", e))
            }),
        };
        r.map_err(|(kind, source)| {
            errors.push(SceneError::InvalidPolygon {
                body: b.id.clone(),
                kind,
                source,
            });
        })
        .ok()
    });
    let motion = validate_motion(b, errors);
    if errors.len() != before {
        return None;
    }
    let (shape, motion) = (shape?, motion?);
    let radius = radius(shape.vertices());
    Some(Body {
        id: b.id.clone(),
        shape,
        motion,
        radius,
    })
}

fn body_vertices(
    b: &BodySpec,
    origin: &Origin,
    errors: &mut Vec<SceneError>,
) -> Option<Vec<DVec2>> {
    let found = usize::from(b.vertices.is_some())
        + usize::from(b.file.is_some())
        + usize::from(b.generator.is_some());
    if found != 1 {
        errors.push(SceneError::ShapeSource {
            body: b.id.clone(),
            found,
        });
        return None;
    }
    let too_many = |count: u64| SceneError::TooManyVertices {
        body: b.id.clone(),
        count,
        limit: MAX_VERTICES,
    };
    if let Some(v) = &b.vertices {
        if v.len() as u64 > MAX_VERTICES {
            errors.push(too_many(v.len() as u64));
            return None;
        }
        return Some(v.iter().map(|&p| DVec2::from(p)).collect());
    }
    if let Some(g) = &b.generator {
        return match generate(g) {
            Ok(v) => Some(v),
            Err(GenError::TooMany(n)) => {
                errors.push(too_many(n));
                None
            }
            Err(GenError::Bad(reason)) => {
                errors.push(SceneError::BadGenerator {
                    body: b.id.clone(),
                    generator: generator_name(g),
                    reason,
                });
                None
            }
        };
    }
    let file = b.file.as_deref().unwrap_or_default();
    let bad = |path: &str, reason: String| SceneError::BadPolygonFile {
        body: b.id.clone(),
        path: path.to_owned(),
        reason,
    };
    let Some(dir) = &origin.dir else {
        errors.push(bad(
            file,
            format!(
                "{} has no directory to resolve polygon files against",
                origin.name
            ),
        ));
        return None;
    };
    let path = dir.join(file);
    let shown = path.display().to_string();
    match std::fs::metadata(&path) {
        Ok(m) if m.len() > MAX_FILE_BYTES => {
            errors.push(bad(
                &shown,
                format!("{} bytes; the limit is {MAX_FILE_BYTES}", m.len()),
            ));
            return None;
        }
        Err(e) => {
            errors.push(bad(&shown, e.to_string()));
            return None;
        }
        Ok(_) => {}
    }
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => {
            errors.push(bad(&shown, e.to_string()));
            return None;
        }
    };
    match parse_polygon_file(&text, file.to_ascii_lowercase().ends_with(".json")) {
        Ok(v) if v.len() as u64 > MAX_VERTICES => {
            errors.push(too_many(v.len() as u64));
            None
        }
        Ok(v) => Some(v),
        Err(reason) => {
            errors.push(bad(&shown, reason));
            None
        }
    }
}

/// Parses a polygon file: JSON `[[x, y], ...]`, or text with one vertex `x y` (or `x, y`) per line,
/// `#` starting a comment, blank lines ignored.
///
/// # Errors
/// A message naming the line and what was expected.
///
/// # Complexity
/// Linear in the text.
pub fn parse_polygon_file(text: &str, json: bool) -> Result<Vec<DVec2>, String> {
    if json {
        let v: Vec<[f64; 2]> = serde_json::from_str(text).map_err(|e| e.to_string())?;
        return Ok(v.into_iter().map(DVec2::from).collect());
    }
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let content = line.split('#').next().unwrap_or("").trim();
        if content.is_empty() {
            continue;
        }
        let fields: Vec<&str> = content
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|s| !s.is_empty())
            .collect();
        let parse = |s: &str| s.parse::<f64>().ok();
        match fields.as_slice() {
            [x, y] => match (parse(x), parse(y)) {
                (Some(x), Some(y)) => out.push(DVec2::new(x, y)),
                _ => {
                    return Err(format!(
                        "line {}: expected two numbers `x y`, found `{content}`",
                        i + 1
                    ));
                }
            },
            _ => {
                return Err(format!(
                    "line {}: expected two numbers `x y`, found {} field(s) in `{content}`",
                    i + 1,
                    fields.len()
                ));
            }
        }
        if out.len() as u64 > MAX_VERTICES {
            return Err(format!("more than {MAX_VERTICES} vertices"));
        }
    }
    Ok(out)
}

fn validate_motion(b: &BodySpec, errors: &mut Vec<SceneError>) -> Option<Motion> {
    let id = &b.id;
    let pose_spec = b.pose.unwrap_or_default();
    let mut ok = finite(id, "pose.x", pose_spec.x, errors)
        & finite(id, "pose.y", pose_spec.y, errors)
        & finite(id, "pose.angle", pose_spec.angle, errors);
    let start = Pose {
        translation: DVec2::new(pose_spec.x, pose_spec.y),
        rotation: pose_spec.angle,
    };
    let motion = match b.motion.clone().unwrap_or(MotionSpec::Static) {
        MotionSpec::Static => Motion::Static(start),
        MotionSpec::Linear { velocity, angular } => {
            ok &= finite(id, "motion.velocity[0]", velocity[0], errors)
                & finite(id, "motion.velocity[1]", velocity[1], errors)
                & finite(id, "motion.angular", angular, errors);
            Motion::Linear {
                start,
                velocity: DVec2::from(velocity),
                angular,
            }
        }
        MotionSpec::Keyframes { keys } => {
            if b.pose.is_some() {
                errors.push(SceneError::PoseWithKeyframes { body: id.clone() });
                ok = false;
            }
            if keys.is_empty() {
                errors.push(SceneError::BadKeyframes {
                    body: id.clone(),
                    index: 0,
                    reason: "there must be at least one key",
                });
                ok = false;
            }
            let mut out = Vec::with_capacity(keys.len());
            for (i, k) in keys.iter().enumerate() {
                let f = |name: &str| format!("motion.keys[{i}].{name}");
                let fin = finite(id, &f("t"), k.t, errors)
                    & finite(id, &f("x"), k.x, errors)
                    & finite(id, &f("y"), k.y, errors)
                    & finite(id, &f("angle"), k.angle, errors);
                ok &= fin;
                if fin && i > 0 && keys[i - 1].t.is_finite() && k.t <= keys[i - 1].t {
                    errors.push(SceneError::BadKeyframes {
                        body: id.clone(),
                        index: i,
                        reason: "times must increase strictly",
                    });
                    ok = false;
                }
                out.push(Keyframe {
                    t: k.t,
                    pose: Pose {
                        translation: DVec2::new(k.x, k.y),
                        rotation: k.angle,
                    },
                });
            }
            Motion::Keyframes(out)
        }
    };
    ok.then_some(motion)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_col_counts_characters() {
        let t = "ab\nçd = x\n";
        assert_eq!(line_col(t, 0), (1, 1));
        assert_eq!(line_col(t, 3), (2, 1));
        // 'ç' is two bytes: byte 8 is the 5th character... of "çd = x" → column 6 is 'x'.
        assert_eq!(line_col(t, t.find('x').unwrap()), (2, 6));
        assert_eq!(line_col(t, 1000), (3, 1));
    }

    #[test]
    fn polygon_file_text_and_json() {
        let v = parse_polygon_file("# a square\n0 0\n1, 0\n\n1 1  # corner\n0 1\n", false).unwrap();
        assert_eq!(v.len(), 4);
        assert_eq!(v[1], DVec2::new(1.0, 0.0));
        let e = parse_polygon_file("0 0\n1 x\n", false).unwrap_err();
        assert!(e.contains("line 2"), "{e}");
        let e = parse_polygon_file("0 0 0\n", false).unwrap_err();
        assert!(e.contains("3 field"), "{e}");
        let v = parse_polygon_file("[[0, 0], [2, 0], [0, 2]]", true).unwrap();
        assert_eq!(v.len(), 3);
        assert!(parse_polygon_file("[[0, 0], [2]]", true).is_err());
    }

    #[test]
    fn frames_include_the_end_despite_rounding() {
        let spec = |end: f64, step: f64| SceneSpec {
            time: Some(crate::spec::TimeSpec {
                start: 0.0,
                end,
                step,
            }),
            ..SceneSpec::default()
        };
        let mut e = Vec::new();
        let t = validate_time(&spec(0.3, 0.1), &mut e).unwrap();
        assert_eq!(t.frames, 4);
        assert_eq!(t.frame(3), 0.3);
        let t = validate_time(&spec(1.0, 0.3), &mut e).unwrap();
        assert_eq!(t.frames, 4);
        assert!((t.frame(3) - 0.9).abs() < 1e-15);
        let t = validate_time(&spec(0.0, 0.3), &mut e).unwrap();
        assert_eq!(t.frames, 1);
        assert!(e.is_empty());
        assert!(validate_time(&spec(1e15, 1.0), &mut e).is_none());
        assert!(matches!(e[0], SceneError::TooManyFrames { .. }));
    }
}
