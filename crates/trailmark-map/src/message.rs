//! `nav_msgs/OccupancyGrid` messages as JSON, as rosbridge and `ros2 topic echo` give them:
//! `info` (width, height, resolution, origin pose) and row-major `data` (-1..=100) starting at
//! the origin's row, the bottom of the map.
//!
//! ```
//! use trailmark_core::grid::Cell;
//! use trailmark_map::OccupancyGrid;
//!
//! let json = r#"{"header": {"frame_id": "map"},
//!   "info": {"resolution": 0.5, "width": 3, "height": 2,
//!            "origin": {"position": {"x": -1.0, "y": 0.0, "z": 0.0},
//!                       "orientation": {"x": 0.0, "y": 0.0, "z": 0.0, "w": 1.0}}},
//!   "data": [0, 0, 100,
//!            -1, 0, 0]}"#;
//! let map = OccupancyGrid::from_message_json(json)?;
//! // The message's first row is the bottom row of the map.
//! assert_eq!(map.value(Cell::new(2, 1)), Some(100));
//! assert_eq!(map.value(Cell::new(0, 0)), Some(-1));
//! let back = OccupancyGrid::from_message_json(&map.to_message_json())?;
//! assert_eq!(back, map);
//! # Ok::<(), trailmark_map::MapError>(())
//! ```

use serde::{Deserialize, Serialize};

use crate::error::MapError;
use crate::frame::MapFrame;
use crate::occupancy::OccupancyGrid;

/// The largest message text read: 1 GiB.
pub const MAX_MESSAGE_BYTES: usize = 1 << 30;

#[derive(Debug, Serialize, Deserialize)]
struct Message {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    header: Option<Header>,
    info: Info,
    data: Vec<i64>,
}

#[derive(Debug, Serialize, Deserialize)]
struct Header {
    #[serde(default)]
    frame_id: String,
}

#[derive(Debug, Serialize, Deserialize)]
struct Info {
    resolution: f64,
    width: u64,
    height: u64,
    origin: PoseMsg,
}

#[derive(Debug, Serialize, Deserialize)]
struct PoseMsg {
    position: Xyz,
    orientation: Quaternion,
}

#[derive(Debug, Serialize, Deserialize)]
struct Xyz {
    x: f64,
    y: f64,
    #[serde(default)]
    z: f64,
}

#[derive(Debug, Serialize, Deserialize)]
struct Quaternion {
    x: f64,
    y: f64,
    z: f64,
    w: f64,
}

impl OccupancyGrid {
    /// Reads a `nav_msgs/OccupancyGrid` message from JSON (the header is optional and not
    /// used). The origin's orientation must be a rotation about z ([`MapError::NotLevel`]);
    /// its yaw becomes the frame's.
    pub fn from_message_json(json: &str) -> Result<Self, MapError> {
        if json.len() > MAX_MESSAGE_BYTES {
            return Err(MapError::Message {
                reason: format!("the text is larger than {MAX_MESSAGE_BYTES} bytes"),
            });
        }
        let message: Message =
            serde_json::from_str(json).map_err(|e| MapError::Message { reason: e.to_string() })?;
        let Info { resolution, width, height, origin } = message.info;
        let q = origin.orientation;
        let norm = (q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w).sqrt();
        let level = norm.is_finite() && norm > 0.0 && (q.x / norm).abs() < 1e-9 && (q.y / norm).abs() < 1e-9;
        if !level {
            return Err(MapError::NotLevel { quaternion: [q.x, q.y, q.z, q.w] });
        }
        let yaw = 2.0 * q.z.atan2(q.w);
        let too_large = || MapError::TooLarge { width, height };
        let (w, h) = (
            usize::try_from(width).map_err(|_| too_large())?,
            usize::try_from(height).map_err(|_| too_large())?,
        );
        let frame = MapFrame::new(w, h, resolution, [origin.position.x, origin.position.y, yaw])?;
        frame.check_count(message.data.len())?;
        if let Some(index) = message.data.iter().position(|v| !(-1..=100).contains(v)) {
            return Err(MapError::Occupancy { index, value: message.data[index] });
        }
        // The message's row 0 is the bottom of the map; trailmark's is the top.
        let mut values = Vec::with_capacity(message.data.len());
        for row in message.data.chunks(w).rev() {
            values.extend(row.iter().map(|&v| v as i8));
        }
        OccupancyGrid::new(frame, values)
    }

    /// The map as a `nav_msgs/OccupancyGrid` message in JSON, frame `map`.
    pub fn to_message_json(&self) -> String {
        let frame = self.frame();
        let [x, y, yaw] = frame.origin();
        let w = frame.width() as usize;
        let mut data = Vec::with_capacity(self.values().len());
        for row in self.values().chunks(w).rev() {
            data.extend(row.iter().map(|&v| i64::from(v)));
        }
        let message = Message {
            header: Some(Header { frame_id: "map".into() }),
            info: Info {
                resolution: frame.resolution(),
                width: u64::from(frame.width()),
                height: u64::from(frame.height()),
                origin: PoseMsg {
                    position: Xyz { x, y, z: 0.0 },
                    orientation: Quaternion { x: 0.0, y: 0.0, z: (yaw / 2.0).sin(), w: (yaw / 2.0).cos() },
                },
            },
            data,
        };
        serde_json::to_string(&message).expect("a message of numbers serializes")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message(info: &str, data: &str) -> String {
        format!(r#"{{"info": {info}, "data": {data}}}"#)
    }

    const INFO: &str = r#"{"resolution": 0.1, "width": 2, "height": 2,
        "origin": {"position": {"x": 0, "y": 0, "z": 0}, "orientation": {"x": 0, "y": 0, "z": 0, "w": 1}}}"#;

    #[test]
    fn bad_messages_are_named() {
        let err = |json: String| OccupancyGrid::from_message_json(&json).unwrap_err();
        assert!(matches!(err(message(INFO, "[0, 0, 0]")), MapError::CellCount { found: 3, .. }));
        assert!(matches!(err(message(INFO, "[0, 0, 0, 127]")), MapError::Occupancy { index: 3, value: 127 }));
        assert!(matches!(err(message(INFO, "[0, 0, 0, -2]")), MapError::Occupancy { .. }));
        assert!(matches!(
            err(message(&INFO.replace("0.1", "-0.1"), "[0, 0, 0, 0]")),
            MapError::Resolution { .. }
        ));
        assert!(matches!(
            err(message(
                &INFO.replace(
                    "\"x\": 0, \"y\": 0, \"z\": 0, \"w\": 1",
                    "\"x\": 1, \"y\": 0, \"z\": 0, \"w\": 0"
                ),
                "[0,0,0,0]"
            )),
            MapError::NotLevel { .. }
        ));
        assert!(matches!(
            err(message(&INFO.replace("\"width\": 2", "\"width\": 0"), "[]")),
            MapError::Grid(_)
        ));
        assert!(matches!(
            err(message(&INFO.replace("\"width\": 2", "\"width\": 4294967296000"), "[]")),
            MapError::Grid(_) | MapError::TooLarge { .. }
        ));
        assert!(matches!(err("{".into()), MapError::Message { .. }));
    }

    #[test]
    fn yaw_comes_from_the_quaternion() {
        let half = std::f64::consts::FRAC_PI_4.sin();
        let info = INFO.replace("\"z\": 0, \"w\": 1", &format!("\"z\": {half}, \"w\": {half}"));
        let map = OccupancyGrid::from_message_json(&message(&info, "[0, 0, 0, 0]")).unwrap();
        assert!((map.frame().origin()[2] - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    }
}
