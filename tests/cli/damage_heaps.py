#!/usr/bin/env python3
"""damage_heaps.py MODE FILE: damages the global heap collections of an HDF5 file in place, as
a torn or overwritten file does. Variable-length strings (run names, summary columns, stored
scenarios) live in global heap collections (signature GCOL), which HDF5 reads without bounds:

  zero    the objects of every collection zeroed (the signature kept): HDF5 1.10 loops forever
          on an object of size 0
  ff      the objects of every collection overwritten with 0xff from the first object's size
          on: HDF5 aborts or segfaults
  length  the length of the first string of /batch/summary/name (in the dataset's raw data)
          set to 2^32 - 1: HDF5 allocates 4 GiB for it before it reads the collection

Prints the number of collections damaged (zero, ff) or the offset changed (length)."""
import struct
import sys


def collections(data):
    """Offsets of the collections: the signature, version 1, three zero bytes."""
    offsets, start = [], 0
    while True:
        at = data.find(b"GCOL\x01\x00\x00\x00", start)
        if at < 0:
            return offsets
        offsets.append(at)
        start = at + 8


def main():
    mode, path = sys.argv[1], sys.argv[2]
    with open(path, "rb") as f:
        data = bytearray(f.read())
    if mode in ("zero", "ff"):
        found = collections(data)
        for at in found:
            size = struct.unpack_from("<Q", data, at + 8)[0]
            # The collection's header is 16 bytes; an object's header holds its index (2
            # bytes), reference count (2), 4 reserved bytes, then its size (8).
            start = at + (16 if mode == "zero" else 24)
            end = min(at + min(size, 512 + 16), len(data))
            data[start:end] = (b"\x00" if mode == "zero" else b"\xff") * (end - start)
        print(len(found))
    elif mode == "length":
        import h5py
        with h5py.File(path, "r") as f:
            offset = f["batch/summary/name"].id.get_offset()
        struct.pack_into("<I", data, offset, 0xFFFFFFFF)
        print(offset)
    else:
        sys.exit("damage_heaps.py: unknown mode " + mode)
    if mode in ("zero", "ff") and not found:
        sys.exit("damage_heaps.py: no global heap collection in " + path)
    with open(path, "r+b") as f:
        f.write(data)


if __name__ == "__main__":
    main()
