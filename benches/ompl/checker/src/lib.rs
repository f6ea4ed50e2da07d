//! trailmark's exact collision checks behind a C interface, so that the OMPL driver of
//! `cargo xtask bench --with-ompl` (`benches/ompl/driver.cpp`) validates states and motions with
//! exactly the tests trailmark's planners use: the comparison then measures the planners alone.
//!
//! ```
//! use std::ffi::CString;
//! use trailmark_ompl_checker::*;
//!
//! let world = CString::new(r#"{"bounds": [0, 0, 10, 10],
//!     "obstacles": [[[4, 0], [6, 0], [6, 8], [4, 8]]], "robot_radius": 0.5}"#).unwrap();
//! let checker = unsafe { tm_checker_new(world.as_ptr()) };
//! assert!(!checker.is_null());
//! unsafe {
//!     assert!(tm_point_is_free(checker, 1.0, 1.0));
//!     assert!(!tm_point_is_free(checker, 3.8, 1.0)); // within the radius of the wall
//!     assert!(!tm_segment_is_free(checker, 1.0, 1.0, 9.0, 1.0)); // through the wall
//!     assert!(tm_segment_is_free(checker, 1.0, 9.0, 9.0, 9.0)); // above it
//!     tm_checker_free(checker);
//! }
//! ```

use std::ffi::{CStr, c_char};

use trailmark_core::dubins::DubinsPath;
use trailmark_core::geometry::{Point, Pose, Vector};
use trailmark_core::reeds_shepp::ReedsSheppPath;
use trailmark_core::world::{CollisionChecker, PolygonWorld};

/// The checker of the world given as a JSON document
/// (`{"bounds": [xmin, ymin, xmax, ymax], "obstacles": [...], "robot_radius": r}`), or null when
/// the pointer is null, the text is not UTF-8 or the document is not a valid world (the reason
/// is printed on standard error). Free it with [`tm_checker_free`].
///
/// # Safety
///
/// `json` is null or points to a NUL-terminated string.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tm_checker_new(json: *const c_char) -> *mut CollisionChecker {
    if json.is_null() {
        eprintln!("tm_checker_new: null document");
        return std::ptr::null_mut();
    }
    // SAFETY: the caller passes a NUL-terminated string.
    let text = unsafe { CStr::from_ptr(json) };
    let world = text
        .to_str()
        .map_err(|e| e.to_string())
        .and_then(|t| serde_json::from_str::<PolygonWorld>(t).map_err(|e| e.to_string()));
    match world {
        Ok(world) => Box::into_raw(Box::new(world.checker())),
        Err(e) => {
            eprintln!("tm_checker_new: {e}");
            std::ptr::null_mut()
        }
    }
}

/// Frees a checker made by [`tm_checker_new`] (null is ignored).
///
/// # Safety
///
/// `checker` is null or came from [`tm_checker_new`] and was not freed before.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tm_checker_free(checker: *mut CollisionChecker) {
    if !checker.is_null() {
        // SAFETY: the pointer came from Box::into_raw in tm_checker_new, freed once.
        drop(unsafe { Box::from_raw(checker) });
    }
}

/// Whether the robot at `(x, y)` is collision-free
/// ([`CollisionChecker::point_is_free`]); false for a null checker.
///
/// # Safety
///
/// `checker` is null or a live checker from [`tm_checker_new`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tm_point_is_free(checker: *const CollisionChecker, x: f64, y: f64) -> bool {
    // SAFETY: null or a live checker, by the caller's contract.
    unsafe { checker.as_ref() }.is_some_and(|c| c.point_is_free(Point::new(x, y)))
}

/// Whether the robot moving straight from `(ax, ay)` to `(bx, by)` stays collision-free
/// ([`CollisionChecker::segment_is_free`]); false for a null checker.
///
/// # Safety
///
/// `checker` is null or a live checker from [`tm_checker_new`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tm_segment_is_free(
    checker: *const CollisionChecker,
    ax: f64,
    ay: f64,
    bx: f64,
    by: f64,
) -> bool {
    // SAFETY: null or a live checker, by the caller's contract.
    unsafe { checker.as_ref() }.is_some_and(|c| c.segment_is_free(Point::new(ax, ay), Point::new(bx, by)))
}

/// Whether the robot driving the shortest Reeds-Shepp curve of turning radius `r` from pose
/// `a` to pose `b` (`[x, y, heading]` each) stays collision-free, its arcs and segments checked
/// exactly ([`CollisionChecker::reeds_shepp_is_free`], as trailmark's Reeds-Shepp space checks a
/// motion); false for a null pointer or a curve that cannot be made.
///
/// # Safety
///
/// `checker` is null or a live checker from [`tm_checker_new`]; `a` and `b` are null or point
/// to three numbers each.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tm_reeds_shepp_is_free(
    checker: *const CollisionChecker,
    a: *const [f64; 3],
    b: *const [f64; 3],
    r: f64,
) -> bool {
    // SAFETY: null or live pointers, by the caller's contract.
    unsafe { curve_is_free(checker, a, b) }.is_some_and(|(c, a, b)| {
        ReedsSheppPath::shortest(&a, &b, r).is_ok_and(|path| c.reeds_shepp_is_free(&path))
    })
}

/// As [`tm_reeds_shepp_is_free`] for the shortest Dubins curve (forward only).
///
/// # Safety
///
/// As for [`tm_reeds_shepp_is_free`].
#[unsafe(no_mangle)]
pub unsafe extern "C" fn tm_dubins_is_free(
    checker: *const CollisionChecker,
    a: *const [f64; 3],
    b: *const [f64; 3],
    r: f64,
) -> bool {
    // SAFETY: null or live pointers, by the caller's contract.
    unsafe { curve_is_free(checker, a, b) }
        .is_some_and(|(c, a, b)| DubinsPath::shortest(&a, &b, r).is_ok_and(|path| c.dubins_is_free(&path)))
}

/// The checker and the two poses behind the pointers, or `None` if one is null.
///
/// # Safety
///
/// Each pointer is null or valid.
unsafe fn curve_is_free<'c>(
    checker: *const CollisionChecker,
    a: *const [f64; 3],
    b: *const [f64; 3],
) -> Option<(&'c CollisionChecker, Pose, Pose)> {
    // SAFETY: null or valid, by the caller's contract.
    let (c, a, b) = unsafe { (checker.as_ref()?, a.as_ref()?, b.as_ref()?) };
    Some((c, pose(a), pose(b)))
}

fn pose(p: &[f64; 3]) -> Pose {
    Pose::new(Vector::new(p[0], p[1]), p[2])
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::CString;

    #[test]
    fn bad_documents_give_null_and_null_checkers_refuse() {
        for text in ["", "{}", r#"{"bounds": [0, 0, -1, 1]}"#, "[1, 2]"] {
            let c = CString::new(text).unwrap();
            assert!(unsafe { tm_checker_new(c.as_ptr()) }.is_null(), "{text}");
        }
        assert!(unsafe { tm_checker_new(std::ptr::null()) }.is_null());
        assert!(!unsafe { tm_point_is_free(std::ptr::null(), 1.0, 1.0) });
        assert!(!unsafe { tm_segment_is_free(std::ptr::null(), 1.0, 1.0, 2.0, 2.0) });
        let (a, b) = ([1.0, 1.0, 0.0], [2.0, 2.0, 0.0]);
        assert!(!unsafe { tm_reeds_shepp_is_free(std::ptr::null(), &a, &b, 1.0) });
        assert!(!unsafe { tm_dubins_is_free(std::ptr::null(), &a, &b, 1.0) });
        unsafe { tm_checker_free(std::ptr::null_mut()) };
    }

    #[test]
    fn answers_equal_the_checker() {
        let doc =
            r#"{"bounds": [0, 0, 10, 10], "obstacles": [[[2, 2], [5, 3], [3, 6]]], "robot_radius": 0.3}"#;
        let world: PolygonWorld = serde_json::from_str(doc).unwrap();
        let reference = world.checker();
        let c = CString::new(doc).unwrap();
        let checker = unsafe { tm_checker_new(c.as_ptr()) };
        for i in 0..40 {
            for j in 0..40 {
                let (x, y) = (i as f64 * 0.26 - 0.1, j as f64 * 0.26 - 0.1);
                let p = Point::new(x, y);
                assert_eq!(unsafe { tm_point_is_free(checker, x, y) }, reference.point_is_free(p));
                let q = Point::new(10.0 - y, x);
                assert_eq!(
                    unsafe { tm_segment_is_free(checker, x, y, q.x, q.y) },
                    reference.segment_is_free(p, q)
                );
                let (a, b) = ([x, y, 0.3 * i as f64], [q.x, q.y, -0.2 * j as f64]);
                let rs = ReedsSheppPath::shortest(&pose(&a), &pose(&b), 0.7).unwrap();
                let dubins = DubinsPath::shortest(&pose(&a), &pose(&b), 0.7).unwrap();
                assert_eq!(
                    unsafe { tm_reeds_shepp_is_free(checker, &a, &b, 0.7) },
                    reference.reeds_shepp_is_free(&rs)
                );
                assert_eq!(
                    unsafe { tm_dubins_is_free(checker, &a, &b, 0.7) },
                    reference.dubins_is_free(&dubins)
                );
            }
        }
        unsafe { tm_checker_free(checker) };
    }
}
