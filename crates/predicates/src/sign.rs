//! The answers predicates give: signs and orientations, never raw floats.

use core::cmp::Ordering;

/// The sign of a real number, decided exactly by the `Robust` and `Exact` kernels.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Sign {
    /// Strictly below zero.
    Negative,
    /// Exactly zero.
    Zero,
    /// Strictly above zero.
    Positive,
}

impl Sign {
    /// The sign of an `f64`; NaN maps to [`Sign::Zero`] (the Fast kernel's only answer for it).
    #[inline]
    #[must_use]
    pub fn of_f64(x: f64) -> Self {
        if x > 0.0 {
            Sign::Positive
        } else if x < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        }
    }

    /// `Negative < Zero < Positive` read as the comparison of the value with zero.
    #[inline]
    #[must_use]
    pub fn to_ordering(self) -> Ordering {
        match self {
            Sign::Negative => Ordering::Less,
            Sign::Zero => Ordering::Equal,
            Sign::Positive => Ordering::Greater,
        }
    }

    /// The sign of `a − b` given `a.cmp(b)`.
    #[inline]
    #[must_use]
    pub fn from_ordering(o: Ordering) -> Self {
        match o {
            Ordering::Less => Sign::Negative,
            Ordering::Equal => Sign::Zero,
            Ordering::Greater => Sign::Positive,
        }
    }

    /// The sign of the negated value.
    #[inline]
    #[must_use]
    pub fn reversed(self) -> Self {
        match self {
            Sign::Negative => Sign::Positive,
            Sign::Zero => Sign::Zero,
            Sign::Positive => Sign::Negative,
        }
    }

    /// `true` for [`Sign::Positive`].
    #[inline]
    #[must_use]
    pub fn is_positive(self) -> bool {
        self == Sign::Positive
    }

    /// `true` for [`Sign::Negative`].
    #[inline]
    #[must_use]
    pub fn is_negative(self) -> bool {
        self == Sign::Negative
    }

    /// `true` for [`Sign::Zero`].
    #[inline]
    #[must_use]
    pub fn is_zero(self) -> bool {
        self == Sign::Zero
    }
}

/// The orientation of an ordered triple of points `(a, b, c)`: the sign of `(b − a) × (c − a)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Orientation {
    /// `c` lies strictly to the right of the directed line `a → b`.
    Clockwise,
    /// The three points lie on one line (including coincident points).
    Collinear,
    /// `c` lies strictly to the left of the directed line `a → b`.
    CounterClockwise,
}

impl Orientation {
    /// The orientation whose determinant has sign `s`.
    #[inline]
    #[must_use]
    pub fn from_sign(s: Sign) -> Self {
        match s {
            Sign::Negative => Orientation::Clockwise,
            Sign::Zero => Orientation::Collinear,
            Sign::Positive => Orientation::CounterClockwise,
        }
    }

    /// The sign of the orientation determinant.
    #[inline]
    #[must_use]
    pub fn sign(self) -> Sign {
        match self {
            Orientation::Clockwise => Sign::Negative,
            Orientation::Collinear => Sign::Zero,
            Orientation::CounterClockwise => Sign::Positive,
        }
    }

    /// The orientation of the triple with two points swapped.
    #[inline]
    #[must_use]
    pub fn reversed(self) -> Self {
        Self::from_sign(self.sign().reversed())
    }

    /// `true` for [`Orientation::CounterClockwise`] (a left turn).
    #[inline]
    #[must_use]
    pub fn is_ccw(self) -> bool {
        self == Orientation::CounterClockwise
    }

    /// `true` for [`Orientation::Clockwise`] (a right turn).
    #[inline]
    #[must_use]
    pub fn is_cw(self) -> bool {
        self == Orientation::Clockwise
    }

    /// `true` for [`Orientation::Collinear`].
    #[inline]
    #[must_use]
    pub fn is_collinear(self) -> bool {
        self == Orientation::Collinear
    }
}
