//! The extensions of a shortest-path tree in a triangulated simple polygon: for every vertex `v`
//! where shortest paths from a source `s` bend, where the ray from `v`'s parent through `v` first
//! meets the boundary beyond `v` — every arm of Amato's separator (Step B) in one pass, instead of
//! one triangulation walk per arm.
//!
//! The funnel algorithm over the whole dual tree (Guibas, Hershberger, Leven, Sharir & Tarjan,
//! "Linear-time algorithms for visibility and shortest path problems inside triangulated simple
//! polygons", Algorithmica 2, 1987, §3): a depth-first walk from the triangles at `s` carries, for
//! each diagonal crossed, the funnel of shortest paths from `s` to the diagonal's ends (a left chain,
//! the apex, a right chain). The triangle beyond adds its third vertex `w`; the tangent from `w` to the
//! funnel (the vertex where the path to `w` bends, found by an exponential search from both ends of
//! the funnel: the chains' turn tests are monotone) becomes `w`'s parent and splits the funnel into
//! the funnels of the triangle's two other sides. Reconstructed for arms: a chain vertex `c` that is neither the apex nor an end of its
//! funnel has its extension (the ray from its neighbour toward the apex through `c`) inside the
//! funnel; at a split it stays in exactly one child (the tangent is the apex of one child and an
//! interior chain vertex of the other, which holds its extension), so it is an interior chain vertex
//! of exactly one funnel whose side is a ring edge, and that edge is where its ray leaves; when the
//! new vertex `w` lies exactly on the ray (the first chain edge the tangent test rejects is collinear
//! with `w`), the ray ends at `w`.
//!
//! Funnels live in one array, each a contiguous range `[lo, hi]` with its apex at `ap`; a child is
//! its parent's prefix or suffix with `w` written next to it, undone when the child's subtree is
//! done, so a split costs `O(1)` plus the search. The search costs `O(log min(i, k − i) + 1)` for a
//! funnel of `k` positions split at position `i` (`first_true`), the cost Guibas et al. get from
//! finger search trees, whose §3 analysis (the splits as in Hoffman, Mehlhorn, Rosenstiehl & Tarjan's
//! Jordan sorting) bounds the total by `O(n)`. Every decision is an exact orientation (and a dot sign
//! for collinear hits) through the kernel `K`.
//!
//! # Complexity
//! `O(n)` time and predicates (was `O(n log n)` with a plain binary search per triangle: 4.6 → 12.9
//! orientation tests per vertex from 64 to 65,536 vertices on a thin annular sector, now flat; see
//! `tests/geodesic.rs`), `O(n)` memory. The walks it replaces cost the number of triangles each arm
//! crosses, `Θ(n²)` in all in the worst case.

use glam::DVec2;
use polydist_polygon::predicates::{Kernel, Orientation, Sign};

use crate::geodesic::{Hit, enters};
use crate::triangulate::{Neighbor, Triangulation};

/// The shortest-path tree from one source and the extensions of its edges (see [`extensions`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Extensions {
    /// `parent[v]`: the vertex where the shortest path from the source to `v` last bends (the
    /// source for vertices it sees); `None` for the source itself.
    pub parent: Vec<Option<usize>>,
    /// `hit[v]`: where the ray from `parent[v]` through `v` first meets the boundary beyond `v`, for
    /// every vertex where that ray enters the interior; `None` otherwise.
    pub hit: Vec<Option<Hit>>,
}

/// No write before a task (the fan's funnels are written directly).
const NO_PUT: (usize, u32) = (usize::MAX, 0);

#[derive(Clone, Copy, Debug)]
enum Task {
    /// Write vertex `put.1` at position `put.0` (remembering what was there), then cross into
    /// triangle `t` by its side `side` with the funnel `[lo, hi]`, apex at `ap`.
    Visit {
        t: u32,
        side: u8,
        lo: usize,
        hi: usize,
        ap: usize,
        put: (usize, u32),
    },
    /// Write as for `Visit`, then: the funnel `[lo, hi]` (apex `ap`) reached ring edge `k`.
    Leaf {
        k: u32,
        lo: usize,
        hi: usize,
        ap: usize,
        put: (usize, u32),
    },
    /// Restore the last write.
    Undo,
}

/// The shortest-path tree of the triangulated polygon `ring` from ring vertex `s`, with the hit of
/// every tree edge's extension (see the module documentation). For every vertex `v` with
/// `hit[v] = Some(h)`, `h` equals [`first_hit`](crate::first_hit)`(parent[v], v)`, and every vertex
/// whose extension enters the interior gets one.
///
/// # Complexity
/// `O(n)` time and predicates, `O(n)` memory.
///
/// # Panics
/// Panics if `s` is not a vertex index of `ring`, or `tri` was built for another ring size.
#[must_use]
pub fn extensions<K: Kernel>(tri: &Triangulation, ring: &[DVec2], s: usize) -> Extensions {
    let n = ring.len();
    assert!(s < n, "extensions: vertex index out of range");
    assert_eq!(
        tri.vertex_count(),
        n,
        "extensions: triangulation of another ring"
    );
    let triangles = tri.triangles();
    let neighbors = tri.neighbors();
    let mut parent = vec![None; n];
    let mut hit: Vec<Option<Hit>> = vec![None; n];
    // Depth ≤ the number of triangles, and each level reaches one slot beyond its parent's range.
    let mid = n + 4;
    let mut buf = vec![0u32; 2 * n + 8];
    let mut undo: Vec<(usize, u32)> = Vec::with_capacity(n);
    // The pending work: about two tasks per level of the depth-first walk.
    let mut stack: Vec<Task> = Vec::with_capacity(2 * triangles.len().min(1 << 20) + 8);
    // Each triangle is entered once (the dual graph is a tree); the flag keeps every loop finite and
    // every index in range even on a triangulation built from inconsistent (Fast) signs.
    let mut entered = vec![false; triangles.len()];
    let pt = |v: u32| ring[v as usize];
    let orient = |a: u32, b: u32, c: u32| K::orient(pt(a), pt(b), pt(c));
    // `c`'s ray (from `from` through `c`) enters the interior at `c` and passes through `z` beyond.
    let through = |from: u32, c: u32, z: u32| {
        orient(from, c, z) == Orientation::Collinear
            && K::dot_sign(pt(c), pt(z), pt(from), pt(c)) == Sign::Positive
            && enters::<K>(ring, pt(from), c as usize)
    };
    let side_of = |t: usize, x: u32, y: u32| {
        let tr = triangles[t];
        (0..3).find(|&i| tr[i] == x && tr[(i + 1) % 3] == y)
    };

    // The triangles around `s`: rewind clockwise to the one on ring edge s → s + 1, then forward.
    let corner = |t: usize, v: usize| (0..3).find(|&c| triangles[t][c] as usize == v);
    let mut first = tri.triangle_at(s);
    for _ in 0..triangles.len() {
        let Some(c) = corner(first, s) else { break };
        match neighbors[first][c] {
            Neighbor::Triangle(j) => first = j as usize,
            Neighbor::RingEdge(_) => break,
        }
    }
    let mut fan = Vec::new();
    let mut cur = first;
    for _ in 0..triangles.len() {
        let Some(c) = corner(cur, s) else { break };
        fan.push((cur, c));
        match neighbors[cur][(c + 2) % 3] {
            Neighbor::Triangle(j) => cur = j as usize,
            Neighbor::RingEdge(_) => break,
        }
    }

    for (t, c) in fan {
        let tr = triangles[t];
        let (x, y) = (tr[(c + 2) % 3], tr[(c + 1) % 3]);
        parent[x as usize] = Some(s);
        parent[y as usize] = Some(s);
        let (lo, ap, hi) = (mid - 1, mid, mid + 1);
        buf[lo] = x;
        buf[ap] = s as u32;
        buf[hi] = y;
        match neighbors[t][(c + 1) % 3] {
            // A funnel of two edges has no interior chain vertex.
            Neighbor::RingEdge(_) => continue,
            Neighbor::Triangle(j) => {
                let j = j as usize;
                if let Some(side) = side_of(j, x, y) {
                    stack.push(Task::Visit {
                        t: j as u32,
                        side: side as u8,
                        lo,
                        hi,
                        ap,
                        put: NO_PUT,
                    });
                }
            }
        }
        while let Some(task) = stack.pop() {
            let put = match task {
                Task::Visit { put, .. } | Task::Leaf { put, .. } => put,
                Task::Undo => NO_PUT,
            };
            if put.0 != NO_PUT.0 {
                undo.push((put.0, buf[put.0]));
                buf[put.0] = put.1;
            }
            match task {
                Task::Undo => {
                    if let Some((pos, v)) = undo.pop() {
                        buf[pos] = v;
                    }
                }
                Task::Leaf { k, lo, hi, ap, .. } => {
                    let k = k as usize;
                    let (x, y) = (buf[lo], buf[hi]);
                    for p in lo + 1..hi {
                        if p == ap {
                            continue;
                        }
                        let c = buf[p];
                        let from = if p < ap { buf[p + 1] } else { buf[p - 1] };
                        let h = &mut hit[c as usize];
                        if h.is_none() && enters::<K>(ring, pt(from), c as usize) {
                            *h = Some(if through(from, c, x) {
                                Hit::Vertex(x as usize)
                            } else if through(from, c, y) {
                                Hit::Vertex(y as usize)
                            } else {
                                Hit::Edge(k)
                            });
                        }
                    }
                }
                Task::Visit {
                    t,
                    side,
                    lo,
                    hi,
                    ap,
                    ..
                } => {
                    let (t, side) = (t as usize, usize::from(side));
                    if std::mem::replace(&mut entered[t], true) {
                        continue;
                    }
                    let tr = triangles[t];
                    let w = tr[(side + 2) % 3];
                    // Left chain, outward from the apex: the path to w bends left at buf[p] while
                    // w is strictly left of buf[p + 1] → buf[p]; a block of positions next to ap.
                    let bends_left =
                        |p: usize| orient(buf[p + 1], buf[p], w) == Orientation::CounterClockwise;
                    let bends_right =
                        |p: usize| orient(buf[p - 1], buf[p], w) == Orientation::Clockwise;
                    // The tangent: the first position `p` of the funnel at which the path to w
                    // bends no further out — on the left chain where it bends left at `p`, from
                    // the apex on where it does not bend right at `p + 1` (true at `hi`). False
                    // then true along `[lo, hi]`; found from both ends at once.
                    let tangent_at_or_before = |p: usize| {
                        if p < ap {
                            bends_left(p)
                        } else {
                            p == hi || !bends_right(p + 1)
                        }
                    };
                    let a = first_true(lo, hi, tangent_at_or_before);
                    let tpos = if a < ap {
                        // The first chain edge beyond the tangent, if collinear with w, ends there.
                        if a > lo && through(buf[a], buf[a - 1], w) {
                            hit[buf[a - 1] as usize].get_or_insert(Hit::Vertex(w as usize));
                        }
                        a
                    } else {
                        if a < hi && through(buf[a], buf[a + 1], w) {
                            hit[buf[a + 1] as usize].get_or_insert(Hit::Vertex(w as usize));
                        }
                        if a == ap && ap > lo && through(buf[ap], buf[ap - 1], w) {
                            hit[buf[ap - 1] as usize].get_or_insert(Hit::Vertex(w as usize));
                        }
                        a
                    };
                    parent[w as usize] = Some(buf[tpos] as usize);
                    let (x, y) = (buf[lo], buf[hi]);
                    // Left child: buf[lo..=tpos], w — across the side w → x; right child: w,
                    // buf[tpos..=hi] — across the side y → w. Pushed in reverse order of work.
                    let children = [
                        (
                            (side + 1) % 3,
                            (w, y),
                            tpos - 1,
                            (tpos - 1, hi, if tpos > ap { tpos } else { ap }),
                        ),
                        (
                            (side + 2) % 3,
                            (x, w),
                            tpos + 1,
                            (lo, tpos + 1, if tpos < ap { tpos } else { ap }),
                        ),
                    ];
                    for (s_idx, (cx, cy), pos, (clo, chi, cap)) in children {
                        let put = (pos, w);
                        let work = match neighbors[t][s_idx] {
                            Neighbor::RingEdge(k) => Some(Task::Leaf {
                                k,
                                lo: clo,
                                hi: chi,
                                ap: cap,
                                put,
                            }),
                            Neighbor::Triangle(j) => {
                                side_of(j as usize, cx, cy).map(|side| Task::Visit {
                                    t: j,
                                    side: side as u8,
                                    lo: clo,
                                    hi: chi,
                                    ap: cap,
                                    put,
                                })
                            }
                        };
                        if let Some(work) = work {
                            // The write happens when `work` is popped; `Undo` after its subtree.
                            stack.push(Task::Undo);
                            stack.push(work);
                        }
                    }
                }
            }
        }
    }
    Extensions { parent, hit }
}

/// The first position of `[lo, hi]` where `g` holds, for `g` false then true along the range and
/// true at `hi` (never evaluated there): an exponential search from both ends at once (probes at
/// growing distances from `lo` and from `hi`, alternately), then a binary search in the bracket
/// found. `O(log min(t − lo, hi − t) + 1)` evaluations for the answer `t`: the cost of a search
/// from the nearer of two fingers (Guibas et al. §3 keep funnels in finger search trees for
/// exactly this bound). On a `g` that is not monotone (inconsistent Fast signs) it still returns
/// a position of `[lo, hi]`, after at most `2 log2(hi − lo + 1) + 4` evaluations (tested).
fn first_true(lo: usize, hi: usize, g: impl Fn(usize) -> bool) -> usize {
    // The answer lies in [a, b]; g(b) holds (or b = hi).
    let (mut a, mut b) = (lo, hi);
    let mut step = 1;
    while b - a > step {
        let p = a + step - 1;
        if g(p) {
            b = p;
            break;
        }
        a = p + 1;
        if b - a <= step {
            break;
        }
        let q = b - step;
        if !g(q) {
            a = q + 1;
            break;
        }
        b = q;
        step *= 2;
    }
    while a < b {
        let m = a + (b - a) / 2;
        if g(m) { b = m } else { a = m + 1 }
    }
    a
}

#[cfg(test)]
mod tests {
    use super::first_true;
    use core::cell::Cell;

    /// Against a linear scan on every range and answer up to 200 positions, with the evaluations
    /// counted: at most `4 log2(d + 1) + 4` for the answer `d` positions from the nearer end.
    #[test]
    fn first_true_is_the_scan_and_costs_the_log_of_the_nearer_distance() {
        for lo in [0usize, 3] {
            for len in 0..200 {
                let hi = lo + len;
                for t in lo..=hi {
                    let calls = Cell::new(0u32);
                    let got = first_true(lo, hi, |p| {
                        calls.set(calls.get() + 1);
                        assert!((lo..hi).contains(&p), "evaluated outside [lo, hi)");
                        p >= t
                    });
                    assert_eq!(got, t, "lo {lo} hi {hi}");
                    let d = (t - lo).min(hi - t) as f64;
                    assert!(
                        f64::from(calls.get()) <= 4.0 * (d + 1.0).log2() + 4.0,
                        "lo {lo} hi {hi} t {t}: {} calls",
                        calls.get()
                    );
                }
            }
        }
    }

    /// A predicate that is not monotone (what inconsistent Fast signs give) still yields a
    /// position of the range, after a logarithmic number of evaluations.
    #[test]
    fn first_true_terminates_on_any_predicate() {
        for len in 0..64usize {
            for mask in 0..64u64 {
                let calls = Cell::new(0u32);
                let got = first_true(10, 10 + len, |p| {
                    calls.set(calls.get() + 1);
                    mask >> (p % 64) & 1 == 1
                });
                assert!((10..=10 + len).contains(&got));
                assert!(f64::from(calls.get()) <= 2.0 * ((len + 1) as f64).log2() + 4.0);
            }
        }
    }
}
