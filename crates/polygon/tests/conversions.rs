//! Conversions: slices of `[f64; 2]` and `DVec2`, serde (validating), geo-types (closing duplicate
//! dropped, holes rejected).

use glam::DVec2;
use polydist_polygon::{ConvexPolygon, PolygonError, SimplePolygon};

const SQUARE: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];

#[test]
fn slices_and_vectors_convert_both_ways() {
    let points: Vec<DVec2> = SQUARE.iter().map(|&p| DVec2::from(p)).collect();
    let a = ConvexPolygon::try_from(&SQUARE[..]).expect("square");
    let b = ConvexPolygon::try_from(&points[..]).expect("square");
    let c = ConvexPolygon::try_from(SQUARE.to_vec()).expect("square");
    assert_eq!(a, b);
    assert_eq!(a, c);
    assert_eq!(Vec::<[f64; 2]>::from(a), SQUARE.to_vec());
    let s = SimplePolygon::try_from(&SQUARE[..]).expect("square");
    assert_eq!(Vec::<[f64; 2]>::from(s), SQUARE.to_vec());
    assert_eq!(
        SimplePolygon::try_from(&[[0.0, 0.0]][..]),
        Err(PolygonError::TooFewVertices {
            found: 1,
            needed: 3
        })
    );
}

#[test]
fn errors_say_what_and_where() {
    let messages = [
        (PolygonError::Empty, "no vertices"),
        (PolygonError::NonFinite { index: 3 }, "vertex 3"),
        (PolygonError::OutOfRange { index: 4 }, "vertex 4"),
        (PolygonError::Spike { index: 5 }, "vertex 5 is a spike"),
        (PolygonError::NotConvex { index: 6 }, "vertex 6 is reflex"),
        (
            PolygonError::WindsMoreThanOnce { turns: 2 },
            "winds 2 times",
        ),
        (
            PolygonError::SelfIntersection {
                edge_a: 1,
                edge_b: 7,
            },
            "edges 1 and 7 intersect",
        ),
        (
            PolygonError::TooFewVertices {
                found: 2,
                needed: 3,
            },
            "2 distinct vertices; at least 3",
        ),
        (PolygonError::Degenerate, "collinear"),
        (PolygonError::HasHoles { holes: 2 }, "2 hole"),
    ];
    for (error, expected) in messages {
        assert!(error.to_string().contains(expected), "{error}");
    }
}

#[cfg(feature = "serde")]
mod serde_format {
    use super::SQUARE;
    use polydist_polygon::{ConvexPolygon, SimplePolygon};
    use serde::Deserialize;
    use serde::de::IntoDeserializer;
    use serde::de::value::{Error, SeqDeserializer};

    /// Deserializes a polygon from a list of `[x, y]` pairs through serde's own value deserializers.
    fn from_pairs<'de, T: Deserialize<'de>>(pairs: &[[f64; 2]]) -> Result<T, Error> {
        let seq: Vec<Vec<f64>> = pairs.iter().map(|p| p.to_vec()).collect();
        let de: SeqDeserializer<_, Error> = seq.into_deserializer();
        T::deserialize(de)
    }

    #[test]
    fn deserialization_validates() {
        let square: ConvexPolygon = from_pairs(&SQUARE).expect("square");
        assert_eq!(
            square,
            ConvexPolygon::try_from(&SQUARE[..]).expect("square")
        );
        let pentagram = [
            [0.0, 10.0],
            [-6.0, -8.0],
            [10.0, 3.0],
            [-10.0, 3.0],
            [6.0, -8.0],
        ];
        let err = from_pairs::<ConvexPolygon>(&pentagram).expect_err("pentagram");
        assert!(err.to_string().contains("winds 2 times"), "{err}");
        let err = from_pairs::<SimplePolygon>(&[[0.0, 0.0], [f64::NAN, 1.0], [1.0, 0.0]])
            .expect_err("NaN");
        assert!(err.to_string().contains("vertex 1"), "{err}");
        let bow_tie = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        assert!(from_pairs::<SimplePolygon>(&bow_tie).is_err());
    }

    #[test]
    fn serialized_vertices_deserialize_to_the_same_polygon() {
        // Clockwise with a repeat: serialized as the clean counter-clockwise vertex list.
        let ring = [[0.0, 0.0], [0.0, 2.0], [0.0, 2.0], [2.0, 2.0], [2.0, 0.0]];
        let p = SimplePolygon::try_from(&ring[..]).expect("square");
        let pairs: Vec<[f64; 2]> = p.clone().into();
        assert_eq!(pairs, [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
        let back: SimplePolygon = from_pairs(&pairs).expect("round trip");
        assert_eq!(back.vertices(), p.vertices());
        assert_eq!(back, SimplePolygon::try_new(p.vertices()).expect("clean"));
    }
}

#[cfg(feature = "geo-types")]
mod geo {
    use geo_types::{LineString, Polygon, coord};
    use polydist_polygon::{ConvexPolygon, PolygonError, SimplePolygon};

    fn square() -> LineString<f64> {
        LineString::new(vec![
            coord! { x: 0.0, y: 0.0 },
            coord! { x: 1.0, y: 0.0 },
            coord! { x: 1.0, y: 1.0 },
            coord! { x: 0.0, y: 1.0 },
        ])
    }

    #[test]
    fn the_closing_duplicate_is_dropped() {
        let polygon = Polygon::new(square(), vec![]);
        assert_eq!(polygon.exterior().0.len(), 5); // geo-types closes the ring
        let p = ConvexPolygon::try_from(&polygon).expect("square");
        assert_eq!(p.len(), 4);
        assert_eq!(p.caller_len(), 4);
        let s = SimplePolygon::try_from(&polygon).expect("square");
        assert_eq!(s.caller_len(), 4);
        let open = SimplePolygon::try_from(&square()).expect("open ring");
        assert_eq!(open, s);
    }

    #[test]
    fn holes_are_a_typed_error() {
        let hole = LineString::new(vec![
            coord! { x: 0.25, y: 0.25 },
            coord! { x: 0.5, y: 0.25 },
            coord! { x: 0.25, y: 0.5 },
        ]);
        let polygon = Polygon::new(square(), vec![hole.clone(), hole]);
        assert_eq!(
            ConvexPolygon::try_from(&polygon),
            Err(PolygonError::HasHoles { holes: 2 })
        );
        assert_eq!(
            SimplePolygon::try_from(&polygon),
            Err(PolygonError::HasHoles { holes: 2 })
        );
        let empty = LineString::<f64>::new(vec![]);
        assert_eq!(ConvexPolygon::try_from(&empty), Err(PolygonError::Empty));
    }
}
