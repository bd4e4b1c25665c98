#!/usr/bin/env python3
"""check_pocket_spectrum.py - the pieces of metrics.dambreak_pocket_period on analytic input: the
spectral peak of band_spectrum on a tone of known frequency under a quadratic trend and a tone
outside the band, the band-passed standard deviation (amplitude / sqrt 2), and
closed_pocket_window on a pocket count that closes, opens and closes again. Exit status 1 on a
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
series = {"t": np.arange(7) * 0.02, "pockets": np.array([0, 0, 1, 2, 1, 0, 1])}
t0, t1, snaps = metrics.closed_pocket_window(series)
check((t0, t1, snaps) == (0.04, 0.08, slice(2, 5)), "first pocket from %.2f to %.2f s (snapshots %s)" % (t0, t1, snaps))
check(metrics.closed_pocket_window({"t": series["t"], "pockets": np.zeros(7)}) is None, "no pocket: None")
sys.exit(1 if failed else 0)
