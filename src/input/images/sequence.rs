//! A recorded camera sequence as a source of contact images: frames picked
//! by time, decoded only when a new one is due, rectified into the
//! session's contact image.

use super::{Calibration, CameraImage, Conversion, FrameList, ImagesError, Rectifier, check_frame};
use crate::pipeline::surface::{ContactImage, Sensor};
use std::path::Path;

/// A frames folder and its calibration, played against a session's clock.
#[derive(Debug, Clone)]
pub struct ImageSequence {
    frames: FrameList,
    calibration: Calibration,
    /// Built for the sensor of the session that asked last (the demo can
    /// open another task with another table).
    rectifier: Option<Rectifier>,
    /// The frame now in `image`, if any.
    shown: Option<usize>,
    image: ContactImage,
}

impl ImageSequence {
    /// Reads the calibration and checks every frame's header (see
    /// [`FrameList::open`]).
    pub fn open(dir: &Path, calibration: &Path) -> Result<ImageSequence, ImagesError> {
        let calibration_dir = calibration.parent().unwrap_or_else(|| Path::new("."));
        let cal = Calibration::load(calibration)?;
        let background = match &cal.conversion {
            Conversion::Ir { background: Some(b), .. } => Some(calibration_dir.join(&b.name)),
            _ => None,
        };
        let frames = FrameList::open(dir, cal.kind(), cal.image_size, background.as_deref())?;
        Ok(Self::new(frames, cal))
    }

    pub fn new(frames: FrameList, calibration: Calibration) -> ImageSequence {
        ImageSequence { frames, calibration, rectifier: None, shown: None, image: ContactImage::default() }
    }

    pub fn calibration(&self) -> &Calibration {
        &self.calibration
    }

    pub fn frames(&self) -> &FrameList {
        &self.frames
    }

    /// Seconds from the first frame's time 0 to the last frame.
    pub fn duration(&self, dt: f64) -> f64 {
        self.frames.duration(dt)
    }

    /// The contact image the physics step at time `t` sees (blank before
    /// the first frame and after the last). A frame that turns out not to
    /// decode is an error naming it.
    pub fn image_at(&mut self, t: f64, dt: f64, sensor: &Sensor) -> Result<&ContactImage, ImagesError> {
        if self.rectifier.as_ref().is_some_and(|r| r.sensor() != sensor) {
            self.rectifier = None;
        }
        if self.rectifier.is_none() {
            self.shown = None;
            self.image = ContactImage::new(sensor.width_px as usize, sensor.height_px as usize);
        }
        let rectifier = self.rectifier.get_or_insert_with(|| Rectifier::new(&self.calibration, sensor));
        let due = self.frames.at(t, dt);
        if due != self.shown {
            match due {
                Some(i) => {
                    let path = self.frames.path(i);
                    let frame = CameraImage::read(path)?;
                    if !rectifier.rectify(&frame, &mut self.image) {
                        // The header was checked when the list was made; the
                        // file has changed since. Say what it is now.
                        check_frame(path, self.calibration.kind(), self.calibration.image_size)?;
                    }
                }
                None => self.image.clear(),
            }
            self.shown = due;
        }
        Ok(&self.image)
    }
}
