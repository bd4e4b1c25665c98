#!/usr/bin/env python3
"""Print the shaken tank's translation law (tests/cases/shaken-tank.yaml: A r(t) sin(2 pi t / T)
with the smooth ramp) as a motion table for --set, rows every DT seconds up to T_END.
Usage: motion_table.py DT T_END"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from check_shaken_tank import tank  # noqa: E402


def main(dt, t_end):
    rows, n = [], int(round(float(t_end) / float(dt)))
    for i in range(n + 1):
        t = i * float(dt)
        rows.append(f"[{t!r}, {tank(t)[0]!r}, 0, 0]")
    print("walls.0.motion={table: [" + ", ".join(rows) + "]}")


if __name__ == "__main__":
    main(*sys.argv[1:])
