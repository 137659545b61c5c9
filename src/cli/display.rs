//! Is there a display server behind `WAYLAND_DISPLAY` / `DISPLAY`? The
//! variables alone say nothing: a `DISPLAY=:55` left over from a closed
//! Xvfb made `doctor` report "display: yes". This connects to the server's
//! socket the way a client would, and says what it found.

use std::net::{TcpStream, ToSocketAddrs};
use std::os::unix::net::UnixStream;
use std::path::PathBuf;
use std::time::Duration;

/// How long a TCP display (`host:n`, e.g. SSH X forwarding) may take to answer.
const CONNECT_TIMEOUT: Duration = Duration::from_secs(2);

/// What the display variables lead to.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Display {
    /// A server accepted a connection.
    Live(String),
    /// A variable is set but nothing answers there.
    Dead(String),
    /// Neither variable is set.
    Unset,
}

impl Display {
    pub fn is_live(&self) -> bool {
        matches!(self, Display::Live(_))
    }
}

/// Probes Wayland first (as winit does), then X11.
pub fn probe() -> Display {
    let var = |k: &str| std::env::var(k).ok().filter(|v| !v.is_empty());
    let wayland = var("WAYLAND_DISPLAY").map(|w| probe_wayland(&w, var("XDG_RUNTIME_DIR")));
    if let Some(Display::Live(s)) = &wayland {
        return Display::Live(s.clone());
    }
    match (var("DISPLAY").map(|d| probe_x11(&d)), wayland) {
        (Some(x), _) => x,
        (None, Some(w)) => w,
        (None, None) => Display::Unset,
    }
}

fn probe_wayland(name: &str, runtime_dir: Option<String>) -> Display {
    let path = if name.starts_with('/') {
        PathBuf::from(name)
    } else {
        match runtime_dir {
            Some(dir) => PathBuf::from(dir).join(name),
            None => return Display::Dead(format!("Wayland {name}: XDG_RUNTIME_DIR is unset")),
        }
    };
    match UnixStream::connect(&path) {
        Ok(_) => Display::Live(format!("Wayland {name}")),
        Err(e) => Display::Dead(format!("Wayland {name}: nothing answers at {}: {e}", path.display())),
    }
}

/// `DISPLAY` is `[host]:number[.screen]`; no host (or `unix`) means the
/// local socket `/tmp/.X11-unix/X<number>`, a host means TCP port 6000 + number.
fn probe_x11(display: &str) -> Display {
    let Some((host, rest)) = display.rsplit_once(':') else {
        return Display::Dead(format!("X11 {display}: not of the form [host]:number"));
    };
    let Some(number) = rest.split('.').next().and_then(|n| n.parse::<u16>().ok()) else {
        return Display::Dead(format!("X11 {display}: not of the form [host]:number"));
    };
    let result = if host.is_empty() || host == "unix" {
        let path = format!("/tmp/.X11-unix/X{number}");
        UnixStream::connect(&path).map(drop).map_err(|e| format!("nothing answers at {path}: {e}"))
    } else {
        let port = 6000u16.saturating_add(number);
        match (host, port).to_socket_addrs() {
            Ok(mut addrs) => match addrs.next() {
                Some(addr) => TcpStream::connect_timeout(&addr, CONNECT_TIMEOUT)
                    .map(drop)
                    .map_err(|e| format!("nothing answers at {addr}: {e}")),
                None => Err(format!("{host} has no address")),
            },
            Err(e) => Err(format!("cannot resolve {host}: {e}")),
        }
    };
    match result {
        Ok(()) => Display::Live(format!("X11 {display}")),
        Err(why) => Display::Dead(format!("X11 {display}: {why}")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_display_with_no_server_is_dead() {
        // Display numbers this high are never served here.
        assert!(matches!(probe_x11(":6553"), Display::Dead(s) if s.contains("/tmp/.X11-unix/X6553")));
        assert!(matches!(probe_x11("garbage"), Display::Dead(s) if s.contains("[host]:number")));
        assert!(matches!(probe_wayland("wayland-99", None), Display::Dead(s) if s.contains("XDG_RUNTIME_DIR")));
    }

    #[test]
    fn a_listening_socket_is_live() {
        let dir = std::env::temp_dir().join(format!("surfacelab-wayland-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("dir");
        let _server = std::os::unix::net::UnixListener::bind(dir.join("wayland-7")).expect("bind");
        let found = probe_wayland("wayland-7", Some(dir.display().to_string()));
        assert_eq!(found, Display::Live("Wayland wayland-7".into()));
        let _ = std::fs::remove_dir_all(dir);
    }
}
