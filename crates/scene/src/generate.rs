//! Small deterministic shape generators for scene files: regular `n`-gon, star, comb, random convex.
//!
//! Every generator checks its parameters (counts against [`MAX_VERTICES`] before allocating) and is
//! deterministic: the same parameters give the same `f64` vertices on every machine (`sin`/`cos` of
//! the platform's libm aside, which differs by at most an ulp between platforms).

use core::f64::consts::TAU;

use glam::DVec2;

use crate::spec::GeneratorSpec;

/// The most vertices a body may have (inline, from a file or generated): `2^20`.
pub const MAX_VERTICES: u64 = 1 << 20;

/// Why a generator refused its parameters.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum GenError {
    /// More than [`MAX_VERTICES`].
    TooMany(u64),
    /// A parameter out of range.
    Bad(String),
}

/// The generator's type name, as written in files.
pub(crate) fn generator_name(g: &GeneratorSpec) -> &'static str {
    match g {
        GeneratorSpec::Regular { .. } => "regular",
        GeneratorSpec::Star { .. } => "star",
        GeneratorSpec::Comb { .. } => "comb",
        GeneratorSpec::RandomConvex { .. } => "random_convex",
    }
}

fn positive(name: &str, x: f64) -> Result<(), GenError> {
    if x.is_finite() && x > 0.0 {
        Ok(())
    } else {
        Err(GenError::Bad(format!(
            "{name} must be finite and > 0 (got {x})"
        )))
    }
}

fn count(name: &str, n: u64, min: u64, per: u64) -> Result<usize, GenError> {
    if n < min {
        return Err(GenError::Bad(format!(
            "{name} must be at least {min} (got {n})"
        )));
    }
    let total = n.saturating_mul(per);
    if total > MAX_VERTICES {
        return Err(GenError::TooMany(total));
    }
    usize::try_from(total).map_err(|_| GenError::TooMany(total))
}

/// The point at angle `a` on the circle of radius `r` about the origin.
fn polar(r: f64, a: f64) -> DVec2 {
    let (s, c) = a.sin_cos();
    DVec2::new(r * c, r * s)
}

/// The vertices of the generated shape, counter-clockwise, centred on the origin.
///
/// # Complexity
/// `O(n)` for `n` vertices (`O(n log n)` for `random_convex`, which sorts its angles).
pub(crate) fn generate(g: &GeneratorSpec) -> Result<Vec<DVec2>, GenError> {
    match *g {
        GeneratorSpec::Regular { n, radius } => {
            let k = count("n", n, 3, 1)?;
            positive("radius", radius)?;
            // Vertex i at angle 2πi/n: the same formula for every i, no accumulated error.
            Ok((0..k)
                .map(|i| polar(radius, TAU * (i as f64) / (k as f64)))
                .collect())
        }
        GeneratorSpec::Star {
            points,
            outer,
            inner,
        } => {
            let k = count("points", points, 3, 2)?;
            positive("outer", outer)?;
            positive("inner", inner)?;
            if inner >= outer {
                return Err(GenError::Bad(format!(
                    "inner ({inner}) must be smaller than outer ({outer})"
                )));
            }
            Ok((0..k)
                .map(|i| {
                    let r = if i % 2 == 0 { outer } else { inner };
                    polar(r, TAU * (i as f64) / (k as f64))
                })
                .collect())
        }
        GeneratorSpec::Comb {
            teeth,
            width,
            height,
            spine,
        } => {
            let k = count("teeth", teeth, 1, 4)?;
            positive("width", width)?;
            positive("height", height)?;
            positive("spine", spine)?;
            let teeth = k / 4;
            // Teeth at x = 2iw .. (2i+1)w; the comb spans [0, (2·teeth − 1)·w] × [0, spine + height],
            // centred on the origin.
            let total_w = (2.0 * teeth as f64 - 1.0) * width;
            let (cx, cy) = (total_w / 2.0, (spine + height) / 2.0);
            let mut v = Vec::with_capacity(k);
            v.push(DVec2::new(0.0 - cx, 0.0 - cy));
            v.push(DVec2::new(total_w - cx, 0.0 - cy));
            // Up the right side, then the teeth from right to left.
            for i in (0..teeth).rev() {
                let left = 2.0 * i as f64 * width;
                let right = left + width;
                v.push(DVec2::new(right - cx, spine + height - cy));
                v.push(DVec2::new(left - cx, spine + height - cy));
                if i > 0 {
                    v.push(DVec2::new(left - cx, spine - cy));
                    v.push(DVec2::new(left - width - cx, spine - cy));
                }
            }
            Ok(v)
        }
        GeneratorSpec::RandomConvex { n, radius, seed } => {
            let k = count("n", n, 3, 1)?;
            positive("radius", radius)?;
            let mut rng = SplitMix64(seed);
            let mut angles: Vec<f64> = (0..k).map(|_| rng.unit() * TAU).collect();
            angles.sort_by(f64::total_cmp);
            angles.dedup();
            Ok(angles.into_iter().map(|a| polar(radius, a)).collect())
        }
    }
}

/// SplitMix64 (Steele, Lea, Flood 2014): a tiny seeded generator, identical on every platform.
struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)` with 53 random bits.
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use polydist_polygon::{ConvexPolygon, SimplePolygon};

    #[test]
    fn regular_is_convex_with_n_vertices() {
        for n in 3..40 {
            let v = generate(&GeneratorSpec::Regular { n, radius: 2.5 }).unwrap();
            let p = ConvexPolygon::try_new(&v).unwrap();
            assert_eq!(p.len() as u64, n);
            for x in &v {
                assert!((x.length() - 2.5).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn star_and_comb_are_simple_not_convex() {
        for points in 3..12 {
            let v = generate(&GeneratorSpec::Star {
                points,
                outer: 2.0,
                inner: 0.7,
            })
            .unwrap();
            assert_eq!(v.len() as u64, 2 * points);
            SimplePolygon::try_new(&v).unwrap();
            assert!(ConvexPolygon::try_new(&v).is_err());
        }
        for teeth in 1..10 {
            let v = generate(&GeneratorSpec::Comb {
                teeth,
                width: 0.5,
                height: 2.0,
                spine: 1.0,
            })
            .unwrap();
            assert_eq!(v.len() as u64, 4 * teeth);
            SimplePolygon::try_new(&v).unwrap();
            // One tooth is a rectangle: convex.
            assert_eq!(ConvexPolygon::try_new(&v).is_ok(), teeth == 1);
        }
    }

    #[test]
    fn random_convex_is_deterministic_and_convex() {
        let g = GeneratorSpec::RandomConvex {
            n: 50,
            radius: 3.0,
            seed: 7,
        };
        let (a, b) = (generate(&g).unwrap(), generate(&g).unwrap());
        assert_eq!(a, b);
        let p = ConvexPolygon::try_new(&a).unwrap();
        assert!(p.len() >= 3);
        let other = generate(&GeneratorSpec::RandomConvex {
            n: 50,
            radius: 3.0,
            seed: 8,
        })
        .unwrap();
        assert_ne!(a, other);
    }

    #[test]
    fn limits_and_bad_parameters_are_refused_without_allocating() {
        let huge = GeneratorSpec::Regular {
            n: 1_000_000_000_000,
            radius: 1.0,
        };
        assert_eq!(generate(&huge), Err(GenError::TooMany(1_000_000_000_000)));
        let star = GeneratorSpec::Star {
            points: u64::MAX,
            outer: 2.0,
            inner: 1.0,
        };
        assert_eq!(generate(&star), Err(GenError::TooMany(u64::MAX)));
        assert!(matches!(
            generate(&GeneratorSpec::Regular { n: 2, radius: 1.0 }),
            Err(GenError::Bad(_))
        ));
        assert!(matches!(
            generate(&GeneratorSpec::Regular {
                n: 5,
                radius: f64::NAN
            }),
            Err(GenError::Bad(_))
        ));
        assert!(matches!(
            generate(&GeneratorSpec::Star {
                points: 5,
                outer: 1.0,
                inner: 1.0
            }),
            Err(GenError::Bad(_))
        ));
    }
}
