//! The regions `R(·)` of Amato's section 3 for vertices: the points `u^±` by one top-to-bottom and
//! one bottom-to-top scan with a pointer that moves one way, and the classification of a point
//! against a region.

use core::cmp::Ordering;

use glam::DVec2;
use polydist_predicates::{Kernel, Sign};

use crate::frame::Frame;
use crate::wedge::{Apex, in_wedge};

/// `R(b)` for a vertex `b` of one chain: the vertices `u^+`, `u^-` of the other chain (`None`: the
/// boundary is the perpendicular to the line through `b` itself, the text's `u = b^l`).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Region {
    pub(crate) up: Option<DVec2>,
    pub(crate) down: Option<DVec2>,
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
pub(crate) fn regions<K: Kernel>(bs: &[Apex], fb: Frame, us: &[Apex], fu: Frame) -> Vec<Region> {
    let mut out = vec![Region::default(); bs.len()];
    let admissible = |b: &Apex, u: &Apex| in_wedge::<K>(fb, b, u.pt) && in_wedge::<K>(fu, u, b.pt);
    // Top-to-bottom: u^+.
    let mut k = us.len(); // candidates are us[..k]
    for (j, b) in bs.iter().enumerate().rev() {
        while k > 0 {
            let u = &us[k - 1];
            if fb.cmp_height::<K>(u.pt, b.pt) == Ordering::Less {
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
            && fb.cmp_height::<K>(us[k].pt, b.pt) == Ordering::Equal
        {
            k += 1; // the cap is now H(b): the one u at exactly that height is a candidate again
        }
    }
    // Bottom-to-top: u^-.
    let mut k = 0; // candidates are us[k..]
    for (j, b) in bs.iter().enumerate() {
        while k < us.len() {
            let u = &us[k];
            if fb.cmp_height::<K>(u.pt, b.pt) == Ordering::Greater {
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
            && fb.cmp_height::<K>(us[k - 1].pt, b.pt) == Ordering::Equal
        {
            k -= 1;
        }
    }
    out
}

/// Classifies `z`, a point on the side of the chain holding `u^±` (frame `fu`), against `R(b)`.
///
/// The upper boundary is the segment `(b, u^+)` and then the ray from `u^+` perpendicular to the
/// line, away from it; `z` is above it when `z` is at least as deep as `u^+` and strictly higher, or
/// nearer to the line than `u^+` and strictly left of `b → u^+` (in the frame of `z`'s side). The
/// region is closed. At most three degree-2 tests per boundary.
pub(crate) fn place<K: Kernel>(fu: Frame, b: DVec2, r: &Region, z: DVec2) -> Place {
    let beyond = |u: DVec2, side: Ordering, orient_side: Sign| match fu.cmp_depth::<K>(z, u) {
        Ordering::Less => fu.orient::<K>(b, u, z) == orient_side,
        _ => fu.cmp_height::<K>(z, u) == side,
    };
    let above = match r.up {
        Some(u) => beyond(u, Ordering::Greater, Sign::Positive),
        None => fu.cmp_height::<K>(z, b) == Ordering::Greater,
    };
    if above {
        return Place::Above;
    }
    let below = match r.down {
        Some(u) => beyond(u, Ordering::Less, Sign::Negative),
        None => fu.cmp_height::<K>(z, b) == Ordering::Less,
    };
    if below { Place::Below } else { Place::Inside }
}
