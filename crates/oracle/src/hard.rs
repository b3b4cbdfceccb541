//! The exact answers stored with a case of the hard-case suite (`fixtures/hard/*.txt`, written by
//! the `gen_hard` example), parsed back: shared by the suite's test and the accuracy report.

use core::str::FromStr;

use num_rational::BigRational;

use crate::cmmr_bound::CmmrEnclosure;
use crate::distance::Feature;

/// The answers of one convex case (see `examples/gen_hard.rs` for their meaning).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HardAnswers {
    /// `disjoint`, `touching` or `overlapping` (relative interiors of the filled polygons).
    pub contact: String,
    /// The exact squared distance of the filled polygons (0 when they meet).
    pub dist: BigRational,
    /// Every optimal feature pair `(of P, of Q)`.
    pub pairs: Vec<(Feature, Feature)>,
    /// The exact squared minimum vertex distance.
    pub vdist: BigRational,
    /// Every optimal vertex pair (caller indices).
    pub vpairs: Vec<(usize, usize)>,
    /// `h(P, Q)²` of the filled polygons.
    pub hpq: BigRational,
    /// Every vertex of `P` attaining it.
    pub apq: Vec<usize>,
    /// `h(Q, P)²`.
    pub hqp: BigRational,
    /// Every vertex of `Q` attaining it.
    pub aqp: Vec<usize>,
    /// The exact CMMR value; `None` for the large cases (`fixtures/hard/large_convex.txt`), where
    /// an exact sum of 10⁵ rationals with distinct denominators is out of reach.
    pub cmmr: Option<BigRational>,
    /// For the large cases, a certified enclosure of the CMMR value (`cmmr_enclosure LO HI`, from
    /// [`crate::cmmr_enclosure`]); `None` where the exact value is stored.
    pub cmmr_enclosure: Option<CmmrEnclosure>,
}

/// The answers of one simple-polygon case (`fixtures/hard/simple.txt`): the contact status of the
/// closed polygons and their exact squared boundary distance with every optimal pair.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SimpleHardAnswers {
    /// `disjoint`, `touching` or `overlapping`.
    pub contact: String,
    /// The exact squared distance between the boundaries.
    pub dist: BigRational,
    /// Every optimal feature pair `(of P, of Q)`.
    pub pairs: Vec<(Feature, Feature)>,
}

impl SimpleHardAnswers {
    /// Parses the answer lines of a simple case.
    ///
    /// # Errors
    /// A message naming the keyword that is missing or malformed.
    pub fn from_words(answers: &[(String, Vec<String>)]) -> Result<SimpleHardAnswers, String> {
        let words = Words(answers);
        Ok(SimpleHardAnswers {
            contact: words.get("contact")?[0].clone(),
            dist: words.rational("dist")?,
            pairs: words.feature_pairs("dist")?,
        })
    }
}

/// The answer lines of a case, looked up by keyword.
struct Words<'a>(&'a [(String, Vec<String>)]);

impl Words<'_> {
    fn get(&self, k: &str) -> Result<&[String], String> {
        self.0
            .iter()
            .find(|(key, _)| key == k)
            .map(|(_, w)| w.as_slice())
            .filter(|w| !w.is_empty())
            .ok_or_else(|| format!("missing `{k}`"))
    }

    fn rational(&self, k: &str) -> Result<BigRational, String> {
        BigRational::from_str(&self.get(k)?[0]).map_err(|_| format!("bad rational in `{k}`"))
    }

    /// The words after the first of line `k`, as `V3:E1` feature pairs.
    fn feature_pairs(&self, k: &str) -> Result<Vec<(Feature, Feature)>, String> {
        let feature = |w: &str| -> Result<Feature, String> {
            let i = w.get(1..).and_then(|s| s.parse().ok());
            match (w.as_bytes().first(), i) {
                (Some(b'V'), Some(i)) => Ok(Feature::Vertex(i)),
                (Some(b'E'), Some(i)) => Ok(Feature::Edge(i)),
                _ => Err(format!("bad feature `{w}`")),
            }
        };
        self.get(k)?[1..]
            .iter()
            .map(|w| {
                let (a, b) = w.split_once(':').ok_or_else(|| format!("bad pair `{w}`"))?;
                Ok((feature(a)?, feature(b)?))
            })
            .collect()
    }
}

impl HardAnswers {
    /// Parses the answer lines of a case (keyword and words, as the fixtures loader gives them).
    ///
    /// # Errors
    /// A message naming the keyword that is missing or malformed.
    pub fn from_words(answers: &[(String, Vec<String>)]) -> Result<HardAnswers, String> {
        let words = Words(answers);
        let index = |w: &str| w.parse::<usize>().map_err(|_| format!("bad index `{w}`"));
        let indices = |k: &str| -> Result<Vec<usize>, String> {
            words.get(k)?[1..].iter().map(|w| index(w)).collect()
        };
        Ok(HardAnswers {
            contact: words.get("contact")?[0].clone(),
            dist: words.rational("dist")?,
            pairs: words.feature_pairs("dist")?,
            vdist: words.rational("vdist")?,
            vpairs: words.get("vdist")?[1..]
                .iter()
                .map(|w| {
                    let (a, b) = w.split_once(':').ok_or_else(|| format!("bad pair `{w}`"))?;
                    Ok((index(a)?, index(b)?))
                })
                .collect::<Result<_, String>>()?,
            hpq: words.rational("hpq")?,
            apq: indices("hpq")?,
            hqp: words.rational("hqp")?,
            aqp: indices("hqp")?,
            cmmr: match words.get("cmmr") {
                Ok(_) => Some(words.rational("cmmr")?),
                Err(_) => None,
            },
            cmmr_enclosure: match words.get("cmmr_enclosure") {
                Ok(w) => {
                    let bound = |i: usize| {
                        w.get(i)
                            .and_then(|x| BigRational::from_str(x).ok())
                            .ok_or_else(|| "bad rational in `cmmr_enclosure`".to_owned())
                    };
                    let (lo, hi) = (bound(0)?, bound(1)?);
                    if lo > hi {
                        return Err("`cmmr_enclosure`: LO > HI".to_owned());
                    }
                    Some(CmmrEnclosure { lo, hi })
                }
                Err(_) => None,
            },
        })
    }

    /// What is known of the exact CMMR: the stored exact value as the interval `[c, c]`, or the
    /// stored certified enclosure; `None` if neither is stored. Check a computed value `x` with
    /// [`CmmrEnclosure::ulps_error`], which bounds its error against every point of the interval.
    #[must_use]
    pub fn cmmr_bounds(&self) -> Option<CmmrEnclosure> {
        match (&self.cmmr, &self.cmmr_enclosure) {
            (Some(c), _) => Some(CmmrEnclosure {
                lo: c.clone(),
                hi: c.clone(),
            }),
            (None, e) => e.clone(),
        }
    }
}
