"""Writes a small transient OpenFOAM case like the one of issue 15: a buoyant
plume rising in a 10 m room, y up, with gravity in constant/g.

    make_room_plume_case.py OUT_FOLDER

The mesh is a blockMesh-style lattice of 20 x 10 x 20 hexahedra (0.5 m cells,
10 x 5 x 10 m) written as ASCII polyMesh (points, faces, owner, neighbour,
boundary): internal faces in OpenFOAM's upper-triangular order, normals from
owner to neighbour, boundary faces pointing out. Patches: 'floor' (y = 0,
T fixed at 600 K: the hot patch whose point interpolation gave the issue's
bright slab), 'ceiling' and 'walls'.

Times 0, 30, 60, 90. Time 0 is the initial condition: T uniform 300 K inside,
U zero. Later times hold a plume above the floor's centre: a Gaussian column
whose top rises with time, T excess up to 1.5 K, vertical speed up to
0.29 m/s (the issue's numbers). The cell values are computed here in closed
form, so the tests know the ranges independently of Plume:
  - T cell excess at t = 90: max 1.5 K (the source cell), 300 elsewhere far away;
  - |U| cell max 0.29 m/s.
"""
import math
import os
import sys

NX, NY, NZ = 20, 10, 20
LX, LY, LZ = 10.0, 5.0, 10.0
TIMES = [0, 30, 60, 90]
T_AMBIENT, T_FLOOR, T_EXCESS, U_MAX = 300.0, 600.0, 1.5, 0.29

HEADER = """FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    location    "{loc}";
    object      {obj};
}}
"""


def write(path, cls, loc, obj, body):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(HEADER.format(cls=cls, loc=loc, obj=obj))
        f.write(body)


def pid(i, j, k):
    return i + (NX + 1) * (j + (NY + 1) * k)


def cid(i, j, k):
    return i + NX * (j + NY * k)


def mesh(out):
    dx, dy, dz = LX / NX, LY / NY, LZ / NZ
    points = [(i * dx, j * dy, k * dz) for k in range(NZ + 1) for j in range(NY + 1) for i in range(NX + 1)]
    faces, owner, neighbour = [], [], []
    # faces whose normal is +x, +y, +z at lattice position (i, j, k) of that plane
    fx = lambda i, j, k: (pid(i, j, k), pid(i, j + 1, k), pid(i, j + 1, k + 1), pid(i, j, k + 1))
    fy = lambda i, j, k: (pid(i, j, k), pid(i, j, k + 1), pid(i + 1, j, k + 1), pid(i + 1, j, k))
    fz = lambda i, j, k: (pid(i, j, k), pid(i + 1, j, k), pid(i + 1, j + 1, k), pid(i, j + 1, k))
    # internal faces: by owner, then neighbour (c + 1, c + NX, c + NX NY ascending)
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                c = cid(i, j, k)
                if i + 1 < NX:
                    faces.append(fx(i + 1, j, k)); owner.append(c); neighbour.append(cid(i + 1, j, k))
                if j + 1 < NY:
                    faces.append(fy(i, j + 1, k)); owner.append(c); neighbour.append(cid(i, j + 1, k))
                if k + 1 < NZ:
                    faces.append(fz(i, j, k + 1)); owner.append(c); neighbour.append(cid(i, j, k + 1))
    n_internal = len(faces)
    patches = []

    def patch(name, items):
        patches.append((name, len(faces), len(items)))
        for f, c in items:
            faces.append(f)
            owner.append(c)

    rev = lambda f: tuple(reversed(f))
    patch("floor", [(rev(fy(i, 0, k)), cid(i, 0, k)) for k in range(NZ) for i in range(NX)])
    patch("ceiling", [(fy(i, NY, k), cid(i, NY - 1, k)) for k in range(NZ) for i in range(NX)])
    walls = [(rev(fx(0, j, k)), cid(0, j, k)) for k in range(NZ) for j in range(NY)]
    walls += [(fx(NX, j, k), cid(NX - 1, j, k)) for k in range(NZ) for j in range(NY)]
    walls += [(rev(fz(i, j, 0)), cid(i, j, 0)) for j in range(NY) for i in range(NX)]
    walls += [(fz(i, j, NZ), cid(i, j, NZ - 1)) for j in range(NY) for i in range(NX)]
    patch("walls", walls)

    pm = os.path.join(out, "constant", "polyMesh")
    write(os.path.join(pm, "points"), "vectorField", "constant/polyMesh", "points",
          "%d\n(\n%s\n)\n" % (len(points), "\n".join("(%g %g %g)" % p for p in points)))
    write(os.path.join(pm, "faces"), "faceList", "constant/polyMesh", "faces",
          "%d\n(\n%s\n)\n" % (len(faces), "\n".join("4(%d %d %d %d)" % f for f in faces)))
    note = "nPoints: %d nCells: %d nFaces: %d nInternalFaces: %d" % (len(points), NX * NY * NZ, len(faces), n_internal)
    for name, data in (("owner", owner), ("neighbour", neighbour)):
        write(os.path.join(pm, name), "labelList", "constant/polyMesh", name,
              "// %s\n%d\n(\n%s\n)\n" % (note, len(data), "\n".join(map(str, data))))
    body = "%d\n(\n" % len(patches)
    for name, start, count in patches:
        body += "    %s\n    {\n        type wall;\n        nFaces %d;\n        startFace %d;\n    }\n" % (name, count, start)
    write(os.path.join(pm, "boundary"), "polyBoundaryMesh", "constant/polyMesh", "boundary", body + ")\n")


def fields(t):
    """Cell T and U at time t (closed form; t = 0 is the uniform initial condition)."""
    dx, dy, dz = LX / NX, LY / NY, LZ / NZ
    T, U = [], []
    top = LY * t / TIMES[-1]  # the plume's head rises to the ceiling by the last time
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                x, y, z = (i + 0.5) * dx, (j + 0.5) * dy, (k + 0.5) * dz
                if t == 0:
                    T.append(T_AMBIENT)
                    U.append((0.0, 0.0, 0.0))
                    continue
                r2 = (x - LX / 2) ** 2 + (z - LZ / 2) ** 2
                sigma = 0.6 + 0.15 * y  # the column widens as it rises
                column = math.exp(-r2 / (2 * sigma * sigma))
                head = 1.0 / (1.0 + math.exp((y - top) / 0.3))  # 1 below the rising head, 0 above
                T.append(column * head * math.exp(-(y - dy / 2) / 6.0))
                speed = U_MAX * column * head
                # entrainment towards the axis, weaker than the rise
                rr = math.sqrt(r2) or 1.0
                inflow = 0.1 * speed
                U.append((-inflow * (x - LX / 2) / rr, speed, -inflow * (z - LZ / 2) / rr))
    if t > 0:
        # scaled so the largest excess is T_EXCESS and the largest speed U_MAX exactly
        peak = max(T)
        T = [T_AMBIENT + T_EXCESS * v / peak for v in T]
        fastest = max(math.sqrt(sum(c * c for c in u)) for u in U)
        U = [tuple(U_MAX * c / fastest for c in u) for u in U]
    return T, U


def write_time(out, t):
    T, U = fields(t)
    folder = os.path.join(out, str(t))
    uniform = t == 0
    tbody = "dimensions [0 0 0 1 0 0 0];\n\n"
    tbody += ("internalField uniform %g;\n" % T_AMBIENT) if uniform else \
        "internalField nonuniform List<scalar>\n%d\n(\n%s\n)\n;\n" % (len(T), "\n".join("%.9g" % v for v in T))
    tbody += ("\nboundaryField\n{\n    floor { type fixedValue; value uniform %g; }\n"
              "    ceiling { type zeroGradient; }\n    walls { type zeroGradient; }\n}\n" % T_FLOOR)
    write(os.path.join(folder, "T"), "volScalarField", str(t), "T", tbody)
    ubody = "dimensions [0 1 -1 0 0 0 0];\n\n"
    ubody += "internalField uniform (0 0 0);\n" if uniform else \
        "internalField nonuniform List<vector>\n%d\n(\n%s\n)\n;\n" % (
            len(U), "\n".join("(%.9g %.9g %.9g)" % u for u in U))
    ubody += ("\nboundaryField\n{\n    floor { type fixedValue; value uniform (0 0 0); }\n"
              "    ceiling { type fixedValue; value uniform (0 0 0); }\n"
              "    walls { type fixedValue; value uniform (0 0 0); }\n}\n")
    write(os.path.join(folder, "U"), "volVectorField", str(t), "U", ubody)


def main():
    out = sys.argv[1]
    mesh(out)
    for t in TIMES:
        write_time(out, t)
    write(os.path.join(out, "constant", "g"), "uniformDimensionedVectorField", "constant", "g",
          "dimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81 0);\n")
    write(os.path.join(out, "system", "controlDict"), "dictionary", "system", "controlDict",
          "application buoyantPimpleFoam;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\n"
          "endTime %d;\ndeltaT 1;\nwriteControl timeStep;\nwriteInterval 30;\n" % TIMES[-1])
    open(os.path.join(out, "room.foam"), "w").close()
    T, U = fields(TIMES[-1])
    print("wrote %s: %d cells, times %s; at t = %d: T cells [%.6g, %.6g], |U| cells max %.6g" % (
        out, NX * NY * NZ, TIMES, TIMES[-1], min(T), max(T), max(math.sqrt(sum(c * c for c in u)) for u in U)))


if __name__ == "__main__":
    main()
