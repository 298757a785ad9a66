#!/usr/bin/env python3
"""Writes tests/hostile: a corpus of hostile inputs for `eikon run` and what
each must end in.

Every case is a scene file (tests/hostile/scenes), optional `--set`
overrides, and the files it names (tests/hostile/files: meshes in every
format, environment maps, OpenVDB volumes). tests/hostile/cases.jsonl gives
per case the exit code it must end in and, for a refusal (exit 2), text its
one-line message must contain: the file and the JSON path or line at fault;
"frames", where present, is the run's --frames (default 1).
test_hostile_corpus runs them all and checks, besides, that a refused case
writes nothing. The same files seed the fuzzers (./dev.sh fuzz), and what
the fuzzers find goes into tests/hostile/found, one case each.

The expectations are this script's, stated from the file formats and
docs/scene-format.md, never read back from eikon.

Usage: tools/make_hostile_corpus.py [--eikon build/release/eikon]
  --eikon: writes the valid OpenVDB volume the VDB cases start from,
  tests/hostile/files/vdb/smoke.vdb, by eikon's own export of the base
  scene (grids "delta_index" and "index"); without it the committed file
  is kept.
"""

import argparse
import copy
import json
import math
import pathlib
import re
import shutil
import struct
import subprocess
import tempfile
import zlib

ROOT = pathlib.Path(__file__).resolve().parent.parent
HOSTILE = ROOT / "tests" / "hostile"
SCENES = HOSTILE / "scenes"
FILES = HOSTILE / "files"

BASE = {
    "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
    "medium": {"index": 1.0, "extinction": 0.1},
    "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.2, "index": 1.5}],
    "lights": [{"type": "point", "position": [0, 1.5, 0], "power": [10, 10, 10]}],
    "receivers": [{"type": "plane", "point": [0, 0.05, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 32}],
    "camera": {"position": [0, 1, 2], "target": [0, 0.3, 0], "up": [0, 1, 0], "fov_deg": 45},
    "render": {"photons": 4096, "width": 32, "height": 24, "seed": 3},
    "tracer": {"max_steps": 4096},
}

cases = []


def scene_text(scene):
    return json.dumps(scene, indent=1)


def add_case(name, text, exit_code, message="", overrides=(), frames=1, env=None):
    """One case: its scene written as text (bytes or str) under `name`.json,
    run for `frames` frames (`eikon run --frames`); `env`: environment
    variables eikon runs with."""
    if not re.fullmatch(r"[A-Za-z0-9_]+", name):
        raise ValueError(name + ": a case's name is letters, digits and '_' (it names a test)")
    path = SCENES / (name + ".json")
    path.write_bytes(text if isinstance(text, bytes) else text.encode())
    if exit_code == 2 and not message:
        raise ValueError(name + ": a refusal needs the text its message must hold")
    case = {"name": name, "scene": "scenes/" + path.name, "set": list(overrides), "exit": exit_code,
            "message": message}
    if frames != 1:
        case["frames"] = frames
    if env:
        case["env"] = env
    cases.append(case)


def add_scene_case(name, scene, exit_code, message_path="", overrides=(), env=None):
    """A scene case whose refusal names this scene's file and `message_path`."""
    message = f"{name}.json: {message_path}" if exit_code == 2 and message_path else ""
    add_case(name, scene_text(scene), exit_code, message, overrides, env=env)


def leaves(node, path=""):
    """(JSON path as eikon words it, container, key) for every scalar of a document."""
    items = node.items() if isinstance(node, dict) else enumerate(node)
    for key, value in items:
        here = (f"{path}.{key}" if path else key) if isinstance(node, dict) else f"{path}[{key}]"
        if isinstance(value, (dict, list)):
            yield from leaves(value, here)
        else:
            yield here, node, key


def at_path(scene, words):
    node = scene
    for word in words:
        node = node[word]
    return node


# --- scene documents: syntax ------------------------------------------------


def syntax_cases():
    base = scene_text(BASE)
    for cut in range(1, len(base) - 1, max(1, len(base) // 40)):
        add_case(f"json_truncated_at_{cut:04d}", base[:cut], 2, f"json_truncated_at_{cut:04d}.json: line")
    raw = {
        "json_empty": b"",
        "json_only_whitespace": b"   \n\t\n",
        "json_nul_byte": base[:40].encode() + b"\0" + base[40:].encode(),
        "json_invalid_utf8": base.replace('"sphere"', '"sph\xffere"').encode("latin-1"),
        "json_trailing_comma": base.replace('"seed": 3', '"seed": 3,').encode(),
        "json_comment": ("// a comment\n" + base).encode(),
        "json_single_quotes": base.replace('"seed"', "'seed'").encode(),
        "json_bare_nan": base.replace('"radius": 0.2', '"radius": NaN').encode(),
        "json_bare_infinity": base.replace('"radius": 0.2', '"radius": Infinity').encode(),
        "json_number_1e999": base.replace('"radius": 0.2', '"radius": 1e999').encode(),
        "json_number_minus_1e999": base.replace('"radius": 0.2', '"radius": -1e999').encode(),
        "json_two_documents": (base + base).encode(),
        "json_unclosed_string": base.replace('"sphere"', '"sphere').encode(),
        "json_control_character_in_string": base.replace('"sphere"', '"sph\x01ere"').encode(),
        "json_deep_arrays": b"[" * 200000 + b"]" * 200000,
        "json_deep_objects": b'{"a":' * 100000 + b"1" + b"}" * 100000,
        "json_unterminated_deep": b"[" * 200000,
    }
    for name, text in raw.items():
        add_case(name, text, 2, name + ".json")
    # Valid JSON that is not a scene object.
    for name, text in {"root_array": "[]", "root_null": "null", "root_number": "3", "root_string": '"scene"',
                       "root_empty_object": "{}"}.items():
        add_case(name, text, 2, name + ".json")
    add_case("json_utf8_bom", "\ufeff" + base, 0)
    add_case("json_escaped_keys", base.replace('"radius"', '"r\\u0061dius"'), 0)


# --- scene documents: values ------------------------------------------------

WRONG_FOR_NUMBER = {"string": "hostile", "null": None, "object": {}, "array": [], "bool": True}
WRONG_FOR_STRING = {"number": 7, "null": None, "unknown": "hostile", "array": ["sphere"]}


def value_cases():
    for path, container, key in list(leaves(BASE)):
        value = container[key]
        wrongs = WRONG_FOR_STRING if isinstance(value, str) else WRONG_FOR_NUMBER
        for label, wrong in wrongs.items():
            scene = copy.deepcopy(BASE)
            words = []
            for part in path.replace("[", ".").replace("]", "").split("."):
                words.append(int(part) if part.isdigit() else part)
            at_path(scene, words[:-1])[words[-1]] = wrong
            name = "value_" + path.replace(".", "_").replace("[", "_").replace("]", "") + "_" + label
            # A wrong "type" makes the object's other keys moot: the message
            # is at the type.
            add_scene_case(name, scene, 2, path)


RANGE = [  # (JSON path, value): outside the documented range
    ("grid.resolution[0]", 0), ("grid.resolution[1]", -4), ("grid.resolution[2]", 1e6), ("grid.resolution[0]", 2.5),
    ("grid.resolution[0]", 1e300), ("grid.bounds.min[0]", 1e308), ("grid.bounds.max[1]", -1e308),
    ("grid.bounds.max[0]", -0.5), ("medium.index", 0), ("medium.index", -1), ("medium.index", 1e300),
    ("medium.index", 1e-300), ("medium.extinction", -1), ("medium.extinction", 1e300),
    ("objects[0].radius", 0), ("objects[0].radius", -0.2), ("objects[0].radius", 1e308),
    ("objects[0].index", 1e-300), ("objects[0].index", 0), ("objects[0].center[0]", 1e308),
    ("lights[0].power[0]", -1), ("lights[0].power[0]", 1e308), ("lights[0].position[1]", 1e308),
    ("receivers[0].size", 0), ("receivers[0].size", -1), ("receivers[0].resolution", 0),
    ("receivers[0].resolution", 1e9), ("receivers[0].normal[1]", 0), ("camera.fov_deg", 0), ("camera.fov_deg", 180),
    ("camera.fov_deg", -45), ("render.photons", 0), ("render.photons", -1), ("render.photons", 1e30),
    ("render.width", 0), ("render.width", 1e9), ("render.height", -24), ("render.seed", -1), ("render.seed", 1.5),
    ("tracer.max_steps", 3e9), ("tracer.max_steps", -5), ("tracer.max_steps", 1e30), ("tracer.max_steps", 2.5),
    ("medium.scattering", 0.5), ("objects[0].scattering", [0, 0, 1e31]),
]


def range_cases():
    for number, (path, value) in enumerate(RANGE):
        scene = copy.deepcopy(BASE)
        words = [int(p) if p.isdigit() else p for p in path.replace("[", ".").replace("]", "").split(".")]
        at_path(scene, words[:-1])[words[-1]] = value
        parent = re.sub(r"\[\d+\]$", "", path)  # a vector's component: the message is at the vector
        add_scene_case(f"range_{number:02d}_" + parent.replace(".", "_").replace("[", "_").replace("]", ""), scene, 2,
                       parent)
    # The camera looking along its up vector has no image plane.
    scene = copy.deepcopy(BASE)
    scene["camera"]["target"] = [0, 3, 0]
    scene["camera"]["position"] = [0, 1, 0]
    add_scene_case("range_camera_up_along_view", scene, 2, "camera")


def key_cases():
    for where in ["", "grid", "medium", "objects[0]", "lights[0]", "receivers[0]", "camera", "render", "tracer"]:
        scene = copy.deepcopy(BASE)
        node = scene if not where else at_path(scene, [int(w) if w.isdigit() else w for w in
                                                        where.replace("[", ".").replace("]", "").split(".")])
        node["hostile_key"] = 1
        name = "unknown_key_" + (where.replace("[", "_").replace("]", "").replace(".", "_") or "root")
        add_scene_case(name, scene, 2, (where + "." if where else "") + "hostile_key")
    # Duplicate keys, which JSON parsers resolve silently: refused at the path.
    base = scene_text(BASE)
    for key in ['"radius": 0.2', '"photons": 4096', '"index": 1.0', '"fov_deg": 45', '"size": 1.0']:
        add_case("duplicate_" + key.split('"')[1], base.replace(key, key + ", " + key, 1), 2, "duplicate")
    scene = copy.deepcopy(BASE)
    scene["objects"][0]["h" * 100000] = 1
    add_scene_case("unknown_key_100k_long", scene, 2, "objects[0]")
    scene = copy.deepcopy(BASE)
    scene["objects"][0]["type"] = "s" * 100000
    add_scene_case("type_100k_long", scene, 2, "objects[0].type")
    for label, objects in {"empty": [], "null_entry": [None], "number_entry": [3]}.items():
        scene = copy.deepcopy(BASE)
        scene["objects"] = objects
        add_scene_case("objects_" + label, scene, 0 if label == "empty" else 2,
                       "" if label == "empty" else "objects[0]")
    scene = copy.deepcopy(BASE)
    scene["objects"] = [copy.deepcopy(BASE["objects"][0]) for _ in range(40)]
    add_scene_case("objects_40_sharp", scene, 2, "objects")


# --- --set overrides ---------------------------------------------------------


def override_cases():
    add_scene_case("set_base", BASE, 0)
    bad = {
        "no_equals": ("render.photons", "--set render.photons"),
        "empty_key": ("=3", "--set =3"),
        "double_dot": ("render..photons=3", "--set render..photons=3"),
        "index_past_end": ("objects.99.radius=0.1", "--set objects.99.radius=0.1"),
        "into_number": ("render.photons.x=3", "--set render.photons.x=3"),
        "negative_index": ("objects.-1.radius=0.1", "--set objects.-1.radius=0.1"),
        "huge_index": ("objects.99999999999999999999.radius=0.1", "--set objects.99999999999999999999"),
        "bad_value_type": ("render.photons=\"many\"", "render.photons"),
        "unquoted_string": ("render.photons=many", "render.photons"),
        "value_1e999": ("objects.0.radius=1e999", "objects[0].radius"),
        "value_nan": ("objects.0.radius=NaN", "objects[0].radius"),
        "new_unknown_key": ("render.hostile=1", "render.hostile"),
        "replace_root_section": ("grid=3", "grid"),
        "type_changed": ("objects.0.type=\"cube\"", "objects[0].type"),
        "object_into_array": ("objects={}", "objects"),
        "long_value": ("camera.fov_deg=" + "9" * 20000, "camera.fov_deg"),
        "long_key": ("render." + "k" * 20000 + "=1", "render."),
        "escape_in_value": ("objects.0.type=\"\\u0000\"", "objects[0].type"),
        "deep_new_path": (".".join(["a"] * 200) + "=1", "a"),
    }
    for label, (assignment, message) in bad.items():
        add_case("set_" + label, scene_text(BASE), 2, message, [assignment])
    good = {"photons": "render.photons=2048", "radius": "objects.0.radius=0.1", "string_value": "camera.fov_deg=50",
            "new_section": "tracer.step_policy=\"uniform\""}
    for label, assignment in good.items():
        add_case("set_valid_" + label, scene_text(BASE), 0, "", [assignment])


# --- meshes ------------------------------------------------------------------

CUBE_VERTICES = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
CUBE_QUADS = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
CUBE_TRIANGLES = [t for q in CUBE_QUADS for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def obj_text(vertices, faces):
    lines = [f"v {x} {y} {z}" for x, y, z in vertices] + ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return ("\n".join(lines) + "\n").encode()


def off_text(vertices, faces, counts=None):
    nv, nf = counts or (len(vertices), len(faces))
    lines = ["OFF", f"{nv} {nf} 0"] + [f"{x} {y} {z}" for x, y, z in vertices]
    lines += [f"{len(f)} " + " ".join(map(str, f)) for f in faces]
    return ("\n".join(lines) + "\n").encode()


def off_binary(vertices, faces, counts=None, order="<"):
    """Binary OFF in the byte order OpenMesh reads (the machine's: little-endian)."""
    nv, nf = counts or (len(vertices), len(faces))
    body = struct.pack(order + "iii", nv, nf, 0) + b"".join(struct.pack(order + "fff", *v) for v in vertices)
    body += b"".join(struct.pack(order + "i", len(f)) + struct.pack(f"{order}{len(f)}i", *f) for f in faces)
    return b"OFF BINARY\n" + body


def ply_header(form, nv, nf):
    return (f"ply\nformat {form} 1.0\nelement vertex {nv}\nproperty float x\nproperty float y\nproperty float z\n"
            f"element face {nf}\nproperty list uchar int vertex_indices\nend_header\n").encode()


def ply_ascii(vertices, faces, counts=None):
    nv, nf = counts or (len(vertices), len(faces))
    lines = [f"{x} {y} {z}" for x, y, z in vertices] + [f"{len(f)} " + " ".join(map(str, f)) for f in faces]
    return ply_header("ascii", nv, nf) + ("\n".join(lines) + "\n").encode()


def ply_binary(vertices, faces, counts=None, order="<"):
    nv, nf = counts or (len(vertices), len(faces))
    form = "binary_little_endian" if order == "<" else "binary_big_endian"
    body = b"".join(struct.pack(order + "fff", *v) for v in vertices)
    body += b"".join(struct.pack(order + "B", len(f)) + struct.pack(f"{order}{len(f)}i", *f) for f in faces)
    return ply_header(form, nv, nf) + body


def stl_ascii(vertices, triangles):
    out = ["solid cube"]
    for t in triangles:
        out += ["facet normal 0 0 0", " outer loop"] + [f"  vertex {' '.join(map(str, vertices[i]))}" for i in t]
        out += [" endloop", "endfacet"]
    return ("\n".join(out + ["endsolid cube"]) + "\n").encode()


def stl_binary(vertices, triangles, count=None):
    body = b"".join(struct.pack("<12fH", 0, 0, 0, *vertices[t[0]], *vertices[t[1]], *vertices[t[2]], 0)
                    for t in triangles)
    return b"eikon hostile corpus".ljust(80, b"\0") + struct.pack("<I", len(triangles) if count is None else count) + body


WRITERS = {  # name: (extension, writer(vertices, faces, counts))
    "obj": (".obj", lambda v, f, c=None: obj_text(v, f)),
    "off_ascii": (".off", off_text),
    "off_binary": (".off", off_binary),
    "ply_ascii": (".ply", ply_ascii),
    "ply_little": (".ply", lambda v, f, c=None: ply_binary(v, f, c, "<")),
    "ply_big": (".ply", lambda v, f, c=None: ply_binary(v, f, c, ">")),
    "stl_ascii": (".stl", lambda v, f, c=None: stl_ascii(v, [tuple(x) for x in f])),
    "stl_binary": (".stl", lambda v, f, c=None: stl_binary(v, [tuple(x) for x in f], c and c[1])),
}


def mesh_scene(file_name):
    scene = copy.deepcopy(BASE)
    scene["objects"] = [{"type": "mesh", "mesh": {"path": "../files/meshes/" + file_name, "scale": 0.3,
                                                  "translate": [-0.15, 0.35, -0.15]}, "index": 1.5}]
    return scene


def add_mesh_case(name, extension, data, exit_code):
    file_name = name + extension
    (FILES / "meshes" / file_name).write_bytes(data)
    add_case("mesh_" + name, scene_text(mesh_scene(file_name)), exit_code, file_name if exit_code == 2 else "")


def mesh_cases():
    (FILES / "meshes").mkdir(parents=True, exist_ok=True)
    nan = list(CUBE_VERTICES)
    nan[3] = (float("nan"), 1, 0)
    inf = list(CUBE_VERTICES)
    inf[5] = (1, float("inf"), 1)
    open_faces = CUBE_TRIANGLES[:-1]
    bad_index = [list(t) for t in CUBE_TRIANGLES]
    bad_index[4][1] = 8
    negative_index = [list(t) for t in CUBE_TRIANGLES]
    negative_index[2][0] = -9
    non_manifold = CUBE_TRIANGLES + [CUBE_TRIANGLES[0]]
    for label, (extension, write) in WRITERS.items():
        valid = write(CUBE_VERTICES, CUBE_TRIANGLES)
        add_mesh_case(label + "_cube", extension, valid, 0)
        for percent in (10, 35, 60, 85, 97):
            add_mesh_case(f"{label}_truncated_{percent}", extension, valid[:len(valid) * percent // 100], 2)
        add_mesh_case(label + "_nan_vertex", extension, write(nan, CUBE_TRIANGLES), 2)
        add_mesh_case(label + "_inf_vertex", extension, write(inf, CUBE_TRIANGLES), 2)
        add_mesh_case(label + "_open", extension, write(CUBE_VERTICES, open_faces), 2)
        add_mesh_case(label + "_non_manifold", extension, write(CUBE_VERTICES, non_manifold), 2)
        if not label.startswith("stl"):  # STL has no indices
            add_mesh_case(label + "_index_past_end", extension, write(CUBE_VERTICES, bad_index), 2)
            add_mesh_case(label + "_negative_index", extension, write(CUBE_VERTICES, negative_index), 2)
        if label not in ("obj", "stl_ascii"):  # formats whose header declares counts
            add_mesh_case(label + "_declares_2e9_faces", extension,
                          write(CUBE_VERTICES, CUBE_TRIANGLES, (8, 2000000000)), 2)
            if label != "stl_binary":
                add_mesh_case(label + "_declares_4e9_vertices", extension,
                              write(CUBE_VERTICES, CUBE_TRIANGLES, (4000000000 if "ascii" in label else 2000000000,
                                                                    12)), 2)
        add_mesh_case(label + "_garbage", extension, bytes((i * 97 + 13) % 256 for i in range(700)), 2)
    add_mesh_case("off_binary_big_endian", ".off", off_binary(CUBE_VERTICES, CUBE_TRIANGLES, order=">"), 2)
    add_mesh_case("ply_mangled_element", ".ply",  # fuzz_mesh_ply's crash: a property before any element
                  ply_ascii(CUBE_VERTICES, CUBE_TRIANGLES).replace(b"element vertex", b"el\x01\x00ement vertex"), 2)
    add_mesh_case("ply_no_end_header", ".ply", ply_header("ascii", 8, 12).replace(b"end_header\n", b""), 2)
    add_mesh_case("stl_ascii_no_endsolid", ".stl", stl_ascii(CUBE_VERTICES, CUBE_TRIANGLES).replace(b"endsolid cube\n", b""), 2)
    add_mesh_case("empty", ".obj", b"", 2)
    add_mesh_case("obj_index_overflow", ".obj", obj_text(CUBE_VERTICES, CUBE_TRIANGLES[:-1]) +
                  b"f 1 2 99999999999999999999\n", 2)
    add_mesh_case("obj_no_faces", ".obj", obj_text(CUBE_VERTICES, []), 2)
    add_mesh_case("wrong_extension", ".txt", obj_text(CUBE_VERTICES, CUBE_TRIANGLES), 2)
    add_mesh_case("obj_as_stl", ".stl", obj_text(CUBE_VERTICES, CUBE_TRIANGLES), 2)
    scene = mesh_scene("absent.obj")
    add_case("mesh_missing_file", scene_text(scene), 2, "absent.obj")
    scene = mesh_scene("")
    scene["objects"][0]["mesh"]["path"] = "../files/meshes"
    add_case("mesh_path_is_folder", scene_text(scene), 2, "files/meshes")
    for placement, value in {"translate_1e9": ("translate", [1e9, 0, 0]), "translate_1e300": ("translate", [1e300, 0, 0]),
                             "scale_1e_minus_300": ("scale", 1e-300), "scale_0": ("scale", 0),
                             "scale_1e300": ("scale", 1e300)}.items():
        scene = mesh_scene("obj_cube.obj")
        scene["objects"][0]["mesh"][value[0]] = value[1]
        # Within range (a mesh far outside the grid, or tiny): it covers nothing, and runs.
        far = placement in ("translate_1e9", "scale_1e_minus_300")
        add_case("mesh_" + placement, scene_text(scene), 0 if far else 2, "" if far else "objects[0].mesh." + value[0])


# --- environment maps --------------------------------------------------------


def rgbe(r, g, b):
    top = max(r, g, b)
    if top < 1e-32:
        return bytes(4)
    mantissa, exponent = math.frexp(top)
    scale = mantissa * 256.0 / top
    return bytes((int(r * scale), int(g * scale), int(b * scale), exponent + 128))


def hdr_pixels(width, height):
    return [[rgbe(0.2 + x / width, 0.5, 0.1 + y / height) for x in range(width)] for y in range(height)]


def hdr_header(width, height, magic=b"#?RADIANCE", layout=None):
    return magic + b"\nFORMAT=32-bit_rle_rgbe\n\n" + (layout or f"-Y {height} +X {width}".encode()) + b"\n"


def hdr_flat(width, height):
    return hdr_header(width, height) + b"".join(b"".join(row) for row in hdr_pixels(width, height))


def hdr_rle(width, height, zero_run=False, long_run=False):
    out = hdr_header(width, height)
    for row in hdr_pixels(width, height):
        out += bytes((2, 2, width >> 8, width & 255))
        for channel in range(4):
            values = bytes(pixel[channel] for pixel in row)
            if zero_run:
                out += bytes((0,))
            elif long_run:
                out += bytes((128 + 127, values[0]))
            for start in range(0, width, 128):
                chunk = values[start:start + 128]
                out += bytes((len(chunk),)) + chunk
    return out


def png(width, height, declared=None):
    rows = b"".join(b"\0" + b"".join(bytes((x * 7 % 256, y * 5 % 256, 128)) for x in range(width)) for y in range(height))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    w, h = declared or (width, height)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def environment_scene(file_name):
    scene = copy.deepcopy(BASE)
    scene["render"]["environment"] = {"type": "hdr", "path": "../files/images/" + file_name}
    return scene


def add_image_case(name, data, exit_code):
    (FILES / "images" / name).write_bytes(data)
    add_case("image_" + name.replace(".", "_"), scene_text(environment_scene(name)), exit_code,
             name if exit_code == 2 else "")


def image_cases():
    (FILES / "images").mkdir(parents=True, exist_ok=True)
    flat, rle = hdr_flat(6, 4), hdr_rle(40, 6)
    add_image_case("flat.hdr", flat, 0)
    add_image_case("rle.hdr", rle, 0)
    add_image_case("small.png", png(8, 4), 0)
    for label, data in {"flat": flat, "rle": rle}.items():
        header = len(hdr_header(6, 4) if label == "flat" else hdr_header(40, 6))
        for cut in sorted({header - 3, header, header + 1, header + 5, (header + len(data)) // 2, len(data) - 1}):
            add_image_case(f"{label}_cut_{cut}.hdr", data[:cut], 2)
    add_image_case("rle_zero_run.hdr", hdr_rle(40, 6, zero_run=True), 2)
    add_image_case("rle_run_past_width.hdr", hdr_rle(40, 6, long_run=True), 2)
    add_image_case("size_0x0.hdr", hdr_header(0, 0), 2)
    add_image_case("size_negative.hdr", hdr_header(0, 0, layout=b"-Y -4 +X 6") + flat[len(hdr_header(6, 4)):], 2)
    add_image_case("size_huge.hdr", hdr_header(0, 0, layout=b"-Y 1000000000 +X 1000000000") + rle[-400:], 2)
    add_image_case("layout_plus_y.hdr", hdr_header(0, 0, layout=b"+Y 4 +X 6") + flat[len(hdr_header(6, 4)):], 2)
    add_image_case("no_format_line.hdr", b"#?RADIANCE\n\n-Y 4 +X 6\n" + flat[len(hdr_header(6, 4)):], 2)
    add_image_case("bad_magic.hdr", b"#?RADIANZE" + flat[10:], 2)
    add_image_case("empty.hdr", b"", 2)
    add_image_case("png_truncated.png", png(8, 4)[:40], 2)
    add_image_case("png_declares_huge.png", png(8, 4, (1000000, 1000000)), 2)
    add_image_case("png_declares_wider_than_gl.png", png(8, 4, (70000, 2)), 2)
    add_image_case("garbage.hdr", bytes((i * 31 + 7) % 256 for i in range(500)), 2)
    scene = environment_scene("absent.hdr")
    add_case("image_missing_file", scene_text(scene), 2, "render.environment.path")


# --- OpenVDB volumes -----------------------------------------------------------


def volume_scene(file_name):
    scene = copy.deepcopy(BASE)
    scene["volume"] = {"path": "../files/vdb/" + file_name, "density_extinction": 4,
                       "grids": {"density": "delta_index", "temperature": ""}}
    return scene


def add_vdb_case(name, data, exit_code):
    """exit_code -1: either a run (0) or a refusal (2) naming the file."""
    (FILES / "vdb" / name).write_bytes(data)
    add_case("vdb_" + name.replace(".", "_"), scene_text(volume_scene(name)), exit_code, name if exit_code else "")


def export_vdb_seed(eikon, target):
    with tempfile.TemporaryDirectory() as folder:
        scene = pathlib.Path(folder) / "base.json"
        scene.write_text(scene_text(BASE))
        subprocess.run([eikon, "run", str(scene), "--out", folder + "/run", "--quiet", "--set",
                        "export.vdb.fields=[\"delta_index\",\"index\"]"], check=True)
        shutil.copyfile(folder + "/run/vdb/fields_00000.vdb", target)


def vdb_cases(eikon, kept):
    (FILES / "vdb").mkdir(parents=True, exist_ok=True)
    target = FILES / "vdb" / "smoke.vdb"
    if eikon:
        export_vdb_seed(eikon, target)
    else:
        target.write_bytes(kept)
    data = target.read_bytes()
    add_case("vdb_smoke", scene_text(volume_scene("smoke.vdb")), 0)
    for cut in sorted({0, 4, 8, 12, 40, 100, 200, len(data) // 3, len(data) // 2, len(data) * 3 // 4, len(data) - 1}):
        if cut < len(data):
            add_vdb_case(f"cut_{cut}.vdb", data[:cut], 2)
    # Flipped bytes in the header, the metadata and grid table, and the trees.
    for at in sorted({9, 16, 24, 33, 60, 90, 140, 180, 250, len(data) // 2, len(data) - 20}):
        if at < len(data):
            flipped = bytearray(data)
            flipped[at] ^= 0xFF
            # A flip in some bytes (a name's letters, a float value) still
            # leaves a valid file; only structural bytes are listed above,
            # chosen as refusals, and the rest are left out.
            add_vdb_case(f"flip_{at}.vdb", bytes(flipped), -1)
    add_vdb_case("not_vdb.vdb", b"this is not an OpenVDB file\n" * 10, 2)
    scene = volume_scene("smoke.vdb")
    scene["volume"]["grids"] = {"density": "absent_grid"}
    add_case("vdb_missing_grid", scene_text(scene), 2, "absent_grid")
    scene = volume_scene("smoke_####.vdb")
    add_case("vdb_missing_sequence", scene_text(scene), 2, "smoke_")


# --- what the fuzzers found ---------------------------------------------------

FOUND = HOSTILE / "found"  # committed as found (tests/fuzz), never rewritten here


# --- sizes past the memory limit, and past what the lattice computes ----------


def memory_cases():
    """Documented sizes whose memory passes a limit lowered by
    EIKON_MEMORY_LIMIT_MB (docs/scene-format.md, Memory): refused from the
    parsed scene, naming the size's key, before anything is allocated."""
    limit = {"EIKON_MEMORY_LIMIT_MB": "256"}
    clear = copy.deepcopy(BASE)
    clear["medium"] = {"index": 1.0}  # nothing image space would drop
    add_scene_case("memory_grid_512", BASE, 2, "grid.resolution", ["grid.resolution=[512,512,512]"], limit)
    add_scene_case("memory_receiver_4096", BASE, 2, "receivers[0].resolution", ["receivers.0.resolution=4096"], limit)
    add_scene_case("memory_image_16384", BASE, 2, "render.width × render.height",
                   ["render.width=16384", "render.height=16384"], limit)
    add_scene_case("memory_caustic_maps_4096", clear, 2, "render.caustic_map_texels",
                   ['render.method="image_space"', "render.caustic_map_texels=4096"], limit)
    add_scene_case("memory_wavefront_patches", BASE, 2, "tracer.wavefront.max_patches",
                   ['tracer.estimator="wavefront"', "tracer.wavefront.max_patches=16777216"], limit)
    (FILES / "images" / "sky_4096.hdr").write_bytes(hdr_flat_rle(4096, 4096))
    add_scene_case("memory_environment_4096", environment_scene("sky_4096.hdr"), 2, "render.environment.path",
                   env=limit)
    add_scene_case("memory_within_the_limit", BASE, 0, env=limit)
    # Voxels of albedo 1 forty optical depths thick: the lattice runs, says
    # it is not converged and warns.
    thick = copy.deepcopy(clear)
    thick["medium"] = {"index": 1.0, "extinction": 640, "scattering": 640}
    thick["tracer"]["multiple_scattering"] = "lbm"
    add_scene_case("lattice_albedo_one_beyond_its_depth_limit", thick, 0)


def hdr_flat_rle(width, height):
    """An image of radiance 1 run-length encoded: a few bytes a scanline."""
    out = hdr_header(width, height)
    runs = b"".join(bytes((128 + min(127, width - start), value))
                    for value in rgbe(1, 1, 1) for start in range(0, width, 127))
    return out + (bytes((2, 2, width >> 8, width & 255)) + runs) * height


def found_cases():
    """Each file the fuzzers found a crash, hang or leak with: refused, naming it."""
    for path in sorted(FOUND.iterdir()):
        relative = "../found/" + path.name
        if path.suffix in (".obj", ".ply", ".off", ".stl"):
            scene = mesh_scene(path.name)
            scene["objects"][0]["mesh"]["path"] = relative
        elif path.suffix in (".hdr", ".png"):
            scene = environment_scene(path.name)
            scene["render"]["environment"]["path"] = relative
        elif path.suffix == ".vdb":
            scene = volume_scene(path.name)
            scene["volume"]["path"] = relative
            scene["volume"]["grids"] = {"density": "index", "temperature": "delta_index"}  # both grids read
        else:
            raise ValueError(path.name + ": a found file of a kind no scene reads")
        add_case("found_" + path.stem, scene_text(scene), 2, path.name)


# --- values within their ranges that together cannot be -------------------------

def message_cases():
    """Keys each within its documented range whose combination, or whose
    mapping of a volume's values, makes a field impossible (n <= 0, a value
    past float32): refused naming the scene file, the keys a user edits and
    the position, never an internal cell; and GL limits met by a render
    stage, refused naming the scene file too."""
    def volume_case(name, keys, grids, message):
        scene = volume_scene("smoke.vdb")
        scene["volume"]["grids"] = grids
        scene["volume"].update(keys)
        add_case(name, scene_text(scene), 2, f"{name}.json: {message}")

    heat = {"density": "delta_index", "temperature": "index"}  # the index grid (about 1 to 1.5) read as heat
    volume_case("keys_volume_refractivity_turns_index_negative", {"temperature_scale": 1000, "refractivity": 10}, heat,
                "medium.index, volume.refractivity, volume.pressure, volume.reference_temperature (the refractive "
                "index at (")
    volume_case("keys_volume_pressure_overflows_index", {"pressure": 1e300}, heat, "medium.index, volume.refractivity, "
                "volume.pressure, volume.reference_temperature (the refractive index at (")
    volume_case("keys_volume_emission_scale_overflows", {"emission": "blackbody", "emission_scale": 1e300,
                                                         "temperature_scale": 3000}, heat,
                "volume.emission_scale, volume.temperature_scale, volume.ambient_temperature, "
                "volume.density_extinction, medium.extinction (the emission ε at (")
    volume_case("keys_volume_index_grid_reads_zero", {}, {"density": "", "temperature": "", "index": "delta_index"},
                'volume.grids.index (grid "delta_index" at (')
    volume_case("keys_volume_transform_scale_past_index_range", {"transform": {"scale": 1e-9}}, heat,
                "volume.path: ")
    scene = copy.deepcopy(BASE)
    scene["paint"] = [{"path": [[0, 0.5, 0]], "radius": 0.3, "index": -5}]
    add_scene_case("keys_paint_index_below_zero", scene, 2, "paint[0].index, medium.index (the refractive index at (")
    scene = copy.deepcopy(BASE)
    scene["medium"]["air_temperature_profile"] = {"ground_temperature": 400, "air_temperature": 300,
                                                  "scale_height": 0.1, "pressure": 1e300}
    add_scene_case("keys_air_profile_pressure_overflows_index", scene, 2,
                   "medium.air_temperature_profile, medium.index (the refractive index at (")
    scene = copy.deepcopy(BASE)
    scene["sim"] = {"fluid": "air", "resolution": [8, 8, 8], "optics": {"refractivity": 1e300},
                    "sources": [{"type": "hot_plate", "min": [-0.2, 0, -0.2], "max": [0.2, 0.2, 0.2],
                                 "temperature": 450}]}
    add_scene_case("keys_sim_refractivity_overflows_index", scene, 2, "sim.optics.refractivity")
    scene = copy.deepcopy(BASE)
    # 16 777 216 patches of 256 bytes: past the storage block a GL driver gives
    # (llvmpipe's 128 MiB), documented as the range's other bound.
    scene["tracer"] = {"estimator": "wavefront", "wavefront": {"max_patches": 16777216}}
    add_scene_case("keys_wavefront_max_patches_past_storage_block", scene, 2, "tracer.wavefront.max_patches")


# --- diagnostics: the shadowgraph and BOS ------------------------------------------

def diagnostic_cases():
    """The shadowgraph's and BOS's keys out of range, of the wrong type, or
    beside the wrong camera: each refused at its key path."""
    smooth = copy.deepcopy(BASE)
    smooth["objects"][0]["surface"] = "smooth"
    orthographic = copy.deepcopy(smooth)
    orthographic["camera"] = {"position": [0, 0.5, 2], "target": [0, 0.5, 0], "projection": "orthographic",
                              "width_m": 1.0}
    for name, camera, diagnostic, path in (
            ("diagnostic_shadowgraph_screen_distance_zero", orthographic,
             {"type": "shadowgraph", "screen_distance": 0}, "diagnostic.screen_distance"),
            ("diagnostic_shadowgraph_screen_distance_text", orthographic,
             {"type": "shadowgraph", "screen_distance": "1 m"}, "diagnostic.screen_distance"),
            ("diagnostic_shadowgraph_perspective", smooth, {"type": "shadowgraph"}, "camera"),
            ("diagnostic_bos_orthographic", orthographic, {"type": "bos"}, "camera.projection"),
            ("diagnostic_bos_dot_density_past_half", smooth, {"type": "bos", "dot_density": 0.75},
             "diagnostic.dot_density"),
            ("diagnostic_bos_seed_fraction", smooth, {"type": "bos", "seed": 2.5}, "diagnostic.seed"),
            ("diagnostic_bos_seed_past_32_bits", smooth, {"type": "bos", "seed": 4294967296}, "diagnostic.seed"),
            ("diagnostic_bos_pattern_unknown", smooth, {"type": "bos", "pattern": "checker"}, "diagnostic.pattern"),
            ("diagnostic_bos_background_distance_negative", smooth, {"type": "bos", "background_distance": -1},
             "diagnostic.background_distance")):
        scene = copy.deepcopy(camera)
        scene["diagnostic"] = diagnostic
        add_scene_case(name, scene, 2, path)


# --- a volume sequence whose later file is damaged ------------------------------

def sequence_cases():
    """Three-file sequences of the seed volume run for three frames, the last
    file cut short, overwritten with text, or overwritten inside its last
    grid's leaf buffers (its length kept): every file is checked before frame
    0 is written, so each is refused naming that file, with nothing written."""
    data = (FILES / "vdb" / "smoke.vdb").read_bytes()
    damaged = bytearray(data)
    damaged[-400:-8] = b"\x55" * 392
    for label, last in (("cut", data[:len(data) // 2]), ("text", b"x" * len(data)), ("tree", bytes(damaged))):
        for number, content in ((1, data), (2, data), (3, last)):
            (FILES / "vdb" / f"seq_{label}_{number:04d}.vdb").write_bytes(content)
        scene = volume_scene(f"seq_{label}_####.vdb")
        scene["volume"]["grids"]["temperature"] = "index"  # both grids read: the damaged tree is the last
        add_case(f"vdb_sequence_last_file_{label}", scene_text(scene), 2, f"../files/vdb/seq_{label}_0003.vdb: byte ",
                 frames=3)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--eikon", help="the eikon executable, to write the OpenVDB seed")
    arguments = parser.parse_args()
    kept = FILES / "vdb" / "smoke.vdb"
    if not arguments.eikon and not kept.exists():
        parser.error("no committed " + str(kept.relative_to(ROOT)) + ": give --eikon to write it")
    kept_vdb = kept.read_bytes() if kept.exists() else None
    for folder in (SCENES, FILES):
        if folder.exists():
            shutil.rmtree(folder)
    SCENES.mkdir(parents=True)
    syntax_cases()
    value_cases()
    range_cases()
    key_cases()
    override_cases()
    mesh_cases()
    image_cases()
    vdb_cases(arguments.eikon, kept_vdb)
    memory_cases()
    found_cases()
    message_cases()
    diagnostic_cases()
    sequence_cases()
    with open(HOSTILE / "cases.jsonl", "w") as out:
        for case in cases:
            out.write(json.dumps(case) + "\n")
    print(f"{len(cases)} cases in {HOSTILE.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
