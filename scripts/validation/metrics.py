"""Error metrics of the validated cases, computed from a run's own outputs (snapshots, probes.csv,
stats.csv) against the reference stored in the case folder or an analytic solution coded here
with its derivation cited. Every metric returns (error, notes, curves): the error in the unit its
study states, a short text with secondary figures, and the curves the comparison plot draws."""
import glob
import cmath
import math
import os

import h5py
import numpy as np
import yaml

G = 9.81


def snapshots(run):
    """Sorted snapshot paths of a run folder."""
    return sorted(glob.glob(os.path.join(run, "snap_*.h5")))


def snapshot_time(path):
    """The time [s] of a snapshot (its header only)."""
    with h5py.File(path, "r") as f:
        return float(f["header"].attrs["time"])


def spaced(times, gap):
    """Indices of the times (ascending) kept when each must follow the last kept by at least gap:
    a run's final snapshot (written at time.end) can lie just after the last one of its output
    interval, and two nearly equal times would weigh that instant twice in a fit."""
    keep = [0] if len(times) else []
    for k in range(1, len(times)):
        if times[k] - times[keep[-1]] >= gap:
            keep.append(k)
    return np.array(keep, dtype=int)


def read_snapshot(path):
    """Time [s] and the fluid particles (phase >= 0) of a snapshot: dict of arrays."""
    with h5py.File(path, "r") as f:
        t = float(f["header"].attrs["time"])
        phase = f["particles/phase"][:]
        keep = phase >= 0
        data = {k: f["particles/" + k][:][keep] for k in ("position", "velocity", "density", "pressure", "mass")}
    data["phase"] = phase[keep]
    return t, data


def read_config(run):
    """The resolved case of a run (its config.yaml) as a dict."""
    with open(os.path.join(run, "config.yaml")) as f:
        return yaml.safe_load(f)


def read_csv(path):
    """A CSV with a header row as a dict of float columns."""
    with open(path) as f:
        names = f.readline().strip().split(",")
    rows = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {n: rows[:, k] for k, n in enumerate(names)}


def read_reference(path):
    """A reference CSV of ../shared/data layout (# comment block, then a header row)."""
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    names = lines[0].strip().split(",")
    cols = [l.strip().split(",") for l in lines[1:] if l.strip()]
    return {n: np.array([c[k] for c in cols]) for k, n in enumerate(names)}


# --- two-phase hydrostatic tank (paper 000 section 3.1) -------------------------------------

def hydrostatic_exact(y, h_w=1.0, rho_w=1000.0, rho_a=1.0, lid=None, g=G):
    """Pressure of water (0..Hw) under air (Hw..lid, lid = 2Hw unless given) with p = 0 at the
    lid [Pa]; g [m/s^2]."""
    lid = 2 * h_w if lid is None else lid
    return np.where(y >= h_w, rho_a * g * (lid - y), rho_a * g * (lid - h_w) + rho_w * g * (h_w - y))


def background_pressure(run):
    """The background pressure p_b of the first phase from the run's resolved case [Pa]."""
    return float(read_config(run)["phases"][0]["p_background"])


def hydrostatic_centreline(run, dx):
    """Max |p - p_b - p_exact| / (rho_w g Hw) over the particles within dx of x = Hw/2, 2 dx away
    from the bottom and the lid, in the last snapshot (the acceptance of issue 3, notes section
    3.1); p_b the background pressure of the case (paper 001 runs this tank with one)."""
    t, s = read_snapshot(snapshots(run)[-1])
    x, y, p = s["position"][:, 0], s["position"][:, 1], s["pressure"] - background_pressure(run)
    sel = (np.abs(x - 0.5) < dx) & (y > 2 * dx) & (y < 2.0 - 2 * dx)
    err = np.max(np.abs(p[sel] - hydrostatic_exact(y[sel]))) / (1000.0 * G)
    order = np.argsort(y[sel])
    wrong = np.sum((s["phase"] == 0) & (y > 1 + 3 * dx)) + np.sum((s["phase"] == 1) & (y < 1 - 3 * dx))
    notes = "t = %.3g s; %d particles beyond 3dx of the interface" % (t, wrong)
    return err, notes, {"y": y[sel][order], "p": p[sel][order]}


def hydrostatic_1phase(run, dx):
    """Single-phase tank of depth 1 m: max |p - rho g (1 - y)| / (rho g) over the particles within
    dx of x = 0.5, 2 dx away from the bottom and the free surface, in the last snapshot."""
    t, s = read_snapshot(snapshots(run)[-1])
    x, y, p = s["position"][:, 0], s["position"][:, 1], s["pressure"]
    sel = (np.abs(x - 0.5) < dx) & (y > 2 * dx) & (y < 1.0 - 2 * dx)
    err = np.max(np.abs(p[sel] - hydrostatic_exact(y[sel], rho_a=0.0))) / (1000.0 * G)
    order = np.argsort(y[sel])
    return err, "t = %.3g s; %d centreline particles" % (t, sel.sum()), {"y": y[sel][order], "p": p[sel][order]}


# --- oscillating drop (paper 001 section III.B, notes section 3.8) --------------------------

def drop_affine(t_end, rates, omega=1.0, radius=1.0, n=20000):
    """RK4 of the incompressible ellipsoidal drop in the potential 1/2 w^2 r^2, in any dimension d
    (doc/theory.md section 7b): the affine flow u_k = A_k x_k (sum A_k = 0) keeps a ball of radius R
    an ellipsoid with semi-axes a_k, da_k/dt = A_k a_k, dA_k/dt = K / a_k^2 - A_k^2 - w^2,
    K = (sum A_k^2 + d w^2) / sum a_k^-2 (zero pressure on the surface); a_k(0) = R, A_k(0) = rates
    [1/s], n steps to t_end. Returns t, a (n + 1 rows of d) and K, which sets the pressure
    p = (rho/2)(K - sum_k K x_k^2 / a_k^2): centre pressure rho K / 2 for one fluid, K (rho_in +
    3 rho_out) / 8 for a drop of half the radius inside another fluid."""
    def k_factor(a, amp):
        return (np.sum(amp * amp) + len(a) * omega * omega) / np.sum(1 / (a * a))

    def rhs(q):
        a, amp = np.split(q, 2)
        return np.concatenate([amp * a, k_factor(a, amp) / (a * a) - amp * amp - omega * omega])
    dt = t_end / n
    q = np.empty((n + 1, 2 * len(rates)))
    q[0] = np.concatenate([np.full(len(rates), radius), rates])
    for k in range(n):
        k1 = rhs(q[k])
        k2 = rhs(q[k] + 0.5 * dt * k1)
        k3 = rhs(q[k] + 0.5 * dt * k2)
        k4 = rhs(q[k] + dt * k3)
        q[k + 1] = q[k] + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    a, amp = np.split(q, 2, axis=1)
    return np.linspace(0, t_end, n + 1), a, np.array([k_factor(*v) for v in zip(a, amp)])


def drop_analytic(t_end, omega=1.0, radius=1.0, n=20000):
    """The 2D drop of paper 001 (notes section 3.8), drop_affine with A(0) = (w, -w): t, the
    semi-axis a(t) along x and K (for 2D, da/dt = A a, dA/dt = (A^2 + w^2)(b^2 - a^2)/(a^2 + b^2),
    b = R^2/a)."""
    t, a, k_factor = drop_affine(t_end, np.array([omega, -omega]), omega, radius, n)
    return t, a[:, 0], k_factor


def semi_axes(s):
    """Semi-axes [m] of the particles of a snapshot dict s along the coordinate axes, from their
    volume-weighted second moments about their centroid: a_k = sqrt((d + 2) <x_k^2>), exact for
    a uniform ellipsoid in d dimensions aligned with the axes."""
    vol = s["mass"] / s["density"]
    x = s["position"] - np.sum(vol[:, None] * s["position"], axis=0) / vol.sum()
    return np.sqrt((x.shape[1] + 2) * np.sum(vol[:, None] * x * x, axis=0) / vol.sum())


def drop_semi_axis(run, dx, radius=1.0):
    """Max |a_SPH - a| / R over the snapshots; a_SPH the semi-axis along x of the drop (phase 0),
    semi_axes; R the drop's radius [m] (omega = 1)."""
    ts, a_sph = [], []
    for path in snapshots(run):
        t, s = read_snapshot(path)
        inner = s["phase"] == 0
        ts.append(t)
        a_sph.append(semi_axes({k: v[inner] for k, v in s.items()})[0])
    t_ref, a_ref, _ = drop_analytic(max(ts), radius=radius)
    err = np.max(np.abs(np.array(a_sph) - np.interp(ts, t_ref, a_ref))) / radius
    return err, "%d snapshots to t = %.3g s" % (len(ts), max(ts)), {"t": np.array(ts), "a": np.array(a_sph),
                                                                    "t_ref": t_ref, "a_ref": a_ref}


# --- dam break: surge front (Martin and Moyce 1952) -----------------------------------------

def front_position(s, dx, min_neighbours=2):
    """x of the front: the largest x of a water particle with at least min_neighbours other water
    particles within 1.5 dx (a lone spray particle does not count) [m]."""
    x = s["position"][s["phase"] == 0]
    order = np.argsort(-x[:, 0])
    for i in order[:200]:
        d2 = np.sum((x - x[i]) ** 2, axis=1)
        if np.sum(d2 < (1.5 * dx) ** 2) - 1 >= min_neighbours:
            return x[i, 0]
    return x[order[0], 0]


def dambreak_front(run, dx, column_width, reference):
    """RMS over the experimental points of (Z_SPH - Z_exp) / Z_exp, Z = x_front / a at
    T = t sqrt(2 g / a) (Martin and Moyce, n^2 = 2), the SPH front interpolated in T."""
    ts, zs = [], []
    for path in snapshots(run):
        t, s = read_snapshot(path)
        ts.append(t * math.sqrt(2 * G / column_width))
        zs.append(front_position(s, dx) / column_width)
    err, notes, t_exp, z_exp = front_error(ts, zs, reference)
    return err, notes, {"t": np.array(ts), "z": np.array(zs), "t_ref": t_exp, "z_ref": z_exp}


def front_error(ts, zs, reference, t_last=math.inf):
    """RMS over the experimental points with T <= min(t_last, the series' last T) of
    (Z_SPH - Z_exp) / Z_exp, the series (ts, zs: T and Z, T increasing) interpolated in T; with a
    note naming the points, and the reference's T and Z columns. The error is nan when no point
    falls in the window."""
    ref = read_reference(reference)
    t_exp = ref["T_t_sqrt_2g_over_a"].astype(float)
    z_exp = ref["Z_x_over_a"].astype(float)
    use = t_exp <= min(max(ts), t_last)
    if not use.any():
        return math.nan, "no experimental point before T = %.2f" % min(max(ts), t_last), t_exp, z_exp
    z_sph = np.interp(t_exp[use], ts, zs)
    err = math.sqrt(np.mean(((z_sph - z_exp[use]) / z_exp[use]) ** 2))
    notes = "%d experimental points to T = %.2f; Z_SPH - Z_exp at the last: %+.2f" % (
        use.sum(), t_exp[use].max(), z_sph[-1] - z_exp[use][-1])
    return err, notes, t_exp, z_exp


# --- dam break: first impact on the right wall (Buchner 2002, P1) ---------------------------

def first_crossing(t, p, level):
    """First t where p rises through level, linearly interpolated; nan if never."""
    above = np.nonzero(p > level)[0]
    if len(above) == 0:
        return float("nan")
    k = above[0]
    if k == 0:
        return t[0]
    return t[k - 1] + (level - p[k - 1]) * (t[k] - t[k - 1]) / (p[k] - p[k - 1])


def dambreak_impact(run, dx, reference, h=0.6, level=0.1):
    """|t*_SPH - t*_exp| / t*_exp of the first rise of p* = (p - p_b)/(rho g H) at probe p1 through `level`,
    t* = t sqrt(g/H), against Buchner's P1 (digitised). Notes: the peak p* of both up to t* = 3.2."""
    pr = read_csv(os.path.join(run, "probes.csv"))
    ts, ps = pr["time"] * math.sqrt(G / h), (pr["p1"] - background_pressure(run)) / (1000.0 * G * h)
    ref = read_reference(reference)
    p1 = ref["sensor"] == "P1"
    t_exp, p_exp = ref["t_star"][p1].astype(float), ref["p_star"][p1].astype(float)
    arr_sph, arr_exp = first_crossing(ts, ps, level), first_crossing(t_exp, p_exp, level)
    err = abs(arr_sph - arr_exp) / arr_exp
    win = lambda t: (t < 3.2)
    notes = "arrival t* %.3f vs %.3f (experiment); peak p* to t* = 3.2: %.2f vs %.2f" % (
        arr_sph, arr_exp, ps[win(ts)].max(), p_exp[win(t_exp)].max())
    stats_path = os.path.join(run, "stats.csv")
    if os.path.exists(stats_path):
        notes += "; " + volume_drift_text(read_csv(stats_path))
    return err, notes, {"t": ts, "p": ps, "t_ref": t_exp, "p_ref": p_exp}


def volume_drift_text(stats):
    """Max |V/V0 - 1| of each phase's volume column of stats.csv, as text."""
    parts = []
    for name, v in stats.items():
        if name.startswith("volume_"):
            parts.append("%s volume drift %.3f %%" % (name[7:], 100 * np.max(np.abs(v / v[0] - 1))))
    return ", ".join(parts)


def volume_drift(run, dx, phase):
    """Max |V/V0 - 1| of the phase's volume sum m/rho over the run (stats.csv)."""
    st = read_csv(os.path.join(run, "stats.csv"))
    v = st["volume_" + phase]
    return np.max(np.abs(v / v[0] - 1)), volume_drift_text(st), {"t": st["time"], "v": v / v[0] - 1}


def air_regions(s, dx, air=1):
    """The connected regions of the air particles of snapshot data s: air particles on one cell of
    a dx grid, cells joined through their 8 neighbours. Returns a list of (particle indices into s,
    volume sum m/rho [m^3]) sorted by volume, largest (the open air) first."""
    sel = np.nonzero(s["phase"] == air)[0]
    cell = np.floor(s["position"][sel, :2] / dx).astype(np.int64)
    cells = {}
    for k, c in enumerate(map(tuple, cell)):
        cells.setdefault(c, []).append(sel[k])
    label, regions = {}, []
    for start in cells:
        if start in label:
            continue
        label[start], stack, members = len(regions), [start], []
        while stack:
            cx, cy = stack.pop()
            members += cells[(cx, cy)]
            for nb in ((cx + a, cy + b) for a in (-1, 0, 1) for b in (-1, 0, 1)):
                if nb in cells and nb not in label:
                    label[nb] = len(regions)
                    stack.append(nb)
        idx = np.array(members)
        regions.append((idx, float(np.sum(s["mass"][idx] / s["density"][idx]))))
    return sorted(regions, key=lambda r: -r[1])


def dambreak_air_series(run, dx, h=0.6, min_pocket=10):
    """Per snapshot of a two-phase dam break (water phase 0, air phase 1): time [s]; the mean gauge
    pressure of the open air (its largest region, less the case's background) in units of
    rho_w g H; the count of enclosed air pockets (regions of at least min_pocket particles besides
    the open air) and of stray air particles (smaller regions); the largest pocket's volume [m^3]
    and mean pressure [Pa]. Returns a dict of arrays."""
    out = {k: [] for k in ("t", "open_air_p", "pockets", "stray", "pocket_volume", "pocket_p")}
    p_b = background_pressure(run)
    for path in snapshots(run):
        t, s = read_snapshot(path)
        regions = air_regions(s, dx)
        pockets = [r for r in regions[1:] if len(r[0]) >= min_pocket]
        out["t"].append(t)
        out["open_air_p"].append((np.mean(s["pressure"][regions[0][0]]) - p_b) / (1000.0 * G * h))
        out["pockets"].append(len(pockets))
        out["stray"].append(sum(len(r[0]) for r in regions[1:] if len(r[0]) < min_pocket))
        out["pocket_volume"].append(pockets[0][1] if pockets else 0.0)
        out["pocket_p"].append(float(np.mean(s["pressure"][pockets[0][0]]) - p_b) if pockets else float("nan"))
    return {k: np.array(v) for k, v in out.items()}


def closed_pocket_window(series, min_fraction=0.8):
    """First and last time [s] of the first unbroken run of snapshots of a dambreak_air_series in
    which the pocket that closed first is intact (an enclosed pocket whose volume is at least
    min_fraction of its volume at the closure: when it breaks up, the largest fragment is smaller),
    and the snapshots' indices; None when no snapshot has a pocket."""
    k0 = int(np.argmax(series["pockets"] > 0))
    if series["pockets"][k0] == 0:
        return None
    intact = (series["pockets"] > 0) & (series["pocket_volume"] >= min_fraction * series["pocket_volume"][k0])
    k1 = k0
    while k1 + 1 < len(series["t"]) and intact[k1 + 1]:
        k1 += 1
    return series["t"][k0], series["t"][k1], slice(k0, k1 + 1)


def detrended(t, p):
    """p(t) less its quadratic trend, and the median sampling interval of t [s]."""
    return p - np.polyval(np.polyfit(t, p, 2), t), float(np.median(np.diff(t)))


def band_std(t, p, band):
    """Standard deviation [Pa] of p(t) (uniformly sampled, less its quadratic trend) band-passed to
    band = (f_lo, f_hi) [Hz]."""
    q, dt = detrended(t, p)
    f, spectrum = np.fft.rfftfreq(len(t), dt), np.fft.rfft(q)
    spectrum[(f < band[0]) | (f > band[1])] = 0
    return float(np.fft.irfft(spectrum, len(t)).std())


def band_spectrum(t, p, band, pad=16):
    """Amplitude spectrum of p(t) (uniformly sampled) less its quadratic trend, Hann-windowed and
    zero-padded pad times: frequencies [Hz] and amplitudes within band = (f_lo, f_hi), and the
    standard deviation [Pa] of p band-passed to it (band_std)."""
    q, dt = detrended(t, p)
    f = np.fft.rfftfreq(pad * len(t), dt)
    amp = np.abs(np.fft.rfft(q * np.hanning(len(t)), pad * len(t)))
    inside = (f >= band[0]) & (f <= band[1])
    return f[inside], amp[inside], band_std(t, p, band)


POCKET_PERIOD_REF = 0.0578   # [s] the regression value of study dambreak-pocket (cases/dambreak-2phase/README.md)


def pocket_period(series, probes, period_ref, band=(10.0, 40.0)):
    """|T / period_ref - 1| of the air pocket's oscillation in a two-phase dam break: T = 1/f, f the
    spectral peak of probe p1 (probes: probes.csv as read by read_csv) within band [Hz] while the
    first enclosed pocket of series (a dambreak_air_series) is intact (closed_pocket_window). The
    default band holds the 2D gas-cylinder estimate of 17-23 Hz (cases/dambreak-2phase/README.md)
    and at least 4.6 periods of the 0.46 s the pocket lasts at H/dx = 25. Inf when no pocket
    closes. Notes: the pocket's life and volume, and the band-passed p1 against the same length of
    time before it closes."""
    window = closed_pocket_window(series)
    if window is None:
        return math.inf, "no enclosed air pocket in %d snapshots" % len(series["t"]), {}
    t_close, t_open, snaps = window
    during = (probes["time"] >= t_close) & (probes["time"] <= t_open)
    before = (probes["time"] >= 2 * t_close - t_open) & (probes["time"] < t_close)
    f, amp, std_during = band_spectrum(probes["time"][during], probes["p1"][during], band)
    std_before = band_std(probes["time"][before], probes["p1"][before], band)
    f_peak = f[np.argmax(amp)]
    period = 1.0 / f_peak
    notes = ("pocket closed from t = %.2f to %.2f s, %.4f m^3/m; p1 peak at %.1f Hz (%g-%g Hz): T = %.4f s vs "
             "%.4f s; p1 in that band: std %.0f Pa, %.0f Pa before the closure") % (
        t_close, t_open, np.mean(series["pocket_volume"][snaps]), f_peak, band[0], band[1], period,
        period_ref, std_during, std_before)
    return abs(period / period_ref - 1.0), notes, {"f": f, "amp": amp / amp.max(),
                                                   "f_ref": np.array([1.0, 1.0]) / period_ref,
                                                   "amp_ref": np.array([0.0, 1.0])}


def dambreak_pocket_period(run, dx, period_ref=POCKET_PERIOD_REF):
    """pocket_period of a run's snapshots (dambreak_air_series with dx [m]) and probes.csv."""
    return pocket_period(dambreak_air_series(run, dx), read_csv(os.path.join(run, "probes.csv")), period_ref)


# --- Rayleigh-Taylor (He, Chen and Zhang 1999 set-up) ----------------------------------------

def rt_linear_rate(atwood, g, k, nu):
    """Viscous growth-rate estimate sqrt(At g k + nu^2 k^4) - nu k^2 [1/s] (equal kinematic
    viscosities nu; Duff, Harlow and Hirt 1962, the estimate of notes seeds-003-004 C9). At
    nu k^2 / sqrt(At g k) ~ 0.1 it overestimates the exact rate (rt_viscous_rate) by about 9 %."""
    return math.sqrt(atwood * g * k + nu * nu * k ** 4) - nu * k * k


def rt_mode_matrix(n, k, g, rho, nu):
    """Normal-mode conditions at a flat interface y = 0 between fluid 1 (y < 0) and fluid 2 (y > 0),
    rho = (rho1, rho2), nu = (nu1, nu2), gravity -g y, perturbations exp(i k x + n t): in each fluid
    u = grad phi + curl(psi z), phi = A exp(-+k y) (potential, p' = -rho n phi), psi = B exp(+-q y)
    with q^2 = k^2 + n / nu (vortical). Rows: continuity of u and v, of the shear stress
    mu (u_y + v_x) and of the normal stress -p + 2 mu v_y with the hydrostatic jump (rho1 - rho2) g eta,
    eta = v / n; columns A1, B1, A2, B2 (Chandrasekhar 1961, ch. X, derived anew here)."""
    (r1, r2), (n1, n2) = rho, nu
    m1, m2 = r1 * n1, r2 * n2
    q1, q2 = cmath.sqrt(k * k + n / n1), cmath.sqrt(k * k + n / n2)
    j = 1j
    return np.array([
        [j * k, q1, -j * k, q2],
        [k, -j * k, k, j * k],
        [2j * m1 * k * k, m1 * (q1 * q1 + k * k), 2j * m2 * k * k, -m2 * (q2 * q2 + k * k)],
        [(r1 - r2) * g * k / n + r1 * n + 2 * m1 * k * k, -(r1 - r2) * g * j * k / n - 2j * m1 * k * q1,
         -r2 * n - 2 * m2 * k * k, -2j * m2 * k * q2]])


def rt_viscous_rate(k, g, rho, nu):
    """Exact linear growth rate [1/s] of the Rayleigh-Taylor mode k of two viscous fluids (heavy
    rho[1] above light rho[0]): the real root n of det rt_mode_matrix(n) = 0, by Newton's method
    from the estimate rt_linear_rate. Checked in tests/check_rt_dispersion.py against the inviscid
    sqrt(At g k), the viscous limit At g / (2 nu k) and Lamb's gravity-wave damping 2 nu k^2."""
    atwood = (rho[1] - rho[0]) / (rho[1] + rho[0])
    n = complex(rt_linear_rate(atwood, g, k, 0.5 * (nu[0] + nu[1])))
    return newton_root(lambda z: np.linalg.det(rt_mode_matrix(z, k, g, rho, nu)), n).real


def newton_root(f, z, tol=1e-12, steps=100):
    """A root of the analytic function f near z (Newton's method, central-difference derivative)."""
    for _ in range(steps):
        h = 1e-7 * (abs(z) + 1)
        step = f(z) / ((f(z + h) - f(z - h)) / (2 * h))
        z -= step
        if abs(step) < tol * (abs(z) + 1):
            return z
    raise ValueError("no root found near %s" % z)


def rt_mode_amplitude(s, width=1.0):
    """Amplitude a of the interface mode y0 + a sum_d cos(2 pi x_d / W) [m] (d over the horizontal
    axes: x in 2D, x and y in 3D): the light phase's volume projected on the mode,
    a = (2 / W^(dim-1)) sum_light V_i cos(k x_i,d) averaged over d (the integral of cos(k x_d) over
    the light region below the interface; zero for a flat interface on a lattice of whole
    columns). Continuous in the positions, so it resolves sub-dx amplitudes."""
    light = s["phase"] == 1
    vol = s["mass"][light] / s["density"][light]
    horiz = s["position"][light, :-1]
    proj = np.mean(np.cos(2 * math.pi * horiz / width), axis=1)
    return 2.0 / width ** horiz.shape[1] * np.sum(vol * proj)


def rt_tips(s, dx, width=1.0):
    """Spike tip (lowest heavy particle within 1.5 dx of the centre column, x = W/2 in 2D, (W/2, W/2)
    in 3D) and bubble tip (highest light particle within 1.5 dx of the side walls in 2D, of the
    corner columns in 3D) [m]; the last axis is the vertical."""
    pos, ph = s["position"], s["phase"]
    horiz, z = pos[:, :-1], pos[:, -1]
    centre = np.linalg.norm(horiz - 0.5 * width, axis=1) < 1.5 * dx
    edge = np.all((horiz < 1.5 * dx) | (horiz > width - 1.5 * dx), axis=1)
    return z[(ph == 0) & centre].min(), z[(ph == 1) & edge].max()


def rt_series(run, dx):
    """t, mode amplitude, spike and bubble tips of every snapshot."""
    out = []
    for path in snapshots(run):
        t, s = read_snapshot(path)
        out.append((t, rt_mode_amplitude(s)) + rt_tips(s, dx))
    return np.array(out)


def fit_sinh_cosh(t, a, sigma_lo=0.1, sigma_hi=5.0, n=4901):
    """sigma [1/s] of the least-squares fit a(t) = A sinh(sigma t) + B cosh(sigma t), the general
    solution of linear growth from any initial amplitude and rate: A and B linear for each sigma of
    a uniform scan of [sigma_lo, sigma_hi]; returns (sigma, A, B)."""
    best = None
    for sigma in np.linspace(sigma_lo, sigma_hi, n):
        m = np.column_stack([np.sinh(sigma * t), np.cosh(sigma * t)])
        coef = np.linalg.lstsq(m, a, rcond=None)[0]
        res = float(np.sum((m @ coef - a) ** 2))
        if best is None or res < best[0]:
            best = (res, sigma, coef[0], coef[1])
    return best[1:]


def rt_growth(run, dx, t_fit=(0.6, 1.2), rho=(1.0 / 3.0, 1.0), nu=(3.90625e-3, 3.90625e-3), k=2 * math.pi):
    """|sigma_fit - sigma| / sigma for cases/rayleigh-taylor-linear: sigma the exact viscous linear
    growth rate (rt_viscous_rate), sigma_fit from a(t) = A sinh(sigma t) + B cosh(sigma t) fitted
    over t_fit: from 0.6 s, about one e-folding time, when the potential-flow start's vortex sheet
    has adjusted to the viscous mode, to 1.2 s, where a k is about 0.12 (linear regime)."""
    ser = rt_series(run, dx)
    t, a = ser[:, 0], ser[:, 1]
    use = (t >= t_fit[0] - 1e-9) & (t <= t_fit[1] + 1e-9)
    sigma_fit, amp_sinh, amp_cosh = fit_sinh_cosh(t[use], a[use])
    sigma_start = fit_sinh_cosh(t[t <= t_fit[1] + 1e-9], a[t <= t_fit[1] + 1e-9])[0]
    sigma = rt_viscous_rate(k, 1.0, rho, nu)
    atwood = (rho[1] - rho[0]) / (rho[1] + rho[0])
    notes = ("sigma fit %.3f 1/s over %.1f <= t <= %.1f s vs exact viscous %.3f 1/s (estimate sqrt(At g k + "
             "nu^2 k^4) - nu k^2 = %.3f; fit from t = 0: %.3f; a k %.3f at t = %.1f s)" % (
                 sigma_fit, t_fit[0], t_fit[1], sigma, rt_linear_rate(atwood, 1.0, k, nu[1]), sigma_start,
                 a[use][-1] * k, t_fit[1]))
    return abs(sigma_fit - sigma) / sigma, notes, {
        "t": t, "a": a, "sigma": sigma_fit, "sigma_nu": sigma, "t_fit": t_fit, "fit": (amp_sinh, amp_cosh)}


def rt_tip_positions(run, dx, reference):
    """RMS over He et al.'s points (t* <= the run's end) of the spike and bubble tip positions'
    differences, in units of the width W."""
    ser = rt_series(run, dx)
    ref = read_reference(reference)
    t_ref = ref["t_star"].astype(float)
    sp_ref, bu_ref = ref["y_spike_over_H"].astype(float), ref["y_bubble_over_H"].astype(float)
    use = t_ref <= ser[-1, 0]
    sp = np.interp(t_ref[use], ser[:, 0], ser[:, 2])
    bu = np.interp(t_ref[use], ser[:, 0], ser[:, 3])
    diff = np.concatenate([sp - sp_ref[use], bu - bu_ref[use]])
    err = math.sqrt(np.mean(diff ** 2))
    notes = "spike %.3f vs %.3f, bubble %.3f vs %.3f at t* = %.2f" % (
        sp[-1], sp_ref[use][-1], bu[-1], bu_ref[use][-1], t_ref[use][-1])
    return err, notes, {"t": ser[:, 0], "spike": ser[:, 2], "bubble": ser[:, 3], "t_ref": t_ref,
                        "spike_ref": sp_ref, "bubble_ref": bu_ref}


def rt3d_tip_linear(run, dx, t_max=0.5, k=2 * math.pi, level=2.0, a0=0.1):
    """max over the snapshots at t <= t_max of |dz_SPH / dz_lin - 1| for cases/rayleigh-taylor-3d:
    dz = level - z_tip the spike tip's depth below the mean level, dz_lin = a0 cosh(sigma_nu t) the
    linear prediction from rest (notes seeds-003-004 C9, acceptance (a): a0 = 0.1 m, the two 0.05 m
    modes at the centre; sigma_nu = rt_linear_rate with nu_bar = (mu_h + mu_l) / (rho_h + rho_l),
    At, mu and rho from the run's config, g = 1). z_tip is the lowest heavy particle of the centre
    column (rt_tips) less dx / 2, the half spacing its volume reaches below its centre (on the
    initial lattice, the interface to the lattice's rounding)."""
    heavy, light = read_config(run)["phases"][:2]
    rho_h, rho_l = float(heavy["rho0"]), float(light["rho0"])
    atwood = (rho_h - rho_l) / (rho_h + rho_l)
    sigma = rt_linear_rate(atwood, 1.0, k, (float(heavy["viscosity"]) + float(light["viscosity"])) / (rho_h + rho_l))
    ser = rt_series(run, dx)
    t, z_tip = ser[:, 0], ser[:, 2] - 0.5 * dx
    dz, lin = level - z_tip, a0 * np.cosh(sigma * t)
    use = t <= t_max + 1e-9
    rel = dz[use] / lin[use] - 1
    worst = int(np.argmax(np.abs(rel)))
    last = int(np.argmax(t))
    notes = ("At %.2f, sigma_nu %.3f 1/s; worst at t = %.2f s: dz %.4f vs %.4f m; at t = %.2f s dz %.4f m (linear %.4f), "
             "2 x mode amplitude %.4f m; bubble tip %.3f m" % (
                 atwood, sigma, t[use][worst], dz[use][worst], lin[use][worst], t[last], dz[last], lin[last],
                 2 * ser[last, 1], ser[last, 3]))
    return float(np.max(np.abs(rel))), notes, {"t": t, "dz": dz, "mode": 2 * ser[:, 1], "sigma_nu": sigma,
                                               "a0": a0, "t_max": t_max}


# --- two-phase standing wave (paper 003 section 4.2) -----------------------------------------

def standing_wave_linear(k=2 * math.pi, depth=1.0, nu=6.264e-3):
    """Linear standing wave: period T = 2 pi / sigma, sigma^2 = g k tanh(k d), and the energy
    decay rate 4 nu k^2 of a free surface (Lamb 1932, section 348) [s, 1/s]."""
    sigma = math.sqrt(G * k * math.tanh(k * depth))
    return 2 * math.pi / sigma, 4 * nu * k * k


def kinetic_maxima(t, ke, period):
    """Times and values of the water's kinetic-energy maxima of a wave released from rest: the
    largest value of the 5-point running mean within T/8 of each t = T/4 + n T/2, refined by a
    parabola through it and its neighbours."""
    smooth = np.convolve(ke, np.ones(5) / 5, mode="same")
    out = []
    for n in range(int((t[-1] - period / 4) / (period / 2)) + 1):
        centre = period / 4 + n * period / 2
        idx = np.nonzero(np.abs(t - centre) <= period / 8)[0]
        if len(idx) < 5 or idx[-1] >= len(t) - 3:
            break
        k = idx[np.argmax(smooth[idx])]
        y0, y1, y2 = smooth[k - 1], smooth[k], smooth[k + 1]
        shift = 0.5 * (y0 - y2) / (y0 - 2 * y1 + y2) if y0 - 2 * y1 + y2 != 0 else 0.0
        out.append((t[k] + shift * (t[k + 1] - t[k]), y1 - 0.25 * (y0 - y2) * shift))
    return np.array(out)


def standing_wave_series(run):
    """t and the water's kinetic energy from stats.csv, the linear period and decay rate, and the
    kinetic-energy maxima."""
    st = read_csv(os.path.join(run, "stats.csv"))
    period, decay = standing_wave_linear()
    return st["time"], st["kinetic_energy_water"], period, decay, kinetic_maxima(st["time"], st["kinetic_energy_water"], period)


def velocity_l2_at(run, t_target):
    """sqrt(sum |u|^2 / N_w) of the water in the snapshot nearest t_target (003 Eq. 51) [m/s], and
    the snapshot's time."""
    best = min(snapshots(run), key=lambda p: abs(snapshot_time(p) - t_target))
    t, s = read_snapshot(best)
    v = s["velocity"][s["phase"] == 0]
    return math.sqrt(np.sum(v * v) / len(v)), t


def standing_wave_period(run, dx):
    """|T_SPH / T - 1|, T_SPH twice the mean spacing of the kinetic-energy maxima."""
    t, ke, period, decay, peaks = standing_wave_series(run)
    t_sph = 2 * np.mean(np.diff(peaks[:, 0]))
    err_l2, t_l2 = velocity_l2_at(run, period / 2)
    notes = "T = %.4f s vs %.4f s from %d maxima; water velocity L2 at t = %.2f s (motionless): %.4f m/s" % (
        t_sph, period, len(peaks), t_l2, err_l2)
    return abs(t_sph / period - 1), notes, {"t": t, "ke": ke, "peaks": peaks, "period": period, "decay": decay}


def standing_wave_decay(run, dx):
    """|gamma_SPH / gamma - 1|, gamma_SPH the least-squares slope of -ln KE_max over the maxima,
    gamma = 4 nu k^2 (Lamb)."""
    t, ke, period, decay, peaks = standing_wave_series(run)
    gamma = -np.polyfit(peaks[:, 0], np.log(peaks[:, 1]), 1)[0]
    notes = "energy decay rate %.3f 1/s vs %.3f 1/s from %d maxima; first maximum %.2f J/m (linear: %.2f)" % (
        gamma, decay, len(peaks), peaks[0, 1], 1000 * G * 0.05 ** 2 * 2.0 / 4)
    return abs(gamma / decay - 1), notes, {"t": t, "ke": ke, "peaks": peaks, "period": period, "decay": decay}


# --- two-layer sloshing (paper 000 section 3.5) ----------------------------------------------

def tank_displacement(path, x0_left):
    """Horizontal displacement of a moving tank in a snapshot: the leftmost wall ghost's x minus
    its value at t = 0 [m]."""
    with h5py.File(path, "r") as f:
        ph, x = f["particles/phase"][:], f["particles/position"][:, 0]
    return x[ph < 0].min() - x0_left


def tank_frame_snapshots(run):
    """Each snapshot of a run whose tank moves as (time [s], fluid particles (read_snapshot), the
    tank's horizontal displacement [m] (tank_displacement))."""
    paths = snapshots(run)
    with h5py.File(paths[0], "r") as f:
        x0_left = f["particles/position"][:, 0][f["particles/phase"][:] < 0].min()
    for path in paths:
        t, s = read_snapshot(path)
        yield t, s, tank_displacement(path, x0_left)


def column_interface(s, x_gauge, dx, lower=0, base=0.10):
    """Elevation of the top of the lower phase above its rest level `base` at x_gauge: the lower
    phase's volume weighted by a hat function of half-width 2 dx centred on x_gauge, per unit of
    the hat's integral (2 dx), minus base (smooth in the particles' positions) [m]."""
    sel = s["phase"] == lower
    hat = np.clip(1 - np.abs(s["position"][sel, 0] - x_gauge) / (2 * dx), 0, None)
    return np.sum(hat * s["mass"][sel] / s["density"][sel]) / (2 * dx) - base


def dominant_period(t, y, t_from):
    """Twice the mean spacing of the upward and downward mean crossings of y after t_from [s]."""
    keep = t >= t_from
    t, y = t[keep], y[keep] - np.mean(y[keep])
    k = np.nonzero(np.sign(y[1:]) != np.sign(y[:-1]))[0]
    tc = t[k] - y[k] * (t[k + 1] - t[k]) / (y[k + 1] - y[k])
    return 2 * np.mean(np.diff(tc)) if len(tc) > 2 else float("nan")


def sloshing_period(run, dx, period=0.830, gauges=(0.10, 0.47), t_from=1.66):
    """|T_SPH / T - 1| of the interface elevation at gauge WG2 (0.10 m from the left wall, in the
    tank's frame), T_SPH its dominant period after two forcing periods, T the forcing period."""
    rows = [[t] + [column_interface(s, g + shift, dx) for g in gauges] for t, s, shift in tank_frame_snapshots(run)]
    rows = np.array(rows)
    periods = [dominant_period(rows[:, 0], rows[:, 1 + k], t_from) for k in range(len(gauges))]
    notes = "dominant period WG2 %.4f s, WG1 %.4f s (forcing %.3f s); interface amplitude WG2 %.1f mm" % (
        periods[0], periods[1], period, 1000 * np.max(np.abs(rows[rows[:, 0] >= t_from, 1])))
    return abs(periods[0] / period - 1), notes, {"t": rows[:, 0], "wg2": rows[:, 1], "wg1": rows[:, 2]}


# --- rising bubble (Hysing et al. 2009, test case 1) ----------------------------------------

def bubble_phase(case):
    """Index of the bubble's phase in a resolved case: the lightest."""
    return int(np.argmin([p["rho0"] for p in case["phases"]]))


def bubble_moments(s, bubble):
    """Area (volume) sum V [m^2], centroid height y_c [m] and mean rise velocity v_c [m/s] of the
    particles of phase `bubble` in snapshot particles s, with V = m / rho (Hysing et al. 2009)."""
    b = s["phase"] == bubble
    vol = s["mass"][b] / s["density"][b]
    area = vol.sum()
    return area, np.dot(vol, s["position"][b, 1]) / area, np.dot(vol, s["velocity"][b, 1]) / area


def bubble_series(run):
    """Time [s], y_c [m] and v_c [m/s] of the bubble (the lightest phase) in every snapshot."""
    bubble = bubble_phase(read_config(run))
    rows = []
    for path in snapshots(run):
        t, s = read_snapshot(path)
        rows.append((t,) + bubble_moments(s, bubble)[1:])
    return np.array(rows).T


def bubble_curve_errors(t, y_c, v_c, reference):
    """Largest |v_c - v_ref| / max v_ref and |y_c - y_ref| / max v_ref [s] over the digitised points
    of the reference (series v_c and y_c) within the run's times, the run linear between snapshots;
    both relative to the reference's peak rise velocity (y in units of the distance it rises per second)."""
    ref = read_reference(reference)
    series, tr, val = ref["series"], ref["time"].astype(float), ref["value"].astype(float)
    v_peak = val[series == "v_c"].max()
    out = {}
    for name, f in (("v_c", v_c), ("y_c", y_c)):
        use = (series == name) & (tr <= t[-1])
        out[name] = np.max(np.abs(np.interp(tr[use], t, f) - val[use])) / v_peak
        out[name + "_ref"] = (tr[series == name], val[series == name])
    return out


def bubble_rise(run, dx, reference):
    """Rising bubble: max |v_c - v_ref| / max v_ref over the digitised rise-velocity curve."""
    t, y_c, v_c = bubble_series(run)
    e = bubble_curve_errors(t, y_c, v_c, reference)
    notes = "%d snapshots to t = %.3g; y_c(t_end) = %.4f; largest |y_c - y_ref| = %.4f m" % (
        len(t), t[-1], y_c[-1], e["y_c"] * e["v_c_ref"][1].max())
    return e["v_c"], notes, {"t": t, "v": v_c, "y": y_c, "t_ref": e["v_c_ref"][0], "v_ref": e["v_c_ref"][1]}


# --- static bubble (Laplace jump sigma / R in 2D, 2 sigma / R in 3D) ------------------------

def static_bubble_state(path, h):
    """Time [s], equivalent radius of the inner phase (phase 1) [m] (sqrt(sum V / pi) in 2D,
    (3 sum V / (4 pi))^(1/3) in 3D), p_in - p_out [Pa] (mean pressure of the inner phase within
    R - 3h of the centre minus that of the outer phase beyond R + 3h), the largest fluid speed
    [m/s] and the count of particles 3h or more on the other phase's side of R, of one snapshot."""
    t, s = read_snapshot(path)
    inner = s["phase"] == 1
    r = np.linalg.norm(s["position"], axis=1)
    volume = np.sum(s["mass"][inner] / s["density"][inner])
    radius = np.sqrt(volume / np.pi) if s["position"].shape[1] == 2 else np.cbrt(3 * volume / (4 * np.pi))
    core, far = inner & (r < radius - 3 * h), ~inner & (r > radius + 3 * h)
    jump = s["pressure"][core].mean() - s["pressure"][far].mean()
    stray = np.sum(inner & (r >= radius + 3 * h)) + np.sum(~inner & (r <= radius - 3 * h))
    return t, radius, jump, np.linalg.norm(s["velocity"], axis=1).max(), stray


def static_bubble_series(run, t_start=0.01):
    """Rows of static_bubble_state over the snapshots from t_start on, and the Laplace jump times
    R, (d - 1) sigma [N/m] (sigma in 2D, 2 sigma in 3D)."""
    case = read_config(run)
    h = case["resolution"]["dx"] * case["resolution"]["h_over_dx"]
    rows = np.array([static_bubble_state(p, h) for p in snapshots(run)])
    return rows[rows[:, 0] >= t_start - 1e-12], (case["dimension"] - 1) * case["physics"]["surface_tension"]


def laplace_jump(run, dx, t_start=0.01):
    """Static bubble: |<p_in - p_out> / ((d - 1) sigma / <R>) - 1| over the snapshots from t_start
    on (sigma written for (d - 1) sigma below)."""
    rows, sigma = static_bubble_series(run, t_start)
    t, radius, jump, u_max, stray = rows.T
    err = abs(jump.mean() / (sigma / radius.mean()) - 1)
    notes = "%d snapshots from t = %.3g s; p_in - p_out %.3f Pa against sigma/R %.3f Pa; max |u| %.3g m/s; " \
            "stray particles %d" % (len(t), t[0], jump.mean(), sigma / radius.mean(), u_max.max(), stray.max())
    return err, notes, {"t": t, "jump": jump, "t_ref": t, "jump_ref": sigma / radius}


# --- free-fall wedge water entry (Yettou et al. 2006, via Sun et al. 2015) --------------------

def body_heave(run):
    """Time [s] and downward velocity [m/s] of the first body of a run's bodies.csv (its body<W>_vy
    column, y up, negated)."""
    rows = read_csv(os.path.join(run, "bodies.csv"))
    vy = next(name for name in rows if name.endswith("_vy"))
    return rows["time"], -rows[vy]


def reference_curve(ref, source, quantity):
    """Time [ms] and value of one source's quantity in a reference read by read_reference."""
    use = (ref["source"] == source) & (ref["quantity"] == quantity)
    return ref["t_ms"][use].astype(float), ref["value"][use].astype(float)


def wedge_velocity(run, dx, reference, v_entry=5.05, t_to_ms=40.0):
    """Wedge water entry: max |v_SPH - v_exp| / v_entry over the experiment's digitised points from
    first contact (t = 0 of the run) to t_to_ms, the run's velocity (bodies.csv rows) linear in
    time between rows; downward positive. Sun et al.'s SPH curve is compared the same way in the
    notes."""
    t, v = body_heave(run)
    ref = read_reference(reference)
    t_exp, v_exp = reference_curve(ref, "experiment_yettou2006", "velocity_m_per_s")
    t_sph, v_sph = reference_curve(ref, "sun2015_sph_dx2.5mm_NUMERICAL", "velocity_m_per_s")
    use = (t_exp <= t_to_ms) & (t_exp <= 1000 * t[-1] + 1e-9)
    dev = np.interp(t_exp[use], 1000 * t, v) - v_exp[use]
    k = int(np.argmax(np.abs(dev)))
    near = t_sph <= 1000 * t[-1] + 1e-9
    dev_sph = np.max(np.abs(np.interp(t_sph[near], 1000 * t, v) - v_sph[near])) / v_entry
    notes = "%d points to %.1f ms; largest deviation %+.3f m/s at %.1f ms; v(%.1f ms) = %.3f m/s (experiment %.3f); " \
            "max |v - v_Sun2015 SPH| / v_entry %.3f" % (use.sum(), t_exp[use][-1], dev[k], t_exp[use][k],
                                                        t_exp[use][-1], dev[-1] + v_exp[use][-1], v_exp[use][-1],
                                                        dev_sph)
    return np.max(np.abs(dev)) / v_entry, notes, {"t": 1000 * t, "v": v, "t_ref": t_exp, "v_ref": v_exp,
                                                   "t_sph": t_sph, "v_sph": v_sph}


# --- slamming of an LNG insulation panel with dents (paper 000 section 3.3) ------------------

def inside_polygon(points, polygon):
    """Mask of the points (n x 2) strictly inside a closed polygon (k x 2), by ray casting."""
    x, y = points[:, 0:1], points[:, 1:2]
    x0, y0 = polygon[:, 0], polygon[:, 1]
    x1, y1 = np.roll(x0, -1), np.roll(y0, -1)
    crosses = (y0 > y) != (y1 > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        x_cut = x0 + (y - y0) * (x1 - x0) / (y1 - y0)
    return np.sum(crosses & (x < x_cut), axis=1) % 2 == 1


def panel_contact_time(run, gap):
    """Time [s] at which the first body of a run has fallen by gap [m] (bodies.csv, linear
    between rows): the lowest point of the panel, gap above the water at t = 0, reaches the
    undisturbed surface (paper 000's t = 0); nan if it never does."""
    rows = read_csv(os.path.join(run, "bodies.csv"))
    y = next(name for name in rows if name.endswith("_y"))
    drop = rows[y][0] - rows[y]
    if drop[-1] < gap:
        return float("nan")
    return float(np.interp(gap, drop, rows["time"]))


def panel_polygon_at(run, t):
    """The panel (walls.1 polygon, k x 2) of a run moved by its body's displacement at time t [s]."""
    polygon = np.array(read_config(run)["walls"][1]["polygon"], dtype=float)
    rows = read_csv(os.path.join(run, "bodies.csv"))
    y = next(name for name in rows if name.endswith("_y"))
    return polygon + [0.0, np.interp(t, rows["time"], rows[y]) - rows[y][0]]


def depth_inside(points, polygon):
    """Distance [m] of each point to the nearest edge of a closed polygon (k x 2)."""
    a, b = polygon, np.roll(polygon, -1, axis=0)
    depth = np.full(len(points), np.inf)
    for start, edge in zip(a, b - a):
        f = np.clip((points - start) @ edge / (edge @ edge), 0.0, 1.0)
        depth = np.minimum(depth, np.linalg.norm(points - start - f[:, None] * edge, axis=1))
    return depth


def pocket_air(s, polygon, dents):
    """Air particles of snapshot s (read_snapshot) in the pocket between the panel's two dent tips:
    x between the tips' inner edges, y between the higher tip and the face above it, outside the
    panel. dents: indices of the polygon's vertices (left tip's right corner, right tip's left
    corner, a vertex of the face between them)."""
    left, right, face = polygon[list(dents)]
    p = s["position"]
    box = (p[:, 0] > left[0]) & (p[:, 0] < right[0]) & (p[:, 1] > max(left[1], right[1])) & (p[:, 1] < face[1])
    return box & (s["phase"] == 1) & ~inside_polygon(p, polygon)


def stray_count(s, dx, mine, others, k=12):
    """Number of particles of phase `mine` in snapshot s whose neighbours within 1.5 dx (the k
    nearest) are all of the phases `others`, at least three of them: particles carried into
    another phase, the interface penetration paper 000 adds the sharpness force against."""
    from scipy.spatial import cKDTree
    p, phase = s["position"], s["phase"]
    own = np.where(phase == mine)[0]
    dist, idx = cKDTree(p).query(p[own], k=k + 1, distance_upper_bound=1.5 * dx)
    near = np.isfinite(dist[:, 1:])
    foreign = np.zeros_like(near)
    foreign[near] = np.isin(phase[idx[:, 1:][near]], others)
    return int(np.sum((near.sum(axis=1) >= 3) & (foreign.sum(axis=1) == near.sum(axis=1))))


def stray_air(s, dx):
    """Number of air particles (phase 1) of snapshot s among water (phase 0) only (stray_count)."""
    return stray_count(s, dx, 1, (0,))


def panel_snapshot_checks(run, dx, t_peak, dents):
    """Over the snapshots: the fluid particles inside the panel (summed), the deepest of them [dx]
    and the stray air particles (stray_air, summed); and the air particles in the pocket
    (pocket_air) and their mean pressure [Pa] in the snapshot nearest t_peak [s]."""
    inside = stray = 0
    deepest = 0.0
    best = (float("inf"), 0, float("nan"))
    for path in snapshots(run):
        t, s = read_snapshot(path)
        polygon = panel_polygon_at(run, t)
        within = inside_polygon(s["position"], polygon)
        inside += int(within.sum())
        if within.any():
            deepest = max(deepest, float(depth_inside(s["position"][within], polygon).max()) / dx)
        stray += stray_air(s, dx)
        air = pocket_air(s, polygon, dents)
        if abs(t - t_peak) < best[0]:
            best = (abs(t - t_peak), int(air.sum()), float(s["pressure"][air].mean()) if air.any() else float("nan"))
    return {"inside": inside, "deepest": deepest, "stray": stray, "pocket_air": best[1], "pocket_p": best[2]}


def panel_slamming(run, dx, gap=0.02, window=(0.009, 0.014), t_after=0.03, pocket=("p40", "p47"),
                   dents=(3, 6, 5)):
    """The smoke test of notes seeds-000-001 section 3.3, as the number of its four criteria that
    fail: (1) the run reaches t_after [s] after first contact (panel_contact_time with gap [m]);
    (2) the largest pressure of the pocket probes falls in window [s] after contact; (3) an air
    pocket forms: the snapshot nearest that maximum holds air between the dents (pocket_air) at a
    mean pressure of at least half of it; (4) no interpenetration: no fluid particle inside the
    panel and no stray air particle in the water (stray_air) in any snapshot."""
    t0 = panel_contact_time(run, gap)
    probes = read_csv(os.path.join(run, "probes.csv"))
    t = probes["time"] - t0
    peaks = {name: peak_in(t, probes[name], (0, math.inf)) for name in probes if name not in ("step", "time")}
    p_max, t_max = max(peaks[name] for name in pocket)
    c = panel_snapshot_checks(run, dx, t0 + t_max, dents)
    checks = {"completes": t[-1] >= t_after - 1e-9, "window": window[0] <= t_max <= window[1],
              "pocket": c["pocket_air"] > 0 and c["pocket_p"] >= 0.5 * p_max,
              "no interpenetration": c["inside"] + c["stray"] == 0}
    failed = [name for name, ok in checks.items() if not ok]
    notes = "contact at t = %.2f ms; run to %.1f ms after it; pocket peak %.0f kPa at %.2f ms (window %g-%g ms); " \
            "peaks %s; pocket at the peak: %d air particles, mean p %.0f kPa; fluid particles in the panel %d " \
            "(deepest %.2f dx), stray air %d (all snapshots); failed: %s" % (
                1000 * t0, 1000 * t[-1], p_max / 1000, 1000 * t_max, 1000 * window[0], 1000 * window[1],
                ", ".join("%s %.0f kPa at %.2f ms" % (n, v / 1000, 1000 * w) for n, (v, w) in peaks.items()),
                c["pocket_air"], c["pocket_p"] / 1000, c["inside"], c["deepest"], c["stray"],
                ", ".join(failed) or "none")
    curves = {"t": 1000 * t, "window": (1000 * window[0], 1000 * window[1]),
              **{name: probes[name] / 1000 for name in peaks}}
    return float(len(failed)), notes, curves


# --- free-fall wedge with cavity pinch-off (paper 000 section 3.4) ------------------------------

def enclosed_air_near(s, dx, x_axis, half_width, min_pocket=10):
    """The enclosed air regions of snapshot data s (air regions other than the largest, the open
    air) of at least min_pocket particles whose centre lies within half_width of x = x_axis:
    a list of (particle indices, volume [m^3])."""
    found = []
    for idx, vol in air_regions(s, dx)[1:]:
        if len(idx) >= min_pocket and abs(np.mean(s["position"][idx, 0]) - x_axis) <= half_width:
            found.append((idx, vol))
    return found


def peak_in(t, p, window):
    """The largest p with window[0] <= t <= window[1], and its t; (nan, nan) when no sample is in it."""
    use = (t >= window[0]) & (t <= window[1])
    if not use.any():
        return math.nan, math.nan
    k = int(np.argmax(p[use]))
    return float(p[use][k]), float(t[use][k])


def peaks(t, p, t_from, spacing):
    """Local maxima (time, value) of p after t_from that are the largest within +-spacing [s]."""
    out = []
    for k in np.nonzero(t >= t_from)[0]:
        near = np.abs(t - t[k]) <= spacing
        if p[k] == np.max(p[near]) and p[k] > 0:
            out.append((t[k], p[k]))
    return out


def wedge_pinch_off(run, dx, t_ref=0.352, breadth=0.166, t_slam=0.05, t_earliest=0.1):
    """Wedge entry with cavity pinch-off: |t_pinch - t_ref| / t_ref, t_pinch the first snapshot
    after t_earliest with enclosed air over the wedge (an air region besides the open air, its
    centre within breadth/2 of the wedge's axis x = 0). Notes: the slamming peak of p1 (its
    maximum over 0-t_slam), |p2| from t_slam to the pinch-off against it (the air layer rings
    acoustically after the impact: cases/wedge-cavity-wang/README.md), p2's first and second peaks
    after it and their spacing (the cavity's oscillation)."""
    pr = read_csv(os.path.join(run, "probes.csv"))
    t, p1, p2 = pr["time"], pr["p1"], pr["p2"]
    t_pinch = float("nan")
    for path in snapshots(run):
        if snapshot_time(path) < t_earliest:
            continue
        ts, s = read_snapshot(path)
        if enclosed_air_near(s, dx, 0.0, breadth / 2):
            t_pinch = ts
            break
    p1_peak, t1_peak = peak_in(t, p1, (-math.inf, t_slam))
    notes = "p1 slamming peak %.0f Pa at %.1f ms" % (p1_peak, 1000 * t1_peak)
    if not math.isfinite(t_pinch):
        open_cavity = t > t_slam
        if open_cavity.any():
            notes += "; max |p2| over %.2f-%.3f s %.1f %% of it" % (
                t_slam, t[-1], 100 * np.max(np.abs(p2[open_cavity])) / p1_peak)
        notes += "; no pinch-off by t = %.3f s (paper 000: %.3f s)" % (t[-1], t_ref)
        return float("nan"), notes, {"t": t, "p1": p1, "p2": p2, "t_pinch": t_pinch}
    open_cavity = (t > t_slam) & (t < t_pinch)
    notes += "; max |p2| over %.2f s to the pinch-off %.1f %% of it; pinch-off at %.3f s (paper 000: %.3f s)" % (
        t_slam, 100 * np.max(np.abs(p2[open_cavity])) / p1_peak, t_pinch, t_ref)
    top = peaks(t, p2, t_pinch - 0.01, 0.005)[:2]
    if top:
        notes += "; p2 peaks after it: " + ", ".join("%.0f Pa at %.3f s" % (v, tt) for tt, v in top)
    if len(top) == 2:
        notes += " (spacing %.1f ms)" % (1000 * (top[1][0] - top[0][0]))
    return abs(t_pinch - t_ref) / t_ref, notes, {"t": t, "p1": p1, "p2": p2, "t_pinch": t_pinch}


# --- sloshing with an entrapped air pocket (paper 000 section 3.6, after Luo et al. 2016) ---------

POCKET_PROBES = ("p_w2", "p_w3", "p_w1", "p_a1")


def air_phase(config):
    """Index of the gas phase (the lightest) of a resolved case."""
    return int(np.argmin([p["rho0"] for p in config["phases"]]))


def left_tank_air(config, x_split):
    """True when the case puts air left of x_split (variant #1: air over the open tank's water)."""
    air = config["phases"][air_phase(config)]["name"]
    return any(f["phase"] == air and "box" in f and f["box"]["min"][0] < x_split for f in config["fluids"])


def pocket_series(run, x_split):
    """Time [s], volume V = sum m/rho [m^2], reference volume V0 = sum m/rho0 and particle count of
    the air right of x_split in the tank's frame (the closed tank's pocket), per snapshot."""
    config = read_config(run)
    air = air_phase(config)
    rho0 = config["phases"][air]["rho0"]
    rows = []
    for t, s, shift in tank_frame_snapshots(run):
        sel = (s["phase"] == air) & (s["position"][:, 0] - shift > x_split)
        rows.append([t, np.sum(s["mass"][sel] / s["density"][sel]), np.sum(s["mass"][sel]) / rho0, sel.sum()])
    return np.array(rows)


def adiabatic_pressure(config, volume, volume0):
    """The gauge pressure of a gas volume compressed adiabatically from volume0 at p = p_b, by the
    gas phase's equation of state: B [(V0/V)^gamma - 1] + p_b, B = rho0 c0^2 / gamma [Pa]."""
    gas = config["phases"][air_phase(config)]
    bulk = gas["rho0"] * gas["c0"] ** 2 / gas["gamma"]
    return bulk * ((volume0 / volume) ** gas["gamma"] - 1) + gas.get("p_background", 0.0)


def rms_over_range(a, b):
    """RMS of a - b over the range (max - min) of b."""
    return float(np.sqrt(np.mean((a - b) ** 2)) / (np.max(b) - np.min(b)))


def pocket_partner(run, dx, x_split):
    """The probes (read_csv) of the other variant's run beside this one at the same dx that reached
    the latest time (a sibling folder whose name holds _dx<dx>_ and whose case has, or lacks, the
    left tank's air), or None."""
    own = left_tank_air(read_config(run), x_split)
    best = None
    for other in glob.glob(os.path.join(os.path.dirname(os.path.abspath(run)), "*_dx%g_np*" % dx)):
        path = os.path.join(other, "probes.csv")
        if os.path.exists(path) and left_tank_air(read_config(other), x_split) != own:
            probes = read_csv(path)
            if best is None or probes["time"][-1] > best["time"][-1]:
                best = probes
    return best


def air_pocket(run, dx, x_split, window=(5.0, 12.0), rel=0.05, corr=0.9):
    """Sloshing with an entrapped air pocket: the worst of the acceptance errors of notes section
    3.6 that the run allows, each a fraction with the bar `rel`:
    (a) the pocket's air against adiabatic compression: RMS(p_ad - p_a1) / range(p_a1) over the
        snapshots to window[1], p_ad = B [(V0/V)^1.4 - 1] with V = sum m/rho of the air right of
        x_split (tank frame), p_a1 the probe at the snapshot's time;
    (b) p_a1 and p_w1 in phase: (1 - r) / 2 over the window, r their correlation (rel at r = corr
        when rel = (1 - corr) / 2);
    (c) variants #1 and #2 agree: the largest RMS(p_1 - p_2) / range(p_2) of the four probes over
        the window, from the other variant's run at the same dx (pocket_partner).
    (b) and (c) need runs reaching window[1] (not available, n.a., otherwise)."""
    config = read_config(run)
    probes = read_csv(os.path.join(run, "probes.csv"))
    t, t_end = probes["time"], probes["time"][-1]
    pocket = pocket_series(run, x_split)
    upto = pocket[:, 0] <= window[1] + 1e-9
    p_ad = adiabatic_pressure(config, pocket[upto, 1], pocket[upto, 2])
    p_a1 = np.interp(pocket[upto, 0], t, probes["p_a1"])
    errors = {"adiabatic": rms_over_range(p_ad, p_a1)}
    notes = ["adiabatic %.4f (max |p_ad - p_a1| %.1f Pa, p_a1 range %.1f Pa, %d snapshots to %.2f s; pocket "
             "particles %d to %d)" % (errors["adiabatic"], np.max(np.abs(p_ad - p_a1)), np.ptp(p_a1), upto.sum(),
                                      pocket[upto, 0][-1], pocket[:, 3].min(), pocket[:, 3].max())]
    if t_end < window[1] - 1e-9:
        notes.append("phase and variant agreement n.a. (the run ends at %.2f s, before %g s)" % (t_end, window[1]))
    else:
        win = (t >= window[0]) & (t <= window[1] + 1e-9)
        r = float(np.corrcoef(probes["p_a1"][win], probes["p_w1"][win])[0, 1])
        errors["phase"] = (1 - r) / 2 * rel / ((1 - corr) / 2)
        notes.append("phase %.4f (correlation p_a1-p_w1 %.4f over %g-%g s)" % (errors["phase"], r, *window))
        other = pocket_partner(run, dx, x_split)
        if other is None or other["time"][-1] < window[1] - 1e-9:
            notes.append("variant agreement n.a. (no run of the other variant to %g s beside this one)" % window[1])
        else:
            each = {n: rms_over_range(np.interp(t[win], other["time"], other[n]), probes[n][win]) for n in POCKET_PROBES}
            errors["variants"] = max(each.values())
            notes.append("variants %.4f (%s)" % (errors["variants"], ", ".join("%s %.4f" % kv for kv in each.items())))
    err = max(errors.values())
    notes.insert(0, "worst: %s" % max(errors, key=errors.get))
    return err, "; ".join(notes), {"t": t, "p_a1": probes["p_a1"], "p_w1": probes["p_w1"],
                                   "t_snap": pocket[upto, 0], "p_ad": p_ad}


# --- 3D dam break against a box obstacle (Kleefsman et al. 2005, SPHERIC test 2) ------------

KLEEFSMAN_GAUGES = ("H1", "H2", "H3", "H4")


def gauge_difference(probes, ref, gauge, t_to, depth):
    """(H_SPH - H_exp) / depth of one gauge at the reference's samples with t <= t_to, H_SPH the
    probes.csv column linear in time, a dry gauge (nan: no water on its line) read as 0. probes
    and ref: dicts of columns (ref: t_s and NAME_m, as floats)."""
    use = ref["t_s"] <= t_to + 1e-9
    h_sph = np.interp(ref["t_s"][use], probes["time"], np.nan_to_num(probes[gauge], nan=0.0))
    return (h_sph - ref[gauge + "_m"][use]) / depth


def gauge_rms(probes, ref, gauges, t_to, depth):
    """Per gauge, the RMS of gauge_difference; and the number of samples."""
    each = {g: math.sqrt(np.mean(gauge_difference(probes, ref, g, t_to, depth) ** 2)) for g in gauges}
    return each, int((ref["t_s"] <= t_to + 1e-9).sum())


def kleefsman_dambreak(run, dx, reference, depth=0.55, t_to=6.0, impact=(0.3, 0.7)):
    """3D dam break against a box: the RMS over the gauges H1-H4 and the experiment's samples in
    0 to min(t_to, the run's end) of (H_SPH - H_exp) / depth (the column height), each gauge
    weighted by its samples alike. Notes: the RMS of each gauge, and the peak of P1 in the
    window `impact` [s] (the first impact on the box) against the experiment's."""
    probes = read_csv(os.path.join(run, "probes.csv"))
    ref = {k: v.astype(float) for k, v in read_reference(reference).items()}
    t_end = min(t_to, probes["time"][-1])
    each, n = gauge_rms(probes, ref, KLEEFSMAN_GAUGES, t_end, depth)
    err = math.sqrt(np.mean([e ** 2 for e in each.values()]))
    p_sph, t_sph = peak_in(probes["time"], probes["P1"], impact)
    p_exp, t_exp = peak_in(ref["t_s"], ref["P1_Pa"], impact)
    notes = "%d samples per gauge to %.2f s; RMS / H: %s; P1 peak in %g-%g s %.0f Pa at %.3f s (experiment %.0f Pa " \
            "at %.3f s)" % (n, t_end, ", ".join("%s %.4f" % kv for kv in each.items()), *impact, p_sph, t_sph,
                            p_exp, t_exp)
    curves = {"t": probes["time"], "t_ref": ref["t_s"], "P1": probes["P1"], "P1_ref": ref["P1_Pa"]}
    for g in KLEEFSMAN_GAUGES:
        curves[g], curves[g + "_ref"] = probes[g], ref[g + "_m"]
    return err, notes, curves


# --- 3D two-phase dam break, H = 300 mm (Lobovsky et al. 2014; paper 003 section 4.4) --------

# the water-level record of each gauge (the ones TNL-SPH compares with; the file holds a second
# record of H2-H4) and the end, in t* = t sqrt(g/H), of its window before the second jump (the
# returning wave: the record's second rise starts at t* = 7.1, 6.6, 5.5 at H2, H3, H4;
# cases/dambreak-3d-lobovsky/README.md); H1, in the column, has none before t* = 9.6
LOBOVSKY_LEVELS = {"H1": ("h_over_H_H1_2", 7.15), "H2": ("h_over_H_H2_3", 7.0), "H3": ("h_over_H_H3_3", 6.5),
                   "H4": ("h_over_H_H4_4", 5.4)}
LOBOVSKY_SENSORS = {"P1": "p_star_sensor_1", "P2": "p_star_sensor_2", "P3": "p_star_sensor_3",
                    "P4": "p_star_sensor_4"}


def running_mean(t, p, window):
    """p averaged over a centred window of about `window` (an odd number of samples, evenly spaced in t,
    in t's unit), the ends over fewer samples."""
    n = 2 * int(round(window / (2 * np.median(np.diff(t))))) + 1
    kernel = np.ones(n)
    return np.convolve(p, kernel, mode="same") / np.convolve(np.ones_like(p), kernel, mode="same")


def lobovsky_dambreak(run, dx, levels, pressures, depth=0.3, allow=(0.10, 0.30), scored=("P3", "P4"),
                      smooth=0.005, impact_level=0.5):
    """3D two-phase dam break against the downstream wall: the worst of (a) each gauge's largest
    |H_SPH - H_exp| / depth before its second jump (LOBOVSKY_LEVELS; a dry gauge read as 0) over
    allow[0], and (b) |peak_SPH / peak_exp - 1| of the sensors `scored` over allow[1], the peaks of
    p* = (p - p_b) / (rho g depth) after a running mean over `smooth` [s] on both series, in 0 to the
    run's end (at most the record's 1.25 s). 1 is at the limit. Notes: each gauge's largest and
    RMS difference, the peaks and their times of P1-P4, and the first rise of P1 through
    impact_level (the impact on the wall) against the experiment's."""
    probes = read_csv(os.path.join(run, "probes.csv"))
    lev = {k: v.astype(float) for k, v in read_reference(levels).items()}
    prs = {k: v.astype(float) for k, v in read_reference(pressures).items()}
    scale = math.sqrt(G / depth)   # t* = t scale
    t_end = probes["time"][-1]
    ref = {"t_s": lev["t_star"] / scale}
    scores, parts = [], []
    for g, (column, t_star) in LOBOVSKY_LEVELS.items():
        ref[g + "_m"] = lev[column] * depth
        diff = gauge_difference(probes, ref, g, min(t_star / scale, t_end), depth)
        scores.append(np.abs(diff).max() / allow[0])
        parts.append("%s %.3f (%.4f) to t* %.2f" % (g, np.abs(diff).max(), math.sqrt(np.mean(diff ** 2)),
                                                    min(t_star, t_end * scale)))
    t_sph, t_exp = probes["time"] * scale, prs["t_star"]
    p_b = background_pressure(run)
    curves = {"t": t_sph, "t_ref": ref["t_s"] * scale, "t_p_ref": t_exp}
    for s, column in LOBOVSKY_SENSORS.items():
        p_sph = running_mean(t_sph, (probes[s] - p_b) / (1000.0 * G * depth), smooth * scale)
        p_exp = running_mean(t_exp, prs[column], smooth * scale)
        (pk_sph, at_sph), (pk_exp, at_exp) = peak_in(t_sph, p_sph, (0, t_end * scale)), \
            peak_in(t_exp, p_exp, (0, t_end * scale))
        if s in scored:
            scores.append(abs(pk_sph / pk_exp - 1) / allow[1])
        parts.append("%s peak p* %.2f at t* %.2f (exp. %.2f at %.2f)" % (s, pk_sph, at_sph, pk_exp, at_exp))
        curves[s], curves[s + "_ref"] = p_sph, p_exp
    parts.append("P1 through p* %g at t* %.3f (exp. %.3f)" % (
        impact_level, first_crossing(t_sph, curves["P1"], impact_level),
        first_crossing(t_exp, curves["P1_ref"], impact_level)))
    for g in LOBOVSKY_LEVELS:
        curves[g], curves[g + "_ref"] = probes[g] / depth, ref[g + "_m"] / depth
    notes = "to t* %.2f; max (RMS) of |H_SPH - H_exp| / H: %s" % (t_end * scale, "; ".join(parts))
    return max(scores), notes, curves


# --- 3D sloshing at resonance (Liu and Lin 2008 set-up; paper 004 section 4.1.1) -----------

def forced_sloshing_rate(length, amplitude, omega, x_gauge, g=G):
    """Growth rate [m/s] of the linear first-mode elevation envelope at x_gauge in a tank of
    `length` swayed as x = amplitude sin(omega t) at the mode's natural frequency omega, from rest
    (linear potential theory, notes seeds-003-004 C5): eta_1 = (F / 2 omega) [t cos(omega t) -
    sin(omega t) / omega] cos(pi x_gauge / length), F = 4 length amplitude omega^4 / (g pi^2), so
    that the envelope is (2 length amplitude omega^3 / (g pi^2)) cos(pi x_gauge / length) t."""
    return 2 * length * amplitude * omega ** 3 / (g * math.pi ** 2) * math.cos(math.pi * x_gauge / length)


def forced_sloshing_linear(t, rate, omega):
    """The linear resonant elevation rate [t cos(omega t) - sin(omega t) / omega] [m] (its
    envelope rate t; the sign of the phase convention x = A sin(omega t) left open)."""
    return rate * (t * np.cos(omega * t) - np.sin(omega * t) / omega)


def half_period_extrema(t, eta, omega, t_to):
    """(times, values) of the largest |eta| in each window [(n - 1/2), (n + 1/2)] pi / omega,
    n = 1, 2, ..., of the windows that end by t_to: the envelope's samples (the linear resonant
    solution has its extrema at t = n pi / omega exactly)."""
    half = math.pi / omega
    times, values = [], []
    n = 1
    while (n + 0.5) * half <= t_to + 1e-9:
        win = np.nonzero((t >= (n - 0.5) * half) & (t < (n + 0.5) * half))[0]
        if len(win):
            k = win[np.argmax(np.abs(eta[win]))]
            times.append(t[k])
            values.append(abs(eta[k]))
        n += 1
    return np.array(times), np.array(values)


def sloshing_growth(run, dx, gauge="WG", length=0.57, amplitude=0.005, omega=6.0578, x_gauge=0.02, t_to=3.0):
    """3D sloshing at resonance: |r_SPH / r - 1|, r the linear envelope growth rate at the gauge
    (forced_sloshing_rate), r_SPH the least-squares slope through the origin of the gauge's
    half-period extrema of |eta| in 0 to t_to (half_period_extrema), eta the probes.csv elevation
    minus its value at t = 0. Notes: r_SPH, r, the fit's scatter, the largest |eta| and the
    response's period (metrics.dominant_period over the run, against 2 pi / omega)."""
    probes = read_csv(os.path.join(run, "probes.csv"))
    t = probes["time"]
    eta = probes[gauge] - probes[gauge][0]
    rate = forced_sloshing_rate(length, amplitude, omega, x_gauge)
    t_end = min(t_to, t[-1])
    tn, en = half_period_extrema(t, eta, omega, t_end)
    slope = float(np.sum(tn * en) / np.sum(tn ** 2))
    scatter = float(np.sqrt(np.mean((en - slope * tn) ** 2)))
    period = dominant_period(t, eta, 0.0)
    notes = ("envelope rate %.5f m/s against the linear %.5f m/s (%d extrema in 0-%.2f s, RMS about the line %.2f mm); "
             "max |eta| %.1f mm in 0-%.2f s; response period %.4f s (forcing %.4f s)" % (
                 slope, rate, len(tn), t_end, 1000 * scatter, 1000 * np.max(np.abs(eta[t <= t_end + 1e-9])), t_end,
                 period, 2 * math.pi / omega))
    keep = t <= t_end + 1e-9
    return abs(slope / rate - 1), notes, {"t": t[keep], "eta": eta[keep], "t_ext": tn, "ext": en, "rate": rate,
                                          "slope": slope, "omega": omega}


# --- three-liquid sloshing swayed in x and y (paper 004 section 4.1.2) ----------------------

def layered_modes(k, thickness, rho, g=G):
    """Linear potential-flow modes of wavenumber k of liquid layers stacked in a tank with a free
    surface on top (thickness [m] and rho [kg/m^3] bottom first): (omega^2 [1/s^2] per mode,
    shapes V with V[i, r] the displacement of interface i (i = 0 the lowest, the last the free
    surface) in mode r, normalised as V^T M V = 1, d with d_i = rho_i - rho_{i+1}, rho above the
    surface 0). The interfaces' displacements eta obey M eta'' + K eta = -c a d for a horizontal
    tank acceleration a whose x projects as c on the mode: K = g diag(d), and M from each layer's
    potential cosh/sinh k z: M_ii = (rho_i coth k h_i + rho_{i+1} coth k h_{i+1}) / k,
    M_{i,i+1} = -rho_{i+1} / (k sinh k h_{i+1}) (cases/sloshing-3liquid-3d/reference/README.md)."""
    n = len(rho)
    d = np.array([rho[i] - (rho[i + 1] if i + 1 < n else 0.0) for i in range(n)])
    m = np.zeros((n, n))
    for i in range(n):
        m[i, i] = rho[i] / (k * math.tanh(k * thickness[i]))
        if i + 1 < n:
            m[i, i] += rho[i + 1] / (k * math.tanh(k * thickness[i + 1]))
            m[i, i + 1] = m[i + 1, i] = -rho[i + 1] / (k * math.sinh(k * thickness[i + 1]))
    lower_inv = np.linalg.inv(np.linalg.cholesky(m))
    omega2, u = np.linalg.eigh(lower_inv @ (g * np.diag(d)) @ lower_inv.T)
    return omega2, lower_inv.T @ u, d


def forced_response(omega_r, omega, t):
    """(cos(omega t) - cos(omega_r t)) / (omega_r^2 - omega^2): the response from rest of
    q'' + omega_r^2 q = cos(omega t), written so that it stays exact at and near resonance."""
    return (2 * np.sin(0.5 * (omega_r + omega) * t) / (omega_r + omega) *
            0.5 * t * np.sinc((omega_r - omega) * t / (2 * math.pi)))


def layered_sloshing(t, x_gauge, y_gauge, size, thickness, rho, amplitude, omega, n_odd=32, g=G):
    """Linear elevation [m] of every interface (rows bottom first, the free surface last) at a gauge
    fixed in space at (x_gauge, y_gauge), of layers in a tank of size (L, B) at [0, L] x [0, B] at
    t = 0, swayed from rest as x = A (1 - cos(omega_x t)), y = A (1 - cos(omega_y t)) (paper 004
    Eqs. 51-52): the sum over the modes cos(m pi x / L) and cos(m pi y / B), m odd up to 2 n_odd - 1
    (the only ones a sway excites: x - L/2 = sum of c_m cos(m pi x / L), c_m = -4 L / (m pi)^2), of
    layered_modes driven by the tank's acceleration A omega^2 cos(omega t), taken at the gauge's
    position in the tank's frame."""
    eta = np.zeros((len(rho), len(t)))
    for length, w, gauge in ((size[0], omega[0], x_gauge), (size[1], omega[1], y_gauge)):
        in_tank = gauge - amplitude * (1 - np.cos(w * t))
        for m in range(1, 2 * n_odd, 2):
            k = m * math.pi / length
            c_m = -4 * length / (m * math.pi) ** 2
            omega2, shapes, d = layered_modes(k, thickness, rho, g)
            for r, w_r2 in enumerate(omega2):
                q = -c_m * amplitude * w ** 2 * (shapes[:, r] @ d) * forced_response(math.sqrt(w_r2), w, t)
                eta += np.outer(shapes[:, r], q * np.cos(k * in_tank))
    return eta


def sloshing_layers(run, dx, t_to=1.5, size=(1.5, 1.0), thickness=(0.2, 0.2, 0.2), rho=(1300.0, 1000.0, 780.0),
                    amplitude=0.0425, omega=(4.18, 4.14), t_mixed=2.83):
    """Three-liquid sloshing: the largest |r - 1| over the free-surface gauges S1, S2 and the
    water-cyclohexane interface gauges I1, I2, r the least-squares ratio sum(eta eta_lin) /
    sum(eta_lin^2) over 0 to t_to (one forcing period), eta the gauge's probes.csv elevation minus
    its value at t = 0 and eta_lin the linear layered solution at the gauge's position
    (layered_sloshing, the gauge's x and y read from the run's config). r is eta's projection on
    eta_lin: the part of eta along the linear solution (its amplitude and phase), not what the
    linear theory lacks (a crest higher than the trough is deep). Notes: each r, the RMS of
    eta - eta_lin relative to eta_lin's (which includes that), the largest
    |eta| and |eta_lin| in the window, each layer's largest volume drift over the run (integral
    probes DIC, WAT, CYC), the corner gauges' largest |eta| and the particles among the other
    liquids only at t_mixed (layers_mixed)."""
    probes = read_csv(os.path.join(run, "probes.csv"))
    where = {p["name"]: p.get("position") for p in read_config(run)["probes"]}
    t = probes["time"]
    keep = t <= t_to + 1e-9
    ratios, curves, parts = {}, {"t": t[keep]}, []
    for gauge, row in (("S1", 2), ("S2", 2), ("I1", 1), ("I2", 1)):
        eta = (probes[gauge] - probes[gauge][0])[keep]
        lin = layered_sloshing(t[keep], where[gauge][0], where[gauge][1], size, thickness, rho, amplitude, omega)[row]
        ratios[gauge] = float(np.sum(eta * lin) / np.sum(lin ** 2))
        curves[gauge], curves[gauge + "_lin"] = eta, lin
        misfit = float(np.sqrt(np.sum((eta - lin) ** 2) / np.sum(lin ** 2)))
        parts.append("%s r = %.3f (RMS of eta - eta_lin %.0f %% of eta_lin's; max |eta| %.1f mm, linear %.1f mm)" % (
            gauge, ratios[gauge], 100 * misfit, 1000 * np.max(np.abs(eta)), 1000 * np.max(np.abs(lin))))
    drift = [float(np.max(np.abs(probes[p + "_volume"] / probes[p + "_volume"][0] - 1))) for p in ("DIC", "WAT", "CYC")]
    corners = max(float(np.nanmax(np.abs(probes[c] - probes[c][0]))) for c in ("C1", "C2", "C3", "C4"))
    notes = "; ".join(parts) + (" over 0-%.2f s; layer volume drift %.3f / %.3f / %.3f %% (to %.2f s); corner gauges "
                                "max |eta| %.1f mm" % (t_to, *(100 * np.array(drift)), t[-1], 1000 * corners))
    return max(abs(r - 1) for r in ratios.values()), notes + layers_mixed(run, dx, t_mixed), curves


def layers_mixed(run, dx, t_at):
    """A note on the particles of each liquid among the other liquids only (stray_count) in the snapshot
    nearest t_at [s] (the notes' C6 (b): fewer than 0.5 % of all), or '' without snapshots."""
    paths = snapshots(run)
    if not paths:
        return ""
    t, s = read_snapshot(min(paths, key=lambda path: abs(snapshot_time(path) - t_at)))
    counts = [stray_count(s, dx, ph, [o for o in range(3) if o != ph]) for ph in range(3)]
    fluid = int(np.sum(s["phase"] >= 0))
    return "; at t = %.2f s %d / %d / %d particles among the other liquids only, %.3f %% of %d" % (
        t, *counts, 100 * sum(counts) / fluid, fluid)


# --- non-Boussinesq lock exchange (Lowe et al. 2005 set-up; paper 004 section 4.4) -----------

def lock_exchange_fronts(run, dx, vertical, x_lock=0.905, depth=0.2):
    """Rows (t [s], light front x [m], dense front x [m]) of the snapshots of a lock exchange with
    the light phase (phase 0) left of x_lock. A window 2 dx wide slides along x in steps of dx/8:
    the light front is the rightmost window centre where the light phase is at least half of the
    window's particles in the top quarter of the depth (along the lid), the dense front the
    leftmost one where the dense phase is at least half of those in the bottom quarter (along the
    floor). The sliding window keeps the fronts from snapping to a fixed grid of columns. vertical:
    the index of the up axis (dimension - 1)."""
    rows = []
    for path in snapshots(run):
        t, s = read_snapshot(path)
        x, z, light = s["position"][:, 0], s["position"][:, vertical], s["phase"] == 0
        centres = np.arange(x.min(), x.max(), dx / 8)

        def majority(band, mine):
            xs, xm = np.sort(x[band]), np.sort(x[band & mine])
            total = np.searchsorted(xs, centres + dx) - np.searchsorted(xs, centres - dx)
            count = np.searchsorted(xm, centres + dx) - np.searchsorted(xm, centres - dx)
            return centres[(total > 0) & (2 * count >= total)]

        top = majority(z > 0.75 * depth, light)
        bottom = majority(z < 0.25 * depth, ~light)
        rows.append((t, top.max() if len(top) else x_lock, bottom.min() if len(bottom) else x_lock))
    return np.array(rows)


def lock_exchange_front(run, dx, depth=0.2, t_star_fit=1.5, x_lock=0.905):
    """Lock exchange: |Fr_L / 0.5 - 1|, Fr_L = U_L / sqrt(g' H) the light (water) current's front
    speed, U_L the least-squares slope of its front (lock_exchange_fronts) over t* = t sqrt(g'/H) >=
    t_star_fit (after the release's acceleration), g' = g (1 - rho_light / rho_dense) with the two
    phases' rho0 from the run's config. 1/2 is Benjamin's (1968) energy-conserving current of half
    the depth, which the light current of a full-depth lock exchange is in the two-layer theory
    Lowe et al. (2005) retain (cases/lock-exchange-3d/reference/README.md). The snapshots at least
    half an output interval apart (spaced). Notes: Fr_L, the dense front's Fr_D, both fronts'
    distances from the lock at t* = 3 and at the end."""
    config = read_config(run)
    light_phase, dense_phase = config["phases"][:2]
    g_reduced = G * (1 - float(light_phase["rho0"]) / float(dense_phase["rho0"]))
    u_scale, t_scale = math.sqrt(g_reduced * depth), math.sqrt(depth / g_reduced)
    rows = lock_exchange_fronts(run, dx, int(config["dimension"]) - 1, x_lock, depth)
    rows = rows[spaced(rows[:, 0], 0.5 * float(config["output"]["interval"]))]
    t_star, light, dense = rows[:, 0] / t_scale, rows[:, 1] - x_lock, x_lock - rows[:, 2]
    fit = t_star >= t_star_fit
    if np.count_nonzero(fit) < 3:
        return float("nan"), "fewer than 3 snapshots after t* = %.1f" % t_star_fit, None
    fr_light = np.polyfit(rows[fit, 0], light[fit], 1)[0] / u_scale
    fr_dense = np.polyfit(rows[fit, 0], dense[fit], 1)[0] / u_scale
    at3 = int(np.argmin(np.abs(t_star - 3)))
    notes = ("Fr light %.3f, dense %.3f over t* %.1f-%.2f (sqrt(g'H) = %.3f m/s); fronts from the lock at t* %.2f: "
             "light %.3f m, dense %.3f m; at t* %.2f: %.3f m, %.3f m" % (
                 fr_light, fr_dense, t_star_fit, t_star[-1], u_scale, t_star[at3], light[at3], dense[at3],
                 t_star[-1], light[-1], dense[-1]))
    return abs(fr_light / 0.5 - 1), notes, {"t_star": t_star, "light": light, "dense": dense, "fit": fit,
                                              "depth": depth}


# --- elastic gate (Antoci et al. 2007; paper 002 section 4.4 without air) --------------------

GATE_EXPERIMENT = ("experiment_chrono", "experiment_ng2020")
GATE_RECORD = 0.4   # [s]: the record the error covers; its max |u_exp| is the unit of the errors


def gate_points(reference, comp, t_end):
    """The experiment's points (both digitisations) of displacement component comp ("x", "y") in
    [0, t_end]: times [s] and displacements [m]."""
    ref = read_reference(reference)
    t_ref = ref["t_s"].astype(float)
    keep = np.isin(ref["source"], GATE_EXPERIMENT) & (ref["component"] == comp) & (t_ref >= 0) & (t_ref <= t_end)
    return t_ref[keep], ref["disp_m"][keep].astype(float)


def gate_differences(run, reference, t_end):
    """The gate's free-end displacement from solids.csv (the particle nearest the probe; its x sign
    flipped to the sources', positive downstream: the water runs toward -x in the case) and, per
    component x and y, the experiment's points in [0, t_end], u_SPH - u_exp there (u_SPH
    interpolated) and the unit max |u_exp| over [0, GATE_RECORD]. Returns (t, {comp: u_SPH},
    {comp: (t_exp, u_exp, diff, unit)}), or None when solids.csv ends before the last point."""
    s = read_csv(os.path.join(run, "solids.csv"))
    t = s["time"]
    sim = {"x": -s["solid0_ux"], "y": s["solid0_uy"]}
    points = {}
    for comp in ("x", "y"):
        tk, uk = gate_points(reference, comp, t_end)
        if t[-1] < tk.max():
            return None
        unit = np.abs(gate_points(reference, comp, GATE_RECORD)[1]).max()
        points[comp] = (tk, uk, np.interp(tk, t, sim[comp]) - uk, unit)
    return t, sim, points


def gate_early(run, reference, t_max=0.1):
    """Elastic gate, early stage: per component, the largest |u_SPH - u_exp| over the experiment's
    points with t <= t_max, in the unit of gate_differences."""
    got = gate_differences(run, reference, t_max)
    return None if got is None else {comp: np.abs(d).max() / unit for comp, (tk, uk, d, unit) in got[2].items()}


def gate_tip(run, dx, reference):
    """Elastic gate: for the horizontal and the vertical displacement of the gate's free end, the
    RMS of u_SPH - u_exp over the experiment's points in [0, GATE_RECORD] (gate_differences), in
    units of max |u_exp| of that component; the larger of the two."""
    got = gate_differences(run, reference, GATE_RECORD)
    if got is None:
        return float("nan"), "solids.csv ends before the last reference point", None
    t, sim, points = got
    curves, errors, notes = {"t": t, "ux": sim["x"], "uy": sim["y"]}, {}, []
    for comp, (tk, uk, diff, unit) in points.items():
        errors[comp] = math.sqrt(np.mean(diff ** 2)) / unit
        early = tk <= 0.1
        notes.append("u%s: RMS %.3f of max %.4f m, t <= 0.1 s: largest |diff| %.3f; peak %.4f m at %.3f s "
                     "(experiment %.4f m at %.3f s)" % (
                         comp, errors[comp], unit, np.abs(diff[early]).max() / unit, sim[comp].max(),
                         t[np.argmax(sim[comp])], uk.max(), tk[np.argmax(uk)]))
        curves["t_ref_" + comp], curves["u_ref_" + comp] = tk, uk
    return max(errors.values()), "; ".join(notes), curves


# --- elastic plate (Walhorn et al. 2005 benchmark; six codes' curves) -------------------------

def first_peak(t, u, t_max):
    """Largest u and its time over t <= t_max (the first swing of the plate's top)."""
    keep = t <= t_max
    k = int(np.argmax(u[keep]))
    return u[keep][k], t[keep][k]


def plate_peaks(reference, t_max=0.4):
    """The first peak (value [m], time [s]) of each code's curve in the reference, by source."""
    ref = read_reference(reference)
    out = {}
    for src in sorted(set(ref["source"])):
        keep = ref["source"] == src
        out[src] = first_peak(ref["t_s"][keep].astype(float), ref["ux_m"][keep].astype(float), t_max)
    return out


def plate_peak(run, dx, reference, t_max=0.4):
    """Elastic plate: |u_peak / mean - 1| of the first peak of the plate top's horizontal
    displacement (solids.csv, t <= t_max) against the mean of the six codes' first peaks; the
    band the codes span (the largest of their own deviations from that mean) is the threshold."""
    s = read_csv(os.path.join(run, "solids.csv"))
    if s["time"][-1] < t_max:
        return float("nan"), "solids.csv ends at t = %.3g s, before %g s" % (s["time"][-1], t_max), None
    peaks = plate_peaks(reference, t_max)
    values = np.array([v for v, _ in peaks.values()])
    times = np.array([t for _, t in peaks.values()])
    peak, t_peak = first_peak(s["time"], s["solid0_ux"], t_max)
    mean = values.mean()
    notes = ("first peak %.4f m at %.3f s; the six codes %.4f-%.4f m (mean %.4f, band +-%.1f %%) at %.3f-%.3f s" % (
        peak, t_peak, values.min(), values.max(), mean, 100 * np.abs(values / mean - 1).max(), times.min(), times.max()))
    ref = read_reference(reference)
    curves = {"t": s["time"], "u": s["solid0_ux"], "ref": [(src, ref["t_s"][ref["source"] == src].astype(float),
                                                           ref["ux_m"][ref["source"] == src].astype(float))
                                                          for src in peaks]}
    return abs(peak / mean - 1), notes, curves


def plate_band(reference, t_max=0.4):
    """The six codes' band: the largest |u_peak / mean - 1| among them."""
    values = np.array([v for v, _ in plate_peaks(reference, t_max).values()])
    return float(np.abs(values / values.mean() - 1).max())
