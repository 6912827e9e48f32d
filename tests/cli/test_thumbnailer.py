#!/usr/bin/env python3
"""The desktop thumbnailer as a file manager uses it: install phongrast's
runtime files into a fresh prefix, read the .thumbnailer entry the install
wrote, check its MIME types, and run its Exec line with %i %o %s filled in
(an OBJ, a PLY and a GLB; an output name with and without .png). Each
thumbnail must be an RGBA PNG of the asked size whose corners are
transparent and whose centre is opaque (the mesh, framed as `render` frames it).

    test_thumbnailer.py BUILD_DIR WORK_DIR DATA_DIR
"""
import os
import shlex
import shutil
import struct
import subprocess
import sys
import zlib

MIME_TYPES = ["model/obj", "model/stl", "model/x.stl-ascii", "model/x.stl-binary",
              "model/gltf+json", "model/gltf-binary", "model/x-ply"]


def decode_png(path):
    """(width, height, colour type, rows of bytes) of an 8-bit PNG, any filters."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG"
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour = header[:4]
    assert depth == 8, f"{path}: bit depth {depth}"
    bpp = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
    raw = zlib.decompress(idat)
    stride = width * bpp
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = previous[i]
            c = previous[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        previous = line
    return width, height, colour, rows


def main():
    build, work, data = sys.argv[1:4]
    prefix = os.path.join(work, "prefix")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    subprocess.run(["cmake", "--install", build, "--component", "phongrast_runtime", "--prefix", prefix],
                   check=True, stdout=subprocess.DEVNULL)
    entry = os.path.join(prefix, "share", "thumbnailers", "phongrast.thumbnailer")
    fields = {}
    lines = open(entry).read().splitlines()
    assert lines[0] == "[Thumbnailer Entry]", f"{entry}: first line {lines[0]!r}"
    for line in lines[1:]:
        key, _, value = line.partition("=")
        fields[key] = value
    declared = [t for t in fields["MimeType"].split(";") if t]
    for mime in MIME_TYPES:
        assert mime in declared, f"{entry}: MimeType lacks {mime}: {fields['MimeType']}"
    program = os.path.join(prefix, "bin", "phongrast")
    assert fields["TryExec"] == program, f"TryExec={fields['TryExec']}, expected {program}"
    assert os.path.exists(os.path.join(prefix, "share", "mime", "packages", "phongrast-mesh-mime.xml"))

    size = 96
    for mesh, output in [("triangle.obj", "obj.png"), ("triangle.ply", "ply-thumbnail"),
                         ("triangle.glb", "glb.png")]:
        arguments = []
        for word in shlex.split(fields["Exec"]):
            word = word.replace("%i", os.path.join(data, mesh)).replace("%o", os.path.join(work, output))
            arguments.append(word.replace("%s", str(size)))
        print("running:", " ".join(shlex.quote(a) for a in arguments))
        subprocess.run(arguments, check=True)
        width, height, colour, rows = decode_png(os.path.join(work, output))
        assert (width, height, colour) == (size, size, 6), f"{output}: {width}x{height}, colour type {colour}"
        corners = [rows[0][3], rows[0][4 * size - 1], rows[size - 1][3], rows[size - 1][4 * size - 1]]
        assert corners == [0, 0, 0, 0], f"{output}: corner alpha {corners}, expected transparent"
        opaque = sum(1 for row in rows for x in range(size) if row[4 * x + 3] == 255)
        assert opaque > size * size // 20, f"{output}: only {opaque} opaque pixels"
        assert not [f for f in os.listdir(work) if ".tmp-" in f], "a temporary file was left"
    # A file that is no mesh: non-zero exit, nothing written.
    bad = os.path.join(work, "bad.obj")
    open(bad, "w").write("v 0 0 0\nf 1 2 3\n")
    result = subprocess.run([program, "thumbnail", bad, os.path.join(work, "bad.png"), "--size", "64"],
                            stderr=subprocess.PIPE, text=True)
    assert result.returncode == 2 and "bad.obj" in result.stderr, (result.returncode, result.stderr)
    assert not os.path.exists(os.path.join(work, "bad.png"))
    print("thumbnailer entry works:", fields["Exec"])


if __name__ == "__main__":
    main()
