//! The lexicographic order of a point set by radix sort: the sweep order of the simplicity sweep
//! here and of the triangulation sweep of `polydist-separation`.
//!
//! A finite `f64` maps to a `u64` whose unsigned order is the numeric order (set the sign bit of a
//! nonnegative value, flip every bit of a negative one), with `−0` first turned into `+0` so that
//! the two zeros, equal as coordinates, get one key. So the order is decided on the input's bits,
//! exactly, and a least-significant-digit radix sort of the keys (11-bit digits, six passes, a pass
//! skipped when every key has the same digit there) replaces the comparison sort's `n log n`
//! comparisons by `O(n)` word operations.

use glam::DVec2;

/// Below this many points a comparison sort of the keys is cheaper than the radix passes (whose
/// six 2,048-entry histograms cost about as much as sorting a few hundred keys).
const SMALL: usize = 256;

/// At most this many keys are sorted by insertion (a library sort's call costs more for them).
const TINY: usize = 12;

/// A key and the index of its point (16 bytes, as a `u32` index would be with its padding).
type Keyed = (u64, usize);

/// Digit width of the radix passes.
const BITS: u32 = 11;
/// Digits in a 64-bit key (the last has 9 bits).
const DIGITS: usize = 64_usize.div_ceil(BITS as usize);
/// Buckets a pass.
const RADIX: usize = 1 << BITS;

/// The key of a coordinate: unsigned order = numeric order for finite values, `−0` and `+0` one key.
/// (A NaN gets some key: the order stays total, it is merely not numeric there.)
#[inline]
fn key(v: f64) -> u64 {
    let b = (v + 0.0).to_bits();
    if b >> 63 == 1 { !b } else { b | 1 << 63 }
}

/// The indices `0..points.len()` sorted by the lexicographic order of their points (by `x`, then by
/// `y`, with `−0 = +0`), points that are equal by index: the order `lex_cmp(p[i], p[j])
/// .then(i.cmp(&j))` of a comparison sort, so equal points end up next to each other, the smaller
/// index first.
///
/// # Complexity
/// `O(n)` time and space: a radix sort by `x`; then each run of `r` points with one `x` sorted by
/// `y`, by the same radix sort when `r ≥ 256`, by a comparison sort of `r` keys otherwise
/// (`O(r log r)` with `r < 256`).
#[must_use]
pub fn lex_order(points: &[DVec2]) -> Vec<usize> {
    let n = points.len();
    let mut keys: Vec<Keyed> = points
        .iter()
        .enumerate()
        .map(|(i, p)| (key(p.x), i))
        .collect();
    let mut scratch = vec![(0u64, 0usize); n];
    sort_keys(&mut keys, &mut scratch);
    // Runs of one `x`: sorted by `y` (the index breaks ties in both sorts: each is stable or keyed
    // by it).
    let mut start = 0;
    while start < n {
        let x = keys[start].0;
        let mut end = start + 1;
        while end < n && keys[end].0 == x {
            end += 1;
        }
        if end - start > 1 {
            let run = &mut keys[start..end];
            for k in run.iter_mut() {
                k.0 = key(points[k.1].y);
            }
            sort_keys(run, &mut scratch[start..end]);
        }
        start = end;
    }
    keys.into_iter().map(|(_, i)| i).collect()
}

/// Sorts `keys` by `(key, index)`, given that the indices are distinct and increasing (so a stable
/// sort by key is that order): the radix passes, or a comparison sort below [`SMALL`].
/// `scratch.len() == keys.len()`.
fn sort_keys(keys: &mut [Keyed], scratch: &mut [Keyed]) {
    let n = keys.len();
    if n <= TINY {
        // Insertion sort, stable by key: the increasing indices break ties. (Runs of one `x` are
        // mostly 2 to 4 points, the sides of combs' teeth and of axis-parallel polygons.)
        for i in 1..n {
            let e = keys[i];
            let mut j = i;
            while j > 0 && keys[j - 1].0 > e.0 {
                keys[j] = keys[j - 1];
                j -= 1;
            }
            keys[j] = e;
        }
        return;
    }
    if n < SMALL {
        keys.sort_unstable();
        return;
    }
    radix_sort(keys, scratch);
}

/// The radix passes of [`sort_keys`], apart: their 96 KB of histograms on the stack would make
/// every call probe that much stack, the short runs' calls too.
#[inline(never)]
fn radix_sort(keys: &mut [Keyed], scratch: &mut [Keyed]) {
    let n = keys.len();
    let mut counts = [[0usize; RADIX]; DIGITS];
    let digit = |k: u64, d: usize| ((k >> (BITS as usize * d)) as usize) & (RADIX - 1);
    for &(k, _) in keys.iter() {
        for (d, c) in counts.iter_mut().enumerate() {
            c[digit(k, d)] += 1;
        }
    }
    // The data alternates between the two buffers; `in_keys` says where it is now.
    let mut in_keys = true;
    for (d, c) in counts.iter_mut().enumerate() {
        if c.contains(&n) {
            continue;
        }
        let mut sum = 0;
        for slot in c.iter_mut() {
            let here = *slot;
            *slot = sum;
            sum += here;
        }
        let (from, to): (&[Keyed], &mut [Keyed]) = if in_keys {
            (keys, scratch)
        } else {
            (scratch, keys)
        };
        for &e in from {
            let slot = &mut c[digit(e.0, d)];
            to[*slot] = e;
            *slot += 1;
        }
        in_keys = !in_keys;
    }
    if !in_keys {
        keys.copy_from_slice(scratch);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ring::lex_cmp;
    use proptest::prelude::*;

    /// The comparison sort the radix sort replaces.
    fn reference(points: &[DVec2]) -> Vec<usize> {
        let mut order: Vec<usize> = (0..points.len()).collect();
        order.sort_by(|&i, &j| lex_cmp(points[i], points[j]).then(i.cmp(&j)));
        order
    }

    /// Coordinates drawn from a few values, so that runs of one `x` and repeated points are common,
    /// with both zeros, subnormals, negative values and extremes among them.
    fn coordinate() -> impl Strategy<Value = f64> {
        prop_oneof![
            prop::sample::select(vec![
                0.0,
                -0.0,
                1.0,
                -1.0,
                0.5,
                f64::MIN_POSITIVE,
                -f64::MIN_POSITIVE,
                5e-324,
                -5e-324,
                1e300,
                -1e300,
                3.0,
            ]),
            -1e12..1e12f64,
            (-4i32..4).prop_map(f64::from),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        #[test]
        fn radix_order_is_the_comparison_order(
            pts in prop::collection::vec((coordinate(), coordinate()), 0..1200),
        ) {
            let points: Vec<DVec2> = pts.into_iter().map(|(x, y)| DVec2::new(x, y)).collect();
            prop_assert_eq!(lex_order(&points), reference(&points));
        }

        /// Few points: runs of one `x` short enough for the insertion sort, repeated points among them.
        #[test]
        fn short_runs_order_like_the_comparison_order(
            pts in prop::collection::vec((coordinate(), coordinate()), 0..40),
        ) {
            let points: Vec<DVec2> = pts.into_iter().map(|(x, y)| DVec2::new(x, y)).collect();
            prop_assert_eq!(lex_order(&points), reference(&points));
        }
    }

    #[test]
    fn keys_order_like_the_numbers() {
        let values = [
            -1e308,
            -2.5,
            -f64::MIN_POSITIVE,
            -5e-324,
            0.0,
            5e-324,
            f64::MIN_POSITIVE,
            1.0,
            1e308,
        ];
        for w in values.windows(2) {
            assert!(key(w[0]) < key(w[1]), "{} {}", w[0], w[1]);
        }
        assert_eq!(key(-0.0), key(0.0));
    }

    #[test]
    fn long_runs_of_one_x_use_the_radix_sort_too() {
        // 3 columns of 400 points, y descending, some repeated: every run is sorted by radix.
        let points: Vec<DVec2> = (0..1200)
            .map(|k| DVec2::new(f64::from(k % 3) - 1.0, -f64::from(k / 7)))
            .collect();
        assert_eq!(lex_order(&points), reference(&points));
    }
}
