//! Scenes for polydist: bodies, motions and the effects a scene asks for, and the runner that
//! computes exactly those (layer 4).
//!
//! A scene file (TOML, or JSON; the format is docs/scene-format.md) declares bodies (convex or simple
//! polygons from inline vertices, a polygon file or a generator), their motions over a time span
//! (static, linear and angular velocity, keyframes), a precision kernel, and queries: which pairs and
//! which effects. This crate
//!
//! - parses and validates it, reporting **every** problem as a typed [`SceneError`] (a syntax
//!   error with file, line and column; an invalid polygon with the body and the vertex; unknown ids,
//!   bad time spans, limits): [`load_str`], [`load_file`], [`validate`];
//! - poses bodies ([`Motion::pose_at`]) and bounds the relative speed of any boundary point of a
//!   pair over an interval ([`relative_speed_bound`], Schwartz 1981 §1 with its erratum);
//! - plans ([`plan`]: one job per pair, effects merged, static pairs once; an all-pairs query with
//!   `within` is streamed, never one job per pair) and runs ([`run`](fn@run)):
//!   `distance` and `closest_points` share one convex distance query (Yang 2006, `O(log n + log m)`,
//!   with temporal coherence), `vertex_distance` is McKenna–Toussaint (`O(n + m)`), `first_contact`
//!   is conservative advancement (Schwartz 1981) with a bracket confirmed by the exact intersection
//!   test or a certified clearance, `hausdorff` and `cmmr` are Atallah–Ribeiro–Lifschitz (`O(n + m)`),
//!   `separation` takes simple bodies (Amato 1992 through `polydist_separation::separation`);
//!   the [`Report`] says what each effect computed and what it cost;
//! - answers queries with `within` over many bodies through a broad phase ([`sweep_and_prune`] with a
//!   certified box gap, on the axis of larger spread): an all-pairs query with `within` evaluates
//!   only each frame's candidate pairs, in memory `O(bodies + candidates + results)`; pairs are
//!   evaluated in parallel (rayon), with results independent of both;
//! - answers pairs of polygons as JSON lines ([`batch_pairs`], [`batch_within`]; docs/batch.md);
//! - draws a run as SVG ([`render_svg`]).
//!
//! Every effect but `separation` needs convex bodies ([`SceneError::NeedsConvex`]); `separation`
//! answers every pair of disjoint simple bodies (hulls apart, interlocked, pinched, or one in a pocket
//! of the other); a frame it cannot answer (only under the `Fast` kernel) is reported as
//! `unsupported`, and the run goes on.
//!
//! # Numbers
//! Posed polygons are rounded coordinates: every decision is exact for them (under the Robust and
//! Exact kernels). `first_contact` certificates also cover the gap between the rounded and the exact
//! poses (see the `run` module's docs in the source and docs/scene-format.md).
//!
//! # Examples
//! ```
//! use polydist_scene::{Origin, RunOptions, load_str, run};
//!
//! let scene = load_str(r#"
//!     [[body]]
//!     id = "a"
//!     vertices = [[0, 0], [1, 0], [0, 1]]
//!     [[body]]
//!     id = "b"
//!     generator = { type = "regular", n = 4, radius = 1.0 }
//!     pose = { x = 4.0, y = 0.0 }
//!     [[query]]
//!     pairs = "all"
//!     effects = ["distance", "closest_points"]
//! "#, &Origin::text("example.toml"))?;
//! let report = run(&scene, &RunOptions::default());
//! assert_eq!(report.pairs[0].frames[0].distance, Some(2.0));
//! # Ok::<(), polydist_scene::SceneErrors>(())
//! ```

mod batch;
mod broad;
mod error;
mod generate;
mod load;
mod motion;
mod report;
mod run;
mod spec;
mod svg;

pub use batch::{
    BatchOptions, BatchSummary, LayerPolygon, MAX_LAYER_POLYGONS, MAX_LINE_BYTES, batch_pairs,
    batch_within, read_layer,
};
pub use broad::{Aabb, SweepStats, all_pairs_not_farther, sweep_and_prune};
pub use error::{SceneError, SceneErrors};
pub use generate::MAX_VERTICES;
pub use load::{
    Body, ContactParams, DEFAULT_MAX_STEPS, DEFAULT_RELATIVE_TOLERANCE, FRAME_SLACK, MAX_BODIES,
    MAX_FILE_BYTES, MAX_FRAME_CANDIDATES, MAX_FRAMES, MAX_PAIR_FRAMES, MAX_PAIRS, Origin, PairSet,
    Query, Scene, Shape, TimeSpan, load_file, load_str, parse_polygon_file, parse_spec, validate,
};
pub use motion::{Keyframe, Motion, relative_speed_bound};
pub use report::{
    ClosestPoints, ContactOutcome, ContactResult, Cost, Costs, FeatureRef, FrameResult, PairReport,
    REPORT_VERSION, Report, Status, TimeReport, VertexDistanceResult,
};
pub use run::{PairJob, Plan, RunOptions, Streamed, plan, run, run_with_progress};
pub use spec::{
    BodySpec, Effect, EffectSet, GeneratorSpec, KernelChoice, KeyframeSpec, KindSpec, MotionSpec,
    PairsSpec, PoseSpec, QuerySpec, SceneSpec, TimeSpec,
};
pub use svg::render_svg;
