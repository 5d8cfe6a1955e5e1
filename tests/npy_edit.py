#!/usr/bin/env python3
"""npy_edit.py - edits a .npy file for tests/stages.sh (no numpy needed).

  npy_edit.py FILE info            prints: descr count (elements)
  npy_edit.py FILE flip INDEX      flips the lowest bit of element INDEX
  npy_edit.py FILE magic           breaks the magic string
  npy_edit.py FILE truncate        drops the last byte
  npy_edit.py FILE dtype           '<u4' -> '<i4', '<f4' -> '<i4' (etc.)
  npy_edit.py FILE shape           one row fewer in header and data (a
                                   well-formed file the manifest disagrees with)
  npy_edit.py FILE huge            2^40 rows in the header, the data as it was
                                   (a truncated file whose shape claims 4 TiB
                                   or more: refused without allocating that)
"""
import re
import sys


def parse(data):
    hlen = data[8] | data[9] << 8
    header = data[10:10 + hlen].decode("latin-1")
    descr = re.search(r"'descr': '([^']*)'", header).group(1)
    shape = tuple(int(x) for x in re.search(r"'shape': \(([^)]*)\)", header)
                  .group(1).split(",") if x.strip())
    return hlen, header, descr, shape


def main():
    path, op = sys.argv[1], sys.argv[2]
    with open(path, "rb") as f:
        data = bytearray(f.read())
    hlen, header, descr, shape = parse(data)
    size = int(descr[2])
    count = 1
    for d in shape:
        count *= d
    start = 10 + hlen
    if op == "info":
        print(descr, count)
        return
    if op == "flip":
        i = int(sys.argv[3])
        assert 0 <= i < count
        data[start + i * size] ^= 1  # little-endian: the lowest bit
    elif op == "magic":
        data[1:6] = b"NUMPX"
    elif op == "truncate":
        data = data[:-1]
    elif op == "dtype":
        new = header.replace("'%s'" % descr, "'<i%d'" % size)
        data[10:10 + hlen] = new.encode("latin-1")
    elif op == "shape":
        rows = shape[0] - 1
        new_shape = "(%d,)" % rows if len(shape) == 1 else "(%d, %d)" % (rows, shape[1])
        new = re.sub(r"\([^)]*\)", new_shape, header, count=1)
        new = new.rstrip("\n").ljust(hlen - 1) + "\n"
        assert len(new) == hlen
        row = size * (count // shape[0])
        data = bytearray(b"\x93NUMPY\x01\x00" + bytes([hlen & 255, hlen >> 8])
                         + new.encode("latin-1") + data[start:len(data) - row])
    elif op == "huge":
        rows = 1 << 40
        new_shape = "(%d,)" % rows if len(shape) == 1 else "(%d, %d)" % (rows, shape[1])
        new = re.sub(r"\([^)]*\)", new_shape, header, count=1).rstrip("\n")
        new += " " * ((64 - (10 + len(new) + 1) % 64) % 64) + "\n"
        data = bytearray(b"\x93NUMPY\x01\x00" + bytes([len(new) & 255, len(new) >> 8])
                         + new.encode("latin-1") + data[start:])
    else:
        sys.exit("unknown operation " + op)
    with open(path, "wb") as f:
        f.write(data)


main()
