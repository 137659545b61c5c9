//! A V4L2 capture device through the `v4l` crate (cargo feature `camera`):
//! opened, a format agreed, frames streamed from memory-mapped buffers.

use super::{CameraError, CameraSource, FrameGrabber, PixelFormat, RawFormat, describe};
use crate::input::images::Calibration;
use std::path::Path;
use v4l::buffer::Type;
use v4l::io::mmap::Stream;
use v4l::io::traits::CaptureStream;
use v4l::video::Capture;
use v4l::{Device, FourCC};

/// Buffers the driver fills in turn: enough that a slow frame on our side
/// does not stall the camera.
const BUFFERS: u32 = 4;

/// An open camera, streaming.
pub struct V4lCamera {
    source: CameraSource,
    stream: Stream<'static>,
}

impl V4lCamera {
    /// Opens `path`, picks the first of [`PixelFormat::preference`] the
    /// device offers, at the calibration's size (else the device's current
    /// one), and starts streaming.
    pub fn open(path: &Path, calibration: Option<&Calibration>) -> Result<V4lCamera, CameraError> {
        let device = path.display().to_string();
        let dev = Device::with_path(path).map_err(|source| CameraError::Open { device: device.clone(), source })?;
        let failed = |source| CameraError::Capture { device: device.clone(), source };
        let caps = dev.query_caps().map_err(|source| CameraError::Device {
            device: device.clone(),
            problem: format!("not a V4L2 capture device ({source})"),
        })?;
        if !caps.capabilities.contains(v4l::capability::Flags::VIDEO_CAPTURE) {
            let problem = format!("{} ({}) cannot capture video", caps.card, caps.driver);
            return Err(CameraError::Device { device, problem });
        }
        let offered: Vec<FourCC> = dev.enum_formats().map_err(failed)?.into_iter().map(|d| d.fourcc).collect();
        let wanted = PixelFormat::preference(calibration.map(Calibration::kind));
        let Some(pixel) = wanted.iter().copied().find(|p| offered.contains(&FourCC::new(&p.fourcc()))) else {
            let names = |fs: &mut dyn Iterator<Item = String>| fs.collect::<Vec<_>>().join(", ");
            let problem = format!(
                "offers {}; surfacelab reads {}",
                names(&mut offered.iter().map(ToString::to_string)),
                names(&mut wanted.iter().map(|p| p.name().to_owned()))
            );
            return Err(CameraError::Device { device, problem });
        };
        let current = dev.format().map_err(failed)?;
        let [width, height] = calibration.map_or([current.width, current.height], |c| c.image_size);
        let asked = v4l::Format::new(width, height, FourCC::new(&pixel.fourcc()));
        let got = dev.set_format(&asked).map_err(failed)?;
        let format = RawFormat { width: got.width, height: got.height, stride: got.stride, pixel };
        if got.fourcc != asked.fourcc || [got.width, got.height] != [width, height] {
            let problem = format!(
                "asked for {width}x{height} {}, the driver gave {}x{} {}",
                pixel.name(),
                got.width,
                got.height,
                got.fourcc
            );
            return Err(CameraError::Device { device, problem });
        }
        format.check()?;
        let stream = Stream::with_buffers(&dev, Type::VideoCapture, BUFFERS).map_err(failed)?;
        tracing::info!("{device}: capturing {}", describe(&format));
        Ok(V4lCamera { source: CameraSource { device, format }, stream })
    }
}

impl FrameGrabber for V4lCamera {
    fn source(&self) -> &CameraSource {
        &self.source
    }

    fn grab(&mut self) -> Result<Option<&[u8]>, CameraError> {
        match self.stream.next() {
            Ok((bytes, meta)) => Ok(Some(&bytes[..(meta.bytesused as usize).min(bytes.len())])),
            Err(source) => Err(CameraError::Capture { device: self.source.device.clone(), source }),
        }
    }
}
