#!/usr/bin/env python3
"""csgrt_host.py — render a scene on the ULX3S board over its USB serial port.

    .venv/bin/python tools/csgrt_host.py /dev/ttyUSB0 scene.bin -o scene.png
    .venv/bin/python tools/csgrt_host.py /dev/ttyUSB0 scenes/default.pov -o d.png --width 320 --height 240

SCENE is a compiled scene image (`build/csgrt compile SCENE.pov -o scene.bin
--bits B --width W --height H`), or a .pov file, which this tool compiles
with build/csgrt for the BITS the board reports. The protocol (docs/fpga.md,
rtl/board/csgrt_board_ctrl.v), UART 8N1 at --baud (the bitstream's BAUD,
3,000,000 by default):

  host -> board  'I'                      board -> host  A5 'I' BITS MAX_LEAVES TREE_HEIGHT 00
  host -> board  'P' or 'R', the image    board -> host  A5 code, then (code 0) W*H*3 bytes
                 (32-bit words,                          r g b in raster order, then the
                 little-endian bytes)                    frame's cycle count (8 bytes LE)

'P' renders with the paper's tie policy, 'R' with the regular one.
Needs pyserial (in the project's .venv, which `make synth` creates).
"""
import argparse
import os
import struct
import subprocess
import sys
import tempfile
import time
import zlib

LOAD_ERRORS = {
    1: "bad magic or version",
    2: "BITS differs from the bitstream's",
    3: "more leaves than MAX_LEAVES",
    4: "more lights or materials than the hardware holds",
    5: "tree height differs from TREE_HEIGHT, or no tree section",
    15: "the image stopped arriving before its last word",
}


def write_png(path, width, height, rgb):
    """Writes 8-bit RGB pixels (bytes, raster order) as a PNG (stdlib only)."""
    raw = b"".join(b"\x00" + rgb[y * width * 3:(y + 1) * width * 3] for y in range(height))

    def chunk(kind, data):
        c = struct.pack(">I", len(data)) + kind + data
        return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 6)))
        f.write(chunk(b"IEND", b""))


def read_exact(port, n, timeout, what, progress=None):
    """Reads n bytes or raises after `timeout` seconds without any byte."""
    buf = bytearray()
    last = time.monotonic()
    while len(buf) < n:
        got = port.read(min(n - len(buf), 65536))
        if got:
            buf += got
            last = time.monotonic()
            if progress:
                progress(len(buf))
        elif time.monotonic() - last > timeout:
            raise TimeoutError(f"timeout waiting for {what}: got {len(buf)} of {n} bytes")
    return bytes(buf)


def identify(port, timeout):
    port.write(b"I")
    r = read_exact(port, 6, timeout, "the identify reply")
    if r[0] != 0xA5 or r[1] != ord("I"):
        raise RuntimeError(f"unexpected identify reply {r.hex()}: is the csgrt bitstream loaded?")
    # r[5]: the effect units the bitstream has (bit 0 shadows, bit 1 reflection, bit 2 refraction,
    # bit 3 specular highlights)
    return {"bits": r[2], "max_leaves": r[3], "tree_height": r[4],
            "shadows": bool(r[5] & 1), "reflection": bool(r[5] & 2), "refraction": bool(r[5] & 4),
            "specular": bool(r[5] & 8)}


def render(port, image, ties="paper", timeout=5.0, quiet=False):
    """Sends the scene image (bytes), returns (width, height, rgb bytes, cycles)."""
    if len(image) < 17 * 4 or len(image) % 4:
        raise ValueError("not a scene image (too short or not whole words)")
    words = struct.unpack(f"<{len(image) // 4}I", image)
    if words[0] != 0x52475343:
        raise ValueError("not a scene image (bad magic)")
    width, height = words[3] & 0xFFFF, words[3] >> 16
    port.write(b"R" if ties == "regular" else b"P")
    port.write(image)
    status = read_exact(port, 2, timeout, "the load status")
    if status[0] != 0xA5:
        raise RuntimeError(f"unexpected status {status.hex()}")
    if status[1] != 0:
        raise RuntimeError(f"the board refused the image: code {status[1]} "
                           f"({LOAD_ERRORS.get(status[1], 'unknown')})")
    n = width * height * 3
    t0 = time.monotonic()

    def progress(got):
        if not quiet and (got == n or got % (width * 3 * 8) < 4096):
            sys.stderr.write(f"\r  {got // (width * 3)} of {height} rows")
            sys.stderr.flush()

    rgb = read_exact(port, n, timeout, "the pixels", progress)
    if not quiet:
        sys.stderr.write("\n")
    trailer = read_exact(port, 8, timeout, "the cycle count")
    cycles = struct.unpack("<Q", trailer)[0]
    return width, height, rgb, cycles, time.monotonic() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("port", help="serial port, e.g. /dev/ttyUSB0")
    ap.add_argument("scene", help="compiled scene image (.bin) or a .pov scene")
    ap.add_argument("-o", "--out", required=True, help="PNG to write")
    ap.add_argument("--baud", type=int, default=3000000)
    ap.add_argument("--ties", choices=("paper", "regular"), default="paper")
    ap.add_argument("--width", type=int, default=320, help="for a .pov scene")
    ap.add_argument("--height", type=int, default=240, help="for a .pov scene")
    ap.add_argument("--csgrt", default=os.path.join(os.path.dirname(__file__), "..", "build", "csgrt"),
                    help="the scene compiler, for a .pov scene")
    ap.add_argument("--timeout", type=float, default=5.0, help="seconds without a byte before giving up")
    a = ap.parse_args()

    import serial  # pyserial
    port = serial.Serial(a.port, a.baud, timeout=0.2)
    port.reset_input_buffer()
    ident = identify(port, a.timeout)
    print(f"board: BITS={ident['bits']}, MAX_LEAVES={ident['max_leaves']}, TREE_HEIGHT={ident['tree_height']}, "
          f"shadows {'yes' if ident['shadows'] else 'no'}, reflection {'yes' if ident['reflection'] else 'no'}, "
          f"refraction {'yes' if ident['refraction'] else 'no'}")
    if a.scene.endswith(".pov"):
        with tempfile.TemporaryDirectory() as d:
            binf = os.path.join(d, "scene.bin")
            subprocess.run([a.csgrt, "compile", a.scene, "-o", binf, "--bits", str(ident["bits"]),
                            "--width", str(a.width), "--height", str(a.height),
                            "--max-leaves", str(ident["max_leaves"]), "--tree-height", str(ident["tree_height"])],
                           check=True)
            image = open(binf, "rb").read()
    else:
        image = open(a.scene, "rb").read()
        bits = struct.unpack_from("<I", image, 8)[0] if len(image) >= 12 else 0
        if bits != ident["bits"]:
            sys.exit(f"the image was compiled for BITS={bits}, the board has BITS={ident['bits']}")
    try:
        w, h, rgb, cycles, secs = render(port, image, a.ties, a.timeout)
    except (RuntimeError, TimeoutError, ValueError) as e:
        sys.exit(f"csgrt_host: {e}")
    write_png(a.out, w, h, rgb)
    print(f"wrote {a.out}: {w}x{h}, {secs:.2f} s over the serial line; "
          f"the core counted {cycles} cycles from start to last pixel (paced by the UART)")


if __name__ == "__main__":
    main()
