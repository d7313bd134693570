"""PFM images (the CLI's --out x.pfm), for the evaluation scripts in tools/. Stdlib only."""
import struct


def read_pfm(path):
    """(width, height, channels, values): rows bottom to top as the format stores them,
    channels 3 (PF) or 1 (Pf), values interleaved."""
    with open(path, "rb") as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        ch = 3 if kind == b"PF" else 1
        n = w * h * ch
        data = struct.unpack(("<" if scale < 0 else ">") + "%df" % n, f.read(4 * n))
    return w, h, ch, data
