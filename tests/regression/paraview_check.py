"""Opens a Coulomb result of xml/block_compression.xml in ParaView and checks
what a user sees there (run by pvpython from tests/regression/paraview.cmake).

usage: pvpython paraview_check.py RESULT.e

Checks, on the last time step: 729 points and 512 cells (8x8x8 HEX8), 4 time
steps, a 3-component point array for displacement (ParaView's Exodus reader
groups displacement_x/_y/_z into one vector), point arrays von_mises and
stress_zz, and stress_zz = -100 everywhere (uniaxial stress p = 100) to 1e-6
relative. Exit code 0 when all hold, 1 otherwise (every failed check printed).
"""
import os
import sys

from paraview.simple import ExodusIIReader

EXPECTED_POINTS = 729
EXPECTED_CELLS = 512
EXPECTED_TIME_STEPS = 4
EXPECTED_STRESS_ZZ = -100.0
RELATIVE_TOLERANCE = 1e-6

failures = []


def check(condition, message):
    print(("ok:     " if condition else "FAILED: ") + message)
    if not condition:
        failures.append(message)
    return condition


def main(path):
    if not check(os.path.isfile(path), "result file %s exists" % path):
        return
    reader = ExodusIIReader(FileName=[path])
    available = list(reader.PointVariables.Available)
    print("point variables in the file (as ParaView names them): %s" % available)
    reader.PointVariables = available
    times = list(reader.TimestepValues)
    print("time steps: %s" % times)
    check(len(times) == EXPECTED_TIME_STEPS, "%d time steps (got %d)" % (EXPECTED_TIME_STEPS, len(times)))
    if not times:
        return
    last = times[-1]
    reader.UpdatePipeline(time=last)

    info = reader.GetDataInformation()
    check(info.GetNumberOfPoints() == EXPECTED_POINTS,
          "%d points (got %d)" % (EXPECTED_POINTS, info.GetNumberOfPoints()))
    check(info.GetNumberOfCells() == EXPECTED_CELLS,
          "%d cells (got %d)" % (EXPECTED_CELLS, info.GetNumberOfCells()))

    point_data = reader.PointData
    names = list(point_data.keys())
    print("point arrays at t = %g: %s" % (last, names))
    for name in names:
        array = point_data[name]
        print("  %-16s %d component(s), range %s" % (name, array.GetNumberOfComponents(), array.GetRange(-1)))

    # ParaView 5.11 names the grouped vector "displacement_" (it keeps the
    # separator); other versions may call it "displacement". Either is the
    # vector; three separate scalars are not.
    vector = [n for n in ("displacement", "displacement_") if n in names]
    if check(len(vector) == 1, "one displacement vector array (displacement or displacement_)"):
        components = point_data[vector[0]].GetNumberOfComponents()
        check(components == 3, "'%s' has 3 components (got %d)" % (vector[0], components))
    check("displacement_x" not in names, "displacement_x is grouped into the vector, not a separate array")

    check("von_mises" in names, "point array von_mises exists")
    if check("stress_zz" in names, "point array stress_zz exists"):
        low, high = point_data["stress_zz"].GetRange(0)
        tolerance = RELATIVE_TOLERANCE * abs(EXPECTED_STRESS_ZZ)
        check(abs(low - EXPECTED_STRESS_ZZ) <= tolerance and abs(high - EXPECTED_STRESS_ZZ) <= tolerance,
              "stress_zz range [%.12g, %.12g] within %g relative of %g at t = %g"
              % (low, high, RELATIVE_TOLERANCE, EXPECTED_STRESS_ZZ, last))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: pvpython paraview_check.py RESULT.e")
        sys.exit(2)
    main(sys.argv[1])
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("PASS")
    sys.exit(0)
