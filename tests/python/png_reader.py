"""PNG pixels for the picture tests, read without meshstep."""
import numpy as np


def read_png(data):
    """A PNG's pixels as an (height, width, channels) uint8 array: 8-bit RGB or RGBA, not
    interlaced (what meshstep writes). Independent of meshstep: zlib and the five filters of
    the PNG specification (section 9)."""
    import struct
    import zlib

    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0, header
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    out = np.zeros((height, stride), dtype=np.int64)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1).astype(np.int64)
        above = out[y - 1] if y else np.zeros(stride, dtype=np.int64)
        if kind in (0, 2):
            out[y] = (line + (above if kind == 2 else 0)) % 256
            continue
        row = out[y]
        for x in range(stride):  # Sub, Average and Paeth depend on the pixel just decoded
            left = row[x - channels] if x >= channels else 0
            up_left = above[x - channels] if x >= channels else 0
            if kind == 1:
                predictor = left
            elif kind == 3:
                predictor = (left + above[x]) // 2
            else:
                p = left + above[x] - up_left
                pa, pb, pc = abs(p - left), abs(p - above[x]), abs(p - up_left)
                predictor = left if pa <= pb and pa <= pc else (above[x] if pb <= pc else up_left)
            row[x] = (line[x] + predictor) % 256
    return out.astype(np.uint8).reshape(height, width, channels)
