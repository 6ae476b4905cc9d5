#!/usr/bin/python3
"""The bad-input corpus: hostile scenes, datasets and command lines, each run
through the real `plume` with its expected outcome.

Inputs are written into WORKDIR at test time: hand-written small files
(legacy and XML datasets whose cells name points that do not exist, arrays
shorter than their dataset, headers that lie about sizes, scenes nested
thousands of levels deep or whose datasets depend on each other in a cycle,
FIFOs, devices, directories) and files made from the shared data
($PLUME_DATA_DIR) by truncating them, flipping bits in their payload and
editing their headers.

Every case has one expected outcome:
  error    exit code 2 and exactly one stderr line, "plume: error: ..."
           matching the case's regex (the problem, the value, where from)
  warn     exit code 0 and a "plume: warning: ..." line matching the regex
  ok       exit code 0 (the correct result; stdout matches the regex)
  survive  (payload bit flips only) exit 0, or exit 2 with one error line:
           the values are garbage but the structure may be intact, so
           either outcome is correct; never a crash, a hang or a second line
Any case that crashes (signal, exit code > 100), hangs (killed after
--timeout seconds) or matches the wrong message fails.

usage: plume_bad_inputs.py PLUME WORKDIR [--only REGEX] [--bench-only] [--timeout S] [--jobs N] [--list]
--bench-only runs just the `plume bench` cases: the main build's share when
the sanitizer build (which has no plume-bench) runs the rest.
Prints one line per case and a summary with the counts; exits 1 on any failure.
"""
import argparse
import concurrent.futures
import json
import os
import re
import shutil
import signal
import stat
import subprocess
import sys
import time

from vtkmodules.vtkIOImage import vtkPNGReader  # Debian's /usr/bin/python3 (python3-vtk9): image checks

DATA = os.environ.get("PLUME_DATA_DIR", "/work/shared/data")


# --- helpers writing inputs --------------------------------------------------
class Corpus:
    def __init__(self, work):
        self.work = work
        self.cases = []

    def path(self, name):
        return os.path.join(self.work, name)

    def write(self, name, content, mode="w"):
        p = self.path(name)
        os.makedirs(os.path.dirname(p), exist_ok=True)
        with open(p, mode) as f:
            f.write(content)
        return p

    def scene(self, name, scene):
        text = scene if isinstance(scene, str) else json.dumps(scene)
        return self.write(name + ".json", text)

    def fifo(self, name):
        p = self.path(name)
        os.makedirs(os.path.dirname(p), exist_ok=True)
        if os.path.lexists(p):
            os.remove(p)
        os.mkfifo(p)
        return p

    def symlink(self, name, target):
        p = self.path(name)
        if os.path.lexists(p):
            os.remove(p)
        os.symlink(target, p)
        return p

    def derived(self, name, source, edit):
        """A copy of a shared data file with `edit(bytes) -> bytes` applied."""
        with open(os.path.join(DATA, source), "rb") as f:
            data = f.read()
        return self.write(name, edit(data), "wb")

    def add(self, name, kind, args, expect="", env=None, image=None, limit_mb=None):
        self.cases.append(dict(name=name, kind=kind, args=args, expect=expect, env=env or {}, image=image,
                               limit_mb=limit_mb))

    def render(self, name, kind, scene_path, expect, extra=(), env=None, image=None):
        """`image`: {channel: minimum} the output's brightest value of that channel must reach (0-255)."""
        size = "160x120" if image else "64x48"
        self.add(name, kind, ["render", scene_path, "-o", self.path(name + ".png"), "--size", size, *extra],
                 expect, env, image)


def legacy_poly(section, points="0 0 0 1 0 0 0 1 0 1 1 0", npts=4, tail=""):
    return ("# vtk DataFile Version 3.0\nbad\nASCII\nDATASET POLYDATA\nPOINTS %d float\n%s\n%s\n%s"
            % (npts, points, section, tail))


def legacy_ugrid(cells, types, tail=""):
    return ("# vtk DataFile Version 3.0\nbad\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
            "0 0 0 1 0 0 0 1 0 0 0 1\n%s\n%s\n%s" % (cells, types, tail))


def xml_poly(points, conn, offsets, piece='NumberOfPoints="4" NumberOfPolys="2"', pointdata=""):
    return ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
            '<PolyData><Piece %s>\n%s<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">'
            '%s</DataArray></Points>\n<Polys><DataArray type="Int64" Name="connectivity" format="ascii">%s'
            '</DataArray>\n<DataArray type="Int64" Name="offsets" format="ascii">%s</DataArray></Polys>\n'
            '</Piece></PolyData></VTKFile>\n' % (piece, pointdata, points, conn, offsets))


def xml_image(whole, piece, values):
    return ('<?xml version="1.0"?>\n<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">\n'
            '<ImageData WholeExtent="%s" Origin="0 0 0" Spacing="1 1 1"><Piece Extent="%s">\n'
            '<PointData Scalars="s"><DataArray type="Float32" Name="s" format="ascii">%s</DataArray></PointData>\n'
            '</Piece></ImageData></VTKFile>\n' % (whole, piece, values))


def truncate(fraction):
    return lambda data: data[: int(len(data) * fraction)]


def flip(seed, count, start_fraction):
    """Flips `count` bits at deterministic places after `start_fraction` of the file (the payload)."""
    def edit(data):
        data = bytearray(data)
        state = seed * 2654435761 % 2**32 or 1
        lo = int(len(data) * start_fraction)
        for _ in range(count):
            state = (state * 1103515245 + 12345) % 2**31
            i = lo + state % max(1, len(data) - lo)
            data[i] ^= 1 << (state >> 8) % 8
        return bytes(data)
    return edit


def replace(old, new, count=1):
    def edit(data):
        assert old in data, old
        return data.replace(old, new, count)
    return edit


def nested(depth, leaf="1"):
    return "[" * depth + leaf + "]" * depth


# --- the corpus ----------------------------------------------------------------
def build(c):
    ERR_READ = r"(could not read all of|produced no data|cannot read|gave inconsistent data|no reader|corrupt VTK XML file)"

    # ---- files that are not regular files, and names that are not names
    fifo_vtk = c.fifo("fifo.vtk")
    c.add("InfoFifo", "error", ["info", fifo_vtk], r"'.*fifo\.vtk' is a FIFO \(named pipe\), not a regular file")
    c.add("InfoDevice", "error", ["info", c.symlink("zero.vtk", "/dev/zero")], r"'.*zero\.vtk' is a device")
    c.add("InfoNullDevice", "error", ["info", c.symlink("null.vti", "/dev/null")], r"'.*null\.vti' is a device")
    os.makedirs(c.path("folder.vtk"), exist_ok=True)
    c.add("InfoDirectory", "error", ["info", c.path("folder.vtk")], r"'.*folder\.vtk' is a directory, not a file")
    c.add("InfoMissing", "error", ["info", c.path("nope.vtu")], r"file not found: .*nope\.vtu")
    c.render("SceneFifo", "error", c.fifo("scene_fifo.json"), r"scene file: '.*scene_fifo\.json' is a FIFO")
    c.render("SceneDevice", "error", c.symlink("scene_zero.json", "/dev/zero"), r"scene file: '.*scene_zero\.json' is a device")
    c.render("DatasetFifo", "error", c.scene("dataset_fifo", {
        "datasets": {"d": {"path": fifo_vtk}}, "representations": [{"type": "outline", "dataset": "d"}]}),
        r"datasets\.d: '.*fifo\.vtk' is a FIFO")
    c.render("LightTextureFifo", "error", c.scene("light_texture_fifo", {
        "datasets": {"d": {"path": "classic/carotid.vtk"}}, "representations": [{"type": "outline", "dataset": "d"}],
        "lights": [{"type": "scene", "position": [0, 0, 100], "focal_point": [0, 0, 0], "positional": True,
                    "cone_angle": 30, "texture": c.fifo("texture_fifo.png")}]}),
        r"lights\[0\]: texture: '.*texture_fifo\.png' is a FIFO")
    c.render("DatasetDirectory", "error", c.scene("dataset_dir", {
        "datasets": {"d": {"path": c.path("folder.vtk")}}, "representations": [{"type": "outline", "dataset": "d"}]}),
        r"datasets\.d: '.*folder\.vtk' is a directory")
    c.render("DatasetPathNul", "error", c.scene("dataset_nul", {
        "datasets": {"d": {"path": "classic/carotid.vtk\u0000.junk"}},
        "representations": [{"type": "outline", "dataset": "d"}]}),
        r"datasets\.d: 'path' holds a NUL character: 'classic/carotid\.vtk\\u0000\.junk'")
    c.add("InfoQFifo", "error", ["info", os.path.join(DATA, "plot3d/combxyz.bin"), "--q", c.fifo("q_fifo.bin")],
          r"PLOT3D solution \(Q\) file: '.*q_fifo\.bin' is a FIFO")
    c.write("pvd_fifo/list.pvd", '<?xml version="1.0"?><VTKFile type="Collection" version="0.1"><Collection>'
            '<DataSet timestep="0" file="%s"/></Collection></VTKFile>' % c.fifo("pvd_fifo/part.vtu"))
    c.add("PvdListsFifo", "error", ["info", c.path("pvd_fifo/list.pvd")],
          r"'.*part\.vtu' is a FIFO .*\(listed in .*list\.pvd\)")

    # ---- cells naming points that do not exist (VTK's readers accept them)
    poly_cases = [
        ("PolygonIdTooLarge", "POLYGONS 2 8\n3 0 1 2\n3 1 3 99\n", r"polygons: cell 1 references point id 99, but the dataset has 4 points"),
        ("PolygonIdNegative", "POLYGONS 1 4\n3 0 -5 2\n", r"polygons: cell 0 references point id -5"),
        ("PolygonIdHuge", "POLYGONS 1 4\n3 0 1 2147483647\n", r"polygons: cell 0 references point id 2147483647"),
        ("LineIdTooLarge", "LINES 1 3\n2 0 4\n", r"lines: cell 0 references point id 4, but the dataset has 4 points"),
        ("StripIdTooLarge", "TRIANGLE_STRIPS 1 5\n4 0 1 2 7\n", r"triangle strips: cell 0 references point id 7"),
        ("VertexIdTooLarge", "VERTICES 2 4\n1 0\n1 12\n", r"vertices: cell 1 references point id 12"),
    ]
    for name, section, expect in poly_cases:
        p = c.write("conn/%s.vtk" % name, legacy_poly(section))
        c.add("Info" + name, "error", ["info", p], r"the legacy reader gave inconsistent data from .*%s\.vtk \(corrupt file\?\): %s" % (name, expect))
    ug = c.write("conn/ugrid_bad.vtk", legacy_ugrid("CELLS 1 5\n4 0 1 2 40\n", "CELL_TYPES 1\n10\n"))
    c.add("InfoUGridIdTooLarge", "error", ["info", ug], r"cells: cell 0 references point id 40, but the dataset has 4 points")
    ugn = c.write("conn/ugrid_negative.vtk", legacy_ugrid("CELLS 1 5\n4 0 -1 2 3\n", "CELL_TYPES 1\n10\n"))
    c.add("InfoUGridIdNegative", "error", ["info", ugn], r"cells: cell 0 references point id -1")
    vtp = c.write("conn/poly_bad.vtp", xml_poly("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 1 3 77", "3 6"))
    c.add("InfoXmlPolygonIdTooLarge", "error", ["info", vtp], r"the xml reader gave inconsistent data .*polygons: cell 1 references point id 77")
    vtpo = c.write("conn/poly_offsets.vtp", xml_poly("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 1 3 2", "3 60"))
    c.add("InfoXmlOffsetBeyond", "error", ["info", vtpo], r"(polygons: cell 1 has offset 60 out of order or beyond the 6 point ids|xml reader)")
    # the crashes of issue 12: a sheet from a .vtk and a .vtp, glyphs from a resampled grid
    sheet_vtk = c.write("conn/sheet_bad.vtk", legacy_poly("POLYGONS 2 8\n3 0 1 2\n3 1 3 1000000\n",
                        tail="POINT_DATA 4\nSCALARS s float 1\nLOOKUP_TABLE default\n1 1 1 1\n"))
    for name, path, rep in [
        ("SheetBadIdsVtk", sheet_vtk, {"type": "sheet", "dataset": "d"}),
        ("SheetBadIdsVtp", vtp, {"type": "sheet", "dataset": "d"}),
        ("SurfaceBadIdsVtk", sheet_vtk, {"type": "surface", "dataset": "d"}),
        ("GlyphsResampledBadIds", ug, {"type": "glyphs", "dataset": "d", "vectors": "v"}),
        ("VolumeResampledBadIds", ug, {"type": "volume", "dataset": "d", "array": "s"}),
    ]:
        c.render(name, "error", c.scene("scene_" + name, {"datasets": {"d": {"path": path}}, "representations": [rep]}),
                 r"datasets\.d: the (legacy|xml) reader gave inconsistent data .*references point id")
    c.render("SplatLinesBadIds", "error", c.scene("splat_lines_bad", {
        "datasets": {"l": {"path": c.write("conn/lines_bad.vtk", legacy_poly("LINES 1 4\n3 0 1 9\n"))},
                     "s": {"source": "splat", "lines": "l", "dimensions": [8, 8, 8]}},
        "representations": [{"type": "outline", "dataset": "s"}]}),
        r"datasets\.l: the legacy reader gave inconsistent data .*lines: cell 0 references point id 9")

    # ---- arrays and headers that lie about sizes
    short = c.write("lies/short_array.vtp", xml_poly("0 0 0 1 0 0 0 1 0 1 1 0", "0 1 2 1 3 2", "3 6",
        pointdata='<PointData><DataArray type="Float32" Name="s" format="ascii">1 2</DataArray></PointData>\n'))
    c.add("InfoXmlShortPointArray", "error", ["info", short], r"(point array 's' has 2 tuples, but the dataset has 4 points|xml reader)")
    many = c.write("lies/more_points.vtp", xml_poly("0 0 0 1 0 0 0 1 0", "0 1 2", "3", piece='NumberOfPoints="4" NumberOfPolys="1"'))
    c.add("InfoXmlFewerPointsThanHeader", "error", ["info", many], ERR_READ)
    lp = c.write("lies/legacy_point_data.vtk", legacy_poly("POLYGONS 1 4\n3 0 1 2\n",
        tail="POINT_DATA 4\nSCALARS s float 1\nLOOKUP_TABLE default\n1 2\n"))
    c.add("InfoLegacyShortPointData", "error", ["info", lp], ERR_READ)
    lp2 = c.write("lies/legacy_points_short.vtk", legacy_poly("POLYGONS 1 4\n3 0 1 2\n", points="0 0 0 1 0 0", npts=4))
    c.add("InfoLegacyPointsShort", "error", ["info", lp2], ERR_READ)
    c.add("InfoImageExtentAbsurd", "error", ["info", c.write("lies/absurd.vti", xml_image("0 999999 0 999999 0 999999", "0 999999 0 999999 0 999999", "1 2 3"))],
          r"the extent \[0, 999999, 0, 999999, 0, 999999\] in .*absurd\.vti \(1e\+18 points\) needs about 9\.54e\+11 MB, over the memory budget of 512 MB \(PLUME_MEMORY_BUDGET_MB\)")
    c.add("InfoImageExtentNegative", "error", ["info", c.write("lies/negative.vti", xml_image("0 -5 0 3 0 3", "0 -5 0 3 0 3", "1 2 3"))], ERR_READ)
    c.add("InfoImagePieceOutside", "error", ["info", c.write("lies/piece_outside.vti", xml_image("0 1 0 1 0 0", "0 9 0 9 0 0", "1 2 3 4"))], ERR_READ)
    c.add("InfoImageShortValues", "error", ["info", c.write("lies/short_values.vti", xml_image("0 3 0 3 0 0", "0 3 0 3 0 0", "1 2 3"))], ERR_READ)
    sp = "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS %s\nSPACING 1 1 1\nORIGIN 0 0 0\nPOINT_DATA %s\nSCALARS s float 1\nLOOKUP_TABLE default\n1 2 3 4\n"
    c.add("InfoLegacyDimensionsHuge", "error", ["info", c.write("lies/dims_huge.vtk", sp % ("100000 100000 100000", "4"))],
          r"(point array 's' has \d+ tuples, but the dataset has 1000000000000000 points|memory budget|legacy reader)")
    c.add("InfoLegacyDimensionsNegative", "error", ["info", c.write("lies/dims_negative.vtk", sp % ("-2 2 1", "4"))],
          r"(image extent .* means 0 points, but it has -4|legacy reader|point array)")
    c.add("InfoLegacyPointDataHuge", "error", ["info", c.write("lies/pointdata_huge.vtk", sp % ("2 2 1", "1000000000000"))], ERR_READ)
    # the shared data with lying headers
    c.add("InfoCarotidDimensionsLie", "error", ["info", c.derived("lies/carotid_dims.vtk", "classic/carotid.vtk",
          replace(b"DIMENSIONS 76 49 45", b"DIMENSIONS 76 49 4500"))],
          r"(point array '.*' has 167580 tuples, but the dataset has 16758000 points|could not read all)")
    c.add("InfoCarotidDimensionsNegative", "error", ["info", c.derived("lies/carotid_negdims.vtk", "classic/carotid.vtk",
          replace(b"DIMENSIONS 76 49 45", b"DIMENSIONS 76 49 -45"))],
          r"(image extent .* means 0 points, but it has -167580|could not read all|point array)")
    c.add("InfoCarotidPointDataLie", "error", ["info", c.derived("lies/carotid_pd.vtk", "classic/carotid.vtk",
          replace(b"POINT_DATA 167580", b"POINT_DATA 999999999"))], ERR_READ)
    c.add("InfoOfficeDimensionsLie", "error", ["info", c.derived("lies/office_dims.vtk", "classic/office.binary.vtk",
          replace(b"DIMENSIONS 21 20 20", b"DIMENSIONS 21 20 2"))], r"(structured grid extent .* means 840 points, but it has 8400|legacy reader|point array)")
    c.add("InfoOfficePointsLie", "error", ["info", c.derived("lies/office_points.vtk", "classic/office.binary.vtk",
          replace(b"POINTS 8400 float", b"POINTS 84000000 float"))], ERR_READ)
    c.add("InfoVtiWholeExtentHuge", "error", ["info", c.derived("lies/office_image_extent.vti", "derived/office_image.vti",
          replace(b'WholeExtent="0 45 0 45 0 25"', b'WholeExtent="0 45000 0 45000 0 25000"'))],
          r"the extent \[0, 45000, 0, 45000, 0, 25000\] .* over the memory budget of 512 MB")
    # Self-consistent after the lie (VTK reads the first 26 slices / the first 7 cells, all valid):
    # nothing downstream can tell, so success is a correct outcome; never a crash.
    c.add("InfoVtiPieceExtentLie", "survive", ["info", c.derived("lies/office_image_piece.vti", "derived/office_image.vti",
          replace(b'<Piece Extent="0 45 0 45 0 25"', b'<Piece Extent="0 45 0 45 0 99"'))], ERR_READ)
    c.add("InfoVtpNumberOfPointsLie", "error", ["info", c.derived("lies/sheet_npts.vtp", "derived/office_stream_sheet.vtp",
          replace(b'NumberOfPoints="24060"', b'NumberOfPoints="24"'))], ERR_READ)
    c.add("InfoVtpNumberOfPolysLie", "error", ["info", c.derived("lies/sheet_npolys.vtp", "derived/office_stream_sheet.vtp",
          replace(b'NumberOfPolys="24000"', b'NumberOfPolys="99999999"'))], ERR_READ)
    c.add("InfoVtpOffsetLie", "error", ["info", c.derived("lies/sheet_offset.vtp", "derived/office_stream_sheet.vtp",
          replace(b'offset="193832"', b'offset="999999999"'))], ERR_READ)
    c.add("InfoVtuNumberOfCellsLie", "survive", ["info", c.derived("lies/fire_ncells.vtu", "classic/fire_ug.vtu",
          lambda d: re.sub(rb'NumberOfCells="(\d+)"', b'NumberOfCells="7"', d, count=1))], ERR_READ)
    c.add("InfoVtuNumberOfPointsLie", "error", ["info", c.derived("lies/fire_npts.vtu", "classic/fire_ug.vtu",
          lambda d: re.sub(rb'NumberOfPoints="(\d+)"', b'NumberOfPoints="3"', d, count=1))], ERR_READ)

    # ---- the shared data cut short: every format, several places
    truncations = [
        ("Carotid", "classic/carotid.vtk", "vtk"), ("Office", "classic/office.binary.vtk", "vtk"),
        ("Kitchen", "classic/kitchen.vtk", "vtk"), ("Blow", "classic/blow.vtk", "vtk"),
        ("FireVtu", "classic/fire_ug.vtu", "vtu"), ("SheetVtp", "derived/office_stream_sheet.vtp", "vtp"),
        ("OfficeVti", "derived/office_image.vti", "vti"), ("CombustorVti", "derived/combustor_image.vti", "vti"),
        ("DiskExodus", "classic/disk_out_ref.ex2", "ex2"), ("CombPlot3d", "plot3d/combxyz.bin", "bin"),
    ]
    for name, source, ext in truncations:
        for pct in (0, 1, 10, 50, 90, 99):
            p = c.derived("trunc/%s_%d.%s" % (name, pct, ext), source, truncate(pct / 100.0))
            c.add("Truncated%s%d" % (name, pct), "error", ["info", p], ERR_READ + r"|corrupt (Exodus II|legacy VTK) file .*(truncated file|too short)|not a|no data")
    # legacy cell lists cut short or not numeric: VTK 9.1 reads on from the file it closed (SEGV;
    # found by plumeFuzzDatasetReader)
    for keyword in ("VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS"):
        c.add("LegacyCellsNotNumber_" + keyword, "error", ["info", c.write("legacy_cells/%s_x.vtk" % keyword,
              legacy_poly("%s 1 4\n3 0 1 x\n" % keyword))],
              r"corrupt legacy VTK file .*: the %s section \(1 cells, 4 values\): value 3 is 'x', not an integer" % keyword)
        c.add("LegacyCellsShort_" + keyword, "error", ["info", c.write("legacy_cells/%s_short.vtk" % keyword,
              legacy_poly("%s 1 4\n3 0 1\n" % keyword))],
              r"corrupt legacy VTK file .*: the %s section \(1 cells, 4 values\) ends after 3 values \(truncated file\?\)" % keyword)
    c.add("LegacyCellsFuzzFinding", "error", ["info", c.write("legacy_cells/fuzz.vtk", legacy_poly(
          "POLYGONS 2 8\n3 0 1 ~2\n3 1 3 2\n", tail="POINT_DATA 4\nSCALARS s float 0\nLOOKUP_TABLE default\n1 2 3 4\n"))],
          r"the POLYGONS section \(2 cells, 8 values\): value 3 is '~2', not an integer")
    # VTK matches a keyword by its first letters in any case ("POLYGONS[" is POLYGONS) and reads the
    # counts as the next words, on the same line or not: the cell-list check does too (a short list
    # behind such a header was the same SEGV; found by plumeFuzzDatasetReader)
    c.add("LegacyCellsKeywordPrefix", "error", ["info", c.write("legacy_cells/prefix.vtk", legacy_poly(
          "POLYGONS[ 2 8\n3 0 1 2\n"))], r"the POLYGONS\[ section \(2 cells, 8 values\) ends after 4 values")
    c.add("LegacyCellsCountsNextLine", "error", ["info", c.write("legacy_cells/next_line.vtk", legacy_poly(
          "polygons\n2 8\n3 0 1 2\n"))], r"the polygons section \(2 cells, 8 values\) ends after 4 values")
    c.add("LegacyCellsNulInValue", "error", ["info", c.write("legacy_cells/nul.vtk", legacy_poly(
          "POLYGONS 2 8\n3 0 1 2\n3\0\0\0\x13 1 2 2\n"))], r"the POLYGONS section \(2 cells, 8 values\): value 4 is '3\?\?\?\?', not an integer")
    # a CELL_TYPES list shorter than announced, or a count other than the CELLS section's: VTK 9.1's
    # unstructured grid reader returns without freeing its cell arrays (a leak; found by
    # plumeFuzzDatasetReader, regression-legacy-cell-types-short) or pairs the lists by index
    c.add("LegacyCellTypesCount", "error", ["info", c.write("legacy_cells/types_count.vtk", legacy_ugrid(
          "CELLS 1 5\n4 0 1 2 3", "CELL_TYPES 2\n12 12"))],
          r"the CELL_TYPES section \(2 types\) does not match the CELLS section's 1 cells")
    c.add("LegacyCellTypesShort", "error", ["info", c.write("legacy_cells/types_short.vtk", legacy_ugrid(
          "CELLS 2 10\n4 0 1 2 3\n4 0 1 2 3", "CELL_TYPES 2\n10"))],
          r"the CELL_TYPES section \(2 types\) ends after 1 values \(truncated file\?\)")
    c.add("LegacyCellTypesNotNumber", "error", ["info", c.write("legacy_cells/types_x.vtk", legacy_ugrid(
          "CELLS 1 5\n4 0 1 2 3", "CELL_TYPES 1\nx"))], r"the CELL_TYPES section \(1 types\): value 0 is 'x', not an integer")
    c.add("LegacyCellsCountsNextLineOk", "ok", ["info", c.write("legacy_cells/next_line_ok.vtk", legacy_poly(
          "polygons 2\n8\n3 0 1 2\n3 1 3 2\n"))], r"Points: 4\s+Cells: 2")
    # a malformed FIELD section: VTK 9.1's legacy readers dereference the null field data they
    # return (SEGV in every dataset type; found by plumeFuzzDatasetReader). Such files are read in a
    # child process first, so the crash is one error; a well-formed FIELD section still reads.
    # (signal 6 in the sanitizer build: ASan reports the child's SEGV, then aborts)
    crashed = r"the legacy reader crashed \(signal (11|6), [^)]*\) reading .*%s\.vtk in a child process"
    for name, text in [
            ("poly_header", legacy_poly("", tail="FIELD x\n")),
            ("poly_array", legacy_poly("POLYGONS 1 4\n3 0 1 2\n", tail="FIELD FieldData 1\nbad 1 1 nonsense\n")),
            ("poly_in_points", legacy_poly("", points="0 0 0field0 0 1 0 10", tail="P1OLYGONS 2 8\n0 0 1\n")),
            ("ugrid_header", legacy_ugrid("FIELD x", "")),
            ("image_header", "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET STRUCTURED_POINTS\n"
                             "DIMENSIONS 2 2 2\nFIELD x\n")]:
        c.add("LegacyFieldMalformed_" + name, "error", ["info", c.write("legacy_field/%s.vtk" % name, text)],
              crashed % name)
    c.add("LegacyFieldWellFormed", "ok", ["info", c.write("legacy_field/good.vtk", legacy_poly(
          "POLYGONS 1 4\n3 0 1 2\n", tail="FIELD FieldData 1\nTIME 1 1 double\n2.5\n"))], r"Points: 4\s+Cells: 1")
    # cells with fewer points than their type reads: VTK's cell classes index a cell's first points
    # without looking at its size (SEGV in the glyph and volume resampling and the surface filter;
    # the sizes were unchecked, only the ids); the validation after every read refuses them
    vel = "POINT_DATA 4\nVECTORS v float\n1 0 0 1 0 0 1 0 0 1 0 0\n"
    def rep_scene(tag, path, rep):
        return c.scene("cell_size_" + tag, {"datasets": {"d": {"path": path}},
                                             "representations": [{"type": rep, "dataset": "d"}]})
    inconsistent = r"datasets\.d: the %s reader gave inconsistent data from .*%s \(corrupt file\?\): "
    for tag, section, rep, expect in [
            ("polygon1", "POLYGONS 2 5\n1 0\n2 1 2\n", "glyphs", r"polygons: cell 0 has 1 point; a polygon needs at least 3"),
            ("polygon0", "POLYGONS 2 4\n0\n2 1 2\n", "volume", r"polygons: cell 0 has 0 points; a polygon needs at least 3"),
            ("line1", "LINES 2 3\n1 0\n0\n", "volume", r"lines: cell 0 has 1 point; a line needs at least 2"),
            ("strip2", "TRIANGLE_STRIPS 1 3\n2 0 1\n", "glyphs", r"triangle strips: cell 0 has 2 points; a triangle strip needs at least 3")]:
        path = c.write("cell_size/%s.vtk" % tag, legacy_poly(section, tail=vel))
        c.render("CellSize_" + tag, "error", rep_scene(tag, path, rep), inconsistent % ("legacy", tag + r"\.vtk") + expect)
    for tag, types, rep, expect in [
            ("hexahedron4", "CELL_TYPES 1\n12\n", "surface", r"cells: cell 0 \(vtkHexahedron, type 12\) has 4 points; it needs 8"),
            ("type250", "CELL_TYPES 1\n250\n", "surface", r"cells: cell 0 has type 250, which is no VTK cell type")]:
        path = c.write("cell_size/%s.vtk" % tag, legacy_ugrid("CELLS 1 5\n4 0 1 2 3", types))
        c.render("CellSize_" + tag, "error", rep_scene(tag, path, rep), inconsistent % ("legacy", tag + r"\.vtk") + expect)
    zero_offsets = ('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n'
                    '<UnstructuredGrid><Piece NumberOfPoints="4" NumberOfCells="2">\n<Points><DataArray type="Float32" '
                    'NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>\n<Cells>'
                    '<DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3</DataArray>\n'
                    '<DataArray type="Int64" Name="offsets" format="ascii">0 0</DataArray>\n'
                    '<DataArray type="UInt8" Name="types" format="ascii">10 10</DataArray></Cells>\n'
                    '</Piece></UnstructuredGrid></VTKFile>\n')
    path = c.write("cell_size/offsets_zero.vtu", zero_offsets)
    c.render("CellSize_xml_offsets_zero", "error", rep_scene("offsets_zero", path, "surface"),
             inconsistent % ("xml", r"offsets_zero\.vtu") + r"cells: cell 0 \(vtkTetra, type 10\) has 0 points; it needs 4")
    c.add("CellSizeWellFormed", "ok", ["info", c.write("cell_size/good.vtk", legacy_ugrid(
          "CELLS 1 5\n4 0 1 2 3", "CELL_TYPES 1\n10\n"))], r"Points: 4\s+Cells: 1")
    # the office stream sheet as legacy 4.2 polydata (binary and ASCII), cut inside its polygons
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
    from vtkmodules.vtkIOLegacy import vtkPolyDataWriter
    sheet_reader = vtkXMLPolyDataReader()
    sheet_reader.SetFileName(os.path.join(DATA, "derived/office_stream_sheet.vtp"))
    sheet_reader.Update()
    for file_type, name in ((2, "Binary"), (1, "Ascii")):
        writer = vtkPolyDataWriter()
        writer.SetInputData(sheet_reader.GetOutput())
        writer.SetFileName(c.path("legacy_cells/sheet_%s.vtk" % name))
        writer.SetFileType(file_type)
        writer.SetFileVersion(42)
        writer.Write()
        for pct in (40, 45):
            c.add("LegacySheet%sCut%d" % (name, pct), "error", ["info", c.derived("legacy_cells/sheet_%s_%d.vtk" % (name, pct),
                  c.path("legacy_cells/sheet_%s.vtk" % name), truncate(pct / 100.0))],
                  r"corrupt legacy VTK file .*: the POLYGONS section \(24000 cells, 96000 values\) (needs 384000 bytes, but the file ends after \d+|ends after \d+ values) \(truncated file\?\)")
        c.add("LegacySheet%sWhole" % name, "ok", ["info", c.path("legacy_cells/sheet_%s.vtk" % name)], r"Points: 24060   Cells: 24000")

    # committed inputs (fuzzer findings): an XML header announcing ~10^10 compressed blocks; VTK's
    # reader allocates them (std::bad_alloc under a 4 GB address-space limit, as in the fuzzer)
    committed = os.path.join(os.path.dirname(os.path.abspath(__file__)), "files")
    # (now refused before VTK's parser sees it; a std::bad_alloc from VTK's readers is reported as
    # "the xml reader ran out of memory reading ...", see vtkPlumeDatasetReader::ProcessRequest)
    c.add("XmlHugeBlockCount", "error", ["info", os.path.join(committed, "xml_huge_block_count.vtu")],
          r"corrupt VTK XML file .*xml_huge_block_count\.vtu: array 'TimeValue' \(appended offset 0\) announces 140737488355329 compressed blocks, more than the file holds",
          limit_mb=4096)
    # fuzzer findings: a block header whose last block exceeds the block size (SEGV in vtkXMLDataParser::ReadBlock),
    # and a block count of 4e9 (VTK allocated 16.8 GB before failing)
    c.add("XmlBadBlockHeader", "error", ["info", os.path.join(committed, "xml_bad_block_header.vti")],
          r"corrupt VTK XML file .*: array 'scalars' \(appended offset 1\): its last block \(4244635739 bytes\) is larger than the block size \(2684354688\)")
    c.add("XmlHugeBlockCountVtp", "error", ["info", os.path.join(committed, "xml_huge_block_count.vtp")],
          r"corrupt VTK XML file .*: array 'vectors' \(appended offset 0\) announces 4294963465 compressed blocks, more than the file holds")

    # a PLOT3D grid whose header gives negative dimensions (SEGV in VTK's reader under ASan)
    c.add("Plot3dNegativeDimensions", "error", ["info", os.path.join(committed, "plot3d_negative_dims.bin")],
          r"(corrupt PLOT3D file .*: grid 0 has dimensions|the plot3d reader cannot read .*Auto detection check failed)")

    # EnSight Gold: VTK's reader read past the end of a cut geometry file (SEGV)
    def ensight(name, geo_edit=None, vel_edit=None):
        folder = "ensight/" + name
        for f in os.listdir(os.path.join(DATA, "ensight_cylinder_re35")):
            if f.endswith(".md"):
                continue
            edit = geo_edit if f.endswith(".geo") else vel_edit if f.endswith(".vel") else None
            c.derived(folder + "/" + f, "ensight_cylinder_re35/" + f, edit or (lambda d: d))
        return c.path(folder + "/cylinder_Re35.case")
    for pct in (1, 10, 50, 90, 99):
        c.add("TruncatedEnSightGeometry%d" % pct, "error", ["info", ensight("geo%d" % pct, truncate(pct / 100.0))],
              r"corrupt EnSight case .*geometry file .*cylinder_Re35\.geo( is cut short \(truncated file\?\)|: part 4 claims 14831 nodes, more than the file can hold)")
    c.add("TruncatedEnSightVariable", "error", ["info", ensight("vel50", None, truncate(0.5))],
          r"the ensight reader could not read all of .*cylinder_Re35\.case \(truncated or corrupt\?\): Read failed")
    def bad_quad(data):
        import struct
        o = 80 * 5  # header words; then part, number, description, 'coordinates', count, xyz
        o += 80 + 4 + 80 + 80
        nodes = struct.unpack("<i", data[o:o + 4])[0]
        o += 4 + 12 * nodes
        assert data[o:o + 5] == b"tria3"
        o += 80 + 4 + 12 * struct.unpack("<i", data[o + 80:o + 84])[0]
        assert data[o:o + 5] == b"quad4"
        o += 80 + 4
        return data[:o] + struct.pack("<i", 999999) + data[o + 4:]
    c.add("EnSightNodeIdTooLarge", "error", ["info", ensight("badquad", bad_quad)],
          r"corrupt EnSight case .*: a 'quad4' element of part 4 names node 999999, but the part has 14831 nodes \(valid 1 to 14831\)")
    for seed in (1, 2, 3, 4):
        c.add("BitFlipEnSightGeometry%d" % seed, "survive", ["info", ensight("flip%d" % seed, flip(seed, 8, 0.0))])

    # payload bit flips: garbage values, maybe garbage structure; never a crash or a second line
    for name, source, ext in truncations:
        for seed in (1, 2):
            p = c.derived("flip/%s_%d.%s" % (name, seed, ext), source, flip(seed, 8, 0.3))
            c.add("BitFlip%s%d" % (name, seed), "survive", ["info", p])

    # ---- the formats no structural check covers (HDF5 Exodus, EnSight, inline XML, PLOT3D Q,
    # OpenFOAM, CGNS, VRML): read once in a child process first (vtkPlumeFormatCheck::RunIsolated),
    # so a crash of VTK's reader is one error. Cut short and bit-flipped copies of the shared data,
    # and files written here; with PLUME_READER_ISOLATION=0 some of these crash (see Testing.md).
    # a hung reader is stopped after PLUME_READER_TIMEOUT: 15 s here, within the case timeout;
    # the inputs known to hang VTK's reader get 5 s, the hang's length, not the check's (each
    # second of it is a busy core: these were 45 of the corpus's 260 s of CPU at 15 s)
    def c_add(name, kind, args, expect="", hangs=False):
        c.add(name, kind, args, expect, env={"PLUME_READER_TIMEOUT": "5" if hangs else "15"})
    exposed = [("CGNS", "cgns/sqnz_s.adf.cgns", "cgns"), ("VRML", "classic/room_vis.wrl", "wrl")]
    for name, source, ext in exposed:
        for pct in (1, 10, 50, 90):
            c_add("Exposed%sTruncated%d" % (name, pct), "survive",
                  ["info", c.derived("exposed/%s_%d.%s" % (name, pct, ext), source, truncate(pct / 100.0))])
        for seed in (1, 2, 3, 4, 5, 6):
            c_add("Exposed%sBitFlip%d" % (name, seed), "survive",
                  ["info", c.derived("exposed/%s_flip%d.%s" % (name, seed, ext), source, flip(seed, 16, 0.0))],
                  hangs=(name, seed) == ("CGNS", 5))

    def plot3d_q(tag, edit):
        folder = c.path("exposed/q_" + tag)
        os.makedirs(folder, exist_ok=True)
        shutil.copyfile(os.path.join(DATA, "plot3d/combxyz.bin"), os.path.join(folder, "combxyz.bin"))
        with open(os.path.join(DATA, "plot3d/combq.bin"), "rb") as f:
            data = edit(f.read())
        with open(os.path.join(folder, "combq.bin"), "wb") as f:
            f.write(data)
        return os.path.join(folder, "combxyz.bin")
    for pct in (1, 10, 50, 90):
        c_add("ExposedPlot3dQTruncated%d" % pct, "survive", ["info", plot3d_q("t%d" % pct, truncate(pct / 100.0))])
    for seed in (1, 2, 3, 4):
        c_add("ExposedPlot3dQHeaderFlip%d" % seed, "survive", ["info", plot3d_q("f%d" % seed, flip(seed, 4, 0.0))])
    c_add("ExposedPlot3dQHeaderLie", "survive", ["info", plot3d_q("lie", lambda d: d[:4] + (999999).to_bytes(4, "big") + d[8:])])

    def foam(tag, rel, edit):
        folder = c.path("exposed/foam_" + tag)
        if not os.path.isdir(folder):
            shutil.copytree(os.path.join(DATA, "openfoam_cavity/cavity"), folder)
        target = os.path.join(folder, rel)
        os.chmod(target, 0o644)
        with open(target, "rb") as f:
            data = edit(f.read())
        with open(target, "wb") as f:
            f.write(data)
        return os.path.join(folder, "case.foam")
    for rel in ("constant/polyMesh/faces", "constant/polyMesh/owner", "constant/polyMesh/points", "2.5/U"):
        short = rel.replace("constant/polyMesh/", "").replace("2.5/", "")
        for pct in (10, 50, 90):
            c_add("ExposedFoam_%s_Truncated%d" % (short, pct), "survive", ["info", foam("%s_t%d" % (short, pct), rel, truncate(pct / 100.0))])
        for seed in (1, 2):
            c_add("ExposedFoam_%s_BitFlip%d" % (short, seed), "survive", ["info", foam("%s_f%d" % (short, seed), rel, flip(seed, 16, 0.3))])
        # header lie: the list claims ten times its entries
        def lie(data):
            m = re.search(rb"\n(\d+)\n\(", data)
            return data if not m else data[:m.start(1)] + str(int(m.group(1)) * 10 + 7).encode() + data[m.end(1):]
        c_add("ExposedFoam_%s_CountLie" % short, "survive", ["info", foam("%s_lie" % short, rel, lie)])

    # inline XML (ascii and base64 arrays) written here from fire_ug.vtu
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter
    for mode in ("ascii", "binary"):
        inline = c.path("exposed/fire_inline_%s.vtu" % mode)
        if not os.path.exists(inline):
            r = vtkXMLUnstructuredGridReader()
            r.SetFileName(os.path.join(DATA, "classic/fire_ug.vtu"))
            w = vtkXMLUnstructuredGridWriter()
            w.SetInputConnection(r.GetOutputPort())
            w.SetFileName(inline)
            w.SetCompressorTypeToNone()
            w.SetDataModeToAscii() if mode == "ascii" else w.SetDataModeToBinary()
            w.Write()
        with open(inline, "rb") as f:
            data = f.read()
        for pct in (10, 50, 90):
            c_add("ExposedXmlInline_%s_Truncated%d" % (mode, pct), "survive",
                  ["info", c.write("exposed/fire_%s_t%d.vtu" % (mode, pct), truncate(pct / 100.0)(data), "wb")])
        for seed in (1, 2, 3):
            c_add("ExposedXmlInline_%s_BitFlip%d" % (mode, seed), "survive",
                  ["info", c.write("exposed/fire_%s_f%d.vtu" % (mode, seed), flip(seed, 16, 0.05)(data), "wb")])
        if mode == "ascii":
            # the XML parser's reason, not "the reader failed (no details)" (its parser is made
            # inside the reader and reports to the output window only)
            c_add("ExposedXmlInlineParseReason", "error", ["info", c.path("exposed/fire_ascii_t50.vtu")],
                  r"the xml reader cannot read .*fire_ascii_t50\.vtu: Error parsing XML in stream at line \d+, "
                  r"column \d+, byte index \d+: no element found$")
        c_add("ExposedXmlInline_%s_CountLie" % mode, "survive", ["info", c.write("exposed/fire_%s_lie.vtu" % mode,
              re.sub(rb'NumberOfPoints="(\d+)"', b'NumberOfPoints="99"', data, count=1), "wb")])

    # ASCII EnSight Gold (the structural check reads C binary only): one hexahedron
    ens_geo = ("Plume\nASCII test\nnode id off\nelement id off\npart\n         1\nblock\ncoordinates\n"
               "         8\n" + "".join("%12.5e\n" % v for v in (0, 1, 1, 0, 0, 1, 1, 0)) +
               "".join("%12.5e\n" % v for v in (0, 0, 1, 1, 0, 0, 1, 1)) +
               "".join("%12.5e\n" % v for v in (0, 0, 0, 0, 1, 1, 1, 1)) +
               "hexa8\n         1\n         1         2         3         4         5         6         7         8\n")
    ens_case = "FORMAT\ntype:  ensight gold\nGEOMETRY\nmodel: box.geo\n"
    def ens(tag, geo):
        c.write("exposed/ens_%s/box.geo" % tag, geo)
        return c.write("exposed/ens_%s/box.case" % tag, ens_case)
    c_add("ExposedEnSightAsciiOk", "ok", ["info", ens("ok", ens_geo)], r"Points: 8")
    for pct in (30, 60, 90):
        c_add("ExposedEnSightAsciiTruncated%d" % pct, "survive", ["info", ens("t%d" % pct, ens_geo[: len(ens_geo) * pct // 100])])
    c_add("ExposedEnSightAsciiNodeLie", "survive", ["info", ens("nodelie", ens_geo.replace("         1         2", "    999999         2"))])
    c_add("ExposedEnSightAsciiCountLie", "survive", ["info", ens("countlie", ens_geo.replace("coordinates\n         8", "coordinates\n  99999999"))],
          hangs=True)
    c_add("ExposedEnSightAsciiElementLie", "survive", ["info", ens("elemlie", ens_geo.replace("hexa8\n         1", "hexa8\n   9999999"))],
          hangs=True)

    # a series whose later step is corrupt: the first step read in a child said nothing of the
    # others, which were read in process (a count lie in step 1's geometry hangs VTK's reader,
    # a node lie is caught by the validation after it). Each step is read in a child first.
    ens_series = ("FORMAT\ntype:  ensight gold\nGEOMETRY\nmodel: 1 box*.geo\nTIME\ntime set: 1\n"
                  "number of steps: 2\nfilename start number: 0\nfilename increment: 1\ntime values: 0.0 0.5\n")
    def ens_steps(tag, later):
        c.write("exposed/series_%s/box0.geo" % tag, ens_geo)
        c.write("exposed/series_%s/box1.geo" % tag, later)
        return c.write("exposed/series_%s/box.case" % tag, ens_series)
    c.add("ExposedSeriesLaterStepCountLie", "error", ["info", ens_steps("countlie",
          ens_geo.replace("coordinates\n         8", "coordinates\n  99999999"))],
          r"the ensight reader did not finish within 5 s \(PLUME_READER_TIMEOUT\) reading time step 1 \(t = 0\.5\) "
          r"of .*series_countlie/box\.case in a child process \(a corrupt file\?\); not read",
          env={"PLUME_READER_TIMEOUT": "5"})  # the hang's length, not the check's: kept short
    c_add("ExposedSeriesFirstStepOk", "ok", ["info", ens_steps("countlie2", ens_geo.replace(
          "coordinates\n         8", "coordinates\n  99999999")), "--time-step", "0"], r"Points: 8")
    c_add("ExposedSeriesLaterStepOk", "ok", ["info", ens_steps("ok", ens_geo)], r"read step 1, t = 0\.5")

    # HDF5 (netCDF-4) Exodus: not parsed here; a forged and a cut HDF5 signature
    c_add("ExposedExodusHdf5Forged", "survive", ["info", c.write("exposed/forged.ex2", b"\x89HDF\r\n\x1a\n" + bytes(range(256)) * 8, "wb")])
    c_add("ExposedExodusHdf5Cut", "survive", ["info", c.write("exposed/cut.ex2", b"\x89HDF\r\n\x1a\n\x00\x00", "wb")])

    # ---- triangle counts against the budgets (the office stream sheet: 24000 triangles)
    sheet_path = os.path.join(DATA, "derived/office_stream_sheet.vtp")
    for mode, env, expect in [
        ("exact", {"PLUME_MEMORY_BUDGET_MB": "1"},
         r"representations\[0\] \(sheet\): dataset 's': the vertex data of the sheet's 2\d{4} triangles needs about [\d.]+ MB, over the memory budget of 1 MB \(PLUME_MEMORY_BUDGET_MB\)"),
        ("grid", {"PLUME_WORK_BUDGET": "1e6"},
         r"the sheet grid of 2\d{4} triangles \(about [\d.e+]+ quadrature points merged into about [\d.e+]+ Gaussians on \d+x\d+x\d+ nodes\) needs about [\d.e+]+ operations, "
         r"over the work budget of 1e\+06 \(PLUME_WORK_BUDGET\); use fewer triangles"),
    ]:
        scene = c.scene("sheet_budget_" + mode, {"datasets": {"s": {"path": sheet_path}},
                                                   "representations": [{"type": "sheet", "dataset": "s", "mode": mode}]})
        c.render("SheetTriangleBudget_" + mode, "error", scene, expect, env=env)
        c.render("SheetTriangleBudgetOk_" + mode, "ok", scene, "")

    # ---- derived geometry against the budgets: estimated before the filter
    # (contour: cells x values against the work budget; traced lines: seeds x
    # steps x directions points against both) and the result checked after it
    vortex40 = {"source": "vortex", "dimensions": [40, 40, 40]}
    many_values = [i / 1000.0 for i in range(1, 1000)]
    def derived_scene(tag, derived):
        return c.scene("derived_budget_" + tag, {"datasets": {"v": vortex40, "d": dict(derived, input="v")},
                                                  "representations": [{"type": "surface", "dataset": "d"}]})
    contour = derived_scene("contour", {"source": "contour", "values": many_values})
    c.render("DerivedBudgetContourResult", "error", contour,
             r"datasets\.d: contour: the result's \d{7} cells and \d{7} points \(estimated before the filter: at most "
             r"2\.96298e\+08 triangles, 5 per cell and value\) needs about [\d.]+ MB, over the memory budget of 2 MB "
             r"\(PLUME_MEMORY_BUDGET_MB\)", env={"PLUME_MEMORY_BUDGET_MB": "2"})
    c.render("DerivedBudgetContourWork", "error", contour,
             r"datasets\.d: contour: the contour of 59319 cells at 999 values needs about 5\.93e\+07 operations, "
             r"over the work budget of 1e\+06 \(PLUME_WORK_BUDGET\)", env={"PLUME_WORK_BUDGET": "1e6"})
    c.render("DerivedBudgetClipResult", "error", derived_scene("clip", {"source": "clip"}),
             r"datasets\.d: clip: the result's \d+ cells and \d+ points needs about [\d.]+ MB, over the memory budget "
             r"of 1 MB \(PLUME_MEMORY_BUDGET_MB\)", env={"PLUME_MEMORY_BUDGET_MB": "1"})
    for source, env, expect in [
        ("stream_surface", {"PLUME_MEMORY_BUDGET_MB": "2"},
         r"datasets\.d: stream_surface: the lines traced from 100001 seeds x \d+ steps \(maximum_length / step_length\) "
         r"x 2 directions \([\d.e+]+ points\) needs about [\d.]+ MB, over the memory budget of 2 MB \(PLUME_MEMORY_BUDGET_MB\)"),
        ("streamlines", {"PLUME_WORK_BUDGET": "1e5"},
         r"datasets\.d: streamlines: the lines traced from 1001 seeds x \d+ steps \(maximum_length / step_length\) "
         r"x 2 directions \([\d.e+]+ points\) needs about [\d.e+]+ operations, over the work budget of 1e\+05 \(PLUME_WORK_BUDGET\)"),
        ("ribbon", {"PLUME_MEMORY_BUDGET_MB": "2"},
         r"datasets\.d: ribbon: the lines traced from 100001 seeds x \d+ steps .* needs about [\d.]+ MB, over the memory budget of 2 MB"),
    ]:
        name = "DerivedBudget" + "".join(w.capitalize() for w in source.split("_"))
        seeds = 1000 if source == "streamlines" else 100000  # streamlines: within memory, over the work budget
        c.render(name, "error", derived_scene(source, {"source": source, "seed_resolution": seeds}), expect, env=env)
    # vtkStreamSurface's iterative version (VTK 9.1: no abort hook) copies its whole surface once a
    # step and adds seeds where the front spreads, so its work grows with steps^2 and the front may
    # double every step: refused before tracing when steps^2 alone is over the work budget, else
    # stopped when the next step would pass a budget (on the office the default surface ran for
    # hours and grew past 1 M points by step 100 of 143)
    office = {"path": "classic/office.binary.vtk"}
    def iterative_scene(tag, derived):
        return c.scene("iterative_" + tag, {"datasets": {"o": office, "d": dict(derived, input="o",
                       source="stream_surface", iterative_seeding=True)},
                       "representations": [{"type": "outline", "dataset": "d"}]})
    c.render("IterativeSurfaceRefused", "error", iterative_scene("refused", {"seed_resolution": 100, "step": 0.05}),
             r"datasets\.d: stream_surface: the iterative stream surface \(iterative_seeding\) from 101 seeds x \d+ steps "
             r"x 2 directions, which copies its whole surface once a step \([\d.e+]+ point copies before it adds any seed\) "
             r"needs about [\d.e+]+ operations, over the work budget of 1e\+10 \(PLUME_WORK_BUDGET\)")
    c.render("IterativeSurfaceGrowsWork", "error", iterative_scene("grows", {}),
             r"datasets\.d: stream_surface: the next step of the iterative stream surface \(iterative_seeding; grown to \d+ "
             r"points, a front of about \d+ seeds from the 21 given, after \d+ of \d+ steps\) needs about [\d.e+]+ operations, "
             r"over the work budget of 2e\+09 \(PLUME_WORK_BUDGET\); set iterative_seeding false, a larger step or a shorter "
             r"maximum_length", env={"PLUME_WORK_BUDGET": "2e9"})
    c.render("IterativeSurfaceGrowsMemory", "error", iterative_scene("grows_mem", {}),
             r"datasets\.d: stream_surface: the next step of the iterative stream surface \(iterative_seeding; grown to \d+ "
             r"points, .* steps\) needs about [\d.]+ MB, over the memory budget of 16 MB \(PLUME_MEMORY_BUDGET_MB\)",
             env={"PLUME_MEMORY_BUDGET_MB": "16"})
    c.render("IterativeSurfaceOk", "ok", iterative_scene("ok", {"maximum_length": 1.0}), r"wrote")
    # the same kinds of scene within the budget still render
    c.render("DerivedBudgetContourOk", "ok", derived_scene("contour_ok", {"source": "contour", "values": [0.1, 0.5]}),
             "", env={"PLUME_MEMORY_BUDGET_MB": "64"})
    c.render("DerivedBudgetStreamSurfaceOk", "ok", derived_scene("stream_surface_ok", {"source": "stream_surface"}),
             "", env={"PLUME_MEMORY_BUDGET_MB": "64"})
    # the surface representation's own triangles against the memory budget, before any upload
    # (a 40^3 vortex: 6 x 39^2 quads = 18252 triangles on 6 x 40^2 = 9600 points, the faces unshared)
    surface = c.scene("surface_budget", {"datasets": {"v": vortex40},
                                         "representations": [{"type": "surface", "dataset": "v"}]})
    c.render("SurfaceBudget", "error", surface,
             r"representations\[0\] \(surface\): dataset 'v': the surface's 18252 triangles and 9600 points needs "
             r"about 1\.18 MB, over the memory budget of 1 MB \(PLUME_MEMORY_BUDGET_MB\)", env={"PLUME_MEMORY_BUDGET_MB": "1"})
    c.render("SurfaceBudgetOk", "ok", surface, "", env={"PLUME_MEMORY_BUDGET_MB": "64"})
    # the contour representation (not the derived contour dataset): the same work check before the
    # filter (cells x values) and the surface's memory check after it (without them 999 values of a
    # 40^3 vortex rendered 2818140 triangles with 600 MB RSS, whatever the budgets; 19 values make
    # 57096 triangles, 4.2 MB)
    contour_rep = c.scene("contour_rep_budget", {"datasets": {"v": vortex40}, "representations": [
        {"type": "contour", "dataset": "v", "array": "speed", "values": many_values}]})
    c.render("ContourRepBudgetWork", "error", contour_rep,
             r"representations\[0\] \(contour\): dataset 'v': the contour of 59319 cells at 999 values needs about "
             r"5\.93e\+07 operations, over the work budget of 1e\+06 \(PLUME_WORK_BUDGET\)", env={"PLUME_WORK_BUDGET": "1e6"})
    c.render("ContourRepBudgetMemory", "error", c.scene("contour_rep_memory", {"datasets": {"v": vortex40},
             "representations": [{"type": "contour", "dataset": "v", "array": "speed", "values": [i / 20.0 for i in range(1, 20)]}]}),
             r"representations\[0\] \(contour\): dataset 'v': the contour's 57096 triangles and 29520 points needs "
             r"about [\d.]+ MB, over the memory budget of 2 MB \(PLUME_MEMORY_BUDGET_MB\)", env={"PLUME_MEMORY_BUDGET_MB": "2"})
    c.render("ContourRepBudgetOk", "ok", c.scene("contour_rep_ok", {"datasets": {"v": vortex40}, "representations": [
        {"type": "contour", "dataset": "v", "array": "speed", "values": [0.1, 0.5]}]}), r"wrote",
        env={"PLUME_MEMORY_BUDGET_MB": "2", "PLUME_WORK_BUDGET": "1e6"})

    # ---- scenes: nesting, cycles, budgets, parameter arithmetic
    c.render("NestedRepresentations", "error", c.scene("nested_reps", '{"representations": %s}' % nested(5000)),
             r"scene file '.*nested_reps\.json' nests JSON deeper than 64 levels")
    c.render("NestedWrongType", "error", c.scene("nested_value",
             '{"datasets": {"v": {"source": "vortex"}}, "representations": [{"type": "glyphs", "dataset": "v", "scale": %s}]}' % nested(4000)),
             r"nests JSON deeper than 64 levels")
    c.render("NestedObjects", "error", c.scene("nested_objects", '{"datasets": ' + '{"a": ' * 3000 + '1' + '}' * 3000 + '}'),
             r"nests JSON deeper than 64 levels")
    c.render("NestedShallowOk", "error", c.scene("nested_shallow", '{"representations": %s}' % nested(20)),
             r"representations\[0\]: needs a string 'type'")
    vortex = {"source": "vortex", "dimensions": [12, 12, 12]}
    c.render("CycleReference", "error", c.scene("cycle_reference", {"datasets": {
        "a": {"source": "splat", "points": [[0, 0, 0], [1, 0, 0]], "reference": "b"},
        "b": {"source": "splat", "points": [[0, 0, 0], [1, 0, 0]], "reference": "a"}},
        "representations": [{"type": "outline", "dataset": "a"}]}),
        r"datasets depend on each other in a cycle: a -> b -> a")
    c.render("CycleTrace", "error", c.scene("cycle_trace", {"datasets": {
        "a": {"source": "splat", "trace": {"dataset": "b"}},
        "b": {"source": "splat", "trace": {"dataset": "a"}}},
        "representations": [{"type": "outline", "dataset": "a"}]}),
        r"datasets depend on each other in a cycle: a -> b -> a")
    c.render("CycleThree", "error", c.scene("cycle_three", {"datasets": {
        "a": {"source": "splat", "lines": "b"}, "b": {"source": "splat", "trace": {"dataset": "c"}},
        "c": {"source": "splat", "points": [[0, 0, 0], [1, 0, 0]], "reference": "a"}},
        "representations": [{"type": "outline", "dataset": "a"}]}),
        r"datasets depend on each other in a cycle: a -> b -> c -> a")
    c.render("ReferenceChainOk", "ok", c.scene("chain_ok", {"datasets": {"v": vortex,
        "a": {"source": "splat", "points": [[0, 0, 0], [0.5, 0, 0]], "reference": "v", "sigma": 0.2}},
        "representations": [{"type": "outline", "dataset": "a"}]}), r"wrote")
    c.render("SplatSigmaHuge", "error", c.scene("splat_sigma", {"datasets": {"s": {
        "source": "splat", "circle": {"radius": 1, "resolution": 20000}, "sigma": 1e6, "dimensions": [200, 200, 200],
        "bounds": [-1, 1, -1, 1, -1, 1]}}, "representations": [{"type": "outline", "dataset": "s"}]}),
        r"datasets\.s: splatting \d+ splats \(radius 1e\+06, cutoff 4\) onto 200x200x200 voxels needs about .* operations, over the work budget of .* \(PLUME_WORK_BUDGET\)")
    c.render("SplatGridHuge", "error", c.scene("splat_grid", {"datasets": {"s": {
        "source": "splat", "points": [[0, 0, 0], [1, 0, 0]], "dimensions": [1024, 1024, 1024]}},
        "representations": [{"type": "outline", "dataset": "s"}]}),
        r"datasets\.s: the splat grid \(1024x1024x1024\) needs about 12288 MB, over the memory budget of 512 MB")
    c.render("SplatSaveUnwritable", "error", c.scene("splat_save", {"datasets": {"s": {
        "source": "splat", "points": [[0, 0, 0], [1, 0, 0]], "dimensions": [8, 8, 8],
        "save": "/nonexistent-plume-folder/s.vti"}}, "representations": [{"type": "outline", "dataset": "s"}]}),
        r"datasets\.s: could not write 'save' file '/nonexistent-plume-folder/s\.vti'")
    c.render("SplatSaveNul", "error", c.scene("splat_save_nul", {"datasets": {"s": {
        "source": "splat", "points": [[0, 0, 0], [1, 0, 0]], "dimensions": [8, 8, 8],
        "save": c.path("s.vti") + "\u0000x"}}, "representations": [{"type": "outline", "dataset": "s"}]}),
        r"datasets\.s: 'save' path holds a NUL character")
    c.render("ResampleOverBudget", "error", c.scene("resample_budget", {"datasets": {"f": {
        "path": "classic/fire_ug.vtu", "image_dimension": 1024}},
        "representations": [{"type": "glyphs", "dataset": "f", "vectors": "v"}]}),
        r"'image_dimension' 1024 .* over the memory budget of 512 MB")
    for name, rep, expect in [
        ("LightIntensityHuge", None, r"lights\[0\]: parameter 'intensity' must be a finite number in \[0, 10000\], got 1e\+300"),
        ("OpacityUnitDistanceTiny", {"type": "volume", "dataset": "v", "array": "speed", "opacity_unit_distance": 1e-300},
         r"parameter 'opacity_unit_distance' must be .*got 1e-300"),
        ("VolumeIsoHuge", {"type": "volume", "dataset": "v", "array": "speed", "mode": "isosurface", "iso_value": 1e300},
         r"parameter 'iso_value' must be .*got 1e\+300"),
        ("GlyphScaleHuge", {"type": "glyphs", "dataset": "v", "scale": 1e300}, r"parameter 'scale' must be .*got (a number )?1e\+300"),
        ("GlyphMinSpeedHuge", {"type": "glyphs", "dataset": "v", "min_speed": 1e39}, r"parameter 'min_speed' must be .*got (a number )?1e\+39"),
        ("SphereRadiusHuge", {"type": "sphere", "radius": 1e300}, r"parameter 'radius' must be .*got 1e\+300"),
        ("SphereRadiusTiny", {"type": "sphere", "radius": 1e-300}, r"parameter 'radius' must be .*got 1e-300"),
    ]:
        scene = {"datasets": {"v": vortex}, "representations": [rep or {"type": "outline", "dataset": "v"}]}
        if rep is None:
            scene["lights"] = [{"type": "headlight", "intensity": 1e300}]
        c.render(name, "error", c.scene("param_" + name, scene), expect)
    sheet = {"type": "sheet", "dataset": "s", "density": 0.05, "thickness": 0.02}
    # sigmas are squared in float shaders: 1e18 and more gave a black frame
    for key, value, kind, expect in [
            ("blur", 1e30, "error", r"parameter 'blur' must be a finite number in \[0, 1e\+15\], got (a number )?1e\+30"),
            ("thickness", 1e25, "error", r"parameter 'thickness' must be a finite number in \[0, 1e\+15\], got (a number )?1e\+25"),
            ("density_scale", 1e-300, "error", r"parameter 'density_scale' must be .*got 1e-300"),
            ("blur_max", 1e15, "ok", r"wrote"),  # the largest blur renders (the background: smoke spread to nothing)
            ("density", 1e30, "ok", r"wrote")]:  # opaque absorbing smoke: a black sheet, the correct image
        rep = dict(sheet)
        rep[key.replace("_max", "")] = value
        c.render("Sheet_" + key, kind, c.scene("sheet_" + key, {"datasets": {"s": {"path": "derived/office_stream_sheet.vtp"}},
                 "representations": [rep]}), expect)
    for name, camera, expect in [
        ("CameraFar", {"position": [1e300, 0, 0]}, r"camera: parameter 'position' must be .*got \[1e\+300,0,0\]"),
        ("CameraFocalFar", {"focal_point": [0, -1e200, 0]}, r"camera: parameter 'focal_point' must be .*got \[0,-1e\+200,0\]"),
        ("CameraUpTiny", {"view_up": [1e-320, 0, 0]}, r"camera: parameter 'view_up' must be .*got \[1e-320,0,0\]"),
        ("CameraZoomNaN", {"zoom": "NaN"}, r"camera: parameter 'zoom' must be a number, got \"NaN\""),
    ]:
        c.render(name, "error", c.scene("camera_" + name, {"datasets": {"v": vortex},
                 "representations": [{"type": "outline", "dataset": "v"}], "camera": camera}), expect)

    # ---- non-finite values in arrays: left out of default ranges, with a warning, and the
    # picture drawn (before: the volume drew nothing, the glyphs were all one dark red)
    values, vectors = [], []
    for k in range(8):
        for j in range(8):
            for i in range(8):
                n = i + 8 * (j + 8 * k)
                values.append("inf" if n in (5, 77) else "-inf" if n == 300 else "nan" if n == 301 else str(i + j + k))
                vectors.append("inf 0 0" if n == 100 else "%g %g %g" % (1, (i - 3.5) / 4, (j - 3.5) / 4))
    inf_vti = c.write("nonfinite/inf.vti", '<?xml version="1.0"?>\n<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">'
        '<ImageData WholeExtent="0 7 0 7 0 7" Origin="0 0 0" Spacing="1 1 1"><Piece Extent="0 7 0 7 0 7"><PointData Scalars="s" Vectors="v">'
        '<DataArray type="Float32" Name="s" format="ascii">%s</DataArray><DataArray type="Float32" Name="v" NumberOfComponents="3" '
        'format="ascii">%s</DataArray></PointData></Piece></ImageData></VTKFile>\n' % (" ".join(values), " ".join(vectors)))
    c.render("VolumeInfScalars", "warn", c.scene("nonfinite_volume", {"datasets": {"d": {"path": inf_vti}},
             "representations": [{"type": "volume", "dataset": "d", "array": "s"}]}),
             r"plume: warning: representations\[0\] \(volume\): 4 NaN or infinite value\(s\) of array 's' left out of the colour range \[2, 19\]",
             image={0: 100})  # the viridis volume: red up to ~230 (background 26)
    c.render("GlyphsInfVectors", "warn", c.scene("nonfinite_glyphs", {"datasets": {"d": {"path": inf_vti}},
             "representations": [{"type": "glyphs", "dataset": "d", "vectors": "v", "roots": "lattice", "scale": 0.5}]}),
             r"plume: warning: representations\[0\] \(glyphs\): 1 NaN or infinite value\(s\) of array 'v' left out of the colour range \[1\.0155, 1\.59099\]",
             image={1: 100})  # green glyphs exist (all dark red before)
    c.render("SurfaceInfScalars", "warn", c.scene("nonfinite_surface", {"datasets": {"d": {"path": inf_vti}},
             "representations": [{"type": "surface", "dataset": "d", "color_array": "s"}]}),
             r"plume: warning: representations\[0\] \(surface\): 4 NaN or infinite value\(s\) of array 's' left out of the colour range \[2, 19\]")

    # ---- command lines
    vs = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Examples", "Scenes", "vortex_streamlets.json")
    for name, size, expect in [
        ("SizeOverflow", "4294967297x10", r"--size must be WxH with positive integers up to 16384, got '4294967297x10'"),
        ("SizeOverflowHeight", "10x18446744073709551617", r"got '10x18446744073709551617'"),
        ("SizeNegative", "-1x10", r"got '-1x10'"), ("SizeZero", "0x10", r"got '0x10'"),
        ("SizeTooLarge", "16385x10", r"got '16385x10'"), ("SizeTrailing", "10x10x", r"got '10x10x'"),
        ("SizeSpace", " 10x10", r"got ' 10x10'"), ("SizePlus", "+10x10", r"got '\+10x10'"),
        ("SizeFloat", "10.5x10", r"got '10\.5x10'"), ("SizeEmptyWidth", "x10", r"got 'x10'"),
    ]:
        c.add(name, "error", ["render", vs, "-o", c.path(name + ".png"), "--size", size], expect)
    c.add("SizeOverBudget", "error", ["render", vs, "-o", c.path("SizeOverBudget.png"), "--size", "16384x16384"],
          r"image size 16384x16384 needs about 28160 MB to render .*over the memory budget of 512 MB \(PLUME_MEMORY_BUDGET_MB.*choose a smaller --size")
    for bench in ("sheets", "glyphs", "volume", "splat"):
        c.add("BenchUnknownJob_" + bench, "error", ["bench", bench, "--job", "no:such:job"],
              r"bench %s: unknown job 'no:such:job' \(known: " % bench)
    c.add("BenchSheetsJobMissingField", "error", ["bench", "sheets", "--job", "ours"], r"bench sheets: unknown job 'ours'")
    c.add("BenchSheetsJobNotNumber", "error", ["bench", "sheets", "--job", "reference:abc"], r"unknown job 'reference:abc'")


def is_bench(case):
    """A `plume bench` case (it needs plume-bench beside plume)."""
    return case["args"][:1] == ["bench"]


def run_case(plume, case, timeout):
    env = dict(os.environ)
    env.setdefault("PLUME_MEMORY_BUDGET_MB", "512")
    env["PLUME_DATA_DIR"] = DATA
    env.update(case["env"])
    env.pop("PLUME_VERBOSE", None)
    t0 = time.time()
    try:
        limit = case["limit_mb"]

        def set_limit():
            # not under AddressSanitizer (the sanitizer run sets ASAN_OPTIONS): its runtime reserves
            # terabytes of address space for shadow memory at start-up and cannot start under the limit
            if limit and "ASAN_OPTIONS" not in os.environ:
                import resource
                resource.setrlimit(resource.RLIMIT_AS, (limit << 20, limit << 20))
        proc = subprocess.run([plume] + case["args"], stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, timeout=timeout, env=env, start_new_session=True,
                              preexec_fn=set_limit)
    except subprocess.TimeoutExpired:
        return "hang", "killed after %g s" % timeout, time.time() - t0
    seconds = time.time() - t0
    code = proc.returncode
    out = proc.stdout.decode("utf-8", "replace")
    err = proc.stderr.decode("utf-8", "replace")
    lines = [l for l in err.strip().splitlines() if l.strip()]
    if code < 0 or code > 100:
        return "crash", "exit %d (signal %s)\n%s" % (code, -code if code < 0 else "?", err[-2000:]), seconds
    kind, expect = case["kind"], case["expect"]
    if kind in ("error", "survive") and code != 0:
        if code != 2:
            return "fail", "exit %d, expected 2\n%s" % (code, err), seconds
        if len(lines) != 1 or not lines[0].startswith("plume: error: "):
            return "fail", "expected one 'plume: error:' line, got:\n%s" % err, seconds
        if kind == "error" and not re.search(expect, lines[0]):
            return "fail", "stderr does not match /%s/:\n%s" % (expect, err), seconds
        return "error", lines[0], seconds
    if kind == "error":
        return "fail", "expected an error, got exit 0\nstdout: %s\nstderr: %s" % (out[-1500:], err[-1500:]), seconds
    if code != 0:
        return "fail", "exit %d\n%s" % (code, err), seconds
    if kind == "warn" and not re.search(expect, err):
        return "fail", "no warning matching /%s/:\n%s" % (expect, err), seconds
    if kind == "ok" and expect and not re.search(expect, out):
        return "fail", "stdout does not match /%s/:\n%s" % (expect, out), seconds
    if case["image"]:
        reader = vtkPNGReader()
        reader.SetFileName(case["args"][case["args"].index("-o") + 1])
        reader.Update()
        scalars = reader.GetOutput().GetPointData().GetScalars()
        for channel, minimum in case["image"].items():
            if scalars is None or scalars.GetRange(channel)[1] < minimum:
                return "fail", "image channel %d never reaches %d (%s): nothing drawn?" % (
                    channel, minimum, scalars.GetRange(channel) if scalars else "no image"), seconds
    return "ok", (lines[0] if lines else out.strip().splitlines()[-1] if out.strip() else ""), seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("plume")
    parser.add_argument("work")
    parser.add_argument("--only", default="")
    parser.add_argument("--bench-only", action="store_true")
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--verbose", action="store_true")
    args = parser.parse_args()
    if os.path.isdir(args.work):
        shutil.rmtree(args.work)
    os.makedirs(args.work)
    corpus = Corpus(args.work)
    build(corpus)
    names = [c["name"] for c in corpus.cases]
    assert len(names) == len(set(names)), "duplicate case names"
    cases = [c for c in corpus.cases if re.search(args.only, c["name"])]
    if args.bench_only:
        cases = [c for c in cases if is_bench(c)]
    if not os.path.exists(os.path.join(os.path.dirname(os.path.abspath(args.plume)), "plume-bench")):
        # a build without benchmarks (the sanitizer run: PLUME_BUILD_BENCHMARKS=OFF) cannot run `plume bench`
        skipped = [c for c in cases if is_bench(c)]
        cases = [c for c in cases if not is_bench(c)]
        print("skipped %d 'plume bench' cases: no plume-bench beside %s" % (len(skipped), args.plume))
    if args.list:
        for c in cases:
            print(c["kind"], c["name"], " ".join(c["args"]))
        return 0
    counts = dict(ok=0, error=0, fail=0, crash=0, hang=0)
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        results = list(pool.map(lambda c: run_case(args.plume, c, args.timeout), cases))
    for case, (outcome, detail, seconds) in zip(cases, results):
        counts[outcome] += 1
        bad = outcome in ("fail", "crash", "hang")
        if bad or args.verbose:
            print("%-6s %-36s %5.1fs %s" % (outcome.upper(), case["name"], seconds, detail.replace("\n", "\n       ")))
    print("bad-input corpus: %d inputs; %d clear errors, %d correct results or warnings; "
          "%d wrong outcomes, %d crashes, %d hangs" %
          (len(cases), counts["error"], counts["ok"], counts["fail"], counts["crash"], counts["hang"]))
    return 1 if counts["fail"] + counts["crash"] + counts["hang"] else 0


if __name__ == "__main__":
    sys.exit(main())
