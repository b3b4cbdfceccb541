//! The scene file as written: the serde model of TOML and JSON scene files, before validation.
//!
//! Every type here mirrors docs/scene-format.md field by field. Unknown fields are errors (a typo is
//! never silently ignored). [`crate::load_str`] turns a [`SceneSpec`] into a validated
//! [`Scene`](crate::Scene).

use core::fmt;

use serde::de::{self, SeqAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize};

/// A whole scene file.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    /// A name for the report (default: the file name, or `scene`).
    #[serde(default)]
    pub name: Option<String>,
    /// The time span and frame step (default: one frame at `t = 0`).
    #[serde(default)]
    pub time: Option<TimeSpec>,
    /// The precision kernel of every decision.
    #[serde(default)]
    pub kernel: KernelChoice,
    /// Temporal coherence for moving convex pairs (start from the previous frame's closest features).
    /// Results are identical either way; only the cost changes. Default `true`.
    #[serde(default)]
    pub coherence: Option<bool>,
    /// The bodies (`[[body]]` in TOML, `"body"` or `"bodies"` in JSON).
    #[serde(default, rename = "body", alias = "bodies")]
    pub bodies: Vec<BodySpec>,
    /// The queries (`[[query]]` in TOML, `"query"` or `"queries"` in JSON).
    #[serde(default, rename = "query", alias = "queries")]
    pub queries: Vec<QuerySpec>,
}

/// The time span `[start, end]` and the frame step.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct TimeSpec {
    /// The first frame's time (default `0`).
    #[serde(default)]
    pub start: f64,
    /// The last time of the span (`end ≥ start`).
    pub end: f64,
    /// The distance between frames (`step > 0`).
    pub step: f64,
}

/// The precision kernel: how every geometric decision is made.
#[derive(Clone, Copy, Debug, Default, Deserialize, Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum KernelChoice {
    /// Plain `f64` predicates: fastest, may misjudge near-degenerate input.
    Fast,
    /// Exact predicates with floating-point filters (the default).
    #[default]
    Robust,
    /// Exact arithmetic for every predicate.
    Exact,
}

impl KernelChoice {
    /// The name used in files and reports: `fast`, `robust` or `exact`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            KernelChoice::Fast => "fast",
            KernelChoice::Robust => "robust",
            KernelChoice::Exact => "exact",
        }
    }
}

/// How the loader should read a body's vertices.
#[derive(Clone, Copy, Debug, Default, Deserialize, Serialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum KindSpec {
    /// Convex if the ring is a valid convex polygon (points and segments included), else simple.
    #[default]
    Auto,
    /// A convex polygon (validated by `ConvexPolygon::try_new`).
    Convex,
    /// A simple polygon (validated by `SimplePolygon::try_new`).
    Simple,
}

/// One body: an id, a shape from exactly one source, an initial pose and a motion.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// The body's id, unique in the scene.
    pub id: String,
    /// Convex, simple, or detected at load (default).
    #[serde(default)]
    pub kind: KindSpec,
    /// Inline vertices `[[x, y], ...]` in the body's own frame.
    #[serde(default)]
    pub vertices: Option<Vec<[f64; 2]>>,
    /// A polygon file, relative to the scene file's directory (the fixtures keep theirs in
    /// `fixtures/polygons/`).
    #[serde(default)]
    pub file: Option<String>,
    /// A generated shape.
    #[serde(default)]
    pub generator: Option<GeneratorSpec>,
    /// The pose at `t = 0` (default: the identity). Not allowed with keyframes, which give the pose.
    #[serde(default)]
    pub pose: Option<PoseSpec>,
    /// The motion (default: static).
    #[serde(default)]
    pub motion: Option<MotionSpec>,
}

/// A rigid pose: rotate by `angle` radians counter-clockwise about the body frame's origin, then move
/// the origin to `(x, y)`.
#[derive(Clone, Copy, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PoseSpec {
    /// The origin's x in the world.
    #[serde(default)]
    pub x: f64,
    /// The origin's y in the world.
    #[serde(default)]
    pub y: f64,
    /// Counter-clockwise, in radians.
    #[serde(default)]
    pub angle: f64,
}

/// A shape generator (`generator = { type = "regular", n = 6, radius = 1.0 }`). Generated shapes are
/// centred on the body frame's origin and deterministic.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum GeneratorSpec {
    /// A regular `n`-gon with circumradius `radius`, first vertex at angle 0 (convex).
    Regular {
        /// The number of vertices (`n ≥ 3`).
        n: u64,
        /// The circumradius (`> 0`).
        radius: f64,
    },
    /// A star with `points` tips on the circle `outer` and notches on the circle `inner` (simple,
    /// `2·points` vertices).
    Star {
        /// The number of tips (`≥ 3`).
        points: u64,
        /// The tips' radius.
        outer: f64,
        /// The notches' radius (`0 < inner < outer`).
        inner: f64,
    },
    /// A comb: a spine of height `spine` under `teeth` rectangular teeth of height `height`, each
    /// tooth and gap `width` wide (simple, `4·teeth` vertices).
    Comb {
        /// The number of teeth (`≥ 1`).
        teeth: u64,
        /// The width of a tooth and of a gap (`> 0`).
        width: f64,
        /// The teeth's height above the spine (`> 0`).
        height: f64,
        /// The spine's height (`> 0`).
        spine: f64,
    },
    /// `n` points at seeded random angles on the circle `radius` (a convex polygon).
    RandomConvex {
        /// The number of vertices (`≥ 3`).
        n: u64,
        /// The circle's radius (`> 0`).
        radius: f64,
        /// The seed (SplitMix64): the same seed gives the same polygon on every machine. TOML
        /// integers are 64-bit signed, so a TOML file can give seeds below 2^63.
        seed: u64,
    },
}

/// A motion (`motion = { type = "linear", velocity = [1.0, 0.0], angular = 0.5 }`).
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum MotionSpec {
    /// The body stays at its pose.
    Static,
    /// `pose(t) = pose + t·(velocity, angular)`.
    Linear {
        /// The translation velocity (default `[0, 0]`).
        #[serde(default)]
        velocity: [f64; 2],
        /// The angular velocity in radians per time unit (default `0`).
        #[serde(default)]
        angular: f64,
    },
    /// Poses at given times, linearly interpolated (position and angle); held before the first
    /// and after the last key.
    Keyframes {
        /// The keys, in strictly increasing time.
        keys: Vec<KeyframeSpec>,
    },
}

/// One keyframe.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct KeyframeSpec {
    /// The time of the key.
    pub t: f64,
    /// The origin's x.
    #[serde(default)]
    pub x: f64,
    /// The origin's y.
    #[serde(default)]
    pub y: f64,
    /// The angle in radians (interpolated as a number: no wrap-around).
    #[serde(default)]
    pub angle: f64,
}

/// One query: which pairs, which effects, and the `first_contact` parameters.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct QuerySpec {
    /// A name for messages and reports (default `query #k`, 1-based).
    #[serde(default)]
    pub name: Option<String>,
    /// `"all"` or a list of `[id, id]` pairs.
    pub pairs: PairsSpec,
    /// The effects to compute for each pair.
    pub effects: Vec<Effect>,
    /// `first_contact`: the largest width of the bracket `[t_safe, t_hit]`, in time units
    /// (default [`DEFAULT_RELATIVE_TOLERANCE`](crate::DEFAULT_RELATIVE_TOLERANCE) times the span).
    #[serde(default)]
    pub tolerance: Option<f64>,
    /// `first_contact`: the most conservative-advancement steps per pair (default
    /// [`DEFAULT_MAX_STEPS`](crate::DEFAULT_MAX_STEPS)).
    #[serde(default)]
    pub max_steps: Option<u64>,
    /// Per-frame effects only for pairs at distance at most `within` (decided exactly); farther
    /// pair-frames are left out of the report (counted), and the broad phase answers most of them
    /// from bounding boxes without a narrow-phase query. With `pairs = "all"` (and no
    /// `first_contact`) the query is streamed: its pairs are never materialized, each frame takes
    /// its candidates from the broad phase. Default: every pair (no threshold). Must be `≥ 0`.
    #[serde(default)]
    pub within: Option<f64>,
}

/// Which pairs a query covers.
#[derive(Clone, Debug, Serialize, PartialEq, Eq)]
#[serde(untagged)]
pub enum PairsSpec {
    /// Every unordered pair of distinct bodies (written `"all"`).
    #[serde(serialize_with = "serialize_all")]
    All,
    /// The listed pairs of ids.
    List(Vec<[String; 2]>),
}

fn serialize_all<S: serde::Serializer>(s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str("all")
}

impl<'de> Deserialize<'de> for PairsSpec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = PairsSpec;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(r#""all" or a list of pairs of body ids like [["a", "b"]]"#)
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<PairsSpec, E> {
                if v == "all" {
                    Ok(PairsSpec::All)
                } else {
                    Err(E::invalid_value(de::Unexpected::Str(v), &self))
                }
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<PairsSpec, A::Error> {
                let mut pairs = Vec::new();
                while let Some(pair) = seq.next_element::<[String; 2]>()? {
                    pairs.push(pair);
                }
                Ok(PairsSpec::List(pairs))
            }
        }
        d.deserialize_any(V)
    }
}

/// An effect a query asks for: all seven of the issue, every one available. `separation` takes simple
/// (and convex) bodies; the others need convex bodies.
#[derive(Clone, Copy, Debug, Deserialize, Serialize, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[serde(rename_all = "snake_case")]
pub enum Effect {
    /// The distance per frame (convex pairs).
    Distance,
    /// The closest points and features per frame (convex pairs; shares its query with `distance`).
    ClosestPoints,
    /// The minimum vertex distance per frame (convex pairs, McKenna–Toussaint).
    VertexDistance,
    /// Directed and symmetric Hausdorff distances of the filled bodies (convex bodies).
    Hausdorff,
    /// The CMMR distance of the filled bodies (convex bodies).
    Cmmr,
    /// The separation σ of two simple polygons per frame (Amato 1992): the distance between their
    /// boundaries with a realizing pair, or that they meet. Takes simple and convex bodies with area.
    Separation,
    /// The time of first contact over the span, by conservative advancement (convex pairs).
    FirstContact,
}

impl Effect {
    /// Every effect, in report order.
    pub const ALL: [Effect; 7] = [
        Effect::Distance,
        Effect::ClosestPoints,
        Effect::VertexDistance,
        Effect::Hausdorff,
        Effect::Cmmr,
        Effect::Separation,
        Effect::FirstContact,
    ];

    /// The name used in files and reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Effect::Distance => "distance",
            Effect::ClosestPoints => "closest_points",
            Effect::VertexDistance => "vertex_distance",
            Effect::Hausdorff => "hausdorff",
            Effect::Cmmr => "cmmr",
            Effect::Separation => "separation",
            Effect::FirstContact => "first_contact",
        }
    }

    /// Whether this build of the runner computes the effect (all of them since `separation` arrived;
    /// kept so that a future effect can be parsed before its algorithm lands).
    #[must_use]
    pub fn is_available(self) -> bool {
        true
    }

    /// Whether the effect needs two convex bodies (every effect but `separation`).
    #[must_use]
    pub fn needs_convex(self) -> bool {
        !matches!(self, Effect::Separation)
    }

    fn bit(self) -> u8 {
        1 << (self as u8)
    }
}

/// A set of effects.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct EffectSet(u8);

impl EffectSet {
    /// The empty set.
    pub const EMPTY: EffectSet = EffectSet(0);

    /// Adds `e`.
    pub fn insert(&mut self, e: Effect) {
        self.0 |= e.bit();
    }

    /// Whether `e` is in the set.
    #[must_use]
    pub fn contains(self, e: Effect) -> bool {
        self.0 & e.bit() != 0
    }

    /// Whether the set is empty.
    #[must_use]
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The union.
    #[must_use]
    pub fn union(self, other: EffectSet) -> EffectSet {
        EffectSet(self.0 | other.0)
    }

    /// Whether the set has an effect computed per frame (`distance`, `closest_points`,
    /// `vertex_distance`, `hausdorff`, `cmmr`, `separation`).
    #[must_use]
    pub fn has_per_frame(self) -> bool {
        [
            Effect::Distance,
            Effect::ClosestPoints,
            Effect::VertexDistance,
            Effect::Hausdorff,
            Effect::Cmmr,
            Effect::Separation,
        ]
        .into_iter()
        .any(|e| self.contains(e))
    }

    /// The effects in report order.
    pub fn iter(self) -> impl Iterator<Item = Effect> {
        Effect::ALL.into_iter().filter(move |&e| self.contains(e))
    }
}

impl FromIterator<Effect> for EffectSet {
    fn from_iter<I: IntoIterator<Item = Effect>>(iter: I) -> Self {
        let mut s = EffectSet::EMPTY;
        for e in iter {
            s.insert(e);
        }
        s
    }
}
