//! Named tests for the tricky inputs: each one a case that a plausible implementation gets wrong.

use glam::DVec2;
use polydist_polygon::predicates::Robust;
use polydist_polygon::{
    ConvexPolygon, Feature, Location, PolygonError, SimplePolygon, convex_hull,
};

fn pts(coords: &[[f64; 2]]) -> Vec<DVec2> {
    coords.iter().map(|&p| DVec2::from(p)).collect()
}

fn convex(coords: &[[f64; 2]]) -> Result<ConvexPolygon, PolygonError> {
    let r = ConvexPolygon::try_new(&pts(coords));
    if let Ok(p) = &r {
        assert_eq!(p.check_invariants(), Ok(()));
    }
    r
}

fn simple(coords: &[[f64; 2]]) -> Result<SimplePolygon, PolygonError> {
    let r = SimplePolygon::try_new(&pts(coords));
    if let Ok(p) = &r {
        assert_eq!(p.check_invariants(), Ok(()));
    }
    let brute = SimplePolygon::try_new_brute_force(&pts(coords));
    assert_eq!(
        r.is_ok(),
        brute.is_ok(),
        "sweep and brute force disagree on {coords:?}"
    );
    r
}

fn sources(p: &ConvexPolygon) -> Vec<usize> {
    (0..p.len()).map(|i| p.source_index(i)).collect()
}

#[test]
fn pentagram_winds_twice() {
    // Vertices of a regular pentagon visited every second one: all turns left, total turning 4π.
    let star = [
        [0.0, 10.0],
        [-6.0, -8.0],
        [10.0, 3.0],
        [-10.0, 3.0],
        [6.0, -8.0],
    ];
    assert_eq!(
        convex(&star),
        Err(PolygonError::WindsMoreThanOnce { turns: 2 })
    );
    // The same star clockwise.
    let mut cw = star;
    cw.reverse();
    assert_eq!(
        convex(&cw),
        Err(PolygonError::WindsMoreThanOnce { turns: 2 })
    );
    // And it is not simple either.
    assert!(matches!(
        simple(&star),
        Err(PolygonError::SelfIntersection { .. })
    ));
}

#[test]
fn heptagram_winds_three_times() {
    let star: Vec<[f64; 2]> = (0..7)
        .map(|i| {
            let a = f64::from(i) * 6.0 * std::f64::consts::PI / 7.0;
            [(1000.0 * a.cos()).round(), (1000.0 * a.sin()).round()]
        })
        .collect();
    assert_eq!(
        convex(&star),
        Err(PolygonError::WindsMoreThanOnce { turns: 3 })
    );
}

#[test]
fn spike_is_an_error_not_dropped() {
    // (2, 0) → (1, 0) doubles back along the bottom edge.
    let spike = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [0.0, 2.0]];
    assert_eq!(convex(&spike), Err(PolygonError::Spike { index: 1 }));
    assert_eq!(simple(&spike), Err(PolygonError::Spike { index: 1 }));
    // A spike going out and straight back: the ring folds at its tip (index 2).
    let out_and_back = [[0.0, 0.0], [1.0, 0.0], [3.0, 0.0], [1.0, 0.0], [1.0, 1.0]];
    assert_eq!(simple(&out_and_back), Err(PolygonError::Spike { index: 2 }));
}

#[test]
fn collinear_runs_are_dropped_and_mapped() {
    // Two straight vertices on the bottom edge, one on the left edge, given clockwise.
    let ring = [
        [0.0, 0.0],
        [0.0, 1.0],
        [0.0, 3.0],
        [3.0, 0.0],
        [2.0, 0.0],
        [1.0, 0.0],
    ];
    let p = convex(&ring).expect("convex");
    assert_eq!(p.vertices(), pts(&[[0.0, 0.0], [3.0, 0.0], [0.0, 3.0]]));
    assert_eq!(sources(&p), [0, 3, 2]);
    // Along internal edge 0 = (0,0) → (3,0), the caller's vertices 5 and 4 sit at x = 1 and 2.
    let below = |x: f64| DVec2::new(x, -1.0);
    let f = |x| p.caller_feature_on_edge::<Robust>(0, below(x));
    assert_eq!(f(-1.0), Some(Feature::Vertex(0)));
    assert_eq!(f(0.5), Some(Feature::Edge(5)));
    assert_eq!(f(1.0), Some(Feature::Vertex(5)));
    assert_eq!(f(1.5), Some(Feature::Edge(4)));
    assert_eq!(f(2.0), Some(Feature::Vertex(4)));
    assert_eq!(f(2.5), Some(Feature::Edge(3)));
    assert_eq!(f(3.0), Some(Feature::Vertex(3)));
    // Internal edge 2 = (0,3) → (0,0) runs through caller vertex 1.
    let left = |y: f64| DVec2::new(-1.0, y);
    assert_eq!(
        p.caller_feature_on_edge::<Robust>(2, left(2.0)),
        Some(Feature::Edge(1))
    );
    assert_eq!(
        p.caller_feature_on_edge::<Robust>(2, left(1.0)),
        Some(Feature::Vertex(1))
    );
    assert_eq!(
        p.caller_feature_on_edge::<Robust>(2, left(0.5)),
        Some(Feature::Edge(0))
    );
}

#[test]
fn closing_duplicate_is_merged_into_vertex_zero() {
    let closed = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [0.0, 0.0]];
    let p = convex(&closed).expect("convex");
    assert_eq!(p.len(), 3);
    assert_eq!(sources(&p), [0, 1, 2]);
    assert_eq!(p.caller_len(), 4);
    // Internal edge 2 = (0,1) → (0,0) is the caller's edge 2 (edge 3 has length zero).
    assert_eq!(
        p.caller_feature_on_edge::<Robust>(2, DVec2::new(-1.0, 0.5)),
        Some(Feature::Edge(2))
    );
    assert_eq!(
        p.caller_feature_on_edge::<Robust>(2, DVec2::new(-1.0, -1.0)),
        Some(Feature::Vertex(0))
    );
    // Repeats in the middle and at both ends.
    let repeats = [
        [0.0, 0.0],
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 0.0],
        [0.0, 1.0],
        [0.0, 0.0],
    ];
    let p = convex(&repeats).expect("convex");
    assert_eq!(sources(&p), [0, 2, 4]);
    // Internal edge 0 = (0,0) → (1,0): caller edge 0 has length zero, edge 1 is the real one.
    assert_eq!(
        p.caller_feature_on_edge::<Robust>(0, DVec2::new(0.5, -1.0)),
        Some(Feature::Edge(1))
    );
    let s = simple(&repeats).expect("simple");
    assert_eq!(s.len(), 3);
}

#[test]
fn all_collinear_input() {
    // B strictly between A and C: the segment AC, B dropped.
    let abc = [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]];
    let p = convex(&abc).expect("segment");
    assert_eq!(p.vertices(), pts(&[[0.0, 0.0], [2.0, 2.0]]));
    assert_eq!(sources(&p), [0, 2]);
    assert_eq!(p.locate(DVec2::new(1.0, 1.0)), Location::Boundary);
    assert_eq!(p.locate(DVec2::new(3.0, 3.0)), Location::Outside);
    assert_eq!(
        p.caller_feature_on_edge::<Robust>(0, DVec2::new(0.0, 1.0)),
        Some(Feature::Edge(0))
    );
    assert_eq!(
        p.caller_feature_on_edge::<Robust>(0, DVec2::new(0.0, 2.0)),
        Some(Feature::Vertex(1))
    );
    // The extreme points given in the middle: still one back-and-forth.
    let acb = [[0.0, 0.0], [2.0, 2.0], [1.0, 1.0]];
    assert_eq!(convex(&acb).map(|p| sources(&p)), Ok(vec![0, 1]));
    // Back and forth twice is a spike at the first reversal that is not an extreme point.
    let twice = [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [3.0, 0.0]];
    assert_eq!(convex(&twice), Err(PolygonError::Spike { index: 1 }));
    // Simple polygons need area.
    assert_eq!(simple(&abc), Err(PolygonError::Degenerate));
    assert_eq!(
        simple(&[[0.0, 0.0], [1.0, 0.0]]),
        Err(PolygonError::TooFewVertices {
            found: 2,
            needed: 3
        })
    );
    // One point, repeated.
    let point = convex(&[[1.0, 2.0], [1.0, 2.0], [1.0, 2.0]]).expect("point");
    assert_eq!(point.len(), 1);
    assert_eq!(point.locate(DVec2::new(1.0, 2.0)), Location::Boundary);
    assert_eq!(
        point.caller_feature_on_edge::<Robust>(0, DVec2::ZERO),
        Some(Feature::Vertex(0))
    );
    assert_eq!(
        simple(&[[1.0, 2.0], [1.0, 2.0]]),
        Err(PolygonError::TooFewVertices {
            found: 1,
            needed: 3
        })
    );
}

#[test]
fn invalid_coordinates_name_the_vertex() {
    let huge = f64::from_bits((1023 + 501) << 52);
    assert_eq!(convex(&[]), Err(PolygonError::Empty));
    assert_eq!(simple(&[]), Err(PolygonError::Empty));
    assert_eq!(
        convex(&[[0.0, 0.0], [f64::NAN, 0.0]]),
        Err(PolygonError::NonFinite { index: 1 })
    );
    assert_eq!(
        simple(&[[0.0, 0.0], [1.0, 0.0], [0.0, f64::NEG_INFINITY]]),
        Err(PolygonError::NonFinite { index: 2 })
    );
    assert_eq!(
        convex(&[[huge, 0.0]]),
        Err(PolygonError::OutOfRange { index: 0 })
    );
    // Exactly 2^500 is allowed.
    let max = polydist_polygon::predicates::MAX_COORDINATE;
    assert!(convex(&[[max, -max], [0.0, max], [-max, -max]]).is_ok());
    assert_eq!(
        convex_hull(&pts(&[[0.0, 0.0], [1.0, f64::NAN]])).err(),
        Some(PolygonError::NonFinite { index: 1 })
    );
}

#[test]
fn reflex_vertex_is_named() {
    // Counter-clockwise arrow head with a reflex vertex at index 3.
    let arrow = [[0.0, 0.0], [4.0, 2.0], [0.0, 4.0], [1.0, 2.0]];
    assert_eq!(convex(&arrow), Err(PolygonError::NotConvex { index: 3 }));
    // Clockwise: still vertex 3.
    let cw = [[0.0, 0.0], [1.0, 2.0], [0.0, 4.0], [4.0, 2.0]];
    assert_eq!(convex(&cw), Err(PolygonError::NotConvex { index: 1 }));
    assert!(simple(&arrow).is_ok());
}

#[test]
fn orientation_is_normalised_to_ccw_keeping_the_first_vertex() {
    let cw = [[1.0, 1.0], [1.0, 3.0], [3.0, 3.0], [3.0, 1.0]];
    let p = convex(&cw).expect("convex");
    assert_eq!(
        p.vertices(),
        pts(&[[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]])
    );
    assert_eq!(sources(&p), [0, 3, 2, 1]);
    let s = simple(&cw).expect("simple");
    assert_eq!(s.vertices(), p.vertices());
    assert_eq!(
        (0..4).map(|i| s.source_index(i)).collect::<Vec<_>>(),
        [0, 3, 2, 1]
    );
    // Internal edge 0 = (1,1) → (3,1) is the caller's edge 3 (from caller 3 to caller 0).
    assert_eq!(
        s.caller_feature_on_edge::<Robust>(0, DVec2::new(2.0, 0.0)),
        Some(Feature::Edge(3))
    );
}

#[test]
fn vertical_edges_and_many_vertices_on_one_x() {
    // A comb-like polygon with every edge axis-parallel and many vertices on x = 0, 1, 2.
    let ok = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 3.0],
        [1.0, 3.0],
        [1.0, 1.0],
        [0.5, 1.0],
        [0.5, 2.0],
        [0.0, 2.0],
    ];
    assert!(simple(&ok).is_ok());
    // A vertical edge crossing a horizontal one.
    let cross = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 2.0],
        [1.0, 2.0],
        [1.0, -1.0],
        [0.0, -1.0],
    ];
    assert!(matches!(
        simple(&cross),
        Err(PolygonError::SelfIntersection { .. })
    ));
    // Two vertical edges overlapping on x = 0.
    let overlap = [
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 3.0],
        [0.0, 3.0],
        [0.0, 2.0],
        [0.5, 1.5],
        [0.0, 1.0],
    ];
    assert!(simple(&overlap).is_ok());
    let overlap = [
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 3.0],
        [0.0, 3.0],
        [0.0, 1.0],
        [0.5, 1.5],
        [0.0, 2.0],
    ];
    assert!(matches!(
        simple(&overlap),
        Err(PolygonError::SelfIntersection { .. })
    ));
    // A vertex touching a vertical edge from inside.
    let touch = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, 2.0],
        [0.0, 2.0],
        [0.0, 1.5],
        [1.0, 1.0],
        [0.0, 1.0],
    ];
    assert!(simple(&touch).is_ok());
    // Vertex 4 touches the vertical edge 1 from inside; either of its edges may be reported with it.
    let touch = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 1.0]];
    let found = simple(&touch);
    assert!(
        matches!(
            found,
            Err(PolygonError::SelfIntersection {
                edge_a: 1,
                edge_b: 3 | 4
            })
        ),
        "{found:?}"
    );
}

#[test]
fn figure_eight_touching_at_a_vertex_is_rejected() {
    let eight = [
        [0.0, 0.0],
        [1.0, 1.0],
        [2.0, 0.0],
        [2.0, 2.0],
        [1.0, 1.0],
        [0.0, 2.0],
    ];
    assert_eq!(
        simple(&eight),
        Err(PolygonError::SelfIntersection {
            edge_a: 1,
            edge_b: 4
        })
    );
    // A vertex of one lobe touching the interior of an edge of the other.
    let kiss = [
        [0.0, 0.0],
        [4.0, 0.0],
        [2.0, 2.0],
        [3.0, 4.0],
        [1.0, 4.0],
        [2.0, 2.0 + 1.0 / 1024.0],
    ];
    assert!(simple(&kiss).is_ok());
    let kiss = [[0.0, 0.0], [4.0, 0.0], [4.0, 2.0], [2.0, 0.0], [0.0, 2.0]];
    assert_eq!(
        simple(&kiss),
        Err(PolygonError::SelfIntersection {
            edge_a: 0,
            edge_b: 3
        })
    );
}

#[test]
fn overlapping_collinear_edges_are_rejected() {
    // Edges 0 and 3 both lie on y = 0 and overlap in [1, 2].
    let ring = [
        [0.0, 0.0],
        [2.0, 0.0],
        [2.0, -1.0],
        [1.0, 0.0],
        [3.0, 0.0],
        [3.0, 1.0],
        [0.0, 1.0],
    ];
    assert!(matches!(
        simple(&ring),
        Err(PolygonError::SelfIntersection { .. })
    ));
    // Collinear edges meeting only end to end at a repeated vertex.
    let ring = [
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, -1.0],
        [2.0, -1.0],
        [2.0, 0.0],
        [1.0, 0.0],
        [1.0, 1.0],
    ];
    assert!(matches!(
        simple(&ring),
        Err(PolygonError::SelfIntersection { .. })
    ));
}

#[test]
fn one_ulp_decides() {
    let above = f64::from_bits(1.0f64.to_bits() + 1);
    // (1, 1 + ulp) is strictly left of (0,0) → (2,2): a strict turn, kept.
    let t = convex(&[[0.0, 0.0], [2.0, 2.0], [1.0, above]]).expect("triangle");
    assert_eq!(t.len(), 3);
    // Exactly on the diagonal: the segment.
    assert_eq!(
        convex(&[[0.0, 0.0], [2.0, 2.0], [1.0, 1.0]]).map(|p| p.len()),
        Ok(2)
    );
    // A square whose top-right corner is pushed one ulp inward is not convex.
    let below = f64::from_bits(2.0f64.to_bits() - 1);
    let dent = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, below], [0.0, 2.0]];
    assert_eq!(convex(&dent), Err(PolygonError::NotConvex { index: 3 }));
    assert!(simple(&dent).is_ok());
}

#[test]
fn hull_of_polygon_with_lids_maps_features() {
    // A square with a notch: the top edge of the hull is a lid over the notch.
    let notch = [
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 4.0],
        [3.0, 4.0],
        [2.0, 1.0],
        [1.0, 4.0],
        [0.0, 4.0],
    ];
    let poly = simple(&notch).expect("simple");
    let hull = poly.convex_hull();
    assert_eq!(hull.check_invariants(), Ok(()));
    assert_eq!(sources(&hull), [0, 1, 2, 6]);
    assert!(!hull.is_lid(0) && !hull.is_lid(1) && hull.is_lid(2) && !hull.is_lid(3));
    assert_eq!(
        hull.caller_feature_on_edge::<Robust>(2, DVec2::new(2.0, 5.0)),
        None
    );
    assert_eq!(
        hull.caller_feature_on_edge::<Robust>(2, DVec2::new(9.0, 5.0)),
        Some(Feature::Vertex(2))
    );
    assert_eq!(
        hull.caller_feature_on_edge::<Robust>(1, DVec2::new(5.0, 2.0)),
        Some(Feature::Edge(1))
    );
    // The same hull from the point set, whose edges are all lids.
    let soup = convex_hull(poly.vertices()).expect("hull");
    assert_eq!(soup.vertices(), hull.vertices());
    assert!((0..soup.len()).all(|e| soup.is_lid(e)));
}

#[test]
fn locate_on_vertices_edges_and_outside() {
    let hex = convex(&[
        [2.0, 0.0],
        [4.0, 1.0],
        [4.0, 3.0],
        [2.0, 4.0],
        [0.0, 3.0],
        [0.0, 1.0],
    ])
    .expect("hexagon");
    let s = SimplePolygon::try_new(hex.vertices()).expect("simple");
    let cases = [
        ([2.0, 2.0], Location::Inside),
        ([2.0, 0.0], Location::Boundary),
        ([0.0, 3.0], Location::Boundary),
        ([0.0, 2.0], Location::Boundary),
        ([3.0, 0.5], Location::Boundary),
        ([1.0, 3.5], Location::Boundary),
        ([0.0, 4.0], Location::Outside),
        ([0.0, -1.0], Location::Outside),
        ([2.0, -1.0], Location::Outside),
        ([5.0, 2.0], Location::Outside),
        ([-1.0, 2.0], Location::Outside),
        ([f64::NAN, 2.0], Location::Outside),
        ([f64::INFINITY, 2.0], Location::Outside),
    ];
    for (p, expected) in cases {
        assert_eq!(hex.locate(DVec2::from(p)), expected, "convex locate {p:?}");
        assert_eq!(s.locate(DVec2::from(p)), expected, "simple locate {p:?}");
    }
}
