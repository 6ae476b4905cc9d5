"""Measures what a rendered PNG shows against its background and checks it.

    check_drawn_pixels.py IMAGE.png [--drawn-min F] [--drawn-max F]
                                    [--height-min F] [--height-max F]

A pixel is drawn when any channel differs from the background (the colour of
the top-left pixel) by more than 16 levels. Printed and checked:
  drawn    the fraction of the picture's pixels that are drawn;
  height   the fraction of the picture's rows between the lowest and the
           highest row holding at least 1 % of the drawn pixels (a column
           rising through the picture is tall, a slab on a floor is low).
Exit 0 when every given bound holds, 1 otherwise.
"""
import argparse
import sys

import vtk


def measure(path):
    reader = vtk.vtkPNGReader()
    if not reader.CanReadFile(path):
        sys.exit("cannot read PNG '%s'" % path)
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    comps = min(3, scalars.GetNumberOfComponents())
    background = [scalars.GetComponent(w * (h - 1), c) for c in range(comps)]  # VTK rows run bottom-up
    rows = [0] * h
    drawn = 0
    for y in range(h):
        for x in range(w):
            i = x + w * y
            if any(abs(scalars.GetComponent(i, c) - background[c]) > 16 for c in range(comps)):
                rows[y] += 1
                drawn += 1
    if drawn == 0:
        return 0.0, 0.0
    busy = [y for y in range(h) if rows[y] >= 0.01 * drawn]
    return drawn / float(w * h), (max(busy) - min(busy) + 1) / float(h)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("image")
    for bound in ("drawn-min", "drawn-max", "height-min", "height-max"):
        parser.add_argument("--" + bound, type=float)
    args = parser.parse_args()
    drawn, height = measure(args.image)
    print("%s: drawn %.4f of the pixels, height %.3f of the rows" % (args.image, drawn, height))
    failed = []
    for name, value in (("drawn", drawn), ("height", height)):
        low, high = getattr(args, name + "_min"), getattr(args, name + "_max")
        if low is not None and value < low:
            failed.append("%s %.4f < %g" % (name, value, low))
        if high is not None and value > high:
            failed.append("%s %.4f > %g" % (name, value, high))
    if failed:
        print("FAILED: " + "; ".join(failed))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
