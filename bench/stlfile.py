"""STL files for the bench scripts (Python's standard library only): the
corners of a binary or ASCII STL, and a binary STL writer."""

import struct


def stl_corners(path):
    """The corners of every facet of an STL file, three by three."""
    with open(path, "rb") as f:
        return _stl_corners(f.read())


def write_binary_stl(path, facets, header=b"Reparam bench"):
    """Writes facets (triples of points) as a binary STL, normals left 0."""
    with open(path, "wb") as f:
        f.write(header.ljust(80, b" ")[:80])
        f.write(struct.pack("<I", len(facets)))
        for facet in facets:
            f.write(struct.pack("<3f", 0.0, 0.0, 0.0))
            for p in facet:
                f.write(struct.pack("<3f", *p))
            f.write(b"\0\0")


def _stl_corners(data):
    # A binary header may start with "solid" too: a size that matches the
    # triangle count says binary; else ASCII, else binary with a few bytes
    # appended (some writers do)
    count = struct.unpack_from("<I", data, 80)[0] if len(data) >= 84 else -1
    end = 84 + 50 * count
    if len(data) == end:
        return _binary_stl_corners(data[84:end])
    try:
        return _ascii_stl_corners(data)
    except ValueError:
        if count < 0 or len(data) < end:
            raise
        return _binary_stl_corners(data[84:end])


def _binary_stl_corners(records):
    corners = []
    for record in struct.iter_unpack("<12fH", records):
        corners += [record[3:6], record[6:9], record[9:12]]
    return corners


def _ascii_stl_corners(data):
    corners = []
    for line in data.decode("ascii", "replace").splitlines():
        words = line.split()
        if len(words) == 4 and words[0] == "vertex":
            corners.append(tuple(float(w) for w in words[1:]))
    if not corners or len(corners) % 3:
        raise ValueError("not an STL file (or a truncated one)")
    return corners
