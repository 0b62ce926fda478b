//! The ROS 2 payload of a message: a 4-byte encapsulation header (`00 01 00 00`, CDR little-endian,
//! i.e. XCDR1) followed by the plain-CDR body, aligned from the body's first byte. This is what DDS
//! puts in a sample and what rosbag2 stores in an MCAP (`message_encoding = cdr`).

use byteorder::LittleEndian;
use serde::{de::DeserializeOwned, Serialize};

use crate::BridgeError;

/// Encapsulation identifier CDR_LE with zero options.
pub const CDR_LE_HEADER: [u8; 4] = [0x00, 0x01, 0x00, 0x00];

/// Serialises a message as a ROS 2 CDR payload.
pub fn encode<M: Serialize>(message: &M) -> Result<Vec<u8>, BridgeError> {
    let mut out = CDR_LE_HEADER.to_vec();
    cdr_encoding::to_writer::<M, LittleEndian, _>(&mut out, message)
        .map_err(|e| BridgeError::Encode(e.to_string()))?;
    Ok(out)
}

/// Parses a ROS 2 CDR payload (little-endian only, as every ROS 2 middleware on x86 and ARM writes).
pub fn decode<M: DeserializeOwned>(payload: &[u8]) -> Result<M, BridgeError> {
    let Some((header, body)) = payload.split_first_chunk::<4>() else {
        return Err(BridgeError::Decode(format!(
            "payload of {} bytes has no encapsulation header",
            payload.len()
        )));
    };
    if header[..2] != CDR_LE_HEADER[..2] {
        return Err(BridgeError::Decode(format!(
            "encapsulation {:02x}{:02x} is not CDR_LE (0001)",
            header[0], header[1]
        )));
    }
    cdr_encoding::from_bytes::<M, LittleEndian>(body)
        .map(|(m, _)| m)
        .map_err(|e| BridgeError::Decode(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::msg::{CameraLandmarks, Header, JointTrajectory, JointTrajectoryPoint, Time};

    /// Bytes worked out by hand from the XCDR1 rules (4-byte aligned i32/u32/f32 and lengths,
    /// strings as length-with-NUL + bytes + NUL).
    #[test]
    fn camera_landmarks_known_bytes() {
        let m = CameraLandmarks {
            header: Header {
                stamp: Time { sec: 1, nanosec: 2 },
                frame_id: "c".into(),
            },
            camera_id: "ab".into(),
            image_width: 640,
            image_height: 480,
            x_px: vec![1.0],
            y_px: vec![],
            visibility: vec![0.5],
            presence: vec![],
        };
        let bytes = encode(&m).unwrap();
        let mut expected = vec![0, 1, 0, 0];
        expected.extend([1, 0, 0, 0, 2, 0, 0, 0]); // stamp
        expected.extend([2, 0, 0, 0, b'c', 0, 0, 0]); // frame_id "c" + NUL, padded
        expected.extend([3, 0, 0, 0, b'a', b'b', 0, 0]); // camera_id "ab" + NUL, padded
        expected.extend(640u32.to_le_bytes());
        expected.extend(480u32.to_le_bytes());
        expected.extend([1, 0, 0, 0]);
        expected.extend(1.0f32.to_le_bytes());
        expected.extend([0, 0, 0, 0]);
        expected.extend([1, 0, 0, 0]);
        expected.extend(0.5f32.to_le_bytes());
        expected.extend([0, 0, 0, 0]);
        assert_eq!(bytes, expected);
        assert_eq!(decode::<CameraLandmarks>(&bytes).unwrap(), m);
    }

    #[test]
    fn trajectory_round_trips_and_float64_is_8_aligned() {
        let m = JointTrajectory {
            header: Header::new(5, "base"),
            joint_names: vec!["joint_1".into()],
            points: vec![JointTrajectoryPoint {
                positions: vec![0.25],
                time_from_start: crate::msg::Duration::from_secs_f64(0.5),
                ..JointTrajectoryPoint::default()
            }],
        };
        let bytes = encode(&m).unwrap();
        assert_eq!(decode::<JointTrajectory>(&bytes).unwrap(), m);
        let at = bytes
            .windows(8)
            .position(|w| w == 0.25f64.to_le_bytes())
            .unwrap();
        assert_eq!((at - 4) % 8, 0, "float64 aligned to 8 from the body start");
    }

    #[test]
    fn marker_array_round_trips() {
        use crate::msg::{Marker, MarkerArray, Point};
        let m = MarkerArray {
            markers: vec![Marker {
                header: Header::new(7, "world"),
                ns: "operator".into(),
                id: 1,
                r#type: Marker::SPHERE_LIST,
                points: vec![Point {
                    x: 1.0,
                    y: 2.0,
                    z: 3.0,
                }],
                text: "t".into(),
                ..Marker::default()
            }],
        };
        let bytes = encode(&m).unwrap();
        assert_eq!(decode::<MarkerArray>(&bytes).unwrap(), m);
        // sequence length 1, then the header's stamp (7 ns)
        assert_eq!(&bytes[4..16], &[1, 0, 0, 0, 0, 0, 0, 0, 7, 0, 0, 0]);
    }

    #[test]
    fn refuses_foreign_encapsulation_and_short_payloads() {
        assert!(matches!(
            decode::<Time>(&[0, 1]),
            Err(BridgeError::Decode(_))
        ));
        assert!(matches!(
            decode::<Time>(&[0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0]),
            Err(BridgeError::Decode(_))
        ));
    }
}
