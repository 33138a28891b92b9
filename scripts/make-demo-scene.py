#!/usr/bin/env python3
"""Writes the demo's own scene: assets/demo/crate.babylon (a cube with
texture coordinates, a camera and a light, in the newer exporter's layout)
and its texture assets/demo/crate.png (64x64, a framed plank pattern).

The bake tool turns them into src/scenes/baked.rs (see .ci/bake.sh, which
checks that the committed file is current). Run from the repository root:
    python3 scripts/make-demo-scene.py
"""
import json
import struct
import zlib

SIZE = 64


def texel(x, y):
    """A wooden crate face: a dark frame, diagonal brace, planks."""
    edge = min(x, y, SIZE - 1 - x, SIZE - 1 - y)
    if edge < 6:
        return (120, 72, 30) if edge in (0, 5) else (168, 110, 52)
    if abs(x - y) < 4:
        return (150, 96, 44)
    plank = (y // 13) % 2
    grain = ((x * 7 + y * 3) % 11) * 3
    return (200 - grain - 18 * plank, 150 - grain - 14 * plank, 80 - grain // 2)


def write_png(path):
    rows = b"".join(b"\x00" + bytes(c for x in range(SIZE) for c in texel(x, y)) for y in range(SIZE))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", SIZE, SIZE, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)


def cube(half):
    """24 vertices (4 per face, own normal and UVs) and 36 indices, wound
    the way Babylon's exporter winds them (the loader rewinds on load)."""
    faces = [  # normal, u axis, v axis (u x v = normal)
        ((0, 0, -1), (1, 0, 0), (0, -1, 0)),
        ((0, 0, 1), (-1, 0, 0), (0, -1, 0)),
        ((1, 0, 0), (0, 0, 1), (0, -1, 0)),
        ((-1, 0, 0), (0, 0, -1), (0, -1, 0)),
        ((0, 1, 0), (1, 0, 0), (0, 0, -1)),
        ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
    ]
    positions, normals, uvs, indices = [], [], [], []
    for n, u, v in faces:
        base = len(positions) // 3
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            p = [half * (n[k] + su * u[k] + sv * v[k]) for k in range(3)]
            positions += p
            normals += list(n)
            uvs += [(su + 1) / 2, (sv + 1) / 2]
        indices += [base, base + 2, base + 1, base, base + 3, base + 2]
    return positions, normals, uvs, indices


def main():
    write_png("assets/demo/crate.png")
    positions, normals, uvs, indices = cube(0.7)
    scene = {
        "ambientColor": [0.25, 0.25, 0.25],
        "cameras": [{"name": "Camera", "id": "Camera", "position": [0, 2.2, -6], "target": [0, 0, 0],
                     "fov": 0.8, "minZ": 0.1, "maxZ": 100}],
        "activeCamera": "Camera",
        "lights": [{"name": "Sun", "id": "Sun", "type": 1, "direction": [0.3, -0.8, 0.5],
                    "intensity": 1, "diffuse": [1, 1, 1]}],
        "materials": [{"name": "Wood", "id": "Wood", "diffuse": [1, 1, 1], "specular": [0, 0, 0],
                       "specularPower": 64, "alpha": 1, "backFaceCulling": True,
                       "diffuseTexture": {"name": "crate.png", "hasAlpha": False}}],
        "meshes": [{"name": "Crate", "id": "Crate", "materialId": "Wood", "position": [0, 0, 0],
                    "rotation": [0, 0, 0], "scaling": [1, 1, 1], "isVisible": True,
                    "positions": positions, "normals": normals, "uvs": uvs, "indices": indices,
                    "subMeshes": [{"materialIndex": 0, "verticesStart": 0, "verticesCount": 24,
                                   "indexStart": 0, "indexCount": 36}]}],
    }
    with open("assets/demo/crate.babylon", "w") as f:
        json.dump(scene, f, separators=(",", ":"))
        f.write("\n")


if __name__ == "__main__":
    main()
