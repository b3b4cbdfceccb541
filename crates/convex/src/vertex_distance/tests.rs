//! Checks of the reconstruction that need the internals: the hidden runs found by the walks are those
//! of a full convex hull (claims S1–S3 of the doc), and every SMAWK block is totally monotone (the
//! convex-position claims behind each USERNG of the nine cases).

use std::collections::HashSet;

use glam::DVec2;
use polydist_oracle::{Relation, SplitMix64, convex_pair, random_convex};
use polydist_polygon::predicates::Robust;
use polydist_polygon::{ConvexPolygon, convex_hull};

use super::cases::{Hidden, hidden};
use super::chain::Callers;
use super::min_vertex_distance_with;
use super::scanset::record;
use super::tenstep::{Ring, bridge_up, chains};
use crate::hint::{Solved, solve};

/// Disjoint pairs of many shapes, with their mirror images and swaps.
fn inputs() -> Vec<(Vec<DVec2>, Vec<DVec2>)> {
    let mut rng = SplitMix64::new(77);
    let mut out = Vec::new();
    let rels = [
        Relation::Far,
        Relation::NearlyTouching { ulps: 1 },
        Relation::NearlyTouching { ulps: 5 },
        Relation::ParallelFacing,
        Relation::HugeOffset,
        Relation::Sliver,
    ];
    for round in 0..150 {
        for rel in rels {
            let (n, m) = (3 + rng.index(30), 3 + rng.index(30));
            let pair = convex_pair(&mut rng, n, m, rel);
            out.push((pair.p, pair.q));
        }
        // Two discs of different sizes at a random offset.
        let n = 3 + rng.index(if round % 10 == 0 { 300 } else { 30 });
        let r = 1.0 + 5.0 * rng.unit_f64();
        let p = random_convex(&mut rng, n, DVec2::ZERO, r);
        let a = rng.unit_f64() * std::f64::consts::TAU;
        let c = DVec2::new(a.cos(), a.sin()) * 10.0;
        let m = 3 + rng.index(30);
        let r = 0.5 + 3.0 * rng.unit_f64();
        let q = random_convex(&mut rng, m, c, r);
        out.push((p, q));
    }
    let mirror = |v: &[DVec2]| v.iter().map(|a| DVec2::new(-a.x, a.y)).collect::<Vec<_>>();
    let extra: Vec<_> = out
        .iter()
        .flat_map(|(p, q)| [(q.clone(), p.clone()), (mirror(p), mirror(q))])
        .collect();
    out.extend(extra);
    out
}

#[test]
fn hidden_runs_match_the_hull() {
    let mut seen = [0usize; 10];
    for (p_in, q_in) in inputs() {
        let (pp, qq) = (
            ConvexPolygon::try_new(&p_in).expect("valid"),
            ConvexPolygon::try_new(&q_in).expect("valid"),
        );
        let Solved::Disjoint(_, pair) = solve::<Robust>(&pp, &qq) else {
            panic!("the inputs are disjoint");
        };
        let (v, w) = (pp.vertices(), qq.vertices());
        let Some((t0, t1)) = bridge_up(v, w, pair) else {
            continue;
        };
        let ch = chains::<Robust>(
            Ring {
                pts: v,
                caller: Callers::Polygon(&pp),
            },
            Ring {
                pts: w,
                caller: Callers::Polygon(&qq),
            },
            t0,
            t1,
        );
        let (a, b) = (ch.v_l, ch.w_r);
        let h = hidden::<Robust>(&a, &b, &ch.f);
        let pa: Vec<DVec2> = (0..a.len()).map(|k| a.pt(k)).collect();
        let pb: Vec<DVec2> = (0..b.len()).map(|k| b.pt(k)).collect();
        let all: Vec<DVec2> = pa.iter().chain(&pb).copied().collect();
        let hull = convex_hull(&all).expect("hull");
        let key = |x: &DVec2| (x.x.to_bits(), x.y.to_bits());
        let corners: HashSet<_> = hull.vertices().iter().map(key).collect();
        let on = |pts: &[DVec2]| {
            pts.iter()
                .map(|x| corners.contains(&key(x)))
                .collect::<Vec<_>>()
        };
        let (on_a, on_b) = (on(&pa), on(&pb));
        let lead = |f: &[bool]| f.iter().take_while(|&&c| !c).count();
        let trail = |f: &[bool]| f.iter().rev().take_while(|&&c| !c).count();
        let expected = Hidden {
            a_top: lead(&on_a),
            a_bot: trail(&on_a),
            b_bot: lead(&on_b),
            b_top: trail(&on_b),
        };
        assert_eq!(h, expected, "P = {p_in:?}\nQ = {q_in:?}");
        // S1: the corners of U on each chain form one contiguous run.
        assert!(
            on_a[h.a_top..a.len() - h.a_bot].iter().all(|&c| c),
            "A's run"
        );
        assert!(
            on_b[h.b_bot..b.len() - h.b_top].iter().all(|&c| c),
            "B's run"
        );
        // S3: at most one chain is hidden at each end.
        assert!(h.a_top == 0 || h.b_top == 0);
        assert!(h.a_bot == 0 || h.b_bot == 0);
        seen[h.case()] += 1;
    }
    println!("cases seen: {seen:?}");
    assert!(seen[1..].iter().all(|&c| c > 0), "{seen:?}");
}

#[test]
fn every_smawk_block_is_totally_monotone() {
    let cmp = |x: &(DVec2, DVec2), y: &(DVec2, DVec2)| {
        use polydist_polygon::predicates::Kernel;
        Robust::cmp_dist4(x.0, x.1, y.0, y.1)
    };
    let mut blocks = 0;
    for (p_in, q_in) in inputs() {
        let (pp, qq) = (
            ConvexPolygon::try_new(&p_in).expect("valid"),
            ConvexPolygon::try_new(&q_in).expect("valid"),
        );
        let _ = record::take();
        let _ = min_vertex_distance_with::<Robust>(&pp, &qq);
        for (rows, columns) in record::take() {
            let m =
                monotone_minima::from_fn(rows.len(), columns.len(), |i, j| (rows[i], columns[j]));
            assert_eq!(
                monotone_minima::check_totally_monotone_by(&m, cmp),
                Ok(()),
                "rows {rows:?}\ncolumns {columns:?}\nP = {p_in:?}\nQ = {q_in:?}"
            );
            blocks += 1;
        }
    }
    println!("{blocks} blocks checked");
    assert!(blocks > 1000);
}
