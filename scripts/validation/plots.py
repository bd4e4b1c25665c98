"""The comparison plots of the validation studies: each draws every rung's curve (from the
metric's curves) and the reference on one axis. items: list of (rung, curves)."""
import numpy as np

from . import metrics


def _label(r):
    return "%s, dx = %g" % (r["label"], r["dx"])


def _runs_and_reference(ax, items, keys, ref_keys, style, ref_style, ref_label, axes=None):
    """Each rung's curve c[keys[0]], c[keys[1]] and the reference curve of the last rung; axes, when
    given, the (x, y) axis labels."""
    for r, c in items:
        ax.plot(c[keys[0]], c[keys[1]], style, ms=3, lw=0.8, label=_label(r))
    if items:
        c = items[-1][1]
        ax.plot(c[ref_keys[0]], c[ref_keys[1]], ref_style, ms=4, lw=0.8, label=ref_label)
    if axes:
        ax.set_xlabel(axes[0])
        ax.set_ylabel(axes[1])


def _centreline(ax, items, top, rho_a):
    """Centreline pressure against height of every rung, with the exact profile to y = top (air of
    density rho_a above Hw = 1 m)."""
    for r, c in items:
        ax.plot(c["p"] / 1000.0, c["y"], ".", ms=3, label=_label(r))
    y = np.linspace(0, top, 200)
    ax.plot(metrics.hydrostatic_exact(y, rho_a=rho_a) / 1000.0, y, "k-", lw=0.8, label="exact")
    ax.set_xlabel("p [kPa]")
    ax.set_ylabel("y [m]")


def hydrostatic(ax, items):
    """Centreline pressure against height in the two-phase tank, with the exact profile."""
    _centreline(ax, items, 2.0, 1.0)


def drop(ax, items):
    """Semi-axis a(t) against the analytic solution."""
    _runs_and_reference(ax, items, ("t", "a"), ("t_ref", "a_ref"), "o-", "k-", "analytic")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("a [m]")


def front(ax, items):
    """Surge front Z = x/a against T = t sqrt(2g/a), with Martin and Moyce's table."""
    _runs_and_reference(ax, items, ("t", "z"), ("t_ref", "z_ref"), "-", "ks", "Martin & Moyce 1952")
    ax.set_xlabel("T = t sqrt(2g/a)")
    ax.set_ylabel("Z = x_front / a")


def impact(ax, items):
    """p* at probe p1 against t*, with Buchner's P1."""
    _runs_and_reference(ax, items, ("t", "p"), ("t_ref", "p_ref"), "-", "k.", "Buchner 2002 P1")
    ax.set_xlim(1.5, 3.4)
    ax.set_ylim(-0.2, 2.0)
    ax.set_xlabel("t* = t sqrt(g/H)")
    ax.set_ylabel("p* = p / (rho g H)")


def pocket(ax, items):
    """Amplitude spectrum of p1 while the air pocket is closed, with the regression period."""
    _runs_and_reference(ax, items, ("f", "amp"), ("f_ref", "amp_ref"), "-", "k--", "regression value",
                        axes=("f [Hz]", "p1 amplitude / its peak"))


def rt_growth(ax, items):
    """Mode amplitude a(t) of each run with its fit, and the linear theory's growth from the finest
    run's initial rate, a'(0) sinh(sigma_nu t) / sigma_nu."""
    for r, c in items:
        line = ax.plot(c["t"], c["a"], "o", ms=3, label=_label(r))[0]
        t = np.linspace(0, c["t_fit"], 100)
        ax.plot(t, c["fit"][0] * np.sinh(c["sigma"] * t) + c["fit"][1] * np.cosh(c["sigma"] * t), "-",
                lw=0.8, color=line.get_color())
    if items:
        c = items[-1][1]
        rate0 = c["fit"][0] * c["sigma"]
        t = np.linspace(0, c["t"].max(), 100)
        ax.plot(t, rate0 * np.sinh(c["sigma_nu"] * t) / c["sigma_nu"], "k--", lw=0.8,
                label="exact viscous rate %.3f 1/s, from the fit's initial rate" % c["sigma_nu"])
    ax.set_xlabel("t [s]")
    ax.set_ylabel("mode amplitude a [m]")


def rt_tips(ax, items):
    """Spike and bubble tips against He et al. 1999."""
    for r, c in items:
        line = ax.plot(c["t"], c["spike"], "-", label=_label(r))[0]
        ax.plot(c["t"], c["bubble"], "-", color=line.get_color())
    if items:
        c = items[-1][1]
        ax.plot(c["t_ref"], c["spike_ref"], "k.", ms=4, label="He et al. 1999 (LBM)")
        ax.plot(c["t_ref"], c["bubble_ref"], "k.", ms=4)
    ax.set_xlabel("t* = t sqrt(g/W)")
    ax.set_ylabel("tip height / W")


def rt3d_tip(ax, items):
    """3D spike-tip depth below the mean level and twice the mode amplitude of each run against its
    own linear prediction a0 cosh(sigma_nu t) (dashed), with the +-25 % band over the compared
    window (dotted)."""
    for r, c in items:
        line = ax.plot(c["t"], c["dz"], "o-", ms=3, lw=0.8, label=_label(r) + ", tip")[0]
        ax.plot(c["t"], c["mode"], "x", ms=3, color=line.get_color(), label=_label(r) + ", 2 x mode amplitude")
        t = np.linspace(0, c["t"].max(), 100)
        lin = c["a0"] * np.cosh(c["sigma_nu"] * t)
        ax.plot(t, lin, "--", lw=0.8, color=line.get_color(), label="linear, sigma_nu = %.3f 1/s" % c["sigma_nu"])
        win = t <= c["t_max"]
        for f in (0.75, 1.25):
            ax.plot(t[win], f * lin[win], ":", lw=0.6, color=line.get_color())
    ax.set_xlabel("t [s]")
    ax.set_ylabel("depth below z = 2 m [m]")


def standing_wave(ax, items):
    """The water's kinetic energy against the linear solution E0 exp(-4 nu k^2 t) sin^2(sigma t)."""
    for r, c in items:
        line = ax.plot(c["t"], c["ke"], "-", lw=0.8, label=_label(r))[0]
        ax.plot(c["peaks"][:, 0], c["peaks"][:, 1], "o", ms=3, color=line.get_color())
    if items:
        c = items[-1][1]
        t = np.linspace(0, c["t"].max(), 600)
        e0 = 1000 * 9.81 * 0.05 ** 2 * 2.0 / 4
        ax.plot(t, e0 * np.exp(-c["decay"] * t) * np.sin(2 * np.pi * t / c["period"]) ** 2, "k-", lw=0.6,
                label="linear (Lamb)")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("kinetic energy of the water [J/m]")


def sloshing(ax, items):
    """Interface elevation at WG2 (solid) and WG1 (dashed) in the tank's frame."""
    for r, c in items:
        line = ax.plot(c["t"], 1000 * c["wg2"], "-", lw=0.8, label=_label(r) + ", WG2")[0]
        ax.plot(c["t"], 1000 * c["wg1"], "--", lw=0.8, color=line.get_color())
    ax.set_xlabel("t [s]")
    ax.set_ylabel("interface elevation [mm]")


def bubble(ax, items):
    """Mean rise velocity of the bubble against time, with the digitised benchmark curve."""
    _runs_and_reference(ax, items, ("t", "v"), ("t_ref", "v_ref"), "-", "ks", "Hysing et al. 2009 (digitised)",
                        ("t", "mean rise velocity v_c"))


def laplace(ax, items):
    """Pressure jump p_in - p_out of the static bubble against time, with sigma / R."""
    _runs_and_reference(ax, items, ("t", "jump"), ("t_ref", "jump_ref"), ".-", "k-", "sigma / R",
                        ("t [s]", "p_in - p_out [Pa]"))


def hydrostatic_1phase(ax, items):
    """Centreline pressure against height in the single-phase tank, with rho g (H - y)."""
    _centreline(ax, items, 1.0, 0.0)


def wedge(ax, items):
    """Downward velocity of the wedge against time from first contact, with Yettou et al.'s
    experiment and Sun et al.'s SPH (dashed)."""
    _runs_and_reference(ax, items, ("t", "v"), ("t_ref", "v_ref"), "-", "ks", "Yettou et al. 2006 (experiment)",
                        ("t [ms] from first contact", "downward velocity [m/s]"))
    if items:
        c = items[-1][1]
        ax.plot(c["t_sph"], c["v_sph"], "k--", lw=0.8, label="Sun et al. 2015 SPH, dx = 2.5 mm")


def panel(ax, items):
    """Pressure at the pocket probes 40 (solid) and 47 (dashed) against time from first contact,
    with the window of the pocket's pressure maximum (paper 000) shaded."""
    for r, c in items:
        line, = ax.plot(c["t"], c["p40"], "-", lw=0.8, label=_label(r) + " (p40; p47 dashed)")
        ax.plot(c["t"], c["p47"], "--", lw=0.8, color=line.get_color())
    if items:
        ax.axvspan(*items[-1][1]["window"], color="0.85", label="pocket peak window (paper 000)")
    ax.set_xlabel("t [ms] from first contact")
    ax.set_ylabel("pressure [kPa]")


def wedge_cavity(ax, items):
    """Pressures p1 (wetted face, solid) and p2 (top face, facing the cavity, dashed) on the wedge
    against time, the pinch-off marked, with paper 000's pinch-off time."""
    for r, c in items:
        line = ax.plot(c["t"], c["p1"], "-", lw=0.8, label=_label(r) + ", p1")[0]
        ax.plot(c["t"], c["p2"], "--", lw=0.8, color=line.get_color(), label=_label(r) + ", p2")
        if np.isfinite(c["t_pinch"]):
            ax.axvline(c["t_pinch"], color=line.get_color(), lw=0.5)
    ax.axvline(0.352, color="k", lw=0.6, ls=":", label="paper 000 pinch-off (0.352 s)")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("pressure [Pa]")


def air_pocket(ax, items):
    """Pressure of the entrapped pocket at p_a1 (solid) and that of adiabatic compression of its
    air's volume at the snapshots (dots), and the water pressure p_w1 beside it (dashed)."""
    for r, c in items:
        line = ax.plot(c["t"], c["p_a1"], "-", lw=0.8, label=_label(r) + ", p_a1")[0]
        ax.plot(c["t_snap"], c["p_ad"], ".", ms=3, color=line.get_color())
        ax.plot(c["t"], c["p_w1"], "--", lw=0.6, color=line.get_color())
    ax.set_xlabel("t [s]")
    ax.set_ylabel("p [Pa] (dots: adiabatic from volume)")


def _gauge_heights(ax, items, ref_label, axes, t_default):
    """Water heights at the gauges H1-H4 against time, each rung in its colour (H1 solid, H2
    dashed, H3 dash-dotted, H4 dotted), with the reference in the same styles in black; axes the
    (x, y) axis labels, t_default the x range without runs."""
    styles = dict(zip(metrics.KLEEFSMAN_GAUGES, ("-", "--", "-.", ":")))
    for r, c in items:
        color = None
        for g, ls in styles.items():
            color = ax.plot(c["t"], c[g], ls, lw=0.8, color=color, label=_label(r) if g == "H1" else None)[0].get_color()
    if items:
        c = items[-1][1]
        for g, ls in styles.items():
            ax.plot(c["t_ref"], c[g + "_ref"], ls, lw=0.5, color="k", label=ref_label if g == "H1" else None)
    ax.set_xlim(0, max(c["t"][-1] for _, c in items) if items else t_default)
    ax.set_xlabel(axes[0])
    ax.set_ylabel(axes[1] + " (H1 -, H2 --, H3 -., H4 :)")


def kleefsman(ax, items):
    """The water heights of the 3D dam break against a box (Kleefsman et al. 2005)."""
    _gauge_heights(ax, items, "Kleefsman et al. 2005 (H1-H4)", ("t [s]", "water height [m]"), 6.0)


def lobovsky(ax, items):
    """The water levels of the 3D two-phase dam break (Lobovsky et al. 2014), h/H against t sqrt(g/H)."""
    _gauge_heights(ax, items, "Lobovsky et al. 2014 (H1-H4)", ("t sqrt(g/H)", "h / H"), 7.15)


def forced_sloshing(ax, items):
    """The gauge elevation of the resonant 3D sloshing with its half-period extrema (dots), against
    the linear resonant solution's envelope +-r t (black) and its signal (grey)."""
    for r, c in items:
        line = ax.plot(c["t"], 1000 * c["eta"], "-", lw=0.8, label=_label(r))[0]
        ax.plot(c["t_ext"], 1000 * c["ext"], "o", ms=3, color=line.get_color())
    if items:
        c = items[-1][1]
        t = np.linspace(0, c["t"].max(), 600)
        ax.plot(t, 1000 * c["rate"] * t, "k-", lw=0.6, label="linear envelope")
        ax.plot(t, -1000 * c["rate"] * t, "k-", lw=0.6)
        ax.plot(t, 1000 * metrics.forced_sloshing_linear(t, c["rate"], c["omega"]), "-", color="0.6", lw=0.5,
                label="linear solution")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("elevation at the gauge [mm]")


def sloshing_layers(ax, items):
    """The free surface (S1) and the water-cyclohexane interface (I1) at the gauge near the left
    wall, against the linear layered solution (black, dashed for the interface)."""
    for r, c in items:
        line = ax.plot(c["t"], 1000 * c["S1"], "-", lw=0.8, label=_label(r) + ", free surface")[0]
        ax.plot(c["t"], 1000 * c["I1"], "--", lw=0.8, color=line.get_color(), label=_label(r) + ", interface")
    if items:
        c = items[-1][1]
        ax.plot(c["t"], 1000 * c["S1_lin"], "k-", lw=0.6, label="linear, free surface")
        ax.plot(c["t"], 1000 * c["I1_lin"], "k--", lw=0.6, label="linear, interface")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("elevation at gauge 1 [mm]")


def lock_exchange(ax, items):
    """Distance of the light (water) front along the lid and of the dense front along the floor from
    the lock, in units of H, against t* = t sqrt(g'/H), with the slope Fr = 1/2 of the
    energy-conserving light current (dashed) through the light front's mean point over the fitted
    window."""
    for r, c in items:
        depth = c["depth"]
        line = ax.plot(c["t_star"], c["light"] / depth, "o-", ms=3, lw=0.8, label=_label(r) + ", light front")[0]
        ax.plot(c["t_star"], c["dense"] / depth, "x--", ms=3, lw=0.6, color=line.get_color(),
                label=_label(r) + ", dense front")
        t, x = c["t_star"][c["fit"]], c["light"][c["fit"]] / depth
        ax.plot(t, x.mean() + 0.5 * (t - t.mean()), "k--", lw=0.8)
    ax.plot([], [], "k--", lw=0.8, label="Fr = 1/2 (energy-conserving light current)")
    ax.set_xlabel("t* = t sqrt(g'/H)")
    ax.set_ylabel("front distance from the lock / H")


def gate(ax, items):
    """Horizontal (solid) and vertical (dashed) displacement of the gate's free end against time,
    with the experiment's points (both digitisations)."""
    for r, c in items:
        line, = ax.plot(c["t"], c["ux"], "-", lw=0.8, label=_label(r) + ", x")
        ax.plot(c["t"], c["uy"], "--", lw=0.8, color=line.get_color(), label=_label(r) + ", y")
    if items:
        c = items[-1][1]
        ax.plot(c["t_ref_x"], c["u_ref_x"], "ks", ms=4, label="Antoci et al. 2007, x (digitised)")
        ax.plot(c["t_ref_y"], c["u_ref_y"], "k^", ms=4, label="Antoci et al. 2007, y (digitised)")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("displacement of the free end [m]")


def plate(ax, items):
    """Horizontal displacement of the plate's top against time, with the six codes' curves."""
    for r, c in items:
        ax.plot(c["t"], c["u"], "-", lw=1.2, label=_label(r))
    if items:
        for src, t, u in items[-1][1]["ref"]:
            ax.plot(t, u, ":", lw=0.8, label=src)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("horizontal displacement of the plate's top [m]")
