//! TUIO 1.1 over real UDP: OSC packets sent to the demo's listener on
//! 127.0.0.1 become the hands the demo feeds the session; garbage is
//! counted and ignored.

use rosc::{OscBundle, OscMessage, OscPacket, OscTime, OscType, encoder};
use std::net::UdpSocket;
use std::time::{Duration, Instant};
use surfacelab::input::tuio::TuioListener;
use surfacelab::pipeline::surface::{Hand, HandKind};

const TABLE: [f32; 2] = [1.0, 0.75];

fn message(addr: &str, args: Vec<OscType>) -> OscPacket {
    OscPacket::Message(OscMessage { addr: addr.into(), args })
}

fn s(v: &str) -> OscType {
    OscType::String(v.into())
}

fn f(v: f32) -> OscType {
    OscType::Float(v)
}

/// One TUIO frame as a tracker sends it: source, alive, sets, fseq.
fn frame(profile: &str, frame: i32, sets: &[Vec<OscType>]) -> Vec<u8> {
    let alive = sets.iter().map(|a| a[0].clone());
    let mut content = vec![
        message(profile, vec![s("source"), s("test@127.0.0.1")]),
        message(profile, std::iter::once(s("alive")).chain(alive).collect()),
    ];
    for set in sets {
        content.push(message(profile, std::iter::once(s("set")).chain(set.iter().cloned()).collect()));
    }
    content.push(message(profile, vec![s("fseq"), OscType::Int(frame)]));
    encoder::encode(&OscPacket::Bundle(OscBundle { timetag: OscTime { seconds: 0, fractional: 1 }, content }))
        .expect("encodes")
}

/// Polls the listener until `done` holds (at most 5 s): UDP delivery and
/// the reader thread are asynchronous.
fn wait_for(listener: &TuioListener, done: impl Fn(&[Hand]) -> bool) -> Vec<Hand> {
    let start = Instant::now();
    loop {
        let hands = listener.hands(TABLE);
        if done(&hands) || start.elapsed() > Duration::from_secs(5) {
            return hands;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
}

#[test]
fn cursors_and_blobs_sent_over_udp_become_hands() {
    let listener = TuioListener::bind("127.0.0.1:0".parse().expect("address")).expect("binds a free port");
    let sender = UdpSocket::bind("127.0.0.1:0").expect("sender socket");
    let to = listener.local_addr();

    // Two fingers: the centre of the surface and its top-left quarter point.
    let cursors = [
        vec![OscType::Int(10), f(0.5), f(0.5), f(0.0), f(0.0), f(0.0)],
        vec![OscType::Int(11), f(0.25), f(0.25), f(0.0), f(0.0), f(0.0)],
    ];
    sender.send_to(&frame("/tuio/2Dcur", 1, &cursors), to).expect("sends");
    let hands = wait_for(&listener, |h| h.len() == 2);
    assert_eq!(hands.len(), 2, "two cursors arrive as two fingertips: {hands:?}");
    assert!(hands.iter().all(|h| h.kind == HandKind::Fingertips(1)));
    let at = |x: f32, y: f32| hands.iter().any(|h| (h.pose.x - x).abs() < 1e-5 && (h.pose.y - y).abs() < 1e-5);
    assert!(at(0.0, 0.0) && at(-0.25, 0.1875), "{hands:?}");

    // A forearm-sized blob lying across the table joins them.
    let blob = vec![
        OscType::Int(3),
        f(0.5),
        f(0.75),
        f(0.0),
        f(0.25),
        f(0.07 / 0.75),
        f(0.02),
        f(0.0),
        f(0.0),
        f(0.0),
        f(0.0),
        f(0.0),
    ];
    sender.send_to(&frame("/tuio/2Dblb", 1, &[blob]), to).expect("sends");
    let hands = wait_for(&listener, |h| h.len() == 3);
    let arm = hands.iter().find(|h| h.kind == HandKind::Forearm).expect("the blob became a forearm");
    assert!((arm.scale - 1.0).abs() < 0.05, "scaled to the blob: {}", arm.scale);

    // Garbage in between: counted, ignored, and the listener keeps going.
    for junk in [&b"not osc at all"[..], &[0u8; 3][..], &[0xFF; 200][..]] {
        sender.send_to(junk, to).expect("sends");
    }
    sender.send_to(&frame("/tuio/2Dcur", 2, &cursors[..1]), to).expect("sends");
    let hands = wait_for(&listener, |h| h.len() == 2);
    assert_eq!(hands.len(), 2, "one cursor lifted, the blob stays: {hands:?}");
    let stats = listener.stats();
    assert_eq!(stats.malformed, 3, "{stats:?}");
    assert_eq!(stats.packets, 6, "{stats:?}");

    // Everything lifted.
    sender.send_to(&frame("/tuio/2Dcur", 3, &[]), to).expect("sends");
    sender.send_to(&frame("/tuio/2Dblb", 2, &[]), to).expect("sends");
    assert!(wait_for(&listener, <[Hand]>::is_empty).is_empty());
    // Dropping the listener stops its thread (the test would hang otherwise).
    drop(listener);
}

/// Each physics step sees the tracker's hands at its own wall time (issue
/// 18): a step between two packets sees the finger on the line between
/// the two reports, further along for a later step, and a step before a
/// packet arrived does not see what it reports. Timing-free: every query
/// lies between instants the test observed, so the answers are exact
/// orderings, not tolerances.
#[test]
fn each_step_sees_the_tracker_at_its_own_time() {
    use surfacelab::input::Input;
    let listener = TuioListener::bind("127.0.0.1:0".parse().expect("address")).expect("binds a free port");
    let sender = UdpSocket::bind("127.0.0.1:0").expect("sender socket");
    let to = listener.local_addr();
    let origin = Instant::now();
    let wall = |at: Instant| at.duration_since(origin).as_secs_f64();
    let cursor = |x: f32| vec![OscType::Int(5), f(x), f(0.5), f(0.0), f(0.0), f(0.0)];

    sender.send_to(&frame("/tuio/2Dcur", 1, &[cursor(0.2)]), to).expect("sends");
    let a = wait_for(&listener, |h| h.len() == 1);
    assert_eq!(a.len(), 1, "the first report arrived");
    let seen_a = Instant::now();
    std::thread::sleep(Duration::from_millis(20));
    let before_b = Instant::now();
    sender
        .send_to(
            &frame("/tuio/2Dcur", 2, &[cursor(0.6), vec![OscType::Int(6), f(0.9), f(0.9), f(0.0), f(0.0), f(0.0)]]),
            to,
        )
        .expect("sends");
    let b = wait_for(&listener, |h| h.len() == 2);
    assert_eq!(b.len(), 2, "the second report arrived");
    let seen_b = Instant::now();

    let mut input = Input::new(None, Some(listener));
    input.set_clock(origin);
    let x_at = |input: &mut Input, at: Instant| {
        let hands = input.hands_at(wall(at), 0.0, TABLE);
        (hands.len(), hands.iter().find(|h| (h.pose.y - 0.0).abs() < 1e-3).map(|h| h.pose.x))
    };
    // On a 1 m table, x = 0.2 is -0.3 m and x = 0.6 is +0.1 m.
    let (n, x) = x_at(&mut input, seen_a);
    assert_eq!(n, 1, "the second finger is not down before its packet arrived");
    let early = x.expect("the first finger");
    let (_, x) = x_at(&mut input, before_b);
    let later = x.expect("the first finger");
    assert!(-0.3 <= early && early < later && later < 0.1, "on the line, moving on: {early} then {later}");
    let (n, x) = x_at(&mut input, seen_b);
    assert_eq!(n, 2, "both down once the second packet arrived");
    assert!((x.expect("the first finger") - 0.1).abs() < 1e-5, "at the second report");
}
