//! The capture thread: a camera's frames decoded as they arrive and stamped
//! with the instant they did, for the session to take at each physics
//! step's own time (as the demo's other input sources are).
//!
//! The queue keeps the newest [`QUEUE_FRAMES`] frames and drops older ones:
//! a session that falls behind, or is paused, should see what the camera
//! sees now, not a backlog.

use super::{CameraError, RawFormat, decode};
use crate::input::images::CameraImage;
use std::collections::VecDeque;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex, mpsc};
use std::time::Instant;

/// Frames held for the session at most (a third of a second at 30 fps).
pub const QUEUE_FRAMES: usize = 10;

/// Which camera delivers frames, and what their bytes are.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CameraSource {
    /// The device's name for messages (its path).
    pub device: String,
    /// What every frame's bytes are.
    pub format: RawFormat,
}

/// Something that delivers a camera's frames: the V4L2 device (feature
/// `camera`), or recorded frames in tests.
pub trait FrameGrabber: Send {
    fn source(&self) -> &CameraSource;
    /// Blocks until the next frame and returns its bytes (valid until the
    /// next call); `Ok(None)` when the stream has ended.
    fn grab(&mut self) -> Result<Option<&[u8]>, CameraError>;
}

/// A camera whose frames are handed over on a channel, bytes as a driver
/// would deliver them: a frame source that is not a V4L2 device (the tests
/// hand recorded frames over this way). The stream ends when every sender
/// is dropped.
#[derive(Debug)]
pub struct ChannelCamera {
    source: CameraSource,
    frames: mpsc::Receiver<Vec<u8>>,
    current: Vec<u8>,
}

impl ChannelCamera {
    /// A camera named `device` delivering `format`, and the sender that
    /// hands it frames.
    pub fn new(device: impl Into<String>, format: RawFormat) -> (ChannelCamera, mpsc::Sender<Vec<u8>>) {
        let (tx, frames) = mpsc::channel();
        (ChannelCamera { source: CameraSource { device: device.into(), format }, frames, current: Vec::new() }, tx)
    }
}

impl FrameGrabber for ChannelCamera {
    fn source(&self) -> &CameraSource {
        &self.source
    }

    fn grab(&mut self) -> Result<Option<&[u8]>, CameraError> {
        match self.frames.recv() {
            Ok(bytes) => {
                self.current = bytes;
                Ok(Some(&self.current))
            }
            Err(mpsc::RecvError) => Ok(None),
        }
    }
}

/// A frame decoded, or why no more will come.
pub type Delivery = Result<(Instant, CameraImage), CameraError>;

/// What the capture thread and the session share.
#[derive(Debug, Default)]
pub struct Shared {
    queue: Mutex<VecDeque<Delivery>>,
    stop: AtomicBool,
    dropped: AtomicU64,
}

impl Shared {
    /// Adds a delivery, dropping the oldest frame when the queue is full.
    pub fn deliver(&self, d: Delivery) {
        let mut q = self.queue.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        if q.len() >= QUEUE_FRAMES {
            q.pop_front();
            self.dropped.fetch_add(1, Ordering::Relaxed);
        }
        q.push_back(d);
    }

    /// Everything delivered since the last call, oldest first.
    pub fn take(&self) -> Vec<Delivery> {
        let mut q = self.queue.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        q.drain(..).collect()
    }

    /// Deliveries waiting for the session (tests wait on it).
    #[cfg(test)]
    pub fn queued(&self) -> usize {
        self.queue.lock().unwrap_or_else(std::sync::PoisonError::into_inner).len()
    }

    /// Frames dropped because the session did not take them in time.
    pub fn dropped(&self) -> u64 {
        self.dropped.load(Ordering::Relaxed)
    }

    pub fn stop(&self) {
        self.stop.store(true, Ordering::Relaxed);
    }
}

/// Runs `grabber` on its own thread until it fails, ends, or `shared` is
/// stopped (checked between frames, so a stopped thread ends after at most
/// one more frame). Failing or ending is delivered as the last item.
pub fn spawn(mut grabber: Box<dyn FrameGrabber>, shared: Arc<Shared>) -> std::io::Result<()> {
    std::thread::Builder::new().name("camera".into()).spawn(move || {
        let CameraSource { device, format } = grabber.source().clone();
        while !shared.stop.load(Ordering::Relaxed) {
            let delivery = match grabber.grab() {
                Ok(Some(bytes)) => {
                    let at = Instant::now();
                    decode(&format, bytes).map(|image| (at, image))
                }
                Ok(None) => Err(CameraError::Stopped { device: device.clone() }),
                Err(e) => Err(e),
            };
            let last = delivery.is_err();
            shared.deliver(delivery);
            if last {
                break;
            }
        }
    })?;
    Ok(())
}
