"""A large polyline part for timing `fixel push` on big outlines
(docs/physics.md, "The part in the engine"): the bundled polygon with its
roof replaced by N exact points on a parabola. Prints the scene JSON.

    /usr/bin/python3 bench/big_outline.py 40000 > /tmp/big.json
"""

import json
import sys
from fractions import Fraction as F


def main():
    if len(sys.argv) != 2 or not sys.argv[1].isdigit() or int(sys.argv[1]) < 1:
        sys.exit("usage: big_outline.py N   (N >= 1 roof points)")
    n = int(sys.argv[1])
    # Roof from (3/2, 1/2) to (-1, 1/2): y = 1/2 + (8/5)(3/2 - x)(x + 1), top (1/4, 3).
    roof = []
    for i in range(1, n + 1):
        x = F(3, 2) - F(5, 2) * F(i, n + 1)
        roof.append([x, F(1, 2) + F(8, 5) * (F(3, 2) - x) * (x + 1)])
    points = [[F(-1), F(-1)], [F(3, 2), F(-1)], [F(3, 2), F(1, 2)]] + roof + [[F(-1), F(1, 2)], [F(-1), F(-1)]]
    scene = {
        "name": f"big{n}",
        "description": f"The bundled polygon with a parabolic roof of {n} points (bench/big_outline.py).",
        "time_step": "1",
        "body": {"dof": 3, "velocity": ["0", "0", "0"],
                 "boundary": [{"type": "polyline", "points": [[str(x), str(y)] for x, y in points]}]},
        "fixels": [
            {"point": ["-1", "0"], "normal": ["1", "0"], "mu": "1/10", "gap": "1/10"},
            {"point": ["-1/2", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/20"},
            {"point": ["1", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "3/20"},
        ],
    }  # fmt: skip
    json.dump(scene, sys.stdout)
    print()


if __name__ == "__main__":
    main()
