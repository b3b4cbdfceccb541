//! The map from a polygon's internal vertices and edges back to the caller's indices.
//!
//! A polygon built from the caller's ring `p[0..L]` keeps some of the caller's vertices (internal vertex
//! `i` is caller vertex `source[i]`) and may reverse their order. Internal edge `e` then covers a
//! *chain* of the caller's ring: the caller vertices `c_0, c_1, …, c_m` with `c_{k+1} = c_k + 1 (mod L)`,
//! running in the caller's order from one end of the edge to the other. The chain's inner vertices are
//! the caller vertices that were dropped (exact repeats and collinear vertices strictly between their
//! neighbours); they lie on the edge, in order. Its caller edges are `c_0, …, c_{m−1}`.
//!
//! A hull is built from a subset of the caller's vertices. Its edges between two vertices that are
//! consecutive in the caller's cleaned ring are chains as above; its other edges (*lids*, bridging a
//! pocket, and every edge of the hull of a point set) are no part of the caller's boundary.

use glam::DVec2;
use polydist_predicates::{Kernel, Orientation, Robust, Sign};

use crate::Feature;

/// Internal vertex `i` is the caller's vertex `source[i]`; internal edges map to chains of caller edges.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SourceMap {
    /// The number of caller vertices.
    caller_len: usize,
    /// The caller index of each internal vertex.
    source: Vec<usize>,
    /// The internal order runs against the caller's (the caller gave a clockwise ring).
    reversed: bool,
    /// The caller's points, kept only when some caller vertex was dropped; otherwise every chain is its
    /// two ends, which are internal vertices.
    caller_points: Vec<DVec2>,
    /// `lids[e]`: internal edge `e` is not made of caller edges. Empty when no edge is a lid.
    lids: Vec<bool>,
}

impl SourceMap {
    /// The map of a polygon that keeps the caller vertices `source` of a ring of `caller.len()` points,
    /// in the caller's cyclic order, or in reverse when `reversed`.
    pub(crate) fn ring(caller: &[DVec2], source: Vec<usize>, reversed: bool) -> SourceMap {
        let caller_points = if source.len() == caller.len() {
            Vec::new()
        } else {
            caller.to_vec()
        };
        SourceMap {
            caller_len: caller.len(),
            source,
            reversed,
            caller_points,
            lids: Vec::new(),
        }
    }

    /// The map of a hull whose vertices are the internal vertices `kept` (in order, increasing
    /// cyclically) of a ring polygon with map `self` and `n` vertices.
    pub(crate) fn hull_of_ring(&self, kept: &[usize]) -> SourceMap {
        let n = self.source.len();
        let k = kept.len();
        let lids: Vec<bool> = (0..k)
            .map(|e| kept[(e + 1) % k] != (kept[e] + 1) % n)
            .collect();
        SourceMap {
            caller_len: self.caller_len,
            source: kept.iter().map(|&i| self.source[i]).collect(),
            reversed: self.reversed,
            caller_points: self.caller_points.clone(),
            lids: if lids.contains(&true) {
                lids
            } else {
                Vec::new()
            },
        }
    }

    /// The map of a hull of `caller_len` points whose vertices are the points `source`: every edge is a lid.
    pub(crate) fn point_set(caller_len: usize, source: Vec<usize>) -> SourceMap {
        let lids = vec![true; source.len()];
        SourceMap {
            caller_len,
            source,
            reversed: false,
            caller_points: Vec::new(),
            lids,
        }
    }

    /// The number of caller vertices.
    pub(crate) fn caller_len(&self) -> usize {
        self.caller_len
    }

    /// The caller index of internal vertex `i`.
    pub(crate) fn source(&self, i: usize) -> usize {
        self.source[i]
    }

    /// Whether internal edge `e` is a lid (no part of the caller's boundary).
    pub(crate) fn is_lid(&self, e: usize) -> bool {
        self.lids.get(e).copied().unwrap_or(false)
    }

    /// The chain of internal edge `e`: its first caller vertex `c_0` and its number of caller edges `m`
    /// (the chain is `c_0, …, c_0 + m (mod L)`).
    fn chain(&self, e: usize) -> (usize, usize) {
        let n = self.source.len();
        if n == 1 {
            // A point: every caller vertex repeats it, and the chain goes once around the caller's ring.
            return (self.source[0], self.caller_len);
        }
        let (s, t) = (self.source[e], self.source[(e + 1) % n]);
        let (s, t) = if self.reversed { (t, s) } else { (s, t) };
        (s, (t + self.caller_len - s) % self.caller_len)
    }

    /// The point of caller vertex `c_k` of the chain of internal edge `e` starting at `c_0`.
    fn chain_point(&self, vertices: &[DVec2], e: usize, c0: usize, k: usize) -> DVec2 {
        if self.caller_points.is_empty() {
            // Nothing was dropped: the chain is one caller edge, its ends are the edge's ends.
            let n = vertices.len();
            let (first, last) = if self.reversed {
                ((e + 1) % n, e)
            } else {
                (e, (e + 1) % n)
            };
            if k == 0 {
                vertices[first]
            } else {
                vertices[last]
            }
        } else {
            self.caller_points[(c0 + k) % self.caller_len]
        }
    }

    /// The caller's feature containing the point of internal edge `e` nearest to `q`, decided by exact
    /// dot signs on input points (see [`crate::ConvexPolygon::caller_feature_on_edge`]).
    pub(crate) fn feature_on_edge<K: Kernel>(
        &self,
        vertices: &[DVec2],
        e: usize,
        q: DVec2,
    ) -> Option<Feature> {
        let n = vertices.len();
        let (a, b) = (vertices[e], vertices[(e + 1) % n]);
        if self.is_lid(e) {
            // (q − a)·(b − a) ≤ 0: the nearest point is a; (q − b)·(a − b) ≤ 0: it is b.
            if K::dot_sign(a, q, a, b) != Sign::Positive {
                return Some(Feature::Vertex(self.source[e]));
            }
            if K::dot_sign(b, q, b, a) != Sign::Positive {
                return Some(Feature::Vertex(self.source[(e + 1) % n]));
            }
            return None;
        }
        let (c0, m) = self.chain(e);
        let point = |k: usize| self.chain_point(vertices, e, c0, k);
        let (p0, pm) = (point(0), point(m));
        // s(k) = sign((q − P_k)·(P_m − P_0)): positive while the foot of q lies beyond P_k. The chain is
        // monotone along P_0 → P_m, so s is non-increasing in k.
        let s = |k: usize| K::dot_sign(point(k), q, p0, pm);
        let caller = |k: usize| (c0 + k) % self.caller_len;
        if s(0) != Sign::Positive {
            return Some(Feature::Vertex(caller(0)));
        }
        if s(m) != Sign::Negative {
            return Some(Feature::Vertex(caller(m)));
        }
        // s(0) > 0 > s(m): the first k in 1..=m with s(k) ≤ 0 (binary search on the monotone signs).
        let (mut k, mut hi) = (1, m);
        while k < hi {
            // Invariant: s(j) > 0 for j < k, and s(hi) ≤ 0.
            let mid = k + (hi - k) / 2;
            if s(mid) == Sign::Positive {
                k = mid + 1
            } else {
                hi = mid
            }
        }
        Some(if s(k) == Sign::Zero {
            Feature::Vertex(caller(k))
        } else if self.caller_len == 2 {
            // A two-vertex caller ring is a segment with one edge, Edge(0) (its "closing" edge 1 is the
            // same point set; the oracle and every result use the single-edge convention).
            Feature::Edge(0)
        } else {
            Feature::Edge(caller(k - 1))
        })
    }

    /// Checks the map against the polygon's `vertices`: sizes, indices in range and distinct, the
    /// caller's cyclic order preserved, and every chain's inner caller vertices on its edge, in order.
    pub(crate) fn check(&self, vertices: &[DVec2]) -> Result<(), String> {
        let n = vertices.len();
        let len = self.caller_len;
        if self.source.len() != n {
            return Err(format!(
                "{} source indices for {n} vertices",
                self.source.len()
            ));
        }
        if let Some(&bad) = self.source.iter().find(|&&c| c >= len) {
            return Err(format!(
                "source index {bad} out of range for {len} caller vertices"
            ));
        }
        let mut seen = vec![false; len];
        for &c in &self.source {
            if std::mem::replace(&mut seen[c], true) {
                return Err(format!("caller vertex {c} is the source of two vertices"));
            }
        }
        if !self.lids.is_empty() && self.lids.len() != n {
            return Err(format!("{} lid flags for {n} edges", self.lids.len()));
        }
        if self.lids.len() == n && self.lids.iter().all(|&l| l) {
            // The hull of a point set: any subset of the points, in any order.
            return Ok(());
        }
        if n >= 2 {
            // The source indices, read in the caller's direction, go once around the caller's ring.
            let total: usize = (0..n)
                .map(|e| {
                    let (s, t) = (self.source[e], self.source[(e + 1) % n]);
                    if self.reversed {
                        (s + len - t) % len
                    } else {
                        (t + len - s) % len
                    }
                })
                .sum();
            if total != len {
                return Err(format!(
                    "source indices wind {total}/{len} times around the caller's ring"
                ));
            }
        }
        if !self.caller_points.is_empty() {
            if self.caller_points.len() != len {
                return Err(format!(
                    "{} caller points for {len} caller vertices",
                    self.caller_points.len()
                ));
            }
            for (i, &v) in vertices.iter().enumerate() {
                if self.caller_points[self.source[i]] != v {
                    return Err(format!(
                        "vertex {i} differs from its caller vertex {}",
                        self.source[i]
                    ));
                }
            }
        }
        for e in (0..n).filter(|&e| !self.is_lid(e)) {
            let (c0, m) = self.chain(e);
            if self.caller_points.is_empty() && m != 1 {
                return Err(format!(
                    "edge {e} spans {m} caller edges but no caller points are kept"
                ));
            }
            let point = |k: usize| self.chain_point(vertices, e, c0, k);
            let (p0, pm) = (point(0), point(m));
            for k in 1..m {
                let (prev, here) = (point(k - 1), point(k));
                let on_line = Robust::orient(p0, pm, here) == Orientation::Collinear;
                let in_order = Robust::dot_sign(prev, here, p0, pm) != Sign::Negative
                    && Robust::dot_sign(here, pm, p0, pm) != Sign::Negative;
                if !(on_line && in_order) {
                    return Err(format!(
                        "caller vertex {} is not on edge {e} in order",
                        (c0 + k) % len
                    ));
                }
            }
        }
        Ok(())
    }
}
