#!/usr/bin/env python3
"""Where scenes/hot_road_mirage.json's mirage appears, from its closed form.

In air layered in height, n(y)·cos θ(y) is constant along a ray (θ to the
horizontal). A ray entering the hot layer at depression α from air of index
n_top turns where n(y) = n_top·cos α, which lies above the road while
α < α_c = arccos(n(0)/n_top), and leaves at elevation α. Its horizontal run
between heights y1 and y2 is ∫ dy / tan θ(y). n(y) is Gladstone–Dale's,
n − 1 = 2.93e-4 · 273.15 K / T(y), T(y) = T_air + ΔT·exp(−y/H).

Prints the image rows of the horizon, of the mirage's lower edge (α_c), and
of each receiver square's top and bottom seen directly and by turned rays.
Usage: tools/mirage_closed_form.py [scene.json]
"""
import json
import math
import sys

scene = json.load(open(sys.argv[1] if len(sys.argv) > 1 else "scenes/hot_road_mirage.json"))
profile = scene["medium"]["air_temperature_profile"]
t_air, t_ground, scale = profile["air_temperature"], profile["ground_temperature"], profile["scale_height"]
top = scene["grid"]["bounds"]["max"][1]  # rays outside the grid fly straight
eye, target = scene["camera"]["position"], scene["camera"]["target"]
rows = scene["render"]["height"]
focal = (rows / 2) / math.tan(math.radians(scene["camera"]["fov_deg"] / 2))
pitch = math.atan2(eye[1] - target[1], math.hypot(target[0] - eye[0], target[2] - eye[2]))


def index(y):
    return 1.0 + 2.93e-4 * 273.15 / (t_air + (t_ground - t_air) * math.exp(-y / scale))


n_top = index(top)
critical = math.acos(index(0.0) / n_top)


def turning_height(alpha):
    invariant = n_top * math.cos(alpha)
    low, high = 0.0, top
    for _ in range(80):
        middle = 0.5 * (low + high)
        low, high = (middle, high) if index(middle) < invariant else (low, middle)
    return 0.5 * (low + high)


def run(alpha, y_turn, y):
    """Horizontal distance from the turning point up to height y (y = y_turn + u²)."""
    invariant, steps, b, total = n_top * math.cos(alpha), 2000, math.sqrt(y - y_turn), 0.0
    for i in range(steps):
        u = b * (i + 0.5) / steps
        cos_t = invariant / index(y_turn + u * u)
        total += 2 * u * cos_t / math.sqrt(max(1 - cos_t * cos_t, 1e-30)) * b / steps
    return total


def distance(alpha, z):
    """Camera to where the turned ray of depression alpha is at height z again."""
    y_turn = turning_height(alpha)
    if z <= y_turn:
        return math.inf
    d = (eye[1] - top) / math.tan(alpha) + run(alpha, y_turn, top)
    return d + (run(alpha, y_turn, top) + (z - top) / math.tan(alpha) if z >= top else run(alpha, y_turn, z))


def turned(length, z, samples=120):
    alphas = [critical * (i + 0.5) / samples for i in range(samples)]
    values = [distance(a, z) - length for a in alphas]
    found = []
    for i in range(samples - 1):
        if math.isfinite(values[i]) and math.isfinite(values[i + 1]) and (values[i] > 0) != (values[i + 1] > 0):
            low, high = alphas[i], alphas[i + 1]
            for _ in range(40):
                middle = 0.5 * (low + high)
                low, high = (middle, high) if (distance(middle, z) > length) == (values[i] > 0) else (low, middle)
            found.append(0.5 * (low + high))
    return found


def row(depression):
    return rows / 2 + focal * math.tan(depression - pitch)


print(f"critical angle {critical * 1e3:.3f} mrad (sqrt(2 dn) {math.sqrt(2 * (n_top - index(0))) * 1e3:.3f})")
print(f"horizon at row {row(0.0):.1f}, mirage's lower edge at row {row(critical):.1f}")
for receiver in scene.get("receivers", []):
    x, y, z = receiver["point"]
    length = math.hypot(x - eye[0], z - eye[2])
    for height in (y - receiver["size"] / 2, y + receiver["size"] / 2):
        height = max(height, 0.0)
        direct = row(math.atan((eye[1] - height) / length))
        images = ", ".join(f"{row(a):.1f}" for a in turned(length, height)) or "none"
        print(f"{length:6.0f} m, {height:4.2f} m high: direct row {direct:.1f}, turned rays at rows {images}")
