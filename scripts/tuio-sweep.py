#!/usr/bin/env python3
"""Two hand-sized TUIO 1.1 blobs sweeping the table back and forth.

    python3 scripts/tuio-sweep.py PORT SECONDS

Sends 60 bundles a second to 127.0.0.1:PORT for SECONDS: /tuio/2Dblb blobs
0.12 x 0.08 of the surface (flat hands) at y = 0.35 and 0.65, both at
x = 0.5 + 0.3 sin(2 pi t / 4), as tests/demo_window.rs (`sweeping_blobs`)
sends them. Only the standard library.
"""
import math
import socket
import struct
import sys
import time


def pad(b):
    return b + b"\0" * (4 - len(b) % 4)


def message(address, *args):
    tags, data = ",", b""
    for a in args:
        if isinstance(a, str):
            tags, data = tags + "s", data + pad(a.encode())
        elif isinstance(a, int):
            tags, data = tags + "i", data + struct.pack(">i", a)
        else:
            tags, data = tags + "f", data + struct.pack(">f", a)
    return pad(address.encode()) + pad(tags.encode()) + data


def bundle(frame, t):
    x = 0.5 + 0.3 * math.sin(2 * math.pi * t / 4)
    parts = [message("/tuio/2Dblb", "alive", 1, 2)]
    for session, y in ((1, 0.35), (2, 0.65)):
        parts.append(message("/tuio/2Dblb", "set", session, x, y, 0.0, 0.12, 0.08, 0.0096, 0.0, 0.0, 0.0, 0.0, 0.0))
    parts.append(message("/tuio/2Dblb", "fseq", frame))
    body = b"".join(struct.pack(">i", len(p)) + p for p in parts)
    return b"#bundle\0" + struct.pack(">II", 0, 1) + body


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: tuio-sweep.py PORT SECONDS")
    port, seconds = int(sys.argv[1]), float(sys.argv[2])
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    start = time.monotonic()
    frame = 0
    while (t := time.monotonic() - start) < seconds:
        frame += 1
        sock.sendto(bundle(frame, t), ("127.0.0.1", port))
        time.sleep(max(0.0, start + frame / 60 - time.monotonic()))


if __name__ == "__main__":
    main()
