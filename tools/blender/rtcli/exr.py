"""Reads the scanline OpenEXR files rtcli writes (and Blender's own: uncompressed, RLE-free ZIP and
ZIPS) into numpy arrays, without Blender: the render result is loaded from rtcli's float EXR, and
the tests compare what Blender saved with what rtcli wrote. Tiled, deep, multi-part and the lossy
compressions (PIZ, PXR24, B44, DWA) are refused with a message; rtcli writes none of them.

    read_exr(path) -> (width, height, {channel name: float32 array [height, width]}), rows top first

Licence: Apache-2.0, as the rest of rtcli.
"""
import struct
import zlib

import numpy

_MAGIC = 20000630
_COMPRESSIONS = {0: ('none', 1), 2: ('ZIPS', 1), 3: ('ZIP', 16)}  # scanlines per chunk
_TYPES = {0: ('<u4', 4), 1: ('<f2', 2), 2: ('<f4', 4)}  # UINT, HALF, FLOAT


class ExrError(Exception):
    pass


def _read_header(data):
    if len(data) < 8 or struct.unpack_from('<i', data, 0)[0] != _MAGIC:
        raise ExrError('not an OpenEXR file')
    flags = struct.unpack_from('<i', data, 4)[0]
    if flags & (0x200 | 0x800 | 0x1000):  # tiled, deep, multi-part (0x400, long names, is fine)
        raise ExrError('a tiled, deep or multi-part OpenEXR file (rtcli reads scanline images only)')
    at = 8
    attributes = {}
    while True:
        end = data.index(b'\0', at)
        name = data[at:end].decode('latin-1')
        at = end + 1
        if not name:
            break
        end = data.index(b'\0', at)
        kind = data[at:end].decode('latin-1')
        at = end + 1
        size = struct.unpack_from('<i', data, at)[0]
        at += 4
        if size < 0 or at + size > len(data):
            raise ExrError('a damaged header (attribute %s)' % name)
        attributes[name] = (kind, data[at:at + size])
        at += size
    return attributes, at


def _channels(raw):
    channels = []
    at = 0
    while at < len(raw) and raw[at] != 0:
        end = raw.index(b'\0', at)
        name = raw[at:end].decode('utf-8')
        pixel_type, _linear, x_sampling, y_sampling = struct.unpack_from('<iB3xii', raw, end + 1)
        if pixel_type not in _TYPES or x_sampling != 1 or y_sampling != 1:
            raise ExrError('channel %s: a pixel type or sampling rtcli does not read' % name)
        channels.append((name, pixel_type))
        at = end + 1 + 16
    return channels


def _undo_zip(packed, expected):
    raw = numpy.frombuffer(zlib.decompress(packed), dtype=numpy.uint8)
    if raw.size != expected:
        raise ExrError('a chunk decompressed to %d bytes, not %d' % (raw.size, expected))
    # The predictor: each byte stored as its difference from the last, plus 128.
    delta = raw.astype(numpy.int64)
    delta[1:] -= 128
    t = (numpy.cumsum(delta) & 0xff).astype(numpy.uint8)
    # Then the two halves interleaved back.
    out = numpy.empty_like(t)
    half = (t.size + 1) // 2
    out[0::2] = t[:half]
    out[1::2] = t[half:]
    return out.tobytes()


def read_exr(path):
    with open(path, 'rb') as f:
        data = f.read()
    attributes, at = _read_header(data)
    try:
        channels = _channels(attributes['channels'][1])
        compression = attributes['compression'][1][0]
        x0, y0, x1, y1 = struct.unpack('<4i', attributes['dataWindow'][1])
    except KeyError as missing:
        raise ExrError('no %s attribute' % missing) from None
    if compression not in _COMPRESSIONS:
        raise ExrError('compression %d (rtcli reads none, ZIPS and ZIP)' % compression)
    width, height = x1 - x0 + 1, y1 - y0 + 1
    per_chunk = _COMPRESSIONS[compression][1]
    chunks = (height + per_chunk - 1) // per_chunk
    offsets = struct.unpack_from('<%dQ' % chunks, data, at)
    planes = {name: numpy.empty((height, width), numpy.float32) for name, _ in channels}
    for offset in offsets:
        y, size = struct.unpack_from('<ii', data, offset)
        first = y - y0
        lines = min(per_chunk, height - first)
        if first < 0 or lines <= 0:
            raise ExrError('a chunk at line %d, outside the image' % y)
        line_bytes = sum(_TYPES[t][1] for _, t in channels) * width
        block = data[offset + 8:offset + 8 + size]
        if size < lines * line_bytes:
            block = _undo_zip(block, lines * line_bytes)
        at_byte = 0
        for line in range(lines):
            for name, pixel_type in channels:  # each line holds every channel's row in turn
                dtype, size_of = _TYPES[pixel_type]
                row = numpy.frombuffer(block, dtype=dtype, count=width, offset=at_byte)
                planes[name][first + line] = row.astype(numpy.float32)
                at_byte += size_of * width
    return width, height, planes
