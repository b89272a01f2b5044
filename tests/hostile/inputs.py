"""Input generators of the hostile matrix: meshes, glTF/GLB, PNG, KTX2 (with hand-made Zstandard
frames), stroke lists, styles, scenes. Standard library only, written from the format pages, not from
the project's code: an outside check."""

import base64
import json
import math
import os
import struct
import zlib

# ----------------------------------------------------------------------------------------------
# Meshes


def tetra():
    """A regular-ish tetrahedron: (positions, triangles)."""
    pts = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
    tris = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    return pts, tris


def lathe(segments=32, rings=None, profile=None):
    """A closed surface of revolution about +y (a barrel): (positions, triangles). `rings` resamples
    the profile's side into that many rows (for big meshes)."""
    if profile is None:
        profile = [(0.3, 0.0), (0.38, 0.35), (0.38, 0.65), (0.3, 1.0)]
    if rings is not None and rings > len(profile):
        # Resample the side profile into `rings` rows (linear between the given points).
        out = []
        for k in range(rings):
            t = k / (rings - 1) * (len(profile) - 1)
            i = min(int(t), len(profile) - 2)
            f = t - i
            (r0, h0), (r1, h1) = profile[i], profile[i + 1]
            out.append((r0 + (r1 - r0) * f, h0 + (h1 - h0) * f))
        profile = out
    pts = [(0.0, profile[0][1], 0.0)]  # bottom pole
    for r, h in profile:
        for s in range(segments):
            a = 2 * math.pi * s / segments
            pts.append((r * math.cos(a), h, -r * math.sin(a)))
    top = len(pts)
    pts.append((0.0, profile[-1][1], 0.0))
    tris = []
    ring = lambda k, s: 1 + k * segments + (s % segments)
    for s in range(segments):  # bottom cap, facing -y
        tris.append((0, ring(0, s + 1), ring(0, s)))
    for k in range(len(profile) - 1):
        for s in range(segments):
            a, b = ring(k, s), ring(k, s + 1)
            c, d = ring(k + 1, s), ring(k + 1, s + 1)
            tris.append((a, b, d))
            tris.append((a, d, c))
    for s in range(segments):  # top cap, facing +y
        tris.append((top, ring(len(profile) - 1, s), ring(len(profile) - 1, s + 1)))
    return pts, tris


def fmt(v):
    return repr(float(v)) if not float(v).is_integer() else str(int(v))


def obj_text(mesh):
    pts, tris = mesh
    lines = ["# hostile test mesh"]
    lines += ["v %s %s %s" % tuple(fmt(c) for c in p) for p in pts]
    lines += ["f %d %d %d" % (a + 1, b + 1, c + 1) for a, b, c in tris]
    return "\n".join(lines) + "\n"


def obj_text_uv(mesh):
    """OBJ with a texture coordinate per vertex (x, y + z: every face of the tetrahedron has UV
    area), for the tools that lay patterns out in UV (groovebake --apply-to)."""
    pts, tris = mesh
    lines = ["# hostile test mesh with UVs"]
    lines += ["v %s %s %s" % tuple(fmt(c) for c in p) for p in pts]
    lines += ["vt %s %s" % (fmt(p[0] + 0.5 * p[2]), fmt(p[1] + 0.3 * p[2])) for p in pts]
    lines += ["f %d/%d %d/%d %d/%d" % (a + 1, a + 1, b + 1, b + 1, c + 1, c + 1) for a, b, c in tris]
    return "\n".join(lines) + "\n"


def ply_text(mesh):
    pts, tris = mesh
    head = ["ply", "format ascii 1.0", "element vertex %d" % len(pts), "property float x", "property float y",
            "property float z", "element face %d" % len(tris), "property list uchar int vertex_indices", "end_header"]
    body = ["%s %s %s" % tuple(fmt(c) for c in p) for p in pts] + ["3 %d %d %d" % t for t in tris]
    return "\n".join(head + body) + "\n"


def off_text(mesh):
    pts, tris = mesh
    lines = ["OFF", "%d %d 0" % (len(pts), len(tris))]
    lines += ["%s %s %s" % tuple(fmt(c) for c in p) for p in pts]
    lines += ["3 %d %d %d" % t for t in tris]
    return "\n".join(lines) + "\n"


def stl_text(mesh):
    pts, tris = mesh
    out = ["solid hostile"]
    for a, b, c in tris:
        pa, pb, pc = pts[a], pts[b], pts[c]
        u = [pb[i] - pa[i] for i in range(3)]
        v = [pc[i] - pa[i] for i in range(3)]
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        ln = math.sqrt(sum(x * x for x in n)) or 1.0
        out.append("facet normal %s %s %s" % tuple(fmt(x / ln) for x in n))
        out.append("outer loop")
        for p in (pa, pb, pc):
            out.append("vertex %s %s %s" % tuple(fmt(x) for x in p))
        out.append("endloop")
        out.append("endfacet")
    out.append("endsolid hostile")
    return "\n".join(out) + "\n"


MESH_TEXT = {"obj": obj_text, "ply": ply_text, "off": off_text, "stl": stl_text}

# ----------------------------------------------------------------------------------------------
# glTF / GLB


def mesh_buffer(mesh):
    """Binary buffer of a mesh: float32 positions then uint32 indices; returns (bytes, views, accessors)."""
    pts, tris = mesh
    pos = b"".join(struct.pack("<3f", *p) for p in pts)
    idx = b"".join(struct.pack("<3I", *t) for t in tris)
    lo = [min(p[i] for p in pts) for i in range(3)]
    hi = [max(p[i] for p in pts) for i in range(3)]
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos), "target": 34962},
             {"buffer": 0, "byteOffset": len(pos), "byteLength": len(idx), "target": 34963}]
    accessors = [{"bufferView": 0, "componentType": 5126, "count": len(pts), "type": "VEC3", "min": lo, "max": hi},
                 {"bufferView": 1, "componentType": 5125, "count": 3 * len(tris), "type": "SCALAR"}]
    return pos + idx, views, accessors


def gltf_doc(mesh, uri=None, byte_length=None, extra=None, nodes=None):
    data, views, accessors = mesh_buffer(mesh)
    buf = {"byteLength": byte_length if byte_length is not None else len(data)}
    if uri is not None:
        buf["uri"] = uri
    doc = {"asset": {"version": "2.0", "generator": "hostile"}, "scene": 0, "scenes": [{"nodes": [0]}],
           "nodes": nodes if nodes is not None else [{"mesh": 0, "name": "body"}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
           "buffers": [buf], "bufferViews": views, "accessors": accessors}
    if extra:
        doc.update(extra)
    return doc, data


def glb_bytes(json_text, bin_data=None, json_len=None, bin_len=None, total_len=None):
    """A GLB container. `json_len`, `bin_len`, `total_len` override the declared lengths (hostile)."""
    j = json_text.encode() if isinstance(json_text, str) else json_text
    j += b" " * ((4 - len(j) % 4) % 4)
    out = struct.pack("<I4s", json_len if json_len is not None else len(j), b"JSON") + j
    if bin_data is not None:
        b = bin_data + b"\0" * ((4 - len(bin_data) % 4) % 4)
        out += struct.pack("<I4s", bin_len if bin_len is not None else len(b), b"BIN\0") + b
    total = 12 + len(out)
    return struct.pack("<4sII", b"glTF", 2, total_len if total_len is not None else total) + out


def glb_of(mesh, extra=None, nodes=None):
    doc, data = gltf_doc(mesh, extra=extra, nodes=nodes)
    return glb_bytes(json.dumps(doc, separators=(",", ":")), data)


def gltf_data_uri(mesh, extra=None):
    doc, data = gltf_doc(mesh)
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    if extra:
        doc.update(extra)
    return json.dumps(doc)


def chain_nodes_json(n):
    """The `nodes` array text of an n-node chain: node i has children [i+1]; the last holds mesh 0."""
    parts = ['{"children":[%d]}' % (i + 1) for i in range(n - 1)]
    parts.append('{"mesh":0,"name":"tip"}')
    return "[" + ",".join(parts) + "]"


def chain_glb(mesh, n):
    doc, data = gltf_doc(mesh, nodes=[])
    text = json.dumps(doc, separators=(",", ":")).replace('"nodes":[]', '"nodes":' + chain_nodes_json(n), 1)
    return glb_bytes(text, data)


def chain_gltf(mesh, n):
    doc, data = gltf_doc(mesh, nodes=[])
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    return json.dumps(doc, separators=(",", ":")).replace('"nodes":[]', '"nodes":' + chain_nodes_json(n), 1)


def nested(depth, kind):
    """`depth` nested JSON arrays (kind 'array') or objects (kind 'object')."""
    if kind == "array":
        return "[" * depth + "]" * depth
    return '{"n":' * depth + "0" + "}" * depth


def nested_ext_glb(mesh, depth, kind):
    """A GLB whose BAKE_geodesic extension object holds `depth` nested arrays/objects."""
    doc, data = gltf_doc(mesh, extra={"extensionsUsed": ["BAKE_geodesic"],
                                      "extensions": {"BAKE_geodesic": {"version": 1, "deep": "@@NEST@@"}}})
    text = json.dumps(doc, separators=(",", ":")).replace('"@@NEST@@"', nested(depth, kind), 1)
    return glb_bytes(text, data)


def write_big_data_uri_gltf(path, mesh, total_bytes):
    """A .gltf whose one buffer is a base64 data URI of `total_bytes` bytes: the mesh, then zeros.
    Streamed to disk (the text is about 4/3 of `total_bytes`)."""
    data, views, accessors = mesh_buffer(mesh)
    head = data + b"\0" * ((3 - len(data) % 3) % 3)
    rest = total_bytes - len(head)
    assert rest % 3 == 0 and rest > 0
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
           "buffers": [{"byteLength": total_bytes, "uri": "@@URI@@"}], "bufferViews": views, "accessors": accessors}
    before, after = json.dumps(doc).split('"@@URI@@"')
    chunk = b"A" * (4 * (1 << 20))  # base64 of 3 MiB of zeros
    with open(path, "wb") as f:
        f.write(before.encode() + b'"data:application/octet-stream;base64,')
        f.write(base64.b64encode(head))
        left = rest // 3 * 4
        while left > 0:
            n = min(left, len(chunk))
            f.write(chunk[:n])
            left -= n
        f.write(b'"' + after.encode())


# ----------------------------------------------------------------------------------------------
# PNG


def png_bytes(width, height, row_fn=None, colour_type=0, level=6):
    """A PNG (8-bit grey, colour_type 0, or RGBA, 6). row_fn(y) -> the row's bytes (without the filter
    byte); rows equal to the previous one are written with the Up filter (zeros), so big uniform
    images compress to little, fast."""
    channels = {0: 1, 2: 3, 6: 4}[colour_type]
    if row_fn is None:
        row_fn = lambda y: b"\xff" * (width * channels)
    comp = zlib.compressobj(level)
    chunks = []
    prev = None
    zero = None
    for y in range(height):
        row = row_fn(y)
        assert len(row) == width * channels
        if row == prev:
            if zero is None or len(zero) != len(row) + 1:
                zero = b"\x02" + b"\0" * len(row)
            chunks.append(comp.compress(zero))
        else:
            chunks.append(comp.compress(b"\x00" + row))
        prev = row
    chunks.append(comp.flush())
    idat = b"".join(chunks)

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    ihdr = struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", idat) + chunk(b"IEND", b"")


def png_profile(width, height):
    """A coverage image for revolbake: inked (black) left of 60 % of the width over the middle rows:
    a cylinder. Column 0 is the axis, up is +h."""
    inked = int(width * 0.6)
    full = b"\x00" * inked + b"\xff" * (width - inked)
    empty = b"\xff" * width
    lo, hi = height // 8, height - height // 8
    return png_bytes(width, height, lambda y: full if lo <= y < hi else empty)


def png_pattern(width, height, colour_type=0):
    """A small non-uniform image (height map, base colour, stroke image)."""
    channels = {0: 1, 2: 3, 6: 4}[colour_type]

    def row(y):
        out = bytearray()
        for x in range(width):
            v = (x * 37 + y * 91) % 256
            out += bytes([v] * channels) if colour_type != 6 else bytes([v, v, v, 255 - v])
        return bytes(out)

    return png_bytes(width, height, row, colour_type)


# ----------------------------------------------------------------------------------------------
# KTX2 with Zstandard supercompression


def zstd_rle_frame(size, block=1 << 16, content_size=True, byte=0):
    """A Zstandard frame that inflates to `size` copies of `byte`, made of RLE blocks of `block` bytes
    (RFC 8878: frame header with a 128 KiB window descriptor, optional 8-byte Frame_Content_Size)."""
    assert 0 < block <= 1 << 17
    descriptor = (3 << 6) if content_size else 0  # FCS 8 bytes, Single_Segment 0
    out = bytearray(struct.pack("<I", 0xFD2FB528))
    out.append(descriptor)
    out.append(7 << 3)  # Window_Descriptor: 2^(10+7) = 128 KiB
    if content_size:
        out += struct.pack("<Q", size)
    left = size
    while left > 0:
        n = min(block, left)
        left -= n
        header = (1 if left == 0 else 0) | (1 << 1) | (n << 3)  # Last_Block, RLE, Block_Size
        out += struct.pack("<I", header)[:3] + bytes([byte])
    return bytes(out)


def ktx2_bytes(width, height, layers, vkformat, texel_bytes, levels, kvd=b""):
    """A KTX2 file with Zstandard supercompression (scheme 2). `levels`: list, base level first, of
    (compressed bytes, declared uncompressedByteLength). One sample per channel, 8-bit UNORM. `kvd`:
    raw key/value data (entries with their padding), placed right after the DFD."""
    channels = texel_bytes  # 8-bit formats only
    samples = b""
    ids = [0, 1, 2, 15][:channels] if channels != 1 else [0]
    for k, cid in enumerate(ids):
        samples += struct.pack("<HBB4sII", 8 * k, 7, cid, b"\0\0\0\0", 0, 255)
    block = struct.pack("<IHH", 0, 2, 24 + len(samples)) + bytes([1, 1, 1, 0]) + b"\0\0\0\0" + b"\0" * 8 + samples
    dfd = struct.pack("<I", 4 + len(block)) + block
    n = len(levels)
    dfd_off = 80 + 24 * n
    kvd_off = dfd_off + len(dfd)
    data_off = kvd_off + len(kvd)
    data_off += (-data_off) % 8
    # Mip levels are stored smallest first; the base level ends the file.
    offsets = [0] * n
    body = b""
    at = data_off
    for i in reversed(range(n)):
        offsets[i] = at
        body += levels[i][0]
        at += len(levels[i][0])
    header = b"\xabKTX 20\xbb\r\n\x1a\n" + struct.pack("<9I", vkformat, 1, width, height, 0, layers, 1, n, 2)
    index = struct.pack("<IIIIQQ", dfd_off, len(dfd), kvd_off if kvd else 0, len(kvd), 0, 0)
    level_index = b"".join(struct.pack("<QQQ", offsets[i], len(levels[i][0]), levels[i][1]) for i in range(n))
    head = header + index + level_index + dfd + kvd
    head += b"\0" * (data_off - len(head))
    return head + body


# ----------------------------------------------------------------------------------------------
# Text inputs of the bakers (minimal valid ones, shaped like the project's examples)

SOURCES = {"fields": [{"name": "a", "sources": [{"vertex": 0}]}, {"name": "b", "sources": [{"vertex": 2}]}]}

RING_PROFILE = {"description": "a small ring", "contours": [{"closed": True, "points": [[0.7, 0.25], [0.5, 0.25]],
                                                             "bulges": [1, 1]}]}

CSV_PROFILE = "# r,h,bulge\n0,-0.5,1\n0,0.5,0\n"

SVG_PROFILE = ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 1 1">'
               '<path id="p" d="M 0 0 L 0.4 0 L 0.4 -0.8 L 0 -0.8 Z"/></svg>\n')

SVG_DRAWING = ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">'
               '<line x1="1" y1="5" x2="9" y2="5"/></svg>\n')

TAM_STYLE = {"description": "tiny", "tones": 2, "resolution": 16, "levels": 1, "candidates": 1, "seed": 3,
             "stroke": {"kind": "hatching", "length": {"min": 0.3, "max": 0.5}, "width": {"min": 1.0, "max": 1.5}}}


def groove_scene(svg_name="drawing.svg", extra_grooves=None, generators=None, svg_in_scene=True):
    grooves = [{"name": "cut", "profile": "v", "path": {"line": [[1, 1], [9, 9]]}}]
    if svg_in_scene:
        grooves.append({"name": "logo", "profile": "v", "path": {"svgFile": {"file": svg_name}}})
    grooves += extra_grooves or []
    scene = {"version": 1, "domain": {"size": [10, 10]},
             "profiles": {"v": {"points": [[-0.2, 0], [0, -0.1], [0.2, 0]]}},
             "materials": {"m": {}}, "base": "m", "grooves": grooves}
    if generators:
        scene["generators"] = generators
    return scene


STROKES = {"version": 1, "units": "m",
           "styles": [{"name": "hair", "edgeOpacity": 0.3}],
           "strokes": [{"style": "hair", "points": [{"p": [0, 0, 0], "r": 0.02, "colour": [0.4, 0.25, 0.1]},
                                                    {"p": [0, 0.5, 0.1], "r": 0.015},
                                                    {"p": [0.1, 1, 0.2], "r": 0.005}]},
                       {"points": [{"p": [1, 0, 0], "r": 0.03}, {"p": [1.1, 0.4, 0], "r": 0.02}]}]}

STROKES_CSV = ("stroke,x,y,z,radius,r,g,b\n1,0,0,0,0.02,0.5,0.3,0.1\n1,0,0.5,0,0.015,0.6,0.4,0.2\n"
               "2,1,0,0,0.02,0.5,0.3,0.1\n2,1,1,0,0.01,0.7,0.5,0.3\n")


def strokes_with_grow(mesh_name, count=20):
    doc = json.loads(json.dumps(STROKES))
    doc["generators"] = [{"type": "grow", "mesh": mesh_name, "count": count, "length": 0.1, "pointsPerStroke": 3}]
    return doc


def pipe_scene(input_name="ring.json", name="hostile", objects=None):
    """A bakepipe scene: one revolution object (the ring) with no textures."""
    if objects is None:
        objects = [{"name": "ring", "technique": "revolution", "input": input_name,
                    "options": {"resolution": 64}, "material": "plain"}]
    return {"version": 1, "name": name, "objects": objects,
            "materials": [{"name": "plain", "technique": "revolution",
                           "reads": {"baseColor": False, "displacement": False}}],
            "cameras": [{"name": "front", "eye": [0, 1, 4], "target": [0, 0, 0], "yfov": 40, "width": 64,
                         "height": 64}]}


def write(path, content, mode="w"):
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    if isinstance(content, (dict, list)):
        content = json.dumps(content, indent=1)
    if isinstance(content, str):
        content = content.encode()
    with open(path, "wb") as f:
        f.write(content)
    return path
