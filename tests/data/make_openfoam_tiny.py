#!/usr/bin/env python3
"""Writes tests/data/openfoam_tiny: a 3x2x2-cell OpenFOAM ASCII case (0.3 x 0.2 x 0.2 m)
with cell fields T (K) and p (Pa) in two time directories, 0 and 0.5, as
OpenFOAM's polyMesh format lays them out (internal faces in upper-triangular
order, face normals out of the owner). Run from the repository root."""
import os

NX, NY, NZ, H = 3, 2, 2, 0.1
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "openfoam_tiny")


def header(cls, obj, location=None):
    loc = f'    location    "{location}";\n' if location else ""
    return ("FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
            f"    class       {cls};\n{loc}    object      {obj};\n}}\n\n")


def point(i, j, k):
    return i + (NX + 1) * (j + (NY + 1) * k)


def cell(i, j, k):
    return i + NX * (j + NY * k)


def plus_face(axis, i, j, k):
    """The face on the +axis side of cell (i, j, k), its normal along +axis."""
    if axis == 0:
        return [point(i + 1, j, k), point(i + 1, j + 1, k), point(i + 1, j + 1, k + 1), point(i + 1, j, k + 1)]
    if axis == 1:
        return [point(i, j + 1, k), point(i, j + 1, k + 1), point(i + 1, j + 1, k + 1), point(i + 1, j + 1, k)]
    return [point(i, j, k + 1), point(i + 1, j, k + 1), point(i + 1, j + 1, k + 1), point(i, j + 1, k + 1)]


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def field(name, cls, dims, values, boundary_value):
    body = "\n".join(f"{v:.9g}" for v in values)
    return (header(cls, name, None) + f"dimensions      {dims};\n\n"
            f"internalField   nonuniform List<scalar>\n{len(values)}\n(\n{body}\n)\n;\n\n"
            "boundaryField\n{\n    walls\n    {\n        type            fixedValue;\n"
            f"        value           uniform {boundary_value};\n    }}\n}}\n")


def main():
    points = [(i * H, j * H, k * H) for k in range(NZ + 1) for j in range(NY + 1) for i in range(NX + 1)]
    internal, owner, neighbour = [], [], []
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                for axis, (di, dj, dk), n in ((0, (1, 0, 0), NX), (1, (0, 1, 0), NY), (2, (0, 0, 1), NZ)):
                    if (i, j, k)[axis] + 1 < n:
                        internal.append(plus_face(axis, i, j, k))
                        owner.append(cell(i, j, k))
                        neighbour.append(cell(i + di, j + dj, k + dk))
    boundary, bowner = [], []
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                c = cell(i, j, k)
                for axis, n in ((0, NX), (1, NY), (2, NZ)):
                    idx = (i, j, k)[axis]
                    if idx == 0:
                        low = [i, j, k]
                        low[axis] -= 1
                        boundary.append(list(reversed(plus_face(axis, *low))))
                        bowner.append(c)
                    if idx == n - 1:
                        boundary.append(plus_face(axis, i, j, k))
                        bowner.append(c)
    faces = internal + boundary
    mesh = os.path.join(ROOT, "constant", "polyMesh")
    write(os.path.join(mesh, "points"), header("vectorField", "points", "constant/polyMesh") +
          f"{len(points)}\n(\n" + "\n".join(f"({x:.9g} {y:.9g} {z:.9g})" for x, y, z in points) + "\n)\n")
    write(os.path.join(mesh, "faces"), header("faceList", "faces", "constant/polyMesh") +
          f"{len(faces)}\n(\n" + "\n".join("4(" + " ".join(map(str, f)) + ")" for f in faces) + "\n)\n")
    write(os.path.join(mesh, "owner"), header("labelList", "owner", "constant/polyMesh") +
          f"{len(owner) + len(bowner)}\n(\n" + "\n".join(map(str, owner + bowner)) + "\n)\n")
    write(os.path.join(mesh, "neighbour"), header("labelList", "neighbour", "constant/polyMesh") +
          f"{len(neighbour)}\n(\n" + "\n".join(map(str, neighbour)) + "\n)\n")
    write(os.path.join(mesh, "boundary"), header("polyBoundaryMesh", "boundary", "constant/polyMesh") +
          "1\n(\n    walls\n    {\n        type            wall;\n"
          f"        nFaces          {len(boundary)};\n        startFace       {len(internal)};\n    }}\n)\n")
    write(os.path.join(ROOT, "system", "controlDict"), header("dictionary", "controlDict", "system") +
          "application     buoyantFoam;\nstartFrom       startTime;\nstartTime       0;\nstopAt          endTime;\n"
          "endTime         0.5;\ndeltaT          0.5;\nwriteControl    timeStep;\nwriteInterval   1;\n")
    ncells = NX * NY * NZ
    for step, time in enumerate(("0", "0.5")):
        # A warm cell column over x, hotter in the later step; pressure falling with height (hydrostatic-like).
        temperature = [293.15 + (40.0 + 30.0 * step) * (1 + c % NX) / NX + 2.0 * (c // (NX * NY)) for c in range(ncells)]
        pressure = [101325.0 - 1.2 * 9.81 * H * (0.5 + (c // NX) % NY) + 50.0 * step for c in range(ncells)]
        write(os.path.join(ROOT, time, "T"), field("T", "volScalarField", "[0 0 0 1 0 0 0]", temperature, 293.15))
        write(os.path.join(ROOT, time, "p"), field("p", "volScalarField", "[1 -1 -2 0 0 0 0]", pressure, 101325))
    write(os.path.join(ROOT, "case.foam"), "")


if __name__ == "__main__":
    main()
