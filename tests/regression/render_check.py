"""Checks the pictures scripts/render wrote for a contact result.

usage: render_check.py RESULT.e [--size WxH]

For RESULT.e (pictures next to it, RESULT_*.png and RESULT_render.json):
  - RESULT_pressure.png, _state.png, _qp.png, _pressure_line.png are PNG
    files of more than 5 kB that show something: more than 50 distinct
    colours and more than 1 % of the pixels off the white background
    (the ParaView ones at the --size asked for);
  - the pressure picture's colour-bar limits (ParaView's lookup table, as
    render_paraview.py wrote them into RESULT_render.json) equal the
    minimum and the maximum of contact_pressure over all nodes at the last
    step, read here from the file with netCDF4, to 1e-9 of the maximum; the
    maximum is positive (the run had contact).
Exit code 0 when all hold, 1 otherwise (every failed check printed).
"""
import json
import os
import sys

import matplotlib.image
import netCDF4
import numpy

failures = []


def check(condition, message):
    print(("ok:     " if condition else "FAILED: ") + message)
    if not condition:
        failures.append(message)
    return condition


def pressure_range(path):
    with netCDF4.Dataset(path) as d:
        d.set_auto_mask(False)
        names = [str(n).strip() for n in netCDF4.chartostring(d.variables["name_nod_var"][:])]
        values = d.variables["vals_nod_var%d" % (names.index("contact_pressure") + 1)][-1, :]
    return float(numpy.min(values)), float(numpy.max(values))


def check_png(path, size=None):
    if not check(os.path.isfile(path), "%s exists" % path):
        return
    with open(path, "rb") as f:
        check(f.read(8) == b"\x89PNG\r\n\x1a\n", "%s is a PNG file" % os.path.basename(path))
    check(os.path.getsize(path) > 5000, "%s has %d bytes (> 5000)" % (os.path.basename(path), os.path.getsize(path)))
    image = matplotlib.image.imread(path)[:, :, :3]
    if size:
        check(image.shape[1] == size[0] and image.shape[0] == size[1],
              "%s is %dx%d (got %dx%d)" % (os.path.basename(path), size[0], size[1], image.shape[1], image.shape[0]))
    colours = len(numpy.unique((image * 255).astype(numpy.uint8).reshape(-1, 3), axis=0))
    check(colours > 50, "%s shows %d distinct colours (> 50)" % (os.path.basename(path), colours))
    drawn = float(numpy.mean(numpy.any(image < 0.95, axis=2)))
    check(drawn > 0.01, "%s: %.1f %% of the pixels off the background (> 1 %%)" % (os.path.basename(path), 100 * drawn))


def main(argv):
    result = argv[1]
    size = None
    if len(argv) == 4 and argv[2] == "--size":
        size = tuple(int(v) for v in argv[3].split("x"))
    prefix = result[:-2] if result.endswith(".e") else result
    for suffix in ("_pressure.png", "_state.png"):
        check_png(prefix + suffix, size)
    for suffix in ("_qp.png", "_pressure_line.png"):
        check_png(prefix + suffix)
    with open(prefix + "_render.json") as f:
        report = json.load(f)
    picture = report["pictures"]["pressure"]
    check(picture["field"] == "contact_pressure", "the pressure picture is coloured by contact_pressure (%s)"
          % picture["field"])
    low, high = pressure_range(result)
    check(high > 0, "contact_pressure at the last step peaks above 0 (%g)" % high)
    tolerance = 1e-9 * max(abs(high), 1e-300)
    lut_low, lut_high = picture["range"]
    check(abs(lut_low - low) <= tolerance and abs(lut_high - high) <= tolerance,
          "colour bar [%.10g, %.10g] = contact_pressure range [%.10g, %.10g] in the file" % (lut_low, lut_high, low, high))
    print("PASS" if not failures else "%d check(s) failed" % len(failures))
    return 0 if not failures else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
