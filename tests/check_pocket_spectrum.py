#!/usr/bin/env python3
"""check_pocket_spectrum.py - the pieces of metrics.dambreak_pocket_period on analytic input: the
spectral peak of band_spectrum on a tone of known frequency under a quadratic trend and a tone
outside the band, the band-passed standard deviation (amplitude / sqrt 2), and
closed_pocket_window on a pocket that closes, shrinks (breaks up) or opens, and closes again. Exit status 1 on a
failed check."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts", "validation"))
import metrics  # noqa: E402

failed = 0


def check(ok, what):
    global failed
    print("%s %s" % ("ok  " if ok else "FAIL", what))
    failed += not ok


t = np.arange(1.42, 1.88, 0.0005)
tone_hz, tone_pa = 17.8, 500.0
p = 3000 + 100 * (t - 1.6) ** 2 + tone_pa * np.sin(2 * math.pi * tone_hz * t + 0.3) + 200 * np.sin(2 * math.pi * 68 * t)
f, amp, std = metrics.band_spectrum(t, p, (5.0, 40.0))
peak = f[np.argmax(amp)]
check(abs(peak - tone_hz) < 0.2, "peak %.2f Hz vs the tone's %.2f Hz" % (peak, tone_hz))
check(f.min() >= 5.0 and f.max() <= 40.0, "frequencies within the band: %.2f-%.2f Hz" % (f.min(), f.max()))
check(abs(std / (tone_pa / math.sqrt(2)) - 1) < 0.1, "band-passed std %.1f Pa vs %.1f Pa" % (std, tone_pa / math.sqrt(2)))
series = {"t": np.arange(8) * 0.02, "pockets": np.array([0, 0, 1, 2, 1, 0, 1, 1]),
          "pocket_volume": np.array([0, 0, 0.03, 0.033, 0.02, 0, 0.03, 0.03])}
t0, t1, snaps = metrics.closed_pocket_window(series)
check((t0, t1, snaps) == (0.04, 0.06, slice(2, 4)),
      "first pocket intact from %.2f to %.2f s (snapshots %s): it shrinks below 0.8 of 0.03 m^3 at 0.08 s" % (t0, t1, snaps))
series["pocket_volume"][4] = 0.029
t0, t1, snaps = metrics.closed_pocket_window(series)
check((t0, t1, snaps) == (0.04, 0.08, slice(2, 5)), "kept to %.2f s while at 0.97 of its volume, ended by the opening" % t1)
check(metrics.closed_pocket_window({"t": series["t"], "pockets": np.zeros(8), "pocket_volume": np.zeros(8)}) is None,
      "no pocket: None")
sys.exit(1 if failed else 0)
