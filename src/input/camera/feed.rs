//! A live camera as a source of contact images: the newest frame that had
//! arrived by a physics step's own time, rectified into that step's contact
//! image through the calibration, as recorded frames are
//! ([`crate::input::images::ImageSequence`]).

use super::capture::{self, CameraSource, FrameGrabber, Shared};
use super::{CameraError, RawFormat};
use crate::input::images::{
    BitDepth, Calibration, CameraImage, CameraKind, Conversion, DEFAULT_THRESHOLD, DEFAULT_TOUCH_BAND_MM, Rectifier,
};
use crate::pipeline::surface::{ContactImage, Sensor};
use std::collections::VecDeque;
use std::path::Path;
use std::sync::Arc;
use std::time::Instant;

/// Frames from a capture thread, played against the session's steps.
#[derive(Debug)]
pub struct CameraFeed {
    device: String,
    format: RawFormat,
    /// Given, or made from the first frame (see [`whole_view`]).
    calibration: Option<Calibration>,
    shared: Arc<Shared>,
    /// Taken from the capture thread, not yet due.
    pending: VecDeque<(Instant, CameraImage)>,
    /// Why the stream ended, said once the frames before it are used.
    failed: Option<CameraError>,
    /// The frame now shown, kept to rectify again for another sensor.
    shown: Option<CameraImage>,
    rectifier: Option<Rectifier>,
    image: ContactImage,
    used: u64,
}

impl CameraFeed {
    /// Opens a V4L2 device (`/dev/videoN`) and starts capturing: the size
    /// the calibration was made for, else the device's current size; a
    /// 16-bit format for a depth calibration, a grey or packed one for
    /// infrared, as [`PixelFormat::preference`](super::PixelFormat::preference) orders them.
    pub fn open(device: &Path, calibration: Option<Calibration>) -> Result<CameraFeed, CameraError> {
        #[cfg(feature = "camera")]
        {
            let grabber = super::device::V4lCamera::open(device, calibration.as_ref())?;
            Self::start(Box::new(grabber), calibration)
        }
        #[cfg(not(feature = "camera"))]
        {
            let _ = (device, calibration);
            Err(CameraError::NotBuilt)
        }
    }

    /// Starts a capture thread on `grabber`. A calibration must be for the
    /// grabber's frame size, and a depth one needs 16-bit frames.
    pub fn start(grabber: Box<dyn FrameGrabber>, calibration: Option<Calibration>) -> Result<CameraFeed, CameraError> {
        let CameraSource { device, format } = grabber.source().clone();
        format.check()?;
        if let Some(c) = &calibration {
            fits(&device, &format, c)?;
        }
        let shared = Arc::new(Shared::default());
        capture::spawn(grabber, Arc::clone(&shared))
            .map_err(|source| CameraError::Capture { device: device.clone(), source })?;
        Ok(CameraFeed {
            device,
            format,
            calibration,
            shared,
            pending: VecDeque::new(),
            failed: None,
            shown: None,
            rectifier: None,
            image: ContactImage::default(),
            used: 0,
        })
    }

    pub fn device(&self) -> &str {
        &self.device
    }

    pub fn format(&self) -> RawFormat {
        self.format
    }

    /// The calibration in use: the one given, or the one made from the
    /// first frame (none before it).
    pub fn calibration(&self) -> Option<&Calibration> {
        self.calibration.as_ref()
    }

    /// Frames shown so far, and frames the capture thread dropped because
    /// newer ones came before the session took them.
    pub fn counts(&self) -> (u64, u64) {
        (self.used, self.shared.dropped())
    }

    /// The contact image the physics step at instant `at` sees: the newest
    /// frame that had arrived by then (the previous one while none is new;
    /// blank before the first). The stream's end or failure is an error,
    /// once the frames before it have been shown.
    pub fn image_at(&mut self, at: Instant, sensor: &Sensor) -> Result<&ContactImage, CameraError> {
        for delivery in self.shared.take() {
            match delivery {
                Ok(frame) => self.pending.push_back(frame),
                Err(e) => {
                    self.failed.get_or_insert(e);
                }
            }
        }
        let mut due = None;
        while self.pending.front().is_some_and(|(arrived, _)| *arrived <= at) {
            due = self.pending.pop_front().map(|(_, frame)| frame);
        }
        if due.is_none()
            && self.pending.is_empty()
            && let Some(e) = self.failed.take()
        {
            return Err(e);
        }
        let new_sensor = self.rectifier.as_ref().is_none_or(|r| r.sensor() != sensor);
        if due.is_none() && !new_sensor {
            return Ok(&self.image);
        }
        if let Some(frame) = due {
            self.used += 1;
            self.shown = Some(frame);
        }
        let Some(frame) = &self.shown else {
            self.image = ContactImage::new(sensor.width_px as usize, sensor.height_px as usize);
            return Ok(&self.image);
        };
        if self.calibration.is_none() {
            self.calibration = Some(whole_view(frame, sensor, &self.device)?);
        }
        let calibration = self.calibration.as_ref().expect("set above");
        if new_sensor {
            self.rectifier = Some(Rectifier::new(calibration, sensor));
        }
        let rectifier = self.rectifier.as_ref().expect("set above");
        if !rectifier.rectify(frame, &mut self.image) {
            return Err(CameraError::Mismatch {
                device: self.device.clone(),
                problem: format!(
                    "a {}x{} frame does not fit the {} calibration for {}x{}",
                    frame.width,
                    frame.height,
                    calibration.kind().name(),
                    calibration.image_size[0],
                    calibration.image_size[1]
                ),
            });
        }
        Ok(&self.image)
    }
}

impl Drop for CameraFeed {
    /// The capture thread ends after its next frame.
    fn drop(&mut self) {
        self.shared.stop();
    }
}

/// Whether `calibration` can read frames of `format`.
pub fn fits(device: &str, format: &RawFormat, calibration: &Calibration) -> Result<(), CameraError> {
    let size = [format.width, format.height];
    let problem = if size != calibration.image_size {
        Some(format!(
            "delivers {}x{} frames; the calibration is for {}x{}",
            size[0], size[1], calibration.image_size[0], calibration.image_size[1]
        ))
    } else if calibration.kind() == CameraKind::Depth && !format.pixel.is_16_bit() {
        Some(format!("delivers 8-bit {} frames; a depth calibration needs 16-bit millimetres", format.pixel.name()))
    } else {
        None
    };
    problem.map_or(Ok(()), |problem| Err(CameraError::Mismatch { device: device.to_owned(), problem }))
}

/// The calibration used when none is given: the camera looks straight down
/// and its picture spans the table exactly, corner to corner (image top =
/// the table's far edge). 8-bit frames are infrared with the default
/// threshold and no background; 16-bit frames are depth, the table at the
/// first frame's median reading (the table fills most of the view), with
/// the default touch band.
pub fn whole_view(frame: &CameraImage, sensor: &Sensor, device: &str) -> Result<Calibration, CameraError> {
    let (w, h) = (f64::from(frame.width), f64::from(frame.height));
    let image_points = [[-0.5, -0.5], [w - 0.5, -0.5], [w - 0.5, h - 0.5], [-0.5, h - 0.5]];
    let (hw, hd) = (f64::from(sensor.table_width_m) / 2.0, f64::from(sensor.table_depth_m) / 2.0);
    let table_points = [[-hw, hd], [hw, hd], [hw, -hd], [-hw, -hd]];
    let conversion = match frame.depth() {
        BitDepth::Eight => Conversion::Ir { threshold: DEFAULT_THRESHOLD, background: None },
        BitDepth::Sixteen => {
            let table_depth_mm = frame.median_reading().ok_or_else(|| CameraError::Mismatch {
                device: device.to_owned(),
                problem: "the first depth frame has no readings (all 0); give a --calibration".into(),
            })?;
            Conversion::Depth { table_depth_mm, touch_band_mm: DEFAULT_TOUCH_BAND_MM }
        }
    };
    let origin = format!("{device} (the whole view onto the table)");
    Ok(Calibration::new(conversion, [frame.width, frame.height], image_points, table_points, &origin)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::camera::{ChannelCamera, PixelFormat, encode};
    use crate::input::images::Pixels;
    use std::sync::mpsc;
    use std::time::Duration;

    const W: u32 = 64;
    const H: u32 = 48;

    fn sensor() -> Sensor {
        Sensor::new(32, 24, 0.64, 0.48)
    }

    /// An 8-bit frame, dark but for one bright 8x8 square at pixel `(x, y)`.
    fn square_at(x: u32, y: u32) -> CameraImage {
        let pixels = (0..W * H).map(|i| if (i % W).abs_diff(x) < 4 && (i / W).abs_diff(y) < 4 { 250 } else { 10 });
        CameraImage { width: W, height: H, pixels: Pixels::Grey8(pixels.collect()) }
    }

    fn feed(calibration: Option<Calibration>) -> (CameraFeed, mpsc::Sender<Vec<u8>>, RawFormat) {
        let format = RawFormat { stride: 2 * W + 8, ..RawFormat::packed(W, H, PixelFormat::Yuyv) };
        let (camera, tx) = ChannelCamera::new("test-camera", format);
        (CameraFeed::start(Box::new(camera), calibration).expect("starts"), tx, format)
    }

    /// Waits until the capture thread has queued `n` more frames; returns
    /// the instant after which they had all arrived.
    fn arrived(feed: &CameraFeed, before: usize) -> Instant {
        let deadline = Instant::now() + Duration::from_secs(5);
        while feed.shared.queued() < before + 1 {
            assert!(Instant::now() < deadline, "the capture thread delivered nothing in 5 s");
            std::thread::sleep(Duration::from_millis(1));
        }
        Instant::now()
    }

    /// The grey-weighted centre of a contact image, in pixels (column, row).
    fn centre(image: &ContactImage) -> (f32, f32) {
        let (mut sum, mut c, mut r) = (0.0, 0.0, 0.0);
        for (i, &p) in image.pixels.iter().enumerate() {
            let p = f32::from(p);
            sum += p;
            c += p * (i % image.width) as f32;
            r += p * (i / image.width) as f32;
        }
        assert!(sum > 0.0, "a blank image");
        (c / sum, r / sum)
    }

    #[test]
    fn without_a_calibration_the_picture_spans_the_table() {
        let (mut feed, tx, format) = feed(None);
        let s = sensor();
        assert!(feed.image_at(Instant::now(), &s).expect("blank").pixels.iter().all(|&p| p == 0), "blank before");
        assert!(feed.calibration().is_none());
        // Camera pixel (16, 12) is a quarter in from the top-left: the far-left quarter of the table.
        tx.send(encode(&square_at(16, 12), &format).expect("yuyv")).expect("send");
        let at = arrived(&feed, 0);
        // Camera pixel x is contact pixel (x + 0.5) / 2 - 0.5: 16 → 7.75, 12 → 5.75.
        let (c, r) = centre(feed.image_at(at, &s).expect("frame"));
        assert!((c - 7.75).abs() < 0.3 && (r - 5.75).abs() < 0.3, "centre at {c},{r}; expected 7.75,5.75");
        let cal = feed.calibration().expect("made from the first frame");
        assert_eq!(cal.kind(), CameraKind::Ir);
        let [x, y] = cal.table_points[0];
        assert!((x + 0.32).abs() < 1e-6 && (y - 0.24).abs() < 1e-6, "image top-left is the far-left corner: {x}, {y}");
    }

    #[test]
    fn a_step_sees_the_newest_frame_that_had_arrived_by_its_time() {
        let (mut feed, tx, format) = feed(None);
        let s = sensor();
        let before = Instant::now();
        tx.send(encode(&square_at(16, 12), &format).expect("yuyv")).expect("send");
        let first = arrived(&feed, 0);
        tx.send(encode(&square_at(48, 36), &format).expect("yuyv")).expect("send");
        let second = arrived(&feed, 1);
        // A step timed before either frame arrived sees none yet.
        assert!(feed.image_at(before, &s).expect("blank").pixels.iter().all(|&p| p == 0));
        // At `first` only the first frame had arrived, even though both are queued.
        let (c, _) = centre(feed.image_at(first, &s).expect("first"));
        assert!(c < 16.0, "column {c}: the first frame (left) should show");
        let (c, r) = centre(feed.image_at(second, &s).expect("second"));
        assert!(c > 16.0 && r > 12.0, "{c},{r}: the second frame (near right) should show");
        assert_eq!(feed.counts(), (2, 0));
        // The stream ends: said once the frames before it are shown.
        drop(tx);
        let deadline = Instant::now() + Duration::from_secs(5);
        let e = loop {
            match feed.image_at(Instant::now(), &s) {
                Err(e) => break e,
                Ok(_) => assert!(Instant::now() < deadline, "the end was never said"),
            }
        };
        assert_eq!(e.to_string(), "test-camera: the camera stopped delivering frames");
    }

    #[test]
    fn a_full_queue_drops_the_oldest_frames() {
        let (mut feed, tx, format) = feed(None);
        let bytes = encode(&square_at(16, 12), &format).expect("yuyv");
        for _ in 0..crate::input::camera::QUEUE_FRAMES + 3 {
            tx.send(bytes.clone()).expect("send");
        }
        let deadline = Instant::now() + Duration::from_secs(5);
        while feed.counts().1 < 3 {
            assert!(Instant::now() < deadline, "nothing dropped: {:?}", feed.counts());
            std::thread::sleep(Duration::from_millis(1));
        }
        feed.image_at(Instant::now(), &sensor()).expect("frame");
        assert_eq!(feed.counts(), (1, 3), "one shown (the newest), three dropped");
    }

    #[test]
    fn a_calibration_that_does_not_fit_the_camera_is_refused_at_start() {
        let corners = [[0.0, 0.0], [63.0, 0.0], [63.0, 47.0], [0.0, 47.0]];
        let table = [[-0.3, 0.2], [0.3, 0.2], [0.3, -0.2], [-0.3, -0.2]];
        let ir = Conversion::Ir { threshold: 40, background: None };
        let other_size = Calibration::new(ir, [640, 480], corners, table, "c.toml").expect("calibration");
        let e = feed_error(Some(other_size));
        assert_eq!(e, "test-camera: delivers 64x48 frames; the calibration is for 640x480");
        let depth = Conversion::Depth { table_depth_mm: 1000.0, touch_band_mm: [4.0, 30.0] };
        let depth = Calibration::new(depth, [W, H], corners, table, "c.toml").expect("calibration");
        let e = feed_error(Some(depth));
        assert_eq!(e, "test-camera: delivers 8-bit YUYV frames; a depth calibration needs 16-bit millimetres");
    }

    fn feed_error(calibration: Option<Calibration>) -> String {
        let (camera, _tx) = ChannelCamera::new("test-camera", RawFormat::packed(W, H, PixelFormat::Yuyv));
        CameraFeed::start(Box::new(camera), calibration).expect_err("refused").to_string()
    }
}
