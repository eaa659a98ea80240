#!/usr/bin/env python3
"""Writes the scanline test images of this folder (see README.md): OpenEXR single-part files
with NONE, RLE, ZIPS or ZIP compression, written from the layout in the OpenEXR file-format
document, so the reader is checked against files that no part of Spindulys wrote."""
import struct, sys, zlib

W, H = 40, 20

def value(x, y, c):
    """Pixel values over several octaves, with a run of equal pixels (for RLE) and a zero."""
    if x < 5:
        return (0.25, 0.5, 3.0)[c]
    if x == 12 and c == 2:
        return 0.0
    return (0.01 * (x + 1) * (y + 1), 2.0 ** (x // 2 - 13) * 1.3, y + 0.7 * x + 100 * (x == 37))[c]

def steps(x, y, c):
    """A quantised gradient: few distinct values in long runs, which PIZ compresses (on the
    noisier image above, small PIZ tiles come out larger than raw and are stored raw)."""
    return ((x // 3) * 0.25, (y // 2) * 0.5 + 1, ((x + y) // 5) * 0.125)[c]

def wide(x, y, c):
    """FLOAT values whose low 16-bit words are all different (20000 + pixel index): more than
    16384 distinct words, which makes PIZ use its 16-bit wavelet."""
    return struct.unpack("<f", struct.pack("<I", 0x3F800000 | (20000 + y * 128 + x)))[0]

def attr(name, typ, data):
    return name.encode() + b"\0" + typ.encode() + b"\0" + struct.pack("<i", len(data)) + data

def half(v):
    return struct.pack("<e", v)

def reorder_predict(raw):
    """The byte split and delta predictor that RLE, ZIPS and ZIP apply before compressing."""
    even, odd = raw[0::2], raw[1::2]
    t = bytearray(even + odd)
    p = t[0]
    for i in range(1, len(t)):
        d = (t[i] - p + 128 + 256) & 0xFF
        p = t[i]
        t[i] = d
    return bytes(t)

def rle(data):
    out = bytearray()
    i = 0
    while i < len(data):
        run = 1
        while i + run < len(data) and data[i + run] == data[i] and run < 128:
            run += 1
        if run >= 3:
            out += struct.pack("b", run - 1) + data[i:i + 1]
            i += run
        else:
            j = i
            while j < len(data) and j - i < 127:
                if j + 2 < len(data) and data[j] == data[j + 1] == data[j + 2]:
                    break
                j += 1
            out += struct.pack("b", -(j - i)) + data[i:j]
            i = j
    return bytes(out)

CODECS = {"none": (0, 1), "rle": (1, 1), "zips": (2, 1), "zip": (3, 16)}

def write(path, codec, channels="BGR", kind="half", data_window=(0, 0, W - 1, H - 1), display_window=None, pixel=value):
    display_window = display_window or data_window
    code, lines = CODECS[codec]
    ptype, size = {"uint": (0, 4), "half": (1, 2), "float": (2, 4)}[kind]
    chlist = b"".join(c.encode() + b"\0" + struct.pack("<iB3xii", ptype, 0, 1, 1) for c in sorted(channels)) + b"\0"
    head = b"\x76\x2f\x31\x01" + struct.pack("<i", 2)
    head += attr("channels", "chlist", chlist)
    head += attr("compression", "compression", bytes([code]))
    head += attr("dataWindow", "box2i", struct.pack("<4i", *data_window))
    head += attr("displayWindow", "box2i", struct.pack("<4i", *display_window))
    head += attr("lineOrder", "lineOrder", b"\0")
    head += attr("pixelAspectRatio", "float", struct.pack("<f", 1))
    head += attr("screenWindowCenter", "v2f", struct.pack("<2f", 0, 0))
    head += attr("screenWindowWidth", "float", struct.pack("<f", 1))
    head += b"\0"
    x0, y0, x1, y1 = data_window
    w, h = x1 - x0 + 1, y1 - y0 + 1
    blocks = []
    for b0 in range(0, h, lines):
        raw = b""
        for yy in range(b0, min(h, b0 + lines)):
            for c in sorted(channels):
                ci = "RGBY".index(c)
                for xx in range(w):
                    v = pixel(xx, yy, ci % 3) if c != "Y" else pixel(xx, yy, 1) + 0.5 * pixel(xx, yy, 2)
                    raw += half(v) if kind == "half" else struct.pack("<I", int(v)) if kind == "uint" else struct.pack("<f", v)
        if codec == "none":
            data = raw
        elif codec == "rle":
            data = rle(reorder_predict(raw))
        else:
            data = zlib.compress(reorder_predict(raw), 9)
        if len(data) >= len(raw):
            data = raw  # stored as is, as OpenEXR does when compressing does not pay
        blocks.append(struct.pack("<ii", y0 + b0, len(data)) + data)
    table_at = len(head)
    at = table_at + 8 * len(blocks)
    offsets = []
    for b in blocks:
        offsets.append(at)
        at += len(b)
    with open(path, "wb") as f:
        f.write(head + b"".join(struct.pack("<Q", o) for o in offsets) + b"".join(blocks))

if __name__ == "__main__":
    for codec in CODECS:
        write("scan-%s.exr" % codec, codec)
    write("scan-float-none.exr", "none", kind="float")
    write("scan-float-zip.exr", "zip", kind="float")
    write("luminance-none.exr", "none", channels="Y")
    write("steps-none.exr", "none", data_window=(0, 0, 63, 31), pixel=steps)
    write("steps-zip.exr", "zip", data_window=(0, 0, 63, 31), pixel=steps)
    write("steps-float-zip.exr", "zip", kind="float", data_window=(0, 0, 63, 31), pixel=steps)
    write("steps-uint-zip.exr", "zip", kind="uint", data_window=(0, 0, 63, 31), pixel=lambda x, y, c: 8 * steps(x, y, c))
    write("steps-luminance-none.exr", "none", channels="Y", data_window=(0, 0, 63, 31), pixel=steps)
    write("wide-float-none.exr", "none", channels="R", kind="float", data_window=(0, 0, 127, 127), pixel=wide)
    write("window-none.exr", "none", data_window=(2, 1, 2 + W - 1, 1 + H - 1), display_window=(0, 0, W + 3, H + 1))
