#!/usr/bin/env python3
"""Writes the model corpus of tests/meshes/model_corpus_test.cpp: one small
file per case a user's model brings (texture path forms, a missing texture,
a glTF texture transform, Z-up files, flat models, non-finite vertices, zero
normals). Run from this folder; the files are committed, this documents them."""
import base64, json, math, struct, zlib, os

def png(w, h, rows):
    raw = b"".join(b"\0" + bytes(c for p in row for c in p) for row in rows)
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))

def write(name, data):
    with open(name, "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)

RED = (255, 0, 0)
os.makedirs("textures", exist_ok=True)
write("textures/Red.png", png(4, 4, [[RED] * 4] * 4))

# A 2x2 quad facing +Z, textured; its material's base colour is blue, so a
# texture that is not found shows blue, one that is shows red.
QUAD = """v -1 -1 0
v 1 -1 0
v 1 1 0
v -1 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
usemtl m
f 1/1/1 2/2/1 3/3/1 4/4/1
"""
forms = {
    "tex_backslash": r"textures\Red.png",
    "tex_dot_backslash": r".\textures\Red.png",
    "tex_windows_absolute": r"C:\Users\artist\project\maps\Red.png",
    "tex_drive_slash": "Q:/assets/red.png",
    "tex_blender": "//textures/Red.png",
    "tex_letter_case": "TEXTURES/RED.PNG",
    "tex_missing": "nowhere/not-here.png",
}
for name, path in forms.items():
    write(f"{name}.mtl", f"newmtl m\nKd 0.1 0.2 1\nmap_Kd {path}\n")
    write(f"{name}.obj", f"# texture path form: {path}\nmtllib {name}.mtl\n" + QUAD)
# An empty texture name: no texture, no warning.
write("tex_empty.mtl", "newmtl m\nKd 0.1 0.2 1\nmap_Kd \"\"\n")
write("tex_empty.obj", "mtllib tex_empty.mtl\n" + QUAD)

# Flat models: a quad standing in the YZ plane facing +X (edge-on from the
# orbit's old start on +Z), and one lying in the XZ plane facing up.
write("flat_wall.obj", """# a 2x2 quad in the YZ plane, facing +X
v 0 -1 -1
v 0 -1 1
v 0 1 1
v 0 1 -1
vn 1 0 0
f 1//1 2//1 3//1 4//1
""")
write("flat_floor.obj", """# a 2x2 quad in the XZ plane, facing +Y
v -1 0 -1
v -1 0 1
v 1 0 1
v 1 0 -1
vn 0 1 0
f 1//1 2//1 3//1 4//1
""")

# A cube, and the same cube with vertices at NaN and inf and triangles that
# use them; and a file with nothing finite.
CUBE_V = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
CUBE_F = [(1, 2, 4, 3), (5, 7, 8, 6), (1, 5, 6, 2), (3, 4, 8, 7), (1, 3, 7, 5), (2, 6, 8, 4)]
cube = "".join(f"v {x} {y} {z}\n" for x, y, z in CUBE_V)
faces = "".join("f " + " ".join(map(str, f)) + "\n" for f in CUBE_F)
write("finite_cube.obj", "# the finite part of nonfinite_cube.obj\n" + cube + faces)
write("nonfinite_cube.obj", "# a cube plus three non-finite vertices and triangles that use them\n" +
      cube + "v nan 0 0\nv 0 inf 0\nv 1 2 -inf\n" + faces + "f 1 2 9\nf 9 10 11\nf 3 4 11\n")
write("all_nan.obj", "v nan nan nan\nv nan 0 nan\nv nan nan 0\nf 1 2 3\n")

# Zero normals (written so by a broken exporter): the same quad must be lit.
write("zero_normals.obj", """# a quad facing +Z whose normals are all zero
v -1 -1 0
v 1 -1 0
v 1 1 0
v -1 1 0
vn 0 0 0
f 1//1 2//1 3//1 4//1
""")

# A tall box (1 x 1 x 3 along Z) in Z-up files: FBX with UpAxis metadata,
# and OBJ (no metadata: --up z).
P = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (0, 3)]
quads = []
for axis, (lo, hi) in enumerate([(-0.5, 0.5), (-0.5, 0.5), (0, 3)]):
    for side in (lo, hi):
        q = sorted([p for p in P if p[axis] == side],
                   key=lambda p: tuple(p[a] for a in range(3) if a != axis))
        a, b, c, d = [P.index(p) for p in q]
        quads.append((a, b, d, c))
write("tall_zup.obj", "# a 1x1x3 box standing on Z (Z-up, no metadata)\n" +
      "".join(f"v {x} {y} {z}\n" for x, y, z in P) +
      "".join("f " + " ".join(str(i + 1) for i in q) + "\n" for q in quads))
verts = ",".join(f"{x},{y},{z}" for x, y, z in P)
idx = ",".join(f"{a},{b},{c},{-d - 1}" for a, b, c, d in quads)
write("tall_zup.fbx", f"""; FBX 7.4.0 project file
; a 1x1x3 box standing on Z, with UpAxis = 2 in GlobalSettings
FBXHeaderExtension:  {{
	FBXHeaderVersion: 1003
	FBXVersion: 7400
}}
GlobalSettings:  {{
	Version: 1000
	Properties70:  {{
		P: "UpAxis", "int", "Integer", "",2
		P: "UpAxisSign", "int", "Integer", "",1
		P: "FrontAxis", "int", "Integer", "",1
		P: "FrontAxisSign", "int", "Integer", "",-1
		P: "CoordAxis", "int", "Integer", "",0
		P: "CoordAxisSign", "int", "Integer", "",1
		P: "UnitScaleFactor", "double", "Number", "",1
	}}
}}
Objects:  {{
	Geometry: 1000, "Geometry::box", "Mesh" {{
		Vertices: *{len(P) * 3} {{
			a: {verts}
		}}
		PolygonVertexIndex: *{len(quads) * 4} {{
			a: {idx}
		}}
		GeometryVersion: 124
	}}
	Model: 2000, "Model::box", "Mesh" {{
		Version: 232
	}}
}}
Connections:  {{
	C: "OO",2000,0
	C: "OO",1000,2000
}}
""")

# glTF KHR_texture_transform: a quad with UVs 0..1 and a 2x2 texture (red,
# green / blue, yellow from the top); offset [0.5, 0] and scale 0.5 select
# the top-right texel only: the whole quad is green.
R, G, B, Y = (255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 0)
img = png(2, 2, [[R, G], [B, Y]])
buf = (struct.pack("<12f", -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0) +
       struct.pack("<12f", *([0, 0, 1] * 4)) +
       struct.pack("<8f", 0, 1, 1, 1, 1, 0, 0, 0) + struct.pack("<6H", 0, 1, 2, 0, 2, 3))
g = {"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_texture_transform"],
     "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
     "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                 "indices": 3, "material": 0}]}],
     "materials": [{"pbrMetallicRoughness": {"metallicFactor": 0, "baseColorTexture": {
         "index": 0, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0], "scale": [0.5, 0.5]}}}}}],
     "textures": [{"source": 0, "sampler": 0}], "samplers": [{"magFilter": 9728, "minFilter": 9728}],
     "images": [{"uri": "data:image/png;base64," + base64.b64encode(img).decode()}],
     "buffers": [{"byteLength": len(buf),
                  "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
     "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                     {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                     {"buffer": 0, "byteOffset": 96, "byteLength": 32},
                     {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
     "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                    "min": [-1, -1, 0], "max": [1, 1, 0]},
                   {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                   {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                   {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
write("texture_transform.gltf", json.dumps(g, indent=1) + "\n")

# Projection mappings (LightWave LWO2, binary, written here): a sphere whose
# texture (red and green stripes across u) is mapped by projection, with no
# UVs in the file; both colours show only when UVs are generated.
GRN = (0, 255, 0)
write("textures/stripes.png", png(8, 8, [[RED, RED, GRN, GRN, RED, RED, GRN, GRN]] * 8))

def lwo_sphere(name, projection):
    def s0(s):
        b = s.encode("latin-1") + b"\0"
        return b + (b"\0" if len(b) % 2 else b"")
    def chunk(id_, data):  # top-level chunk: u4 size
        return id_ + struct.pack(">I", len(data)) + data + (b"\0" if len(data) % 2 else b"")
    def sub(id_, data):  # subchunk: u2 size
        return id_ + struct.pack(">H", len(data)) + data + (b"\0" if len(data) % 2 else b"")
    vx = lambda i: struct.pack(">H", i)
    nu, nv = 24, 12
    pts = [(math.sin(math.pi * j / nv) * math.cos(2 * math.pi * i / nu), math.cos(math.pi * j / nv),
            math.sin(math.pi * j / nv) * math.sin(2 * math.pi * i / nu))
           for j in range(nv + 1) for i in range(nu)]
    polys = [(j * nu + i, (j + 1) * nu + i, (j + 1) * nu + (i + 1) % nu, j * nu + (i + 1) % nu)
             for j in range(nv) for i in range(nu)]
    imap = sub(b"IMAP", s0("\x80") + sub(b"CHAN", b"COLR") + sub(b"ENAB", vx(1)))
    tmap = sub(b"TMAP", sub(b"CNTR", struct.pack(">3f", 0, 0, 0) + vx(0)) +
               sub(b"SIZE", struct.pack(">3f", 1, 1, 1) + vx(0)) +
               sub(b"ROTA", struct.pack(">3f", 0, 0, 0) + vx(0)) + sub(b"CSYS", vx(0)))
    blok = sub(b"BLOK", imap + tmap + sub(b"PROJ", vx(projection)) + sub(b"AXIS", vx(1)) +
               sub(b"IMAG", vx(1)) + sub(b"WRAP", struct.pack(">HH", 1, 1)))
    body = (b"LWO2" + chunk(b"TAGS", s0("Surf")) +
            chunk(b"LAYR", struct.pack(">HH3f", 0, 0, 0, 0, 0) + s0("layer")) +
            chunk(b"PNTS", b"".join(struct.pack(">3f", *p) for p in pts)) +
            chunk(b"POLS", b"FACE" + b"".join(struct.pack(">H", 4) + b"".join(vx(i) for i in p)
                                              for p in polys)) +
            chunk(b"PTAG", b"SURF" + b"".join(vx(k) + vx(0) for k in range(len(polys)))) +
            chunk(b"CLIP", struct.pack(">I", 1) + sub(b"STIL", s0("textures/stripes.png"))) +
            chunk(b"SURF", s0("Surf") + s0("") + sub(b"COLR", struct.pack(">3f", 1, 1, 1) + vx(0)) +
                  sub(b"DIFF", struct.pack(">f", 1.0) + vx(0)) + blok))
    write(name, b"FORM" + struct.pack(">I", len(body)) + body)

# LWO2 projection codes: 0 planar, 1 cylindrical, 2 spherical, 3 cubic.
for proj, kind in enumerate(["planar", "cylindrical", "spherical", "box"]):
    lwo_sphere(f"mapping_{kind}.lwo", proj)

# What some importers leave behind and assimp's validation refuses: a face
# with a vertex index out of range (next to a good one), and an STL with an
# empty solid after a real one.
write("bad_index.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
      "-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n4 0 1 2 3\n3 0 2 7\n")
write("empty_solid.stl", "solid quad\n" + "".join(
    "  facet normal 0 0 1\n    outer loop\n" + "".join(f"      vertex {x} {y} 0\n" for x, y in tri) +
    "    endloop\n  endfacet\n" for tri in [((-1, -1), (1, -1), (1, 1)), ((-1, -1), (1, 1), (-1, 1))]) +
      "endsolid quad\nsolid empty\nendsolid empty\n")

# A PLY whose header declares two billion vertices (the memory guard's case).
write("huge_header.ply", "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
