//! The planner and the runner: compute exactly the effects the queries ask for.
//!
//! # The plan
//! [`plan`] merges the queries into one [`PairJob`] per unordered pair (the union of the effects of
//! every query naming it), so a pair named twice is computed once. A **streamed** query (all pairs,
//! `within`, no `first_contact`) gets no jobs ([`Plan::streamed`]): each frame evaluates only the
//! broad phase's candidate pairs without a job (static–static pairs at the first frame only), and
//! keeps only the frames within the threshold; its memory is `O(bodies + candidates of a frame +
//! reported results)`, bounded at run time by [`MAX_FRAME_CANDIDATES`] and [`MAX_PAIR_FRAMES`]. A job's per-frame effects
//! (`distance`, `closest_points`, `vertex_distance`) run at every frame if either body moves and
//! once if neither does; `first_contact` runs once per job over the whole span. Bodies are posed only
//! when a job needs them at that time; a static body is posed once.
//!
//! # Shared work
//! `distance` and `closest_points` are one convex distance query per pair and frame. Moving pairs
//! start each frame from the previous frame's closest features ([`distance_with_hint`]), whose answer
//! is identical to the plain query's under the Robust and Exact kernels; the report counts the
//! hinted queries and (with predicate counting on) what they cost.
//!
//! # First contact (Schwartz 1981, §1)
//! Conservative advancement: at time `t` with certified distance `d` (the computed distance minus
//! its error and the posing error, rounded down) and a bound `V` on the relative speed of any
//! boundary point over `[t, end]` ([`relative_speed_bound`]), no contact happens before
//! `t + d / V`, so `t` advances by `d / V` rounded down (or farther when a shorter window has a
//! smaller bound, see `safe_step`). When that step is smaller than the
//! `tolerance`, the exact intersection test probes `t + tolerance`; a hit gives the bracket
//! `[t_safe, t_hit]` with `t_hit = t + tolerance` and `t_safe` the end of the safe step from `t`
//! (certified too). Reaching `end` certifies the pair apart, and the clearance
//! bound comes from both ends of every step: on `[t_i, t_{i+1}]` (length `L`),
//! `D(s) ≥ max(d_i − V·s, d_{i+1} − V·(L − s)) ≥ (d_i + d_{i+1} − V·L) / 2`, a certified lower
//! bound that is not a sampled minimum.
//!
//! # Many bodies and threads
//! Jobs are independent given the posed bodies of a frame: each frame poses its bodies in parallel,
//! runs the broad phase for queries with `within` (crate::broad: sweep-and-prune with a certified box
//! gap; a pair is skipped only when its boxes are certainly farther apart than `within`), then
//! evaluates the jobs in parallel (rayon), each with its own state (hint, frames). `first_contact`
//! pairs run in parallel too. Costs are measured per call on the calling thread and summed, so a
//! report is the same on any number of threads.

use std::borrow::Cow;
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

use rayon::prelude::*;

use glam::DVec2;
use polydist_convex::{
    Direction, Hint, Pose, Separation, VertexToPolygon, Within, cmmr_value_with, distance_with,
    distance_with_hint, distance_within, hausdorff_with, intersects, min_vertex_distance_with,
};
use polydist_polygon::predicates::{Counted, Exact, Fast, Kernel, Robust, predicate_counts};
use polydist_polygon::{ConvexPolygon, Feature, PolygonError, SimplePolygon};
use polydist_separation::{PolygonSeparation, Route, separation};

use crate::broad::{Aabb, sweep_classes};
use crate::load::{
    Body, ContactParams, MAX_FRAME_CANDIDATES, MAX_PAIR_FRAMES, PairSet, Scene, Shape,
};
use crate::motion::{Motion, down, pose_error, relative_speed_bound, up};
use crate::report::{
    ClosestPoints, ContactOutcome, ContactResult, Cost, Costs, DirectedHausdorff, FrameResult,
    HausdorffResult, PairReport, Report, SeparationResult, Status, TimeReport,
    VertexDistanceResult,
};
use crate::spec::{Effect, EffectSet, KernelChoice};

/// One pair with everything asked of it.
#[derive(Clone, Debug, PartialEq)]
pub struct PairJob {
    /// The first body (as first named).
    pub a: usize,
    /// The second body.
    pub b: usize,
    /// The indices of the queries naming the pair, ascending.
    pub queries: Vec<usize>,
    /// The union of their effects.
    pub effects: EffectSet,
    /// `first_contact`'s parameters (of the first query asking for it).
    pub contact: ContactParams,
    /// Whether either body moves.
    pub moving: bool,
    /// The distance threshold of the per-frame effects: the loosest of the queries naming the pair
    /// (`None` when one of them has none).
    pub within: Option<f64>,
    /// Where the pair is first named: the query's index and the pair's position in it (a list's
    /// index; `a·n + b` for all pairs of `n` bodies, `a < b`). The report lists pairs in this order.
    pub first: (usize, u64),
}

impl PairJob {
    /// Whether the job has a per-frame effect.
    #[must_use]
    pub fn per_frame(&self) -> bool {
        self.effects.has_per_frame()
    }

    /// What a frame of the job computes.
    pub(crate) fn ask(&self) -> Ask {
        Ask {
            effects: self.effects,
            within: self.within,
        }
    }
}

/// What one frame of a pair computes: the effects and the threshold.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ask {
    pub(crate) effects: EffectSet,
    pub(crate) within: Option<f64>,
}

impl Ask {
    /// Whether the convex distance query is needed.
    fn needs_distance(self) -> bool {
        self.effects.contains(Effect::Distance) || self.effects.contains(Effect::ClosestPoints)
    }
}

/// The streamed queries of a plan: all pairs with `within`, without `first_contact`
/// ([`Query::is_streamed`](crate::Query::is_streamed)). Their pairs are never materialized: each
/// frame takes its candidates from the broad phase.
#[derive(Clone, Debug, PartialEq)]
pub struct Streamed {
    /// The streamed queries, ascending.
    pub queries: Vec<usize>,
    /// The union of their effects.
    pub effects: EffectSet,
    /// The loosest of their thresholds.
    pub within: f64,
}

/// The plan: the materialized pair jobs, in the order the queries first name their pairs, and the
/// streamed queries.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    /// The jobs: one per distinct pair of the listed queries and of the all-pairs queries that are
    /// not streamed. A pair of a job is also named by the streamed queries (which name every pair):
    /// their effects, thresholds and names are merged into the job.
    pub jobs: Vec<PairJob>,
    /// The streamed queries: every pair without a job, evaluated from the broad phase's candidates.
    /// `None` when there are none, or when an all-pairs query that is not streamed materializes
    /// every pair anyway (then the streamed queries are merged into its jobs).
    pub streamed: Option<Streamed>,
}

/// Builds the plan of a validated scene (see the module docs).
///
/// # Complexity
/// `O(total pairs named)` expected (hashing); a streamed query names none.
#[must_use]
pub fn plan(scene: &Scene) -> Plan {
    let n = scene.bodies.len();
    let order_key = |a: usize, b: usize| a.min(b) as u64 * n as u64 + a.max(b) as u64;
    // An all-pairs query that is not streamed materializes every pair: then nothing is streamed.
    let materialize_all = scene
        .queries
        .iter()
        .any(|q| matches!(q.pairs, PairSet::All) && !q.is_streamed());
    let is_streamed = |q: &crate::load::Query| !materialize_all && q.is_streamed();
    let mut index = PairIndex::new(n, materialize_all);
    let mut jobs: Vec<PairJob> = Vec::new();
    for (k, q) in scene.queries.iter().enumerate() {
        if is_streamed(q) {
            continue;
        }
        let all = matches!(q.pairs, PairSet::All);
        if all {
            jobs.reserve(PairSet::All.count(n).try_into().unwrap_or(0));
        }
        for (pos, (a, b)) in q.pairs.iter(n).enumerate() {
            let j = index.get_or_insert(a, b, || {
                jobs.push(PairJob {
                    a,
                    b,
                    queries: Vec::new(),
                    effects: EffectSet::EMPTY,
                    contact: q.contact,
                    moving: !(scene.bodies[a].motion.is_static()
                        && scene.bodies[b].motion.is_static()),
                    within: q.within,
                    first: (k, if all { order_key(a, b) } else { pos as u64 }),
                });
                jobs.len() - 1
            });
            let job = &mut jobs[j];
            job.within = match (job.within, q.within) {
                (Some(x), Some(y)) => Some(x.max(y)),
                _ => None,
            };
            if job.queries.last() != Some(&k) {
                job.queries.push(k);
            }
            if q.effects.contains(Effect::FirstContact)
                && !job.effects.contains(Effect::FirstContact)
            {
                job.contact = q.contact;
            }
            job.effects = job.effects.union(q.effects);
        }
    }
    let mut streamed: Option<Streamed> = None;
    for (k, q) in scene.queries.iter().enumerate() {
        if let (true, Some(r)) = (is_streamed(q), q.within) {
            let s = streamed.get_or_insert(Streamed {
                queries: Vec::new(),
                effects: EffectSet::EMPTY,
                within: r,
            });
            s.queries.push(k);
            s.effects = s.effects.union(q.effects);
            s.within = s.within.max(r);
        }
    }
    if let Some(s) = &streamed {
        // The streamed queries name every pair, so every job's pair too.
        let k0 = s.queries[0];
        for job in &mut jobs {
            job.queries.extend(&s.queries);
            job.queries.sort_unstable();
            job.queries.dedup();
            job.effects = job.effects.union(s.effects);
            job.within = job.within.map(|w| w.max(s.within));
            if k0 < job.first.0 {
                job.first = (k0, order_key(job.a, job.b));
                (job.a, job.b) = (job.a.min(job.b), job.a.max(job.b));
            }
        }
        jobs.sort_by_key(|j| j.first);
    }
    Plan { jobs, streamed }
}

/// The job of each pair while planning: a dense table (4 bytes per pair, no hashing) when every
/// pair gets a job anyway, else a hash map of the named pairs.
enum PairIndex {
    Dense { n: usize, slots: Vec<u32> },
    Sparse(HashMap<(usize, usize), usize>),
}

impl PairIndex {
    fn new(n: usize, every_pair: bool) -> PairIndex {
        let pairs = PairSet::All.count(n);
        // u32 slots: MAX_PAIRS (10^7) fits; beyond, the validation refused the scene anyway.
        match usize::try_from(pairs) {
            Ok(len) if every_pair && pairs < u128::from(u32::MAX) => PairIndex::Dense {
                n,
                slots: vec![u32::MAX; len],
            },
            _ => PairIndex::Sparse(HashMap::new()),
        }
    }

    /// The job index of the pair `{a, b}`, made by `make` (which returns the new index) when new.
    fn get_or_insert(&mut self, a: usize, b: usize, make: impl FnOnce() -> usize) -> usize {
        let (lo, hi) = (a.min(b), a.max(b));
        match self {
            PairIndex::Dense { n, slots } => {
                // Rank of (lo, hi) in the order (0, 1), (0, 2), …, (1, 2), …
                let rank = lo * *n - lo * (lo + 1) / 2 + (hi - lo - 1);
                match slots.get_mut(rank) {
                    Some(slot) if *slot != u32::MAX => *slot as usize,
                    Some(slot) => {
                        let j = make();
                        *slot = u32::try_from(j).unwrap_or(u32::MAX);
                        j
                    }
                    // Not reached for a pair of distinct bodies below n.
                    None => make(),
                }
            }
            PairIndex::Sparse(map) => *map.entry((lo, hi)).or_insert_with(make),
        }
    }
}

/// How to run a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RunOptions {
    /// Overrides the scene's kernel.
    pub kernel: Option<KernelChoice>,
    /// Overrides the scene's temporal coherence.
    pub coherence: Option<bool>,
    /// Count exact predicates per effect (through `Counted`; a thread-local increment per predicate,
    /// measured around each call on the thread that makes it and summed over the threads).
    pub count_predicates: bool,
    /// Answer pairs of queries with `within` from bounding boxes where that is certain (the results
    /// are identical either way; only the cost changes). Default `true`.
    pub broad_phase: bool,
    /// The number of threads: `None` uses rayon's global pool (all cores, or `RAYON_NUM_THREADS`);
    /// `Some(n)` runs on a pool of `n` threads. The results are identical for every count.
    pub threads: Option<usize>,
    /// The most candidate pairs of streamed queries in one frame: default and ceiling
    /// [`MAX_FRAME_CANDIDATES`] (a larger value is taken as that). A run reaching it stops the
    /// streamed queries with an error in [`Report::errors`].
    pub max_frame_candidates: u64,
}

impl Default for RunOptions {
    fn default() -> Self {
        RunOptions {
            kernel: None,
            coherence: None,
            count_predicates: true,
            broad_phase: true,
            threads: None,
            max_frame_candidates: MAX_FRAME_CANDIDATES,
        }
    }
}

/// Runs a validated scene: builds the [`plan`] and computes exactly what it asks for.
///
/// Never panics on a validated scene; a body that is invalid at some time (a rotation whose
/// rounding breaks convexity) is reported for that frame or `first_contact` step, and the run goes
/// on with the other frames and pairs.
///
/// # Complexity
/// Per moving pair and frame: `O(n + m)` to pose and re-validate both bodies (shared by every pair
/// of the frame), then `O(log n + log m)` for `distance`/`closest_points` (`O(1)` predicates with a
/// good hint) and `O(n + m)` for `vertex_distance`. `first_contact`: `O(n + m)` per step, at most
/// `max_steps` steps.
///
/// # References
/// J. T. Schwartz, "Finding the minimum distance between two convex polygons", Information
/// Processing Letters 13(4–5), 1981, §1 (conservative advancement; the motion bound with the
/// erratum of papers/INDEX.md); C.-L. Yang et al., J. Zhejiang Univ. SCIENCE A, 2006 (the distance
/// query); M. McKenna, G. T. Toussaint, Comp. & Maths. with Appls., 1985 (vertex distance).
///
/// # Examples
/// ```
/// use polydist_scene::{Origin, RunOptions, load_str, run};
///
/// let scene = load_str(r#"
///     time = { end = 4.0, step = 1.0 }
///     [[body]]
///     id = "a"
///     vertices = [[0, 0], [1, 0], [1, 1], [0, 1]]
///     motion = { type = "linear", velocity = [1.0, 0.0] }
///     [[body]]
///     id = "wall"
///     vertices = [[4, -5], [5, -5], [5, 5], [4, 5]]
///     [[query]]
///     pairs = [["a", "wall"]]
///     effects = ["distance", "first_contact"]
/// "#, &Origin::text("example.toml")).unwrap();
/// let report = run(&scene, &RunOptions::default());
/// let pair = &report.pairs[0];
/// assert_eq!(pair.frames[0].distance, Some(3.0));
/// let contact = pair.first_contact.as_ref().unwrap();
/// // The square reaches the wall at t = 3.
/// assert!(contact.t_safe.unwrap() <= 3.0 && 3.0 <= contact.t_hit.unwrap());
/// ```
#[must_use]
pub fn run(scene: &Scene, options: &RunOptions) -> Report {
    run_with_progress(scene, options, &|_, _| {})
}

/// [`run`], calling `progress(done, total)` after each frame and each `first_contact` pair (from
/// any thread; `total` is the number of frames with per-frame work plus the `first_contact` pairs).
/// `polydist run` draws its progress bar with it.
///
/// # Complexity
/// That of [`run`], plus one call of `progress` per frame and per `first_contact` pair.
#[must_use]
pub fn run_with_progress(
    scene: &Scene,
    options: &RunOptions,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Report {
    let go = || {
        let kernel = options.kernel.unwrap_or(scene.kernel);
        match (kernel, options.count_predicates) {
            (KernelChoice::Fast, true) => {
                run_with::<Counted<Fast>>(scene, options, kernel, progress)
            }
            (KernelChoice::Fast, false) => run_with::<Fast>(scene, options, kernel, progress),
            (KernelChoice::Robust, true) => {
                run_with::<Counted<Robust>>(scene, options, kernel, progress)
            }
            (KernelChoice::Robust, false) => run_with::<Robust>(scene, options, kernel, progress),
            (KernelChoice::Exact, true) => {
                run_with::<Counted<Exact>>(scene, options, kernel, progress)
            }
            (KernelChoice::Exact, false) => run_with::<Exact>(scene, options, kernel, progress),
        }
    };
    match options.threads.map(|t| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(t.max(1))
            .build()
    }) {
        Some(Ok(pool)) => pool.install(go),
        // No pool could be made: the global pool gives the same results.
        _ => go(),
    }
}

/// A body placed at a time: the re-validated polygon (its caller index `k` is the body's internal
/// vertex `k`) and the pose. For a simple body, `simple` is the posed polygon and `poly` its convex
/// hull (used for bounding boxes and the exact `within` test: the hulls' distance is a lower bound of
/// the separation); no convex effect takes a simple body (the loader refuses them).
pub(crate) struct Posed {
    pub(crate) poly: ConvexPolygon,
    pub(crate) pose: Pose,
    pub(crate) simple: Option<SimplePolygon>,
}

/// Measures the calls, predicates and time of a stage.
pub(crate) struct Meter {
    pub(crate) count: bool,
}

impl Meter {
    /// Calls and time only: for stages whose predicates do not go through the counted kernel.
    fn measure_uncounted<T>(&self, cost: &mut Cost, f: impl FnOnce() -> T) -> T {
        Meter { count: false }.measure(cost, f)
    }

    fn measure<T>(&self, cost: &mut Cost, f: impl FnOnce() -> T) -> T {
        let before = self.count.then(|| predicate_counts().total());
        let clock = Instant::now();
        let out = f();
        cost.micros += u64::try_from(clock.elapsed().as_micros()).unwrap_or(u64::MAX);
        cost.calls += 1;
        if let Some(b) = before {
            *cost.predicates.get_or_insert(0) += predicate_counts().total().saturating_sub(b);
        }
        out
    }
}

/// Per-job state of the frame loop: the coherence hint and the frames so far.
#[derive(Default)]
struct JobState {
    hint: Option<Hint>,
    frames: Vec<FrameResult>,
}

/// The posed bodies of a frame (`None`: not posed, no job needs it).
type PosedSlots = Vec<Option<Result<Posed, String>>>;

/// One pair's frame: the per-frame effects of `ask` on the posed bodies, or the invalid frame of a
/// body that could not be posed; `None` when a body was not posed.
#[allow(
    clippy::too_many_arguments,
    reason = "the frame's context, passed by reference"
)]
fn pair_frame<K: Kernel>(
    scene: &Scene,
    ask: Ask,
    t: f64,
    (a, b): (usize, usize),
    posed: &PosedSlots,
    hint: Option<&mut Option<Hint>>,
    meter: &Meter,
    costs: &mut Costs,
) -> Option<FrameResult> {
    let (Some(pa), Some(pb)) = (&posed[a], &posed[b]) else {
        return None;
    };
    Some(match (pa, pb) {
        (Ok(pa), Ok(pb)) => {
            let (ba, bb) = (&scene.bodies[a], &scene.bodies[b]);
            eval_frame::<K>(ask, t, (ba, pa), (bb, pb), hint, meter, costs)
        }
        (Err(e), _) | (_, Err(e)) => {
            let mut f = FrameResult::empty(t, Status::Invalid);
            f.error = Some(e.clone());
            f
        }
    })
}

/// Streamed pair-frames kept for the report, and what they cost.
type Kept = (Vec<((usize, usize), FrameResult)>, Costs);

/// Folds evaluated pair-frames into the frames to keep (beyond ones are only counted) and costs.
fn keep_within(
    (mut kept, costs): Kept,
    (pair, frame, local): ((usize, usize), Option<FrameResult>, Costs),
) -> Kept {
    let mut costs = costs.merge(local);
    match frame {
        Some(f) if f.status == Some(Status::Beyond) => costs.within_beyond += 1,
        Some(f) => kept.push((pair, f)),
        None => {}
    }
    (kept, costs)
}

/// Joins two [`Kept`] of a parallel fold.
fn join_kept((mut a, ca): Kept, (b, cb): Kept) -> Kept {
    a.extend(b);
    (a, ca.merge(cb))
}

#[allow(
    clippy::too_many_lines,
    reason = "the frame loop reads best in one piece"
)]
fn run_with<K: Kernel>(
    scene: &Scene,
    options: &RunOptions,
    kernel: KernelChoice,
    progress: &(dyn Fn(u64, u64) + Sync),
) -> Report {
    let coherence = options.coherence.unwrap_or(scene.coherence);
    let meter = Meter {
        count: options.count_predicates,
    };
    let plan = plan(scene);
    let mut costs = Costs {
        pair_jobs: plan.jobs.len() as u64,
        ..Costs::default()
    };
    let time = scene.time;
    let n = scene.bodies.len();
    let is_static: Vec<bool> = scene.bodies.iter().map(|b| b.motion.is_static()).collect();
    let any_moving = is_static.iter().any(|s| !s);
    let streamed = plan.streamed.as_ref();
    let contact_jobs = plan
        .jobs
        .iter()
        .filter(|j| j.effects.contains(Effect::FirstContact))
        .count() as u64;
    let has_frame_jobs = streamed.is_some() || plan.jobs.iter().any(PairJob::per_frame);
    let total = if has_frame_jobs {
        time.frames as u64
    } else {
        0
    } + contact_jobs;
    let done = AtomicU64::new(0);

    // Per-frame effects: frame-major, so each body is posed once per frame for all its pairs.
    let is_frame_job: Vec<bool> = plan.jobs.iter().map(PairJob::per_frame).collect();
    let mut states: Vec<JobState> = (0..plan.jobs.len()).map(|_| JobState::default()).collect();
    // A streamed query needs every body.
    let mut needed = vec![streamed.is_some(); n];
    // Jobs with a threshold answered by the broad phase, and their bodies (the boxes swept).
    let broad_job: Vec<bool> = plan
        .jobs
        .iter()
        .zip(&is_frame_job)
        .map(|(j, &f)| f && options.broad_phase && j.within.is_some())
        .collect();
    let mut in_broad = vec![false; n];
    let mut broad_r = f64::NEG_INFINITY;
    // The jobs by pair: the broad jobs (for the sweep), and every job when streaming (the streamed
    // queries leave the pairs of jobs to them).
    let mut job_of_pair: HashMap<(usize, usize), usize> = HashMap::new();
    for (j, job) in plan.jobs.iter().enumerate() {
        let key = (job.a.min(job.b), job.a.max(job.b));
        if streamed.is_some() || broad_job[j] {
            job_of_pair.insert(key, j);
        }
        if is_frame_job[j] {
            needed[job.a] = true;
            needed[job.b] = true;
        }
        if broad_job[j] {
            in_broad[job.a] = true;
            in_broad[job.b] = true;
            broad_r = broad_r.max(job.within.unwrap_or(f64::INFINITY));
        }
    }
    let broad_jobs = broad_job.iter().any(|&b| b);
    // The pairs of the streamed queries at a frame: every pair without a job at the first frame,
    // then those with a moving body (static pairs are evaluated once).
    let all_pairs = n as u64 * (n as u64).saturating_sub(1) / 2;
    let n_static = is_static.iter().filter(|&&s| s).count() as u64;
    let static_pairs = n_static * n_static.saturating_sub(1) / 2;
    let moving_jobs = plan.jobs.iter().filter(|j| j.moving).count() as u64;
    let streamed_pairs = all_pairs - plan.jobs.len() as u64;
    let in_scope = |k: usize| {
        if k == 0 {
            streamed_pairs
        } else {
            all_pairs - static_pairs - moving_jobs
        }
    };
    let mut streaming = streamed.is_some();
    let mut streamed_total = 0u64;
    let mut streamed_out: HashMap<(usize, usize), Vec<FrameResult>> = HashMap::new();
    let mut errors: Vec<String> = Vec::new();

    let mut near = vec![false; plan.jobs.len()];
    let mut posed: PosedSlots = (0..n).map(|_| None).collect();
    for k in 0..(if has_frame_jobs { time.frames } else { 0 }) {
        let t = time.frame(k);
        // Posing, in parallel over the bodies that need it.
        let pose_cost = posed
            .par_iter_mut()
            .enumerate()
            .filter(|(i, slot)| needed[*i] && (!is_static[*i] || slot.is_none()))
            .map(|(i, slot)| {
                let mut c = Cost::default();
                *slot = Some(meter.measure_uncounted(&mut c, || pose_body(&scene.bodies[i], t)));
                c
            })
            .reduce(Cost::default, Cost::merge);
        costs.pose = costs.pose.merge(pose_cost);

        // The streamed queries at this frame: the pairs in scope, at most `budget` candidates.
        let stream = streamed.filter(|_| streaming && (k == 0 || any_moving));
        let scope = if stream.is_some() { in_scope(k) } else { 0 };
        let budget = options.max_frame_candidates.min(MAX_FRAME_CANDIDATES).min(
            u64::try_from(MAX_PAIR_FRAMES)
                .unwrap_or(u64::MAX)
                .saturating_sub(streamed_total),
        );
        let sweep_stream = stream.filter(|_| options.broad_phase);
        let mut candidates: Vec<(usize, usize)> = Vec::new();
        let mut cut = stream.is_some() && !options.broad_phase && scope > budget;

        // The broad phase: which broad jobs may be near, and the streamed candidates.
        if (broad_jobs || sweep_stream.is_some()) && (k == 0 || any_moving) {
            let mut cost = Cost::default();
            meter.measure_uncounted(&mut cost, || {
                let boxes: Vec<Option<Aabb>> = (0..n)
                    .map(|i| match &posed[i] {
                        Some(Ok(p)) if in_broad[i] || sweep_stream.is_some() => {
                            Aabb::of(p.poly.vertices())
                        }
                        _ => None,
                    })
                    .collect();
                let far = |a: usize, b: usize, r: f64| {
                    matches!((boxes[a], boxes[b]), (Some(x), Some(y)) if x.certainly_farther(&y, r))
                };
                let r = sweep_stream.map_or(broad_r, |s| broad_r.max(s.within));
                near.iter_mut().for_each(|x| *x = false);
                // After the first frame the static boxes form their own class: static–static
                // pairs are never walked again.
                let class = |i: usize| usize::from(k > 0 && is_static[i]);
                let (stats, stopped) = sweep_classes(&boxes, class, [true, k == 0], r, |a, b| {
                    if let Some(&j) = job_of_pair.get(&(a, b)) {
                        if broad_job[j] {
                            near[j] = !far(a, b, plan.jobs[j].within.unwrap_or(f64::INFINITY));
                        }
                        true
                    } else if let Some(s) = sweep_stream.filter(|s| !far(a, b, s.within)) {
                        let _ = s;
                        candidates.push((a, b));
                        candidates.len() as u64 <= budget
                    } else {
                        true
                    }
                });
                if stopped {
                    // The streamed queries stop here; the broad jobs go to the narrow phase this
                    // frame (the same results).
                    cut = true;
                    near.iter_mut().for_each(|x| *x = true);
                }
                costs.broad_phase_examined += stats.examined;
            });
            costs.broad_phase = costs.broad_phase.merge(cost);
        }
        if sweep_stream.is_some() && !cut {
            // Bodies that could not be posed have no box: their pairs get invalid frames.
            for i in (0..n).filter(|&i| matches!(posed[i], Some(Err(_)))) {
                for j in (0..n).filter(|&j| j != i) {
                    let other_failed = matches!(posed[j], Some(Err(_)));
                    let key = (i.min(j), i.max(j));
                    if (other_failed && j < i)
                        || (k > 0 && is_static[i] && is_static[j])
                        || job_of_pair.contains_key(&key)
                    {
                        continue;
                    }
                    candidates.push(key);
                }
            }
            cut = candidates.len() as u64 > budget;
        }

        // The materialized jobs, in parallel.
        let near = &near;
        let posed_ref = &posed;
        let frame_costs = states
            .par_iter_mut()
            .enumerate()
            .filter(|(j, _)| is_frame_job[*j] && (plan.jobs[*j].moving || k == 0))
            .map(|(j, state)| {
                let job = &plan.jobs[j];
                let mut local = Costs::default();
                let both_posed = matches!(
                    (&posed_ref[job.a], &posed_ref[job.b]),
                    (Some(Ok(_)), Some(Ok(_)))
                );
                let result = if both_posed && broad_job[j] && !near[j] {
                    local.broad_phase_skipped += 1;
                    Some(FrameResult::empty(t, Status::Beyond))
                } else {
                    let hint = (coherence && job.moving).then_some(&mut state.hint);
                    pair_frame::<K>(
                        scene,
                        job.ask(),
                        t,
                        (job.a, job.b),
                        posed_ref,
                        hint,
                        &meter,
                        &mut local,
                    )
                };
                match result {
                    // Not stored: a `within` query over many bodies would otherwise keep one
                    // frame per pair and frame (the report counts them).
                    Some(f) if f.status == Some(Status::Beyond) => local.within_beyond += 1,
                    Some(f) => state.frames.push(f),
                    None => {}
                }
                local
            })
            .reduce(Costs::default, Costs::merge);
        costs = costs.merge(frame_costs);

        // The streamed queries: their candidates, in parallel.
        if let Some(s) = stream {
            if cut {
                streaming = false;
                let names: Vec<&str> = s
                    .queries
                    .iter()
                    .map(|&q| scene.queries[q].name.as_str())
                    .collect();
                errors.push(format!(
                    "{} (all pairs within {}): stopped at frame {k} (t = {t}): more than {budget} \
                     candidate pairs (limits: {} per frame, MAX_FRAME_CANDIDATES; \
                     {MAX_PAIR_FRAMES} pair-frames per run, MAX_PAIR_FRAMES); no frame from \
                     t = {t} on is computed for them: lower `within` or list the pairs",
                    names.join(", "),
                    s.within,
                    options.max_frame_candidates.min(MAX_FRAME_CANDIDATES)
                ));
            } else {
                let ask = Ask {
                    effects: s.effects,
                    within: Some(s.within),
                };
                let eval = |pair: (usize, usize)| {
                    let mut local = Costs::default();
                    let f =
                        pair_frame::<K>(scene, ask, t, pair, posed_ref, None, &meter, &mut local);
                    (pair, f, local)
                };
                let empty = || (Vec::new(), Costs::default());
                let (kept, local) = if options.broad_phase {
                    candidates
                        .par_iter()
                        .map(|&p| eval(p))
                        .fold(empty, keep_within)
                        .reduce(empty, join_kept)
                } else {
                    let job_of_pair = &job_of_pair;
                    let is_static = &is_static;
                    (0..n)
                        .into_par_iter()
                        .flat_map_iter(|a| {
                            (a + 1..n)
                                .filter(move |&b| {
                                    (k == 0 || !(is_static[a] && is_static[b]))
                                        && !job_of_pair.contains_key(&(a, b))
                                })
                                .map(move |b| (a, b))
                        })
                        .map(eval)
                        .fold(empty, keep_within)
                        .reduce(empty, join_kept)
                };
                let evaluated = if options.broad_phase {
                    candidates.len() as u64
                } else {
                    scope
                };
                costs = costs.merge(local);
                costs.streamed_candidates += evaluated;
                costs.max_frame_candidates = costs.max_frame_candidates.max(evaluated);
                // The pairs of the scope the broad phase answered beyond from boxes.
                let skipped = scope.saturating_sub(evaluated);
                costs.broad_phase_skipped += skipped;
                costs.within_beyond += skipped;
                streamed_total += evaluated;
                for (pair, f) in kept {
                    streamed_out.entry(pair).or_default().push(f);
                }
            }
        }
        progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
    }

    // first_contact, in parallel over the pairs that ask for it (results in job order).
    let contact_jobs: Vec<usize> = (0..plan.jobs.len())
        .filter(|&j| plan.jobs[j].effects.contains(Effect::FirstContact))
        .collect();
    let contacts: Vec<(ContactResult, Costs)> = contact_jobs
        .par_iter()
        .map(|&j| {
            let job = &plan.jobs[j];
            let mut local = Costs::default();
            let (ba, bb) = (&scene.bodies[job.a], &scene.bodies[job.b]);
            let mut counts = ContactCounts::default();
            let r = meter.measure(&mut local.first_contact, || {
                first_contact::<K>(scene, ba, bb, job.contact, coherence, &mut counts)
            });
            local.first_contact_steps += counts.steps;
            local.first_contact_intersection_tests += counts.intersection_tests;
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
            (r, local)
        })
        .collect();
    let mut contacts = contact_jobs.into_iter().zip(contacts).peekable();

    let mut pairs: Vec<((usize, u64), PairReport)> = Vec::new();
    let mut failed = !errors.is_empty();
    let mut pairs_beyond = 0u64;
    let names = |qs: &[usize]| -> Vec<String> {
        qs.iter().map(|&q| scene.queries[q].name.clone()).collect()
    };
    for (j, (job, state)) in plan.jobs.iter().zip(states).enumerate() {
        let first_contact = match contacts.peek() {
            Some((cj, _)) if *cj == j => contacts.next().map(|(_, (r, local))| {
                costs = costs.merge(local);
                r
            }),
            _ => None,
        };
        if job.within.is_some() && state.frames.is_empty() && first_contact.is_none() {
            // Beyond the threshold at every frame, and nothing else asked.
            pairs_beyond += 1;
            continue;
        }
        let (ba, bb) = (&scene.bodies[job.a], &scene.bodies[job.b]);
        let pair_failed = state.frames.iter().any(|f| f.error.is_some())
            || first_contact.as_ref().is_some_and(|c| {
                matches!(
                    c.outcome,
                    ContactOutcome::Undecided | ContactOutcome::Invalid
                )
            });
        failed |= pair_failed;
        pairs.push((
            job.first,
            PairReport {
                a: ba.id.clone(),
                b: bb.id.clone(),
                kinds: [ba.shape.kind(), bb.shape.kind()],
                queries: names(&job.queries),
                effects: job.effects.iter().map(Effect::name).collect(),
                moving: job.moving,
                frames: state.frames,
                first_contact,
                failed: pair_failed,
            },
        ));
    }
    if let Some(s) = streamed {
        pairs_beyond += streamed_pairs - streamed_out.len() as u64;
        let mut found: Vec<((usize, usize), Vec<FrameResult>)> = streamed_out.into_iter().collect();
        found.sort_unstable_by_key(|(pair, _)| *pair);
        let effects: Vec<&'static str> = s.effects.iter().map(Effect::name).collect();
        for ((a, b), frames) in found {
            let (ba, bb) = (&scene.bodies[a], &scene.bodies[b]);
            let pair_failed = frames.iter().any(|f| f.error.is_some());
            failed |= pair_failed;
            pairs.push((
                (s.queries[0], a as u64 * n as u64 + b as u64),
                PairReport {
                    a: ba.id.clone(),
                    b: bb.id.clone(),
                    kinds: [ba.shape.kind(), bb.shape.kind()],
                    queries: names(&s.queries),
                    effects: effects.clone(),
                    moving: !(is_static[a] && is_static[b]),
                    frames,
                    first_contact: None,
                    failed: pair_failed,
                },
            ));
        }
        // Jobs and streamed pairs, in the order their queries first name them.
        pairs.sort_by_key(|(key, _)| *key);
    }
    Report {
        version: crate::report::REPORT_VERSION,
        scene: scene.name.clone(),
        kernel: kernel.name(),
        coherence,
        time: TimeReport {
            start: time.start,
            end: time.end,
            step: time.step,
            frames: time.frames,
        },
        pairs: pairs.into_iter().map(|(_, p)| p).collect(),
        pairs_beyond,
        costs,
        failed,
        errors,
    }
}

/// The body at time `t`: its internal (strictly convex, counter-clockwise) vertices moved by the
/// pose and validated again, so that the posed polygon's caller index `k` is the body's internal
/// vertex `k`. An error names the body, the time and the body's own (caller) vertex.
pub(crate) fn pose_body(body: &Body, t: f64) -> Result<Posed, String> {
    let pose = body.motion.pose_at(t);
    let poly = match &body.shape {
        Shape::Convex(poly) => poly,
        Shape::Simple(sp) => {
            // Re-validated as a simple polygon (rounding may make it touch itself); its hull serves
            // the bounding boxes and the `within` test.
            return posed_simple(sp.vertices(), pose)
                .map(|s| Posed {
                    poly: s.convex_hull(),
                    pose,
                    simple: Some(s),
                })
                .map_err(|e| {
                    format!(
                        "body '{}' is not a valid simple polygon at t = {t} after its rigid motion was rounded: {}",
                        body.id,
                        caller_error(sp.len(), |i| sp.source_index(i), e)
                    )
                });
        }
    };
    let moved: Vec<DVec2> = poly.vertices().iter().map(|&v| pose.apply(v)).collect();
    ConvexPolygon::try_new(&moved)
        .map(|p| Posed {
            poly: p,
            pose,
            simple: None,
        })
        .map_err(|e| {
            format!(
                "body '{}' is not a valid convex polygon at t = {t} after its rigid motion was rounded: {}",
                body.id,
                caller_error(poly.len(), |i| poly.source_index(i), e)
            )
        })
}

/// A posed polygon's error with its vertex indices (internal indices of the body, `len` of them,
/// named by `source` in the body's caller indices) in the body's caller indices.
fn caller_error(len: usize, source: impl Fn(usize) -> usize, e: PolygonError) -> PolygonError {
    let map = |i: usize| if i < len { source(i) } else { i };
    match e {
        PolygonError::NonFinite { index } => PolygonError::NonFinite { index: map(index) },
        PolygonError::OutOfRange { index } => PolygonError::OutOfRange { index: map(index) },
        PolygonError::Spike { index } => PolygonError::Spike { index: map(index) },
        PolygonError::NotConvex { index } => PolygonError::NotConvex { index: map(index) },
        PolygonError::SelfIntersection { edge_a, edge_b } => PolygonError::SelfIntersection {
            edge_a: map(edge_a),
            edge_b: map(edge_b),
        },
        other => other,
    }
}

/// The body's internal vertices moved by the pose, validated as a simple polygon (its caller index
/// `k` is the body's internal vertex `k`).
fn posed_simple(internal: &[DVec2], pose: Pose) -> Result<SimplePolygon, PolygonError> {
    let moved: Vec<DVec2> = internal.iter().map(|&v| pose.apply(v)).collect();
    SimplePolygon::try_new(&moved)
}

/// The inverse of a pose, rounded (used only to pick a caller edge along an internal edge that
/// stands for several caller edges).
fn unapply(pose: Pose, x: DVec2) -> DVec2 {
    let (s, c) = pose.rotation.sin_cos();
    let d = x - pose.translation;
    DVec2::new(c * d.x + s * d.y, c * d.y - s * d.x)
}

/// A body's polygon (convex or simple) as a map from its internal vertices and edges to the caller's.
trait CallerMap {
    fn internal_len(&self) -> usize;
    fn caller_count(&self) -> usize;
    fn source(&self, v: usize) -> usize;
    fn on_edge<K: Kernel>(&self, e: usize, q: DVec2) -> Option<Feature>;
}

/// Both polygon types name their caller's vertices and edges through the same inherent methods.
macro_rules! caller_map {
    ($($t:ty),*) => {$(
        impl CallerMap for $t {
            fn internal_len(&self) -> usize {
                self.len()
            }
            fn caller_count(&self) -> usize {
                self.caller_len()
            }
            fn source(&self, v: usize) -> usize {
                self.source_index(v)
            }
            fn on_edge<K: Kernel>(&self, e: usize, q: DVec2) -> Option<Feature> {
                self.caller_feature_on_edge::<K>(e, q)
            }
        }
    )*};
}
caller_map!(ConvexPolygon, SimplePolygon);

/// A feature of a posed polygon (internal indices of `poly`) as the body's caller feature. `x` is
/// the other body's realizing point (world frame).
///
/// A vertex maps through `source_index` exactly. An internal edge whose ends are consecutive caller
/// vertices is that caller edge, exactly. An internal edge running through dropped caller vertices
/// (collinear or repeated) is resolved by `caller_feature_on_edge` at `x` moved back by the inverse
/// pose, a rounded point: not an exact decision when `x` is within rounding of a dropped vertex.
fn caller_feature<K: Kernel, P: CallerMap>(poly: &P, pose: Pose, f: Feature, x: DVec2) -> Feature {
    match f {
        Feature::Vertex(k) => Feature::Vertex(poly.source(k)),
        Feature::Edge(k) => {
            let n = poly.internal_len();
            let l = poly.caller_count();
            let (a, b) = (poly.source(k), poly.source((k + 1) % n));
            if (a + 1) % l == b {
                Feature::Edge(a)
            } else if (b + 1) % l == a {
                Feature::Edge(b)
            } else {
                poly.on_edge::<K>(k, unapply(pose, x))
                    .unwrap_or(Feature::Edge(a))
            }
        }
    }
}

/// The per-frame effects of one job at one frame.
pub(crate) fn eval_frame<K: Kernel>(
    ask: Ask,
    t: f64,
    (ba, pa): (&Body, &Posed),
    (bb, pb): (&Body, &Posed),
    hint: Option<&mut Option<Hint>>,
    meter: &Meter,
    costs: &mut Costs,
) -> FrameResult {
    let mut out = FrameResult::empty(t, Status::Disjoint);
    out.status = None;
    let convex = match (&ba.shape, &bb.shape) {
        (Shape::Convex(a), Shape::Convex(b)) => Some((a, b)),
        _ => None,
    };
    let convex_effects = [
        Effect::Distance,
        Effect::ClosestPoints,
        Effect::VertexDistance,
        Effect::Hausdorff,
        Effect::Cmmr,
    ]
    .into_iter()
    .any(|e| ask.effects.contains(e));
    if convex_effects && convex.is_none() {
        // The loader refuses convex effects on simple bodies (NeedsConvex): not reached from a scene.
        out.status = Some(Status::Invalid);
        out.error = Some("a body is not convex".to_owned());
        return out;
    }
    let mut known: Option<Separation> = None;
    if let Some(r) = ask.within {
        // The threshold, decided exactly; the answer's separation serves the distance effects.
        match meter.measure(&mut costs.distance, || {
            distance_within::<K>(&pa.poly, &pb.poly, r)
        }) {
            Within::Beyond { .. } => {
                out.status = Some(Status::Beyond);
                return out;
            }
            Within::Inside(sep) => known = Some(sep),
        }
    }
    if ask.effects.contains(Effect::Separation) {
        separation_frame::<K>((ba, pa), (bb, pb), &mut out, meter, costs);
    }
    let Some((poly_a, poly_b)) = convex else {
        return out;
    };
    if ask.needs_distance() {
        let sep = match (known, hint) {
            (Some(sep), _) => sep,
            (None, Some(h)) => {
                if h.is_some() {
                    costs.distance_hinted += 1;
                }
                let (sep, next) = meter.measure(&mut costs.distance, || {
                    distance_with_hint::<K>(&pa.poly, &pb.poly, *h)
                });
                *h = Some(next);
                sep
            }
            (None, None) => meter.measure(&mut costs.distance, || {
                distance_with::<K>(&pa.poly, &pb.poly)
            }),
        };
        let (status, closest) = match sep {
            Separation::Disjoint(c) => (
                Status::Disjoint,
                Some(ClosestPoints {
                    point_a: c.point_p.to_array(),
                    point_b: c.point_q.to_array(),
                    feature_a: caller_feature::<K, _>(poly_a, pa.pose, c.feature_p, c.point_q)
                        .into(),
                    feature_b: caller_feature::<K, _>(poly_b, pb.pose, c.feature_q, c.point_p)
                        .into(),
                    parallel: c.parallel,
                }),
            ),
            Separation::Touching {
                point,
                feature_p,
                feature_q,
            } => (
                Status::Touching,
                Some(ClosestPoints {
                    point_a: point.to_array(),
                    point_b: point.to_array(),
                    feature_a: caller_feature::<K, _>(poly_a, pa.pose, feature_p, point).into(),
                    feature_b: caller_feature::<K, _>(poly_b, pb.pose, feature_q, point).into(),
                    parallel: false,
                }),
            ),
            Separation::Overlapping => (Status::Overlapping, None),
        };
        out.status = Some(status);
        if ask.effects.contains(Effect::Distance) {
            let c = sep.closest();
            out.distance = Some(c.map_or(0.0, |c| c.distance));
            out.squared_distance = Some(c.map_or(0.0, |c| c.squared_distance));
        }
        if ask.effects.contains(Effect::ClosestPoints) {
            out.closest_points = closest;
        }
    }
    if ask.effects.contains(Effect::VertexDistance) {
        let v = meter.measure(&mut costs.vertex_distance, || {
            min_vertex_distance_with::<K>(&pa.poly, &pb.poly)
        });
        out.vertex_distance = Some(VertexDistanceResult {
            distance: v.distance,
            squared_distance: v.squared_distance,
            vertex_a: poly_a.source_index(v.vertex_p),
            vertex_b: poly_b.source_index(v.vertex_q),
        });
    }
    if ask.effects.contains(Effect::Hausdorff) {
        let h = meter.measure(&mut costs.hausdorff, || {
            hausdorff_with::<K>(&pa.poly, &pb.poly)
        });
        let directed = |from: &ConvexPolygon, to: &ConvexPolygon, to_pose, d: VertexToPolygon| {
            DirectedHausdorff {
                distance: d.distance,
                squared_distance: d.squared_distance,
                vertex: from.source_index(d.vertex),
                point: d.point.to_array(),
                projection: d.projection.to_array(),
                feature: d
                    .feature
                    .map(|f| caller_feature::<K, _>(to, to_pose, f, d.point).into()),
            }
        };
        out.hausdorff = Some(Box::new(HausdorffResult {
            distance: h.distance,
            squared_distance: h.squared_distance,
            direction: match h.direction {
                Direction::PToQ => "a_to_b",
                Direction::QToP => "b_to_a",
            },
            a_to_b: directed(poly_a, poly_b, pb.pose, h.p_to_q),
            b_to_a: directed(poly_b, poly_a, pa.pose, h.q_to_p),
        }));
    }
    if ask.effects.contains(Effect::Cmmr) {
        out.cmmr =
            Some(meter.measure(&mut costs.cmmr, || cmmr_value_with::<K>(&pa.poly, &pb.poly)));
    }
    out
}

/// The `separation` effect of one pair at one frame (Amato 1992 through
/// [`polydist_separation::separation`]): both bodies as posed simple polygons (a simple body's posed
/// polygon, or a convex body's posed vertices validated as a simple polygon), features mapped back to
/// the bodies' caller indices. Disjoint: `out.separation` (status `disjoint` unless a convex effect
/// sets a finer one); meeting: status `intersecting`; any error of the separation (only under the
/// `Fast` kernel's inconsistent decisions): status `unsupported` with the error; a body without
/// area: status `invalid`.
fn separation_frame<K: Kernel>(
    (ba, pa): (&Body, &Posed),
    (bb, pb): (&Body, &Posed),
    out: &mut FrameResult,
    meter: &Meter,
    costs: &mut Costs,
) {
    fn as_simple<'p>(b: &Body, p: &'p Posed) -> Result<Cow<'p, SimplePolygon>, String> {
        match (&p.simple, &b.shape) {
            (Some(s), _) => Ok(Cow::Borrowed(s)),
            (None, Shape::Convex(poly)) => posed_simple(poly.vertices(), p.pose)
                .map(Cow::Owned)
                .map_err(|e| {
                    format!(
                        "separation needs polygons with area: body '{}' ({} vertices) is not one: {e}",
                        b.id,
                        poly.len()
                    )
                }),
            (None, Shape::Simple(_)) => Err(format!("body '{}' was not posed", b.id)),
        }
    }
    let answer = meter.measure(&mut costs.separation, || {
        let (sa, sb) = (as_simple(ba, pa)?, as_simple(bb, pb)?);
        Ok::<_, String>((separation::<K>(&sa, &sb), sa, sb))
    });
    match answer {
        Err(message) => {
            out.status = Some(Status::Invalid);
            out.error = Some(message);
        }
        Ok((Ok(PolygonSeparation::Separated { pair, route, .. }), _, _)) => {
            // The posed polygons' caller indices are the bodies' internal vertices.
            let feature = |b: &Body, p: &Posed, f: Feature, x: DVec2| match &b.shape {
                Shape::Convex(poly) => caller_feature::<K, _>(poly, p.pose, f, x),
                Shape::Simple(sp) => caller_feature::<K, _>(sp, p.pose, f, x),
            };
            out.status.get_or_insert(Status::Disjoint);
            out.separation = Some(SeparationResult {
                distance: pair.distance,
                squared_distance: pair.squared_distance,
                point_a: pair.point_p.to_array(),
                point_b: pair.point_q.to_array(),
                feature_a: feature(ba, pa, pair.feature_p, pair.point_q).into(),
                feature_b: feature(bb, pb, pair.feature_q, pair.point_p).into(),
                route: match route {
                    Route::HullFeatures => "hull_features",
                    Route::SeparableChains => "separable_chains",
                    Route::MonotoneSweep => "monotone_sweep",
                    Route::EnvelopeSweep => "envelope_sweep",
                    Route::Separators => "separators",
                    Route::BruteForce => "brute_force",
                    Route::Scan => "scan",
                },
            });
        }
        Ok((Ok(PolygonSeparation::Intersecting(_)), _, _)) => {
            out.status = Some(Status::Intersecting);
        }
        Ok((Err(e), _, _)) => {
            out.status = Some(Status::Unsupported);
            out.error = Some(format!("separation of '{}' and '{}': {e}", ba.id, bb.id));
        }
    }
}

/// A certified lower bound on the exact distance of the exactly posed bodies, from the computed
/// distance `d` of the rounded posed polygons: `d` is within 2.5 ulps of the exact distance of the
/// rounded polygons (the convex crate's budget), and each rounded polygon is within
/// [`pose_error`] of the exactly posed one.
fn certified(d: f64, pa: &Posed, ra: f64, pb: &Posed, rb: f64) -> f64 {
    let slack = pose_error(pa.pose, ra) + pose_error(pb.pose, rb);
    down(d * (1.0 - 4.0 * f64::EPSILON) - up(slack))
}

/// A certified lower bound on the distance over a step `[t_i, t_{i+1}]` of length `len` with
/// certified end distances `d0`, `d1` and speed bound `v`: `(d0 + d1 − v·len) / 2` (module docs),
/// rounded down with room for its own roundings, never below zero.
fn step_clearance(d0: f64, d1: f64, v: f64, len: f64) -> f64 {
    let vl = up(v * up(len));
    let raw = (d0 + d1 - vl) / 2.0;
    down(raw - 2.0 * f64::EPSILON * (d0 + d1 + vl))
}

/// The float `t + d/v` rounded down twice (the quotient, then the sum): no more than the exact
/// `t + d/v`.
fn advance(t: f64, d: f64, v: f64) -> f64 {
    (t + (d / v).next_down().max(0.0)).next_down()
}

/// The next time of conservative advancement from `t` with certified distance `d`, and the speed
/// bound valid on `[t, next]`; `None` when the bodies do not move relative to each other for the
/// rest of the span.
///
/// The bound over `[t, end]` gives `t + d/V`. With keyframes the speed may be lower near `t` than
/// later: windows `[t, t + w]` with `w` doubling (at most 8 times) from twice that step give
/// `min(t + w, t + d/V_w)`, valid because `V_w` bounds the speed on the window; the farthest wins.
fn safe_step(a: &Body, b: &Body, t: f64, end: f64, d: f64) -> Option<(f64, f64)> {
    let bound = |hi: f64| relative_speed_bound(&a.motion, a.radius, &b.motion, b.radius, t, hi);
    let v_all = bound(end);
    if v_all == 0.0 {
        return None;
    }
    let mut best = (advance(t, d, v_all).min(end), v_all);
    let keyframed = |m: &Motion| matches!(m, Motion::Keyframes(_));
    if !(keyframed(&a.motion) || keyframed(&b.motion)) {
        // Constant velocities: every window has the same bound.
        return Some(best);
    }
    let mut w = 2.0 * (best.0 - t);
    for _ in 0..8 {
        let w_end = t + w;
        if !(w_end > t && w_end < end) {
            break;
        }
        let v_w = bound(w_end);
        let candidate = if v_w == 0.0 {
            w_end
        } else {
            advance(t, d, v_w).min(w_end)
        };
        if candidate > best.0 {
            best = (candidate, v_w);
        }
        w *= 2.0;
    }
    Some(best)
}

/// What `first_contact` did, for [`Costs`].
#[derive(Default)]
struct ContactCounts {
    steps: u64,
    intersection_tests: u64,
}

/// `first_contact` of one pair by conservative advancement (module docs).
fn first_contact<K: Kernel>(
    scene: &Scene,
    a: &Body,
    b: &Body,
    params: ContactParams,
    coherence: bool,
    costs: &mut ContactCounts,
) -> ContactResult {
    let (start, end) = (scene.time.start, scene.time.end);
    let mut result = ContactResult {
        outcome: ContactOutcome::Undecided,
        t_safe: None,
        t_hit: None,
        clearance_lower_bound: None,
        steps: 0,
        probes: 0,
        tolerance: params.tolerance,
        max_steps: params.max_steps,
        message: None,
    };
    let pose_both =
        |t: f64| -> Result<(Posed, Posed), String> { Ok((pose_body(a, t)?, pose_body(b, t)?)) };
    let mut t = start;
    let mut hint: Option<Hint> = None;
    // The previous step: (time, certified distance, speed bound).
    let mut prev: Option<(f64, f64, f64)> = None;
    let mut clearance = f64::INFINITY;
    loop {
        if result.steps >= params.max_steps {
            result.message = Some(format!(
                "max_steps ({}) reached at t = {t}",
                params.max_steps
            ));
            return result;
        }
        result.steps += 1;
        costs.steps += 1;
        let (pa, pb) = match pose_both(t) {
            Ok(x) => x,
            Err(e) => {
                result.outcome = ContactOutcome::Invalid;
                result.message = Some(e);
                return result;
            }
        };
        let sep = if coherence {
            let (sep, next) = distance_with_hint::<K>(&pa.poly, &pb.poly, hint);
            hint = Some(next);
            sep
        } else {
            distance_with::<K>(&pa.poly, &pb.poly)
        };
        let Separation::Disjoint(c) = sep else {
            // Meeting at t: confirmed by the exact intersection test.
            costs.intersection_tests += 1;
            if intersects::<K>(&pa.poly, &pb.poly) {
                result.t_hit = Some(t);
                result.outcome = if prev.is_none() {
                    ContactOutcome::ContactAtStart
                } else {
                    ContactOutcome::Contact
                };
            } else {
                result.outcome = ContactOutcome::Undecided;
                result.message = Some(format!(
                    "the distance query and the intersection test disagree at t = {t} (inexact kernel)"
                ));
            }
            return result;
        };
        let d = certified(c.distance, &pa, a.radius, &pb, b.radius);
        if let Some((tp, dp, vp)) = prev {
            clearance = clearance.min(step_clearance(dp, d, vp, t - tp));
        }
        result.t_safe = Some(t);
        if t >= end {
            result.outcome = ContactOutcome::Apart;
            result.clearance_lower_bound = Some(clearance.min(d));
            return result;
        }
        let Some((next, v)) = safe_step(a, b, t, end, d) else {
            // No relative motion for the rest of the span: the distance stays d.
            result.outcome = ContactOutcome::Apart;
            result.t_safe = Some(end);
            result.clearance_lower_bound = Some(clearance.min(d));
            return result;
        };
        let h = next - t;
        if h < params.tolerance {
            // The float t + tolerance, moved down (at most twice) so the bracket is no wider than
            // the tolerance as computed in f64.
            let mut probe = t + params.tolerance;
            for _ in 0..2 {
                if probe - t > params.tolerance {
                    probe = probe.next_down();
                }
            }
            let probe = probe.min(end);
            result.probes += 1;
            costs.intersection_tests += 1;
            match pose_both(probe) {
                Ok((qa, qb)) => {
                    if intersects::<K>(&qa.poly, &qb.poly) {
                        result.outcome = ContactOutcome::Contact;
                        result.t_hit = Some(probe);
                        // The step from t is certified too: the bracket starts at its end.
                        if next > t && next < probe {
                            result.t_safe = Some(next);
                        }
                        return result;
                    }
                }
                Err(e) => {
                    result.outcome = ContactOutcome::Invalid;
                    result.message = Some(e);
                    return result;
                }
            }
        }
        if next <= t {
            result.message = Some(format!(
                "the safe step ({h:e}) vanished at t = {t} (distance {:e}, speed bound {v:e})",
                c.distance
            ));
            return result;
        }
        prev = Some((t, d, v));
        t = next;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_clearance_is_the_midpoint_bound() {
        // d0 = 4, d1 = 2, V = 1, L = 3: the lines 4 − s and 2 − (3 − s) cross at s = 2.5 at 1.5.
        let c = step_clearance(4.0, 2.0, 1.0, 3.0);
        assert!(c <= 1.5 && c > 1.5 - 1e-12);
        // Never negative.
        assert_eq!(step_clearance(1.0, 0.0, 10.0, 1.0), 0.0);
    }

    #[test]
    fn certified_is_below_the_distance() {
        let p = Posed {
            simple: None,
            poly: ConvexPolygon::try_new(&[DVec2::ZERO]).unwrap(),
            pose: Pose {
                translation: DVec2::new(100.0, 0.0),
                rotation: 1.0,
            },
        };
        let d = certified(1.0, &p, 2.0, &p, 2.0);
        assert!(d < 1.0 && d > 1.0 - 1e-10, "{d}");
        assert_eq!(certified(0.0, &p, 2.0, &p, 2.0), 0.0);
    }
}
