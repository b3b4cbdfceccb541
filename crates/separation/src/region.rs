//! The regions `R(·)` of Amato's section 3 for vertices: the points `u^±` by one top-to-bottom and
//! one bottom-to-top scan with a pointer that moves one way, and the classification of a point
//! against a region.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::Kernel;

use crate::frame::Frame;
use crate::site::Vertex;
use crate::wedge::{Apex, in_wedge};

/// `R(b)` for a vertex `b` of one chain: the vertices `u^+`, `u^-` of the other chain (`None`: the
/// boundary is the perpendicular to the line through `b` itself, the text's `u = b^l`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Region<V = DVec2> {
    pub(crate) up: Option<V>,
    pub(crate) down: Option<V>,
}

/// Where a point lies relative to a region.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Place {
    Above,
    Inside,
    Below,
}

/// The regions `R(b_j)` of every vertex of `bs` (frame `fb`), with `u^±` among `us` (frame `fu`),
/// both lists strictly increasing in height.
///
/// `u_j^+` is the highest `u` with `H(b_j) ≤ H(u) ≤ H(u_{j+1}^+)`, `u ∈ W(b_j)` and `b_j ∈ W(u)`
/// (`H(u_{n+1}^+) = +∞`; when there is no such `u`, `H(u_j^+)` is taken as `H(b_j)`); `u_j^-`
/// symmetrically. The pointer into `us` only moves down during the first scan (up during the
/// second), except for one step back per `b_j` to readmit the single `u` at exactly the height of
/// the new cap: at most `2(n_u + n_b)` candidate tests, each two wedge tests.
pub(crate) fn regions<K: Kernel, V: Vertex>(
    bs: &[Apex<V>],
    fb: Frame,
    us: &[Apex<V>],
    fu: Frame,
) -> Vec<Region<V>> {
    let mut out = vec![
        Region {
            up: None,
            down: None
        };
        bs.len()
    ];
    let admissible =
        |b: &Apex<V>, u: &Apex<V>| in_wedge::<K, _>(fb, b, u.pt) && in_wedge::<K, _>(fu, u, b.pt);
    // Top-to-bottom: u^+.
    let mut k = us.len(); // candidates are us[..k]
    for (j, b) in bs.iter().enumerate().rev() {
        while k > 0 {
            let u = &us[k - 1];
            if fb.cmp_height::<K, _>(u.pt, b.pt) == Ordering::Less {
                break;
            }
            if admissible(b, u) {
                out[j].up = Some(u.pt);
                break;
            }
            k -= 1;
        }
        if out[j].up.is_none()
            && k < us.len()
            && fb.cmp_height::<K, _>(us[k].pt, b.pt) == Ordering::Equal
        {
            k += 1; // the cap is now H(b): the one u at exactly that height is a candidate again
        }
    }
    // Bottom-to-top: u^-.
    let mut k = 0; // candidates are us[k..]
    for (j, b) in bs.iter().enumerate() {
        while k < us.len() {
            let u = &us[k];
            if fb.cmp_height::<K, _>(u.pt, b.pt) == Ordering::Greater {
                break;
            }
            if admissible(b, u) {
                out[j].down = Some(u.pt);
                break;
            }
            k += 1;
        }
        if out[j].down.is_none()
            && k > 0
            && fb.cmp_height::<K, _>(us[k - 1].pt, b.pt) == Ordering::Equal
        {
            k -= 1;
        }
    }
    out
}

/// Classifies `z`, a vertex of the chain holding `u^±` (frame `fu`) that is one of the apexes the
/// regions were built from, against `R(b)`, by heights alone: above when `H(z) > H(u^+)`, below
/// when `H(z) < H(u^-)` (`H(b)` for a missing `u`), inside otherwise. One degree-2 test per
/// boundary, where the literal boundary (`place`, its test twin in the tests) takes up to three.
///
/// Why the band is the region, for such `z` (docs/algorithms/separation.md, "`R()` of vertices"):
/// when `u^+` is admissible for `b`, no point of `u`'s chain lower than `u^+` lies above the segment
/// `(b, u^+)` (it would be nearer to the line than `u^+` and above the direction of `b` from it, so
/// `l(u^+)` would put `b` below `W(u^+)`), and every point higher than `u^+` lies above the boundary
/// (at least as deep: by the ray; nearer: strictly left of `b → u^+`, a sign read off the
/// coordinates). The apexes have strictly increasing heights, so no `z` other than `u^+` is at its
/// height. The same holds for `u^-` below. `band_is_the_literal_region` checks it.
pub(crate) fn band<K: Kernel, V: Vertex>(fu: Frame, b: V, r: &Region<V>, z: V) -> Place {
    if fu.cmp_height::<K, _>(z, r.up.unwrap_or(b)) == Ordering::Greater {
        Place::Above
    } else if fu.cmp_height::<K, _>(z, r.down.unwrap_or(b)) == Ordering::Less {
        Place::Below
    } else {
        Place::Inside
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chain::{Frames, validate, validate_touching};
    use crate::envelope::prepare;
    use crate::error::Chain;
    use crate::wedge::apexes;
    use crate::wedge::cmp_depth;
    use polydist_oracle::SplitMix64;
    use polydist_predicates::{Exact, Sign};

    /// Classifies `z`, a point on the side of the chain holding `u^±` (frame `fu`), against `R(b)`.
    ///
    /// The upper boundary is the segment `(b, u^+)` and then the ray from `u^+` perpendicular to the
    /// line, away from it; `z` is above it when `z` is at least as deep as `u^+` and strictly higher, or
    /// nearer to the line than `u^+` and strictly left of `b → u^+` (in the frame of `z`'s side). The
    /// region is closed. At most three degree-2 tests per boundary. The test twin of [`band`].
    fn place<K: Kernel>(fu: Frame, b: DVec2, r: &Region, z: DVec2) -> Place {
        let beyond = |u: DVec2, side: Ordering, orient_side: Sign| match cmp_depth::<K, _>(fu, z, u)
        {
            Ordering::Less => fu.orient::<K, _>(b, u, z) == orient_side,
            _ => fu.cmp_height::<K, _>(z, u) == side,
        };
        let above = match r.up {
            Some(u) => beyond(u, Ordering::Greater, Sign::Positive),
            None => fu.cmp_height::<K, _>(z, b) == Ordering::Greater,
        };
        if above {
            return Place::Above;
        }
        let below = match r.down {
            Some(u) => beyond(u, Ordering::Less, Sign::Negative),
            None => fu.cmp_height::<K, _>(z, b) == Ordering::Less,
        };
        if below { Place::Below } else { Place::Inside }
    }

    fn side(rng: &mut SplitMix64, n: usize, sign: f64) -> Vec<DVec2> {
        let mut ys: Vec<i64> = (0..n).map(|_| rng.range_i64(0, 3 * n as i64)).collect();
        ys.sort_unstable();
        ys.dedup();
        ys.into_iter()
            .map(|y| DVec2::new(sign * rng.range_i64(1, 7) as f64, y as f64))
            .collect()
    }

    /// Both chains' apexes (the envelope's vertices after Lemma 3), as `CvvMatrix` builds them.
    fn apexes_of(p: &[DVec2], q: &[DVec2], f: Frames) -> (Vec<Apex>, Vec<Apex>) {
        let pa = apexes::<Exact, _>(&prepare::<Exact, _>(p, f.p, Chain::P).unwrap(), f.p);
        let qa = apexes::<Exact, _>(&prepare::<Exact, _>(q, f.q, Chain::Q).unwrap(), f.q);
        (pa, qa)
    }

    /// The definition of `u^+`, scanned in `O(n_b · n_u)`: from the top, the highest admissible `u`
    /// between `H(b_j)` and the cap `H(u_{j+1}^+)` (or `H(b_{j+1})` when there was none).
    fn up_def(bs: &[Apex], fb: Frame, us: &[Apex], fu: Frame) -> Vec<Option<DVec2>> {
        let mut out = vec![None; bs.len()];
        let mut cap: Option<DVec2> = None;
        for (j, b) in bs.iter().enumerate().rev() {
            let best = us
                .iter()
                .filter(|u| fb.cmp_height::<Exact, _>(u.pt, b.pt) != Ordering::Less)
                .filter(|u| {
                    cap.is_none_or(|c| fb.cmp_height::<Exact, _>(u.pt, c) != Ordering::Greater)
                })
                .filter(|u| in_wedge::<Exact, _>(fb, b, u.pt) && in_wedge::<Exact, _>(fu, u, b.pt))
                .max_by(|x, y| fb.cmp_height::<Exact, _>(x.pt, y.pt));
            out[j] = best.map(|u| u.pt);
            cap = Some(best.map_or(b.pt, |u| u.pt));
        }
        out
    }

    fn down_def(bs: &[Apex], fb: Frame, us: &[Apex], fu: Frame) -> Vec<Option<DVec2>> {
        let mut out = vec![None; bs.len()];
        let mut cap: Option<DVec2> = None;
        for (j, b) in bs.iter().enumerate() {
            let best = us
                .iter()
                .filter(|u| fb.cmp_height::<Exact, _>(u.pt, b.pt) != Ordering::Greater)
                .filter(|u| {
                    cap.is_none_or(|c| fb.cmp_height::<Exact, _>(u.pt, c) != Ordering::Less)
                })
                .filter(|u| in_wedge::<Exact, _>(fb, b, u.pt) && in_wedge::<Exact, _>(fu, u, b.pt))
                .min_by(|x, y| fb.cmp_height::<Exact, _>(x.pt, y.pt));
            out[j] = best.map(|u| u.pt);
            cap = Some(best.map_or(b.pt, |u| u.pt));
        }
        out
    }

    #[test]
    fn pointer_scans_match_the_definition() {
        let mut rng = SplitMix64::new(21);
        let (a, b) = (DVec2::ZERO, DVec2::Y);
        let mut found = 0;
        for n in [1usize, 2, 4, 7, 12, 25] {
            for _ in 0..300 {
                let p = side(&mut rng, n, 1.0);
                let q = side(&mut rng, n, -1.0);
                let f = validate::<Exact>(&p, &q, a, b).unwrap();
                let (pa, qa) = apexes_of(&p, &q, f);
                for (bs, fb, us, fu) in [(&pa, f.p, &qa, f.q), (&qa, f.q, &pa, f.p)] {
                    let r = regions::<Exact, _>(bs, fb, us, fu);
                    let up: Vec<_> = r.iter().map(|r| r.up).collect();
                    let down: Vec<_> = r.iter().map(|r| r.down).collect();
                    assert_eq!(up, up_def(bs, fb, us, fu), "u+ for {p:?} {q:?}");
                    assert_eq!(down, down_def(bs, fb, us, fu), "u- for {p:?} {q:?}");
                    found += up.iter().chain(&down).filter(|u| u.is_some()).count();
                }
            }
        }
        assert!(found > 1000, "the generator must produce regions ({found})");
    }

    /// [`band`] (heights only) against the literal boundary [`place`] for every apex of the other
    /// chain and every region, on chains off the line and chains touching it.
    #[test]
    fn band_is_the_literal_region() {
        let mut rng = SplitMix64::new(22);
        let (a, b) = (DVec2::ZERO, DVec2::Y);
        let mut strict = 0;
        for n in [1usize, 2, 4, 7, 12, 25] {
            for k in 0..400 {
                let mut p = side(&mut rng, n, 1.0);
                if k % 2 == 1 {
                    // Some of P's vertices on the line.
                    for v in &mut p {
                        if rng.range_i64(0, 3) == 0 {
                            v.x = 0.0;
                        }
                    }
                }
                let q = side(&mut rng, n, -1.0);
                let Ok(f) = validate_touching::<Exact>(&p, &q, a, b) else {
                    continue;
                };
                let Some(f) = f.frames else { continue };
                let (pa, qa) = apexes_of(&p, &q, f);
                for (bs, fb, us, fu) in [(&pa, f.p, &qa, f.q), (&qa, f.q, &pa, f.p)] {
                    let r = regions::<Exact, _>(bs, fb, us, fu);
                    for (bj, rj) in bs.iter().zip(&r) {
                        for u in us {
                            let lit = place::<Exact>(fu, bj.pt, rj, u.pt);
                            assert_eq!(
                                band::<Exact, _>(fu, bj.pt, rj, u.pt),
                                lit,
                                "{:?} against R({:?}) = {rj:?}, chains {p:?} {q:?}",
                                u.pt,
                                bj.pt
                            );
                            strict += usize::from(lit != Place::Inside);
                        }
                    }
                }
            }
        }
        assert!(
            strict > 10_000,
            "the generator must place apexes outside regions ({strict})"
        );
    }
}
