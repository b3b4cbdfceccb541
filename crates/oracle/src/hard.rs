//! The exact answers stored with a case of the hard-case suite (`fixtures/hard/*.txt`, written by
//! the `gen_hard` example), parsed back: shared by the suite's test and the accuracy report.

use core::str::FromStr;

use num_rational::BigRational;

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
    /// The exact CMMR value.
    pub cmmr: BigRational,
}

impl HardAnswers {
    /// Parses the answer lines of a case (keyword and words, as the fixtures loader gives them).
    ///
    /// # Errors
    /// A message naming the keyword that is missing or malformed.
    pub fn from_words(answers: &[(String, Vec<String>)]) -> Result<HardAnswers, String> {
        let get = |k: &str| -> Result<&[String], String> {
            answers
                .iter()
                .find(|(key, _)| key == k)
                .map(|(_, w)| w.as_slice())
                .filter(|w| !w.is_empty())
                .ok_or_else(|| format!("missing `{k}`"))
        };
        let rat = |k: &str| -> Result<BigRational, String> {
            BigRational::from_str(&get(k)?[0]).map_err(|_| format!("bad rational in `{k}`"))
        };
        let feature = |w: &str| -> Result<Feature, String> {
            let i = w.get(1..).and_then(|s| s.parse().ok());
            match (w.as_bytes().first(), i) {
                (Some(b'V'), Some(i)) => Ok(Feature::Vertex(i)),
                (Some(b'E'), Some(i)) => Ok(Feature::Edge(i)),
                _ => Err(format!("bad feature `{w}`")),
            }
        };
        let index = |w: &str| w.parse::<usize>().map_err(|_| format!("bad index `{w}`"));
        let indices = |k: &str| -> Result<Vec<usize>, String> {
            get(k)?[1..].iter().map(|w| index(w)).collect()
        };
        fn split(w: &str) -> Result<(&str, &str), String> {
            w.split_once(':').ok_or_else(|| format!("bad pair `{w}`"))
        }
        Ok(HardAnswers {
            contact: get("contact")?[0].clone(),
            dist: rat("dist")?,
            pairs: get("dist")?[1..]
                .iter()
                .map(|w| {
                    let (a, b) = split(w)?;
                    Ok((feature(a)?, feature(b)?))
                })
                .collect::<Result<_, String>>()?,
            vdist: rat("vdist")?,
            vpairs: get("vdist")?[1..]
                .iter()
                .map(|w| {
                    let (a, b) = split(w)?;
                    Ok((index(a)?, index(b)?))
                })
                .collect::<Result<_, String>>()?,
            hpq: rat("hpq")?,
            apq: indices("hpq")?,
            hqp: rat("hqp")?,
            aqp: indices("hqp")?,
            cmmr: rat("cmmr")?,
        })
    }
}
