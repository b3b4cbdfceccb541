//! Errors for people: every problem of a scene, typed, with where it is.

use core::fmt;

use polydist_polygon::PolygonError;

/// One problem found while loading or validating a scene.
///
/// [`crate::load_str`] reports every problem it can find (all of them, not just the first) as
/// [`SceneErrors`]; only a syntax error stops the loader early, since nothing after it can be read.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SceneError {
    /// The text is not valid TOML or JSON, or does not have the scene's shape.
    #[error("{file}:{line}:{column}: {message}")]
    Syntax {
        /// The file name (or `<embedded>` / `<text>`).
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column (in characters).
        column: usize,
        /// What the parser expected.
        message: String,
    },
    /// A file could not be read.
    #[error("cannot read {path}: {reason}")]
    Io {
        /// The path as given.
        path: String,
        /// The system's reason.
        reason: String,
    },
    /// A body's id is empty.
    #[error("body #{index} has an empty id")]
    EmptyId {
        /// The body's position in the file (1-based).
        index: usize,
    },
    /// Two bodies share an id.
    #[error("body id '{id}' is used twice (bodies #{first} and #{second})")]
    DuplicateId {
        /// The id.
        id: String,
        /// 1-based position of the first body.
        first: usize,
        /// 1-based position of the second body.
        second: usize,
    },
    /// A body has no shape source, or more than one.
    #[error(
        "body '{body}' must give exactly one of `vertices`, `file` or `generator` (it gives {found})"
    )]
    ShapeSource {
        /// The body's id.
        body: String,
        /// How many sources it gives.
        found: usize,
    },
    /// A body's vertices do not make a polygon of its kind.
    #[error("body '{body}' is not a valid {kind} polygon: {source}")]
    InvalidPolygon {
        /// The body's id.
        body: String,
        /// `convex` or `simple` (for auto-detected bodies, `simple`: the more general kind).
        kind: &'static str,
        /// What is wrong and at which vertex (the body's own vertex indices, 0-based).
        source: PolygonError,
    },
    /// A generator's parameters are out of range.
    #[error("body '{body}': generator `{generator}`: {reason}")]
    BadGenerator {
        /// The body's id.
        body: String,
        /// The generator's type.
        generator: &'static str,
        /// What is wrong.
        reason: String,
    },
    /// A polygon file could not be read or parsed.
    #[error("body '{body}': polygon file {path}: {reason}")]
    BadPolygonFile {
        /// The body's id.
        body: String,
        /// The path as resolved.
        path: String,
        /// What is wrong (with the line for parse errors).
        reason: String,
    },
    /// More vertices than [`MAX_VERTICES`](crate::MAX_VERTICES).
    #[error("body '{body}' asks for {count} vertices; the limit is {limit}")]
    TooManyVertices {
        /// The body's id.
        body: String,
        /// The number asked for.
        count: u64,
        /// The limit.
        limit: u64,
    },
    /// A pose, velocity or keyframe value is NaN or infinite.
    #[error("body '{body}': {field} is not finite")]
    NonFinite {
        /// The body's id.
        body: String,
        /// Which value.
        field: String,
    },
    /// Keyframes are empty or their times do not increase strictly.
    #[error("body '{body}': keyframe {index} (0-based): {reason}")]
    BadKeyframes {
        /// The body's id.
        body: String,
        /// The offending key.
        index: usize,
        /// What is wrong.
        reason: &'static str,
    },
    /// A body gives both a `pose` and keyframes.
    #[error("body '{body}' gives both `pose` and keyframes; the keyframes give the pose")]
    PoseWithKeyframes {
        /// The body's id.
        body: String,
    },
    /// The time span is invalid.
    #[error("time span: {reason}")]
    BadTime {
        /// What is wrong.
        reason: String,
    },
    /// More frames than [`MAX_FRAMES`](crate::MAX_FRAMES).
    #[error("time span has {frames} frames; the limit is {limit}")]
    TooManyFrames {
        /// The number of frames asked for (rounded).
        frames: f64,
        /// The limit.
        limit: u64,
    },
    /// More bodies than [`MAX_BODIES`](crate::MAX_BODIES).
    #[error("the scene has {count} bodies; the limit is {limit}")]
    TooManyBodies {
        /// The number of bodies.
        count: usize,
        /// The limit.
        limit: usize,
    },
    /// More pairs (over all queries) than [`MAX_PAIRS`](crate::MAX_PAIRS), or more pair-frame
    /// evaluations than [`MAX_PAIR_FRAMES`](crate::MAX_PAIR_FRAMES).
    #[error("the queries ask for {count} {what}; the limit is {limit}")]
    TooMuchWork {
        /// `pairs` or `pair-frame evaluations`.
        what: &'static str,
        /// The number asked for.
        count: u128,
        /// The limit.
        limit: u128,
    },
    /// A query names a body that does not exist.
    #[error("{query}: unknown body '{id}'")]
    UnknownBody {
        /// The query's name.
        query: String,
        /// The id.
        id: String,
    },
    /// A query pairs a body with itself.
    #[error("{query}: the pair ['{id}', '{id}'] pairs a body with itself")]
    SelfPair {
        /// The query's name.
        query: String,
        /// The id.
        id: String,
    },
    /// A query asks for no effect.
    #[error("{query}: no effects requested")]
    NoEffects {
        /// The query's name.
        query: String,
    },
    /// A query asks for an effect whose algorithm this build does not have yet.
    #[error(
        "{query}: effect `{effect}` is not yet available in this version of polydist (it arrives with its algorithm); remove it from the query"
    )]
    EffectNotYetAvailable {
        /// The query's name.
        query: String,
        /// The effect.
        effect: &'static str,
    },
    /// An effect needs convex bodies and the pair has a simple (non-convex) body.
    #[error(
        "{query}: effect `{effect}` on ['{a}', '{b}'] needs convex bodies, and '{body}' is a simple polygon (ask `separation` for the distance of simple polygons)"
    )]
    NeedsConvex {
        /// The query's name.
        query: String,
        /// The effect.
        effect: &'static str,
        /// The pair's first id.
        a: String,
        /// The pair's second id.
        b: String,
        /// The non-convex body.
        body: String,
    },
    /// A `first_contact` parameter is invalid.
    #[error("{query}: {reason}")]
    BadParameter {
        /// The query's name.
        query: String,
        /// What is wrong.
        reason: String,
    },
    /// Two queries ask for `first_contact` on the same pair with different parameters.
    #[error(
        "{query}: first_contact on ['{a}', '{b}'] is also asked by {other} with other tolerance or max_steps"
    )]
    ConflictingParameters {
        /// The later query.
        query: String,
        /// The earlier query.
        other: String,
        /// The pair's first id.
        a: String,
        /// The pair's second id.
        b: String,
    },
}

/// Every problem found in a scene: never empty.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneErrors(pub Vec<SceneError>);

impl SceneErrors {
    /// The problems, in the order found.
    #[must_use]
    pub fn errors(&self) -> &[SceneError] {
        &self.0
    }
}

impl fmt::Display for SceneErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = self.0.len();
        writeln!(
            f,
            "{n} problem{} in the scene:",
            if n == 1 { "" } else { "s" }
        )?;
        for e in &self.0 {
            writeln!(f, "  - {e}")?;
        }
        Ok(())
    }
}

impl std::error::Error for SceneErrors {}

impl From<SceneError> for SceneErrors {
    fn from(e: SceneError) -> Self {
        SceneErrors(vec![e])
    }
}
