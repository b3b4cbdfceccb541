//! What a run reports: per pair, per frame and per effect, with the cost of each effect. The field
//! names are the stable JSON schema of docs/scene-format.md.

use core::fmt::Write as _;

use polydist_polygon::Feature;
use serde::Serialize;

/// The version of the JSON report schema (`"version"` in the report).
pub const REPORT_VERSION: u32 = 1;

/// The whole report of a run.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Report {
    /// [`REPORT_VERSION`].
    pub version: u32,
    /// The scene's name.
    pub scene: String,
    /// `fast`, `robust` or `exact`.
    pub kernel: &'static str,
    /// Whether temporal coherence was on.
    pub coherence: bool,
    /// The time span.
    pub time: TimeReport,
    /// One entry per distinct pair, in the order the queries name them; a pair of `within` queries
    /// that is beyond the threshold at every frame (and asked nothing else) is left out and counted
    /// in `pairs_beyond`.
    pub pairs: Vec<PairReport>,
    /// The pairs left out of `pairs` for being beyond their `within` at every frame.
    pub pairs_beyond: u64,
    /// What each effect computed and what it cost.
    pub costs: Costs,
    /// `true` when some pair failed (an invalid body at some time, or an undecided `first_contact`),
    /// or the run stopped a streamed query at a limit (`errors`).
    pub failed: bool,
    /// Problems of the run as a whole (not of one pair): a streamed query (all pairs with `within`)
    /// stopped at a run-time limit ([`MAX_FRAME_CANDIDATES`](crate::MAX_FRAME_CANDIDATES),
    /// [`MAX_PAIR_FRAMES`](crate::MAX_PAIR_FRAMES)), naming the frame. Omitted from JSON when empty.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub errors: Vec<String>,
}

/// The time span of the run.
#[derive(Clone, Copy, Debug, Serialize, PartialEq)]
pub struct TimeReport {
    /// The first frame's time.
    pub start: f64,
    /// The end of the span.
    pub end: f64,
    /// The frame step.
    pub step: f64,
    /// The number of frames.
    pub frames: usize,
}

/// The results of one pair.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct PairReport {
    /// The first body's id.
    pub a: String,
    /// The second body's id.
    pub b: String,
    /// The kinds of `a` and `b` (`convex` or `simple`).
    pub kinds: [&'static str; 2],
    /// The queries that asked for this pair.
    pub queries: Vec<String>,
    /// The effects computed for this pair.
    pub effects: Vec<&'static str>,
    /// Whether either body moves. Per-frame effects of a pair that does not move are evaluated
    /// once, at the first frame (`frames` has one entry).
    pub moving: bool,
    /// Per-frame results (`distance`, `closest_points`, `vertex_distance`); empty when none asked.
    /// With `within`, only the frames at which the pair is within the threshold (the others are
    /// counted in the costs' `within_beyond`).
    pub frames: Vec<FrameResult>,
    /// The `first_contact` result, when asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub first_contact: Option<ContactResult>,
    /// Whether something failed for this pair (see [`Report::failed`]).
    pub failed: bool,
}

/// How the pair relates at one frame.
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// The bodies do not meet.
    Disjoint,
    /// The boundaries meet, the interiors do not.
    Touching,
    /// The interiors meet.
    Overlapping,
    /// A body is not a valid polygon at this frame (see `error`).
    Invalid,
    /// The pair is farther apart than its query's `within` (decided exactly, by the broad phase's
    /// certified box gap or by the narrow phase); no other field is computed.
    Beyond,
    /// The closed bodies meet (from `separation`, which does not tell touching from overlapping for
    /// simple polygons).
    Intersecting,
    /// The pair could not be answered (see `error`): `separation` failed, which happens only under
    /// the `Fast` kernel's inconsistent decisions (every configuration of two disjoint simple bodies
    /// is built, including one in a pocket of the other).
    Unsupported,
}

/// A feature in the body's own (caller's) vertex indices.
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq)]
pub struct FeatureRef {
    /// `vertex` or `edge` (edge `i` joins vertices `i` and `i + 1`).
    pub kind: &'static str,
    /// The index.
    pub index: usize,
}

impl From<Feature> for FeatureRef {
    fn from(f: Feature) -> Self {
        match f {
            Feature::Vertex(index) => FeatureRef {
                kind: "vertex",
                index,
            },
            Feature::Edge(index) => FeatureRef {
                kind: "edge",
                index,
            },
        }
    }
}

/// The `closest_points` effect at one frame.
#[derive(Clone, Copy, Debug, Serialize, PartialEq)]
pub struct ClosestPoints {
    /// The realizing point on `a` (world frame). For touching bodies, the contact point.
    pub point_a: [f64; 2],
    /// The realizing point on `b`.
    pub point_b: [f64; 2],
    /// The feature of `a` containing `point_a`.
    pub feature_a: FeatureRef,
    /// The feature of `b` containing `point_b`.
    pub feature_b: FeatureRef,
    /// `true` when the bodies face each other along parallel edges (the realizing pair is then not unique).
    pub parallel: bool,
}

/// The separation of two bodies at a frame (their boundaries' distance, Amato 1992), with a realizing
/// pair.
#[derive(Clone, Copy, Debug, Serialize, PartialEq)]
pub struct SeparationResult {
    /// The distance between the boundaries (within 3.5 ulps of the exact value for the posed bodies).
    pub distance: f64,
    /// Its square.
    pub squared_distance: f64,
    /// The realizing point on `a` (world frame).
    pub point_a: [f64; 2],
    /// The realizing point on `b`.
    pub point_b: [f64; 2],
    /// The feature of `a` containing `point_a`.
    pub feature_a: FeatureRef,
    /// The feature of `b` containing `point_b`.
    pub feature_b: FeatureRef,
    /// How it was found: `hull_features` (the hulls' closest features lie on both boundaries),
    /// `monotone_sweep` (both facing chains monotone along a line through a hull edge: the exact
    /// windowed sweep), `envelope_sweep` (the same sweep on section 3's envelopes across that
    /// line), `separable_chains` (section 3's matrices across it) or `separators` (the hulls meet:
    /// Amato's separator).
    pub route: &'static str,
}

/// One directed Hausdorff distance `h(from, to)` of the filled bodies: the realizing vertex of `from`
/// (an exact argmax) and its nearest point on `to`.
#[derive(Clone, Copy, Debug, Serialize, PartialEq)]
pub struct DirectedHausdorff {
    /// The directed distance.
    pub distance: f64,
    /// Its square.
    pub squared_distance: f64,
    /// The realizing vertex of `from` (caller index).
    pub vertex: usize,
    /// The vertex (world frame).
    pub point: [f64; 2],
    /// Its nearest point on filled `to` (world frame; the vertex itself when inside).
    pub projection: [f64; 2],
    /// The feature of `to` holding `projection`; absent when the vertex is strictly inside `to`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub feature: Option<FeatureRef>,
}

/// The `hausdorff` effect at one frame (Atallah–Ribeiro–Lifschitz, linear time).
#[derive(Clone, Copy, Debug, Serialize, PartialEq)]
pub struct HausdorffResult {
    /// `max(h(a, b), h(b, a))`.
    pub distance: f64,
    /// Its square.
    pub squared_distance: f64,
    /// `"a_to_b"` or `"b_to_a"`: which directed distance is the larger (`a_to_b` on exact ties).
    pub direction: &'static str,
    /// `h(a, b)`.
    pub a_to_b: DirectedHausdorff,
    /// `h(b, a)`.
    pub b_to_a: DirectedHausdorff,
}

/// The `vertex_distance` effect at one frame.
#[derive(Clone, Copy, Debug, Serialize, PartialEq)]
pub struct VertexDistanceResult {
    /// The distance between the nearest vertices.
    pub distance: f64,
    /// Its square.
    pub squared_distance: f64,
    /// The vertex of `a` (caller index).
    pub vertex_a: usize,
    /// The vertex of `b` (caller index).
    pub vertex_b: usize,
}

/// The per-frame results of a pair.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct FrameResult {
    /// The frame's time.
    pub t: f64,
    /// How the bodies relate (absent when only `vertex_distance` was asked, which needs no contact status).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub status: Option<Status>,
    /// The distance (`0` when touching or overlapping), when `distance` was asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub distance: Option<f64>,
    /// The squared distance, when `distance` was asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub squared_distance: Option<f64>,
    /// When `closest_points` was asked and the bodies do not overlap.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub closest_points: Option<ClosestPoints>,
    /// When `vertex_distance` was asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vertex_distance: Option<VertexDistanceResult>,
    /// When `hausdorff` was asked (boxed: it is the largest result and rarely asked, so a frame
    /// without it stays small; a report holds one frame per pair and frame).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hausdorff: Option<Box<HausdorffResult>>,
    /// When `cmmr` was asked: the sum over the vertices of each body of the squared distance to the
    /// other filled body (compensated sum of exactly chosen terms).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cmmr: Option<f64>,
    /// When `separation` was asked and the bodies are disjoint.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub separation: Option<SeparationResult>,
    /// Why the frame could not be evaluated (`status` is `invalid` or `unsupported`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// The outcome of `first_contact`.
#[derive(Clone, Copy, Debug, Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ContactOutcome {
    /// The bodies first meet in `(t_safe, t_hit]`: apart (certified) on `[start, t_safe]`, meeting at
    /// `t_hit` (the exact intersection test).
    Contact,
    /// The bodies meet at the first time of the span.
    ContactAtStart,
    /// The bodies stay apart over the whole span, with `clearance_lower_bound` a certified lower
    /// bound on their distance at every time of the span.
    Apart,
    /// `max_steps` ran out (or the step underflowed) before a decision: apart on `[start, t_safe]`.
    Undecided,
    /// A body is not a valid polygon at some time (see `message`).
    Invalid,
}

/// The `first_contact` result of a pair.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct ContactResult {
    /// The outcome.
    pub outcome: ContactOutcome,
    /// The bodies are certified apart on `[start, t_safe]`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t_safe: Option<f64>,
    /// A time at which the exact intersection test says the bodies meet.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub t_hit: Option<f64>,
    /// For `apart`: a certified lower bound on the distance over the whole span.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub clearance_lower_bound: Option<f64>,
    /// Conservative-advancement steps taken (distance queries).
    pub steps: u64,
    /// Intersection tests probing `t_safe + tolerance`.
    pub probes: u64,
    /// The bracket width asked for.
    pub tolerance: f64,
    /// The step limit.
    pub max_steps: u64,
    /// For `invalid` and `undecided`: why.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub message: Option<String>,
}

/// The cost of one stage of the run.
#[derive(Clone, Copy, Debug, Default, Serialize, PartialEq, Eq)]
pub struct Cost {
    /// Calls (queries, poses, steps: see [`Costs`]).
    pub calls: u64,
    /// Exact predicates evaluated by these calls (counted by `Counted`; `null` when counting is off).
    pub predicates: Option<u64>,
    /// Wall time in microseconds (on this machine, this run; not a benchmark).
    pub micros: u64,
}

/// What the run computed, per stage.
#[derive(Clone, Copy, Debug, Default, Serialize, PartialEq, Eq)]
pub struct Costs {
    /// Rigid poses applied and re-validated (`ConvexPolygon::try_new` on the moved vertices). Their
    /// validation uses the Robust kernel directly, outside the counted kernel.
    pub pose: Cost,
    /// Convex distance queries: one per pair and frame serves both `distance` and `closest_points`.
    pub distance: Cost,
    /// Of `distance.calls`, the queries started from the previous frame's hint.
    pub distance_hinted: u64,
    /// Minimum vertex distance queries (McKenna–Toussaint).
    pub vertex_distance: Cost,
    /// Hausdorff distance queries (Atallah–Ribeiro–Lifschitz).
    pub hausdorff: Cost,
    /// CMMR distance queries (Atallah–Ribeiro–Lifschitz).
    pub cmmr: Cost,
    /// Separation queries of simple bodies (Amato), including re-validating the posed bodies as
    /// simple polygons.
    pub separation: Cost,
    /// `first_contact`: `calls` are pairs; their distance queries and probes are counted here (not in
    /// `distance`).
    pub first_contact: Cost,
    /// `first_contact`: advancement steps over all pairs.
    pub first_contact_steps: u64,
    /// `first_contact`: exact intersection tests (probes and confirmations).
    pub first_contact_intersection_tests: u64,
    /// The broad phase (bounding boxes and sweep-and-prune) of queries with `within`: `calls` are
    /// frames swept.
    pub broad_phase: Cost,
    /// Box pairs the sweep examined with the full box test.
    pub broad_phase_examined: u64,
    /// Pair-frames answered `beyond` by the broad phase, without a narrow-phase query.
    pub broad_phase_skipped: u64,
    /// Pair-frames beyond their query's `within` (by the broad or the narrow phase); these frames are
    /// not in the report.
    pub within_beyond: u64,
    /// Pair jobs the plan materialized (one per distinct listed pair, or per pair of an all-pairs
    /// query that is not streamed). A streamed query (all pairs, `within`, no `first_contact`)
    /// adds none.
    pub pair_jobs: u64,
    /// Candidate pair-frames of streamed queries: pairs the broad phase could not certify beyond
    /// `within` (every in-scope pair without the broad phase), each one narrow-phase evaluation.
    pub streamed_candidates: u64,
    /// The most candidate pairs of streamed queries held at once (in one frame): with the bodies
    /// and the reported results, what a streamed query's memory grows with.
    pub max_frame_candidates: u64,
}

impl Cost {
    /// The sum of two costs (predicates: `null` only when both are).
    #[must_use]
    pub fn merge(self, other: Cost) -> Cost {
        Cost {
            calls: self.calls + other.calls,
            predicates: match (self.predicates, other.predicates) {
                (None, None) => None,
                (a, b) => Some(a.unwrap_or(0) + b.unwrap_or(0)),
            },
            micros: self.micros.saturating_add(other.micros),
        }
    }
}

impl Costs {
    /// The sum of two sets of costs (how the per-thread costs of a parallel run are aggregated).
    #[must_use]
    pub fn merge(self, o: Costs) -> Costs {
        Costs {
            pose: self.pose.merge(o.pose),
            distance: self.distance.merge(o.distance),
            distance_hinted: self.distance_hinted + o.distance_hinted,
            vertex_distance: self.vertex_distance.merge(o.vertex_distance),
            hausdorff: self.hausdorff.merge(o.hausdorff),
            cmmr: self.cmmr.merge(o.cmmr),
            separation: self.separation.merge(o.separation),
            first_contact: self.first_contact.merge(o.first_contact),
            first_contact_steps: self.first_contact_steps + o.first_contact_steps,
            first_contact_intersection_tests: self.first_contact_intersection_tests
                + o.first_contact_intersection_tests,
            broad_phase: self.broad_phase.merge(o.broad_phase),
            broad_phase_examined: self.broad_phase_examined + o.broad_phase_examined,
            broad_phase_skipped: self.broad_phase_skipped + o.broad_phase_skipped,
            within_beyond: self.within_beyond + o.within_beyond,
            pair_jobs: self.pair_jobs + o.pair_jobs,
            streamed_candidates: self.streamed_candidates + o.streamed_candidates,
            max_frame_candidates: self.max_frame_candidates.max(o.max_frame_candidates),
        }
    }

    /// The same costs with every wall time set to zero (to compare the counts of two runs).
    #[must_use]
    pub fn without_times(mut self) -> Costs {
        for c in [
            &mut self.pose,
            &mut self.distance,
            &mut self.vertex_distance,
            &mut self.hausdorff,
            &mut self.cmmr,
            &mut self.separation,
            &mut self.first_contact,
            &mut self.broad_phase,
        ] {
            c.micros = 0;
        }
        self
    }
}

impl FrameResult {
    /// A frame with only its time and status.
    #[must_use]
    pub fn empty(t: f64, status: Status) -> FrameResult {
        FrameResult {
            t,
            status: Some(status),
            distance: None,
            squared_distance: None,
            closest_points: None,
            vertex_distance: None,
            hausdorff: None,
            cmmr: None,
            separation: None,
            error: None,
        }
    }
}

fn fmt_num(x: f64) -> String {
    if x == 0.0 || (1e-4..1e7).contains(&x.abs()) {
        let s = format!("{x:.6}");
        let s = s.trim_end_matches('0').trim_end_matches('.');
        s.to_owned()
    } else {
        format!("{x:.6e}")
    }
}

fn fmt_point(p: [f64; 2]) -> String {
    format!("({}, {})", fmt_num(p[0]), fmt_num(p[1]))
}

fn fmt_feature(f: FeatureRef) -> String {
    format!("{} {}", f.kind, f.index)
}

impl Report {
    /// The readable table printed by `polydist run`: one line per pair and effect (per-frame effects
    /// summarised by their minimum over the frames), then the costs.
    #[must_use]
    pub fn to_table(&self) -> String {
        let mut s = String::new();
        let t = &self.time;
        let _ = writeln!(
            s,
            "scene {}: kernel {}, t = {} .. {} step {} ({} frame{}), temporal coherence {}",
            self.scene,
            self.kernel,
            fmt_num(t.start),
            fmt_num(t.end),
            fmt_num(t.step),
            t.frames,
            if t.frames == 1 { "" } else { "s" },
            if self.coherence { "on" } else { "off" }
        );
        let mut rows: Vec<[String; 3]> = Vec::new();
        for p in &self.pairs {
            let pair = format!("{} – {}", p.a, p.b);
            for line in pair_lines(p) {
                rows.push([pair.clone(), line.0, line.1]);
            }
        }
        let w0 = rows
            .iter()
            .map(|r| r[0].chars().count())
            .max()
            .unwrap_or(4)
            .max(4);
        let w1 = rows
            .iter()
            .map(|r| r[1].chars().count())
            .max()
            .unwrap_or(6)
            .max(6);
        let _ = writeln!(s, "\n{:<w0$}  {:<w1$}  result", "pair", "effect");
        for r in &rows {
            let _ = writeln!(s, "{:<w0$}  {:<w1$}  {}", r[0], r[1], r[2]);
        }
        let c = &self.costs;
        let _ = writeln!(
            s,
            "\n{:<16} {:>10} {:>12} {:>10}",
            "cost", "calls", "predicates", "µs"
        );
        let mut cost = |name: &str, k: &Cost| {
            let pred = k.predicates.map_or("-".to_owned(), |p| p.to_string());
            let _ = writeln!(
                s,
                "{name:<16} {:>10} {:>12} {:>10}",
                k.calls, pred, k.micros
            );
        };
        cost("pose", &c.pose);
        cost("distance", &c.distance);
        cost("vertex_distance", &c.vertex_distance);
        cost("hausdorff", &c.hausdorff);
        cost("cmmr", &c.cmmr);
        cost("separation", &c.separation);
        cost("first_contact", &c.first_contact);
        cost("broad_phase", &c.broad_phase);
        let _ = writeln!(
            s,
            "({} distance queries started from a hint; first_contact: {} steps, {} intersection tests)",
            c.distance_hinted, c.first_contact_steps, c.first_contact_intersection_tests
        );
        if c.broad_phase.calls > 0 {
            let _ = writeln!(
                s,
                "(broad phase: {} box pairs examined, {} pair-frames answered beyond `within` from boxes)",
                c.broad_phase_examined, c.broad_phase_skipped
            );
        }
        if c.within_beyond > 0 || self.pairs_beyond > 0 {
            let _ = writeln!(
                s,
                "({} pair-frames beyond `within` not listed; {} pairs beyond at every frame left out)",
                c.within_beyond, self.pairs_beyond
            );
        }
        if c.streamed_candidates > 0 {
            let _ = writeln!(
                s,
                "(all pairs within: {} candidate pair-frames evaluated, at most {} in one frame; {} pair jobs planned)",
                c.streamed_candidates, c.max_frame_candidates, c.pair_jobs
            );
        }
        for e in &self.errors {
            let _ = writeln!(s, "\nerror: {e}");
        }
        if self.failed {
            let _ = writeln!(s, "\nSOME PAIRS FAILED (see above)");
        }
        s
    }
}

/// The table lines of one pair: (effect, result).
fn pair_lines(p: &PairReport) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let frames = &p.frames;
    let when = |f: &FrameResult| {
        if p.moving {
            format!(" at t = {}", fmt_num(f.t))
        } else {
            " (static pair, evaluated once)".to_owned()
        }
    };
    let invalid: Vec<&FrameResult> = frames.iter().filter(|f| f.error.is_some()).collect();
    if let Some(f) = invalid.first() {
        out.push((
            "error".to_owned(),
            format!(
                "{} invalid frame(s); first at t = {}: {}",
                invalid.len(),
                fmt_num(f.t),
                f.error.as_deref().unwrap_or_default()
            ),
        ));
    }
    let by_distance = frames
        .iter()
        .filter(|f| f.distance.is_some())
        .min_by(|x, y| {
            x.distance
                .unwrap_or(0.0)
                .total_cmp(&y.distance.unwrap_or(0.0))
        });
    if let Some(f) = by_distance {
        let status = f.status.map_or("", |s| match s {
            Status::Disjoint => "",
            Status::Touching => " (touching)",
            Status::Overlapping => " (overlapping)",
            Status::Intersecting => " (intersecting)",
            Status::Invalid | Status::Beyond | Status::Unsupported => "",
        });
        let label = if p.moving { "min " } else { "" };
        out.push((
            "distance".to_owned(),
            format!(
                "{label}{}{status}{}",
                fmt_num(f.distance.unwrap_or(0.0)),
                when(f)
            ),
        ));
    }
    if p.effects.contains(&"closest_points") {
        let chosen = by_distance.or_else(|| frames.iter().find(|f| f.error.is_none()));
        if let Some(f) = chosen {
            let text = match f.closest_points {
                Some(c) => format!(
                    "{} on {} – {} on {}{}",
                    fmt_point(c.point_a),
                    fmt_feature(c.feature_a),
                    fmt_point(c.point_b),
                    fmt_feature(c.feature_b),
                    when(f)
                ),
                None => format!("none: the bodies overlap{}", when(f)),
            };
            out.push(("closest_points".to_owned(), text));
        }
    }
    let by_vertex = frames
        .iter()
        .filter_map(|f| f.vertex_distance.map(|v| (f, v)))
        .min_by(|x, y| x.1.distance.total_cmp(&y.1.distance));
    if let Some((f, v)) = by_vertex {
        out.push((
            "vertex_distance".to_owned(),
            format!(
                "{}{} (vertex {} – vertex {}){}",
                if p.moving { "min " } else { "" },
                fmt_num(v.distance),
                v.vertex_a,
                v.vertex_b,
                when(f)
            ),
        ));
    }
    let by_hausdorff = frames
        .iter()
        .filter_map(|f| f.hausdorff.as_deref().map(|h| (f, h)))
        .max_by(|x, y| x.1.distance.total_cmp(&y.1.distance));
    if let Some((f, h)) = by_hausdorff {
        let d = if h.direction == "a_to_b" {
            h.a_to_b
        } else {
            h.b_to_a
        };
        out.push((
            "hausdorff".to_owned(),
            format!(
                "{}{} ({}: vertex {} at {} – {}){}",
                if p.moving { "max " } else { "" },
                fmt_num(h.distance),
                h.direction,
                d.vertex,
                fmt_point(d.point),
                fmt_point(d.projection),
                when(f)
            ),
        ));
    }
    let by_cmmr = frames
        .iter()
        .filter_map(|f| f.cmmr.map(|c| (f, c)))
        .max_by(|x, y| x.1.total_cmp(&y.1));
    if let Some((f, c)) = by_cmmr {
        out.push((
            "cmmr".to_owned(),
            format!(
                "{}{}{}",
                if p.moving { "max " } else { "" },
                fmt_num(c),
                when(f)
            ),
        ));
    }
    if p.effects.contains(&"separation") {
        let by_separation = frames
            .iter()
            .filter_map(|f| f.separation.map(|r| (f, r)))
            .min_by(|x, y| x.1.distance.total_cmp(&y.1.distance));
        let meeting = frames
            .iter()
            .find(|f| f.status == Some(Status::Intersecting));
        let text = match (meeting, by_separation) {
            (Some(f), _) => Some(format!("0: the bodies meet{}", when(f))),
            (None, Some((f, r))) => Some(format!(
                "{}{} ({} on {} – {} on {}, {}){}",
                if p.moving { "min " } else { "" },
                fmt_num(r.distance),
                fmt_point(r.point_a),
                fmt_feature(r.feature_a),
                fmt_point(r.point_b),
                fmt_feature(r.feature_b),
                r.route,
                when(f)
            )),
            (None, None) => None,
        };
        if let Some(text) = text {
            out.push(("separation".to_owned(), text));
        }
    }
    if let Some(c) = &p.first_contact {
        let text = match c.outcome {
            ContactOutcome::Contact => format!(
                "first contact in ({}, {}]",
                fmt_num(c.t_safe.unwrap_or(f64::NAN)),
                fmt_num(c.t_hit.unwrap_or(f64::NAN))
            ),
            ContactOutcome::ContactAtStart => format!(
                "in contact at the start, t = {}",
                fmt_num(c.t_hit.unwrap_or(f64::NAN))
            ),
            ContactOutcome::Apart => format!(
                "apart over the whole span, clearance ≥ {}",
                fmt_num(c.clearance_lower_bound.unwrap_or(0.0))
            ),
            ContactOutcome::Undecided => format!(
                "UNDECIDED: apart until t = {} ({})",
                fmt_num(c.t_safe.unwrap_or(f64::NAN)),
                c.message.as_deref().unwrap_or_default()
            ),
            ContactOutcome::Invalid => {
                format!("INVALID: {}", c.message.as_deref().unwrap_or_default())
            }
        };
        out.push((
            "first_contact".to_owned(),
            format!("{text} [{} steps]", c.steps),
        ));
    }
    out
}
