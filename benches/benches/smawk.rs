//! Row minima of implicit n × n totally monotone matrices: `monotone-minima` against the `smawk`
//! crate (0.3.3), an O(n log n) divide-and-conquer baseline and (small n only) a naive O(n²) scan.
//!
//! Matrices (entries computed on demand, never stored):
//! - D1: `(x_i - y_j)²` with `x`, `y` sorted uniform random in `[0, 1)`.
//! - D2: Euclidean distances (`sqrt(dx² + dy²)`) between points on two disjoint arcs of one
//!   circle, the second arc traversed backwards.
//!
//! Series: `monotone-minima-f64` (`row_minima_f64`, NaN-checked), `monotone-minima-by`
//! (`row_minima_by` with the IEEE order, unchecked like the peer), `smawk-0.3.3`,
//! `divide-and-conquer` and, up to n = 10^4, `naive`.
//!
//! Run with `cargo bench -p polydist-benches --bench smawk`.

use std::cmp::Ordering;
use std::f64::consts::PI;
use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, SamplingMode};

/// splitmix64: a deterministic stream of uniform `f64` in `[0, 1)`.
struct SplitMix(u64);

impl SplitMix {
    fn next_f64(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1_u64 << 53) as f64
    }

    fn sorted(&mut self, n: usize) -> Vec<f64> {
        let mut v: Vec<f64> = (0..n).map(|_| self.next_f64()).collect();
        v.sort_by(f64::total_cmp);
        v
    }
}

/// D1: `(x_i - y_j)²`.
struct SquaredGaps {
    x: Vec<f64>,
    y: Vec<f64>,
}

impl SquaredGaps {
    fn new(n: usize, seed: u64) -> Self {
        let mut rng = SplitMix(seed);
        Self {
            x: rng.sorted(n),
            y: rng.sorted(n),
        }
    }

    #[inline]
    fn at(&self, i: usize, j: usize) -> f64 {
        let d = self.x[i] - self.y[j];
        d * d
    }
}

/// D2: distances from `p_i` on the arc of angles `[0, 0.9π]` (increasing) to `q_j` on the arc
/// `[π, 1.9π]` (decreasing).
struct ArcDistances {
    p: Vec<(f64, f64)>,
    q: Vec<(f64, f64)>,
}

impl ArcDistances {
    fn new(n: usize, seed: u64) -> Self {
        let mut rng = SplitMix(seed);
        let p = rng
            .sorted(n)
            .into_iter()
            .map(|t| (0.9 * PI * t).sin_cos())
            .collect();
        let q = rng
            .sorted(n)
            .into_iter()
            .rev()
            .map(|t| (PI + 0.9 * PI * t).sin_cos())
            .collect();
        Self { p, q }
    }

    #[inline]
    fn at(&self, i: usize, j: usize) -> f64 {
        let (a, b) = (self.p[i], self.q[j]);
        ((a.0 - b.0) * (a.0 - b.0) + (a.1 - b.1) * (a.1 - b.1)).sqrt()
    }
}

/// A benchmark matrix: its size and entries.
trait Implicit {
    fn size(&self) -> usize;
    fn at(&self, i: usize, j: usize) -> f64;
}

impl Implicit for SquaredGaps {
    fn size(&self) -> usize {
        self.x.len()
    }

    #[inline]
    fn at(&self, i: usize, j: usize) -> f64 {
        Self::at(self, i, j)
    }
}

impl Implicit for ArcDistances {
    fn size(&self) -> usize {
        self.p.len()
    }

    #[inline]
    fn at(&self, i: usize, j: usize) -> f64 {
        Self::at(self, i, j)
    }
}

/// The peer crate's view of a benchmark matrix.
struct Peer<'a, M>(&'a M);

impl<M: Implicit> smawk::Matrix<f64> for Peer<'_, M> {
    fn nrows(&self) -> usize {
        self.0.size()
    }

    fn ncols(&self) -> usize {
        self.0.size()
    }

    #[inline]
    fn index(&self, row: usize, column: usize) -> f64 {
        self.0.at(row, column)
    }
}

/// `row_minima_f64`: IEEE order, NaN checked on every lookup, every minimum looked up.
fn ours_f64<M: Implicit>(m: &M) -> Vec<usize> {
    let n = m.size();
    monotone_minima::row_minima_f64(&monotone_minima::from_fn(n, n, |i, j| m.at(i, j)))
        .expect("benchmark matrices have no NaN")
}

/// IEEE order for NaN-free data, as a total order.
fn ieee(a: &f64, b: &f64) -> Ordering {
    if a < b {
        Ordering::Less
    } else if a > b {
        Ordering::Greater
    } else {
        Ordering::Equal
    }
}

/// `row_minima_by` with the IEEE order: no NaN check, like the `smawk` crate's `PartialOrd`.
fn ours_by<M: Implicit>(m: &M) -> Vec<usize> {
    let n = m.size();
    monotone_minima::row_minima_by(&monotone_minima::from_fn(n, n, |i, j| m.at(i, j)), ieee)
}

fn peer<M: Implicit>(m: &M) -> Vec<usize> {
    smawk::row_minima(&Peer(m))
}

/// Baseline: the middle row's leftmost minimum by a scan, then both halves recursively within
/// the columns it leaves them; O(n log n) lookups.
fn divide_and_conquer<M: Implicit>(m: &M) -> Vec<usize> {
    fn recurse<M: Implicit>(
        m: &M,
        rows: (usize, usize),
        columns: (usize, usize),
        out: &mut [usize],
    ) {
        let (top, bottom) = rows;
        if top >= bottom {
            return;
        }
        let mid = top + (bottom - top) / 2;
        let (left, right) = columns;
        let (mut best, mut best_value) = (left, m.at(mid, left));
        for j in left + 1..=right {
            let value = m.at(mid, j);
            if value < best_value {
                (best, best_value) = (j, value);
            }
        }
        out[mid] = best;
        recurse(m, (top, mid), (left, best), out);
        recurse(m, (mid + 1, bottom), (best, right), out);
    }
    let n = m.size();
    let mut out = vec![0; n];
    if n > 0 {
        recurse(m, (0, n), (0, n - 1), &mut out);
    }
    out
}

/// Baseline: every entry; O(n²) lookups.
fn naive<M: Implicit>(m: &M) -> Vec<usize> {
    let n = m.size();
    (0..n)
        .map(|i| {
            let (mut best, mut best_value) = (0, m.at(i, 0));
            for j in 1..n {
                let value = m.at(i, j);
                if value < best_value {
                    (best, best_value) = (j, value);
                }
            }
            best
        })
        .collect()
}

const SIZES: [usize; 4] = [1_000, 10_000, 100_000, 1_000_000];
/// The naive scan only runs up to this size.
const NAIVE_MAX: usize = 10_000;

fn bench_family<M: Implicit>(c: &mut Criterion, name: &str, make: impl Fn(usize) -> M) {
    let mut group = c.benchmark_group(name);
    group
        .sample_size(10)
        .sampling_mode(SamplingMode::Flat)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(2));
    for n in SIZES {
        let m = make(n);
        // All implementations must agree (ties are measure-zero with random reals).
        let expected = divide_and_conquer(&m);
        assert_eq!(
            ours_f64(&m),
            expected,
            "monotone-minima (f64) disagrees at n = {n}"
        );
        assert_eq!(
            ours_by(&m),
            expected,
            "monotone-minima (by) disagrees at n = {n}"
        );
        assert_eq!(peer(&m), expected, "smawk disagrees at n = {n}");
        group.bench_with_input(BenchmarkId::new("monotone-minima-f64", n), &m, |b, m| {
            b.iter(|| ours_f64(black_box(m)))
        });
        group.bench_with_input(BenchmarkId::new("monotone-minima-by", n), &m, |b, m| {
            b.iter(|| ours_by(black_box(m)))
        });
        group.bench_with_input(BenchmarkId::new("smawk-0.3.3", n), &m, |b, m| {
            b.iter(|| peer(black_box(m)))
        });
        group.bench_with_input(BenchmarkId::new("divide-and-conquer", n), &m, |b, m| {
            b.iter(|| divide_and_conquer(black_box(m)))
        });
        if n <= NAIVE_MAX {
            assert_eq!(naive(&m), expected, "naive disagrees at n = {n}");
            group.bench_with_input(BenchmarkId::new("naive", n), &m, |b, m| {
                b.iter(|| naive(black_box(m)))
            });
        }
    }
    group.finish();
}

fn d1_squared_gaps(c: &mut Criterion) {
    bench_family(c, "smawk/D1-squared-gaps", |n| SquaredGaps::new(n, 1));
}

fn d2_arc_distances(c: &mut Criterion) {
    bench_family(c, "smawk/D2-arc-distances", |n| ArcDistances::new(n, 2));
}

// What `criterion_group!` and `criterion_main!` expand to, minus the undocumented `pub fn`.
fn main() {
    let mut c = Criterion::default().configure_from_args();
    d1_squared_gaps(&mut c);
    d2_arc_distances(&mut c);
    c.final_summary();
}
