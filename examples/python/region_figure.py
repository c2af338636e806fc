"""The pushing region of the rounded Example 2 part, drawn to a PNG.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/region_figure.py region.png
"""

import pathlib
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no window
import matplotlib.pyplot as plt  # noqa: E402

import fixel  # noqa: E402
import fixel.plot  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "region.png"
scene = fixel.Scene.load(pathlib.Path(__file__).resolve().parents[2] / "data" / "scenes" / "example2_rounded.json")
region = fixel.region(scene, resolution="1/1024", progress=True)
print("counts", region.counts(), "in-length", region.lengths()["in"], f"({region.stats.seconds:.2f} s)")

fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5))
fixel.plot.region(left, scene, region)
left.legend(loc="best")  # "center" would cover the centre-of-mass mark
left.set_title(f"pushing region of {scene.name} (resolution 1/1024)")
fixel.plot.wrench_sphere(right, scene, region)
right.set_title("unit wrench directions; shaded: ray meets S")
fig.tight_layout()
fig.savefig(out, dpi=100)
print("wrote", out)
