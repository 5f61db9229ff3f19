"""Reading the viewer's window screenshots in the window tests (no imaging library on the test machine):
an 8-bit RGB or RGBA PNG into rows of RGB tuples. Shared by lecture_hall.py and shader_reload.py."""
import itertools, struct, zlib


def read_png(data):
    """(width, height, rows of RGB tuples) of an 8-bit RGB or RGBA PNG, as the viewer writes them."""
    pos, chunks, width, height, channels = 8, b"", 0, 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            channels = {2: 3, 6: 4}[colour]
        elif kind == b"IDAT":
            chunks += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(chunks), width * channels, [], bytearray(width * channels)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if f == 1:  # Sub, what shadelab writes: a running sum per channel (accumulate runs in C)
            for c in range(channels):
                line[c::channels] = bytes(itertools.accumulate(line[c::channels], lambda u, v: (u + v) & 255))
            f = 0
        for i in range(stride if f else 0):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        prev = line
    return width, height, rows
