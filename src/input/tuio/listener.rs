//! The TUIO listener: a UDP socket read on its own thread, each datagram
//! handed to the pure decoder ([`crate::input::tuio::TuioState`]) and its
//! result kept with its arrival time ([`Timeline`]), so that each physics
//! step asks for the hands at its own time.

use super::decode::TuioState;
use super::protocol::TuioStats;
use super::timeline::Timeline;
use crate::pipeline::surface::Hand;
use std::net::{SocketAddr, UdpSocket};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// How often the thread looks at the stop flag while no packet arrives.
const POLL: Duration = Duration::from_millis(50);
/// Largest UDP payload.
const MAX_DATAGRAM: usize = 65_536;
/// Arrival times kept for [`TuioListener::take_arrivals`]: a listener no
/// one drains (the demo's) holds at most this many (512 KiB).
const MAX_ARRIVALS: usize = 65_536;

/// A bound socket and the thread reading it. Dropping it stops the thread.
pub struct TuioListener {
    addr: SocketAddr,
    state: Arc<Mutex<Tracked>>,
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
    start: Instant,
}

impl std::fmt::Debug for TuioListener {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TuioListener").field("addr", &self.addr).finish_non_exhaustive()
    }
}

impl TuioListener {
    /// Binds `addr` (port 0 picks a free port; see [`Self::local_addr`])
    /// and starts reading.
    pub fn bind(addr: SocketAddr) -> std::io::Result<Self> {
        let socket = UdpSocket::bind(addr)?;
        socket.set_read_timeout(Some(POLL))?;
        let addr = socket.local_addr()?;
        let state = Arc::new(Mutex::new(Tracked::default()));
        let stop = Arc::new(AtomicBool::new(false));
        let start = Instant::now();
        let thread = {
            let (state, stop) = (Arc::clone(&state), Arc::clone(&stop));
            std::thread::Builder::new().name("tuio".into()).spawn(move || read_loop(&socket, &state, &stop, start))?
        };
        Ok(Self { addr, state, stop, thread: Some(thread), start })
    }

    pub fn local_addr(&self) -> SocketAddr {
        self.addr
    }

    /// The hands touching a table of [width, depth] metres now.
    pub fn hands(&self, table: [f32; 2]) -> Vec<Hand> {
        self.lock().now.hands(table, self.start.elapsed().as_secs_f64())
    }

    /// The hands on a table of [width, depth] metres as they were at
    /// `at`, between the packets that arrived before and after it (see
    /// [`Timeline`]).
    pub fn hands_at(&self, table: [f32; 2], at: Instant) -> Vec<Hand> {
        let t = at.saturating_duration_since(self.start).as_secs_f64();
        self.lock().past.hands_at(table, t)
    }

    pub fn stats(&self) -> TuioStats {
        self.lock().now.stats()
    }

    /// The arrival times of the well-formed packets that arrived at or
    /// before `until` and were not taken yet: what a step that samples the
    /// hands at `until` sees for the first time, so its caller can measure
    /// how long each packet waited for its contact image.
    pub fn take_arrivals(&self, until: Instant) -> Vec<Instant> {
        let t = until.saturating_duration_since(self.start).as_secs_f64();
        let mut tracked = self.lock();
        let n = tracked.arrivals.partition_point(|&a| a <= t);
        tracked.arrivals.drain(..n).map(|a| self.start + Duration::from_secs_f64(a)).collect()
    }

    /// Live (cursors, blobs) now, TUIO 2.0 pointers and shapes included
    /// (see [`TuioState::counts`]).
    pub fn live_counts(&self) -> (usize, usize) {
        self.lock().now.counts(self.start.elapsed().as_secs_f64())
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, Tracked> {
        // The decoder never panics mid-update; a poisoned lock still holds
        // a consistent state.
        self.state.lock().unwrap_or_else(PoisonError::into_inner)
    }
}

impl Drop for TuioListener {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

/// The decoder's state now and after each packet of the last second.
#[derive(Debug, Default)]
struct Tracked {
    now: TuioState,
    past: Timeline,
    /// Seconds since the start at which each well-formed packet arrived,
    /// oldest first, until taken.
    arrivals: std::collections::VecDeque<f64>,
}

fn read_loop(socket: &UdpSocket, state: &Mutex<Tracked>, stop: &AtomicBool, start: Instant) {
    let mut buf = vec![0u8; MAX_DATAGRAM];
    while !stop.load(Ordering::Relaxed) {
        match socket.recv_from(&mut buf) {
            Ok((n, from)) => {
                let now = start.elapsed().as_secs_f64();
                let mut tracked = state.lock().unwrap_or_else(PoisonError::into_inner);
                match tracked.now.receive(&buf[..n], now) {
                    Ok(()) => {
                        let Tracked { now: current, past, arrivals } = &mut *tracked;
                        past.record(now, current);
                        if arrivals.len() == MAX_ARRIVALS {
                            arrivals.pop_front();
                        }
                        arrivals.push_back(now);
                    }
                    Err(e) => tracing::debug!("TUIO packet from {from} ignored: {e}"),
                }
            }
            Err(e) if matches!(e.kind(), std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut) => {}
            Err(e) => {
                // E.g. ICMP port unreachable echoes; never spin on them.
                tracing::debug!("TUIO socket: {e}");
                std::thread::sleep(POLL);
            }
        }
    }
}
