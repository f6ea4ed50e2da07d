//! The curves of a car's path, for pictures: the positions along the shortest curves between
//! its poses.

use trailmark_core::geometry::{Point, Pose};
use trailmark_sample::space::{Car, CarCurves};

/// The positions along the shortest curves of `space` joining `poses`, every turning radius / 8
/// (at most 10,000 points a curve), for a picture.
pub(super) fn car_curve<C: CarCurves>(space: &Car<C>, poses: &[Pose]) -> Vec<Point> {
    let radius = space.turning_radius();
    let mut curve = Vec::new();
    for pair in poses.windows(2) {
        let Some(piece) = C::path(&pair[0], &pair[1], radius) else { continue };
        let step = (radius / 8.0).max(C::path_length(&piece) / 1e4);
        let samples = C::sample(&piece, step).unwrap_or_default();
        curve.extend(samples.iter().map(|p| Point::from(p.translation.vector)));
    }
    curve
}
