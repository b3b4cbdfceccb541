//! Conversions into the polygon types: from `[f64; 2]` and `DVec2` slices, and, behind the
//! `geo-types` feature, from `geo_types::{Polygon, LineString}`. Every conversion validates.
//! The `Vec<[f64; 2]>` conversions in both directions carry the serde representation.

use glam::DVec2;

use crate::{ConvexPolygon, PolygonError, SimplePolygon};

/// The points of `[x, y]` pairs.
fn points(coords: &[[f64; 2]]) -> Vec<DVec2> {
    coords.iter().map(|&p| DVec2::from(p)).collect()
}

/// Implements the conversions for a polygon type with `try_new(&[DVec2])` and `vertices()`.
macro_rules! conversions {
    ($polygon:ident) => {
        impl TryFrom<&[DVec2]> for $polygon {
            type Error = PolygonError;
            /// See [`Self::try_new`].
            fn try_from(vertices: &[DVec2]) -> Result<Self, PolygonError> {
                $polygon::try_new(vertices)
            }
        }

        impl TryFrom<&[[f64; 2]]> for $polygon {
            type Error = PolygonError;
            /// See [`Self::try_new`].
            fn try_from(coords: &[[f64; 2]]) -> Result<Self, PolygonError> {
                $polygon::try_new(&points(coords))
            }
        }

        impl TryFrom<Vec<[f64; 2]>> for $polygon {
            type Error = PolygonError;
            /// See [`Self::try_new`]. This is the serde representation.
            fn try_from(coords: Vec<[f64; 2]>) -> Result<Self, PolygonError> {
                $polygon::try_new(&points(&coords))
            }
        }

        impl From<$polygon> for Vec<[f64; 2]> {
            /// The vertices, counter-clockwise (the serde representation; the map to the original
            /// caller's indices is not kept).
            fn from(polygon: $polygon) -> Self {
                polygon.vertices().iter().map(|p| p.to_array()).collect()
            }
        }

        #[cfg(feature = "geo-types")]
        impl TryFrom<&geo_types::LineString<f64>> for $polygon {
            type Error = PolygonError;
            /// The ring's coordinates, without the closing duplicate when the ring is closed (so caller
            /// indices are positions in the line string). See [`Self::try_new`].
            fn try_from(ring: &geo_types::LineString<f64>) -> Result<Self, PolygonError> {
                $polygon::try_new(&geo::open_ring(ring))
            }
        }

        #[cfg(feature = "geo-types")]
        impl TryFrom<&geo_types::Polygon<f64>> for $polygon {
            type Error = PolygonError;
            /// The exterior ring, as for a `LineString`.
            ///
            /// # Errors
            /// [`PolygonError::HasHoles`] when the polygon has interior rings, otherwise as
            /// [`Self::try_new`].
            fn try_from(polygon: &geo_types::Polygon<f64>) -> Result<Self, PolygonError> {
                match polygon.interiors().len() {
                    0 => $polygon::try_from(polygon.exterior()),
                    holes => Err(PolygonError::HasHoles { holes }),
                }
            }
        }
    };
}

conversions!(ConvexPolygon);
conversions!(SimplePolygon);

#[cfg(feature = "geo-types")]
mod geo {
    use glam::DVec2;

    /// The ring's points, without the closing duplicate of a closed ring.
    pub(super) fn open_ring(ring: &geo_types::LineString<f64>) -> Vec<DVec2> {
        let mut points: Vec<DVec2> = ring.coords().map(|c| DVec2::new(c.x, c.y)).collect();
        if points.len() >= 2 && points.first() == points.last() {
            points.pop();
        }
        points
    }
}
