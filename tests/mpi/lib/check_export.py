"""Compares a table exported by `pbrfit export` with the HDF5 table it came from (tests/mpi/export_tables.sh).

Usage: check_export.py LIST, each line of LIST the arguments of one check:
  RESULT.h5 FILE --format F [--table T] [--model M] [--precision float|half] [--channels a,b] [--u-axis AXIS]
  [--flip-v] [--readback JSON] [--values TEXT]

The expected texture is built here from the result's datasets, by the layout docs/export.md states (not by
asking pbrfit): every mip level as [layer][z][y][x][channel]. The file is read by a reader pbrfit did not
write: numpy for .npy, pypng for 16-bit PNG (with the value ranges its text chunks hold), the DDS header
parsed field by field as the DDS specification defines it (DDS_HEADER, DDS_PIXELFORMAT with FourCC DX10,
DDS_HEADER_DXT10), three.js's loaders or ktx-parse for EXR, HDR and KTX2 (--readback, from
tests/web/read_textures.mjs), and the values a compiled C++ program or node printed for the source formats
(--values, one number per line, halves as their 16-bit patterns).

Values must match bitwise as float32, as float16 the value rounded to nearest (from the double or from its
float32), within half a 16-bit step of the stated range for PNG and within RGBE's 8-bit mantissa for HDR.
Prints "ok FILE: N values" per check; exits 1 after the checks when one failed, each failure one line.
"""
import argparse
import json
import shlex
import struct
import sys

import h5py
import numpy as np

p = argparse.ArgumentParser()
p.add_argument("result")
p.add_argument("file")
p.add_argument("--format", required=True)
p.add_argument("--table", default="")
p.add_argument("--model", default="")
p.add_argument("--precision", default="float")
p.add_argument("--channels", default="")
p.add_argument("--u-axis", default="")
p.add_argument("--flip-v", action="store_true")
p.add_argument("--readback")
p.add_argument("--values")


class Mismatch(Exception):
    pass


def fail(message):
    raise Mismatch(f"{args.file}: {message}")


def text(attr):
    return attr.decode() if isinstance(attr, bytes) else str(attr)


# --- the expected texture, from the HDF5 datasets -----------------------------------------------------------
LTC_NAMES = {"ltc_1": ["m00", "m20", "m02", "m22"], "ltc_2": ["norm", "fresnel", "zero", "sphere"]}


def planes_of(group, name):
    """A dataset's channels as {channel name: array over the grid}."""
    d = group[name]
    data = d[...].astype(np.float64)
    axes = [a.strip() for a in text(d.attrs.get("axes", "")).split(",") if a.strip()]
    if axes and axes[-1].endswith("_component"):
        names = LTC_NAMES.get(name.replace("published_", ""), [f"{name}.{k}" for k in range(data.shape[-1])])
        return {names[k]: data[..., k] for k in range(data.shape[-1])}, axes[:-1]
    return {name: data}, axes


def as_texture(planes, names, axes):
    """Planes over a 1-3 axis grid -> one level [1][z][y][x][c], with --u-axis and --flip-v applied."""
    stack = np.stack([planes[n] for n in names], axis=-1)
    if args.u_axis and args.u_axis == axes[0]:
        stack = np.swapaxes(stack, 0, 1)
    while stack.ndim < 4:
        stack = stack[np.newaxis]
    if args.flip_v:
        stack = stack[:, ::-1]
    return [stack[np.newaxis]]


def final_level(model):
    for name, g in h5[model].items():
        if isinstance(g, h5py.Group) and text(g.attrs.get("final_level", "")) == "true":
            return g
    fail(f"no final level in model {model}")


def expected():
    chosen = [c for c in args.channels.split(",") if c]
    if kind == "lut":
        group = h5["dfg"] if "dfg" in h5 else h5["disney_diffuse"]
        if "dfg" in h5:
            defaults = ["scale", "bias"] + (["cloth"] if "cloth" in group else [])
        else:
            defaults = ["beta", "zh0", "zh1_ratio", "zh2_ratio"]
        planes = {}
        for name in group:
            if isinstance(group[name], h5py.Dataset) and group[name].ndim == 2:
                planes.update(planes_of(group, name)[0])
        axes = ["roughness", "n_dot_v"]
        return as_texture(planes, chosen or defaults, axes)
    if kind == "sweep":
        model = args.model or list(h5.keys())[0]
        group = final_level(model)
        table = args.table or ("ltc" if "ltc_1" in group else "parameters")
        if table == "ltc":
            one, two = group["ltc_1"][...].astype(np.float64), group["ltc_2"][...].astype(np.float64)
            inner = one.shape[-3:-1]
            one, two = one.reshape((-1,) + inner + (4,)), two.reshape((-1,) + inner + (4,))
            layers = []
            for s in range(one.shape[0]):
                for part in (one[s], two[s]):
                    layers.append(part[::-1] if args.flip_v else part)
            return [np.stack(layers)[:, np.newaxis]]
        if table == "parameters":
            names = [n for n in group if text(group[n].attrs.get("role", "")) == "parameter"]
            planes, axes = {}, None
            for n in names:
                more, axes = planes_of(group, n)
                planes.update(more)
            return as_texture(planes, chosen or names, axes)
        planes, axes = planes_of(group, table)
        return as_texture(planes, chosen or list(planes), axes)
    if kind == "ebrdf":
        base = h5["ebrdf"][args.table or "specular"]
        levels = []
        for name in sorted(base, key=lambda n: int(n[3:])):
            g = base[name]
            m, a, e = (g[k][...].astype(np.float64) for k in ("matrix", "amplitude", "error"))
            rows, cols, views = m.shape[0], m.shape[1], m.shape[2] * m.shape[3]
            m, a, e = m.reshape(rows, cols, views, 9), a.reshape(rows, cols, views), e.reshape(rows, cols, views)
            twelve = np.concatenate([m, a[..., None], e[..., None], np.zeros((rows, cols, views, 1))], axis=-1)
            # [y][x][view][12] -> [view][slice][y][x][4] -> layers (view, slice)
            layers = twelve.reshape(rows, cols, views, 3, 4).transpose(2, 3, 0, 1, 4).reshape(views * 3, rows, cols, 4)
            levels.append(layers[:, np.newaxis])
        return levels
    fail(f"kind {kind} has no tables")




def compare(read, what, stride_in=None):
    """read: the values in the exported order (levels, then layers, z, y, x, channel)."""
    read = np.asarray(read, dtype=np.float64).ravel()
    if read.size != flat.size:
        fail(f"{what}: {read.size} values, expected {flat.size}")
    if args.format == "png" or args.format == "hdr":
        return  # checked by their own tolerances below
    if half:
        from_double = flat.astype(np.float16).astype(np.float64)
        from_float = flat.astype(np.float32).astype(np.float16).astype(np.float64)
        bad = ~((read == from_double) | (read == from_float))
    else:
        bad = read.astype(np.float32).view(np.uint32) != flat.astype(np.float32).view(np.uint32)
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        fail(f"{what}: value {i} is {read[i]!r}, expected {flat[i]!r} ({int(bad.sum())} of {flat.size} differ)")


def check_shape(w, h, d=1, n_layers=1, n_levels=1):
    if (w, h, d, n_layers, n_levels) != (width, height, depth, layers, len(levels)):
        fail(f"shape {w} x {h} x {d}, {n_layers} layers, {n_levels} levels; expected {width} x {height} x {depth}, "
             f"{layers} layers, {len(levels)} levels")


# --- the readers ----------------------------------------------------------------------------------------------
def check(argv):
    global args, h5, kind, levels, half, first, layers, depth, height, width, channels, flat
    args = p.parse_args(argv)
    h5 = h5py.File(args.result, "r")
    kind = text(h5.attrs["job_kind"])
    levels = expected()
    half = args.precision == "half"
    first = levels[0]
    layers, depth, height, width, channels = first.shape
    flat = np.concatenate([lv.ravel() for lv in levels])
    fmt = args.format
    if fmt == "npy":
        a = np.load(args.file)
        want = tuple(n for n, keep in ((layers, layers > 1), (depth, depth > 1), (height, True), (width, True),
                                       (channels, True)) if keep)
        if a.shape != want or a.dtype != (np.float16 if half else np.float32):
            fail(f"npy holds {a.dtype}{a.shape}, expected {'float16' if half else 'float32'}{want}")
        compare(a, "npy")
    elif fmt == "png":
        import png
        reader = png.Reader(filename=args.file)
        w, h, rows, info = reader.asDirect()
        pixels = np.array([list(r) for r in rows], dtype=np.float64).reshape(h, w, info["planes"])
        ranges = {}
        for kind_, data in png.Reader(filename=args.file).chunks():
            if kind_ == b"tEXt" and data.startswith(b"pbrfit:range:"):
                key, value = data[len(b"pbrfit:range:"):].split(b"\0")
                ranges[key.decode()] = [float(v) for v in value.split()]
        check_shape(w, h)
        if info["bitdepth"] != 16 or info["planes"] != channels:
            fail(f"PNG of {info['planes']} planes at {info['bitdepth']} bits; expected {channels} at 16")
        want = first[0, 0]
        for c, (lo, hi) in enumerate(ranges.values()):
            got = lo + (hi - lo) * pixels[..., c] / 65535.0
            step = (hi - lo) / 65535.0
            off = np.abs(got - want[..., c]) - (0.5 * step + 1e-12 * max(abs(lo), abs(hi)))
            if (off > 0).any():
                fail(f"PNG channel {c} is off by up to {np.abs(got - want[..., c]).max():.3g} ({step:.3g} per step)")
            if abs(lo - want[..., c].min()) > 0 or abs(hi - want[..., c].max()) > 0:
                fail(f"PNG channel {c} states the range [{lo!r}, {hi!r}], the table's is [{want[..., c].min()!r}, "
                     f"{want[..., c].max()!r}]")
        if len(ranges) != channels:
            fail(f"PNG states {len(ranges)} value ranges for {channels} channels")
    elif fmt == "dds":
        raw = open(args.file, "rb").read()
        if raw[:4] != b"DDS ":
            fail("no DDS magic")
        (size, flags, h, w, pitch, d, mips), caps = struct.unpack_from("<7I", raw, 4), struct.unpack_from("<4I", raw, 108)
        pf_size, pf_flags, fourcc = struct.unpack_from("<2I4s", raw, 76)
        dxgi, dimension, misc, array_size, misc2 = struct.unpack_from("<5I", raw, 128)
        stored = channels if not (half and channels == 3) else 4
        formats = {(1, 4): 41, (2, 4): 16, (3, 4): 6, (4, 4): 2, (1, 2): 54, (2, 2): 34, (4, 2): 10}
        bytes_per = 2 if half else 4
        want_flags = 0x1 | 0x2 | 0x4 | 0x1000 | (0x20000 if len(levels) > 1 else 0) | (0x800000 if depth > 1 else 0)
        checks = [
            (size, 124, "dwSize"), (pf_size, 32, "ddspf.dwSize"), (pf_flags, 0x4, "ddspf.dwFlags (DDPF_FOURCC)"),
            (fourcc, b"DX10", "ddspf.dwFourCC"), (flags & ~0x80008, want_flags, "dwFlags"), (w, width, "dwWidth"),
            (h, height, "dwHeight"), (dxgi, formats[(stored, bytes_per)], "dxgiFormat"),
            (dimension, 4 if depth > 1 else (2 if height == 1 else 3), "resourceDimension"),
            (array_size, layers, "arraySize"), (misc, 0, "miscFlag"),
            (caps[0] & 0x1000, 0x1000, "dwCaps DDSCAPS_TEXTURE"),
            (bool(caps[0] & 0x400000), len(levels) > 1, "dwCaps DDSCAPS_MIPMAP"),
            (bool(caps[0] & 0x8), len(levels) > 1 or depth > 1 or layers > 1, "dwCaps DDSCAPS_COMPLEX"),
            (caps[1] & 0x200000, 0x200000 if depth > 1 else 0, "dwCaps2 DDSCAPS2_VOLUME"),
            (max(mips, 1), len(levels), "dwMipMapCount"), (max(d, 1), depth, "dwDepth"),
        ]
        if flags & 0x8:
            checks.append((pitch, width * stored * bytes_per, "dwPitchOrLinearSize (pitch)"))
        for got, want, field in checks:
            if got != want:
                fail(f"DDS {field} is {got!r}, the specification wants {want!r}")
        values = np.frombuffer(raw[148:], dtype=np.float16 if half else np.float32).astype(np.float64)
        values = values.reshape(-1, stored)
        # DDS: each layer with its mip chain in turn; a volume: each level with all its slices.
        read = []
        offset = 0
        per_layer = [lv.shape[1] * lv.shape[2] * lv.shape[3] for lv in levels]
        by_layer = []
        for _ in range(layers):
            chain = []
            for count in per_layer:
                chain.append(values[offset:offset + count])
                offset += count
            by_layer.append(chain)
        if offset != len(values):
            fail(f"DDS holds {len(values)} texels after its headers, expected {offset}")
        if stored == 4 and channels == 3 and not np.all(values[:, 3] == 1):
            fail("DDS: the widened alpha of an RGB texture is not 1")
        read = [by_layer[l][k][:, :channels] for k in range(len(levels)) for l in range(layers)]
        compare(np.concatenate([r.ravel() for r in read]), "dds")
    elif fmt in ("exr", "hdr", "ktx2"):
        r = json.load(open(args.readback))
        check_shape(r["width"], r["height"], r["depth"], r["layers"], len(r["levels"]))
        n = r["channels"]
        if fmt == "ktx2" and n != channels:
            fail(f"KTX2 of {n} channels, expected {channels}")
        read = [np.asarray(lv, dtype=np.float64).reshape(-1, n)[:, :channels] for lv in r["levels"]]
        if fmt == "hdr":
            got, want = read[0].reshape(first.shape), first
            # RGBE: three 8-bit mantissas sharing the largest component's exponent; zero below 1e-32.
            largest = np.max(np.pad(want, [(0, 0)] * 4 + [(0, 3 - channels)]), axis=-1, keepdims=True)
            if (np.abs(got - want) > largest * 2.0**-7 + 1e-30).any():
                fail(f"HDR values off by up to {np.abs(got - want).max():.3g}, more than RGBE's 8-bit mantissa allows")
        compare(np.concatenate([x.ravel() for x in read]), f"{fmt} read by {r['reader']}")
    elif fmt in ("cpp", "js"):
        compare(np.loadtxt(args.values, dtype=np.float64, ndmin=1) if not half else
                np.loadtxt(args.values, dtype=np.uint16, ndmin=1).view(np.float16).astype(np.float64), fmt)
    else:
        fail(f"no reader for format {fmt}")
    print(f"ok {args.file}: {flat.size} values")


failures = 0
for line in open(sys.argv[1]):
    if line.strip():
        try:
            check(shlex.split(line))
        except Mismatch as e:
            print(e, file=sys.stderr)
            failures += 1
sys.exit(1 if failures else 0)
