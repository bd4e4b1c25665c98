"""The validation studies: for each, the case, its ladder of rungs (resolution, ranks, overrides),
the metric against its reference, the threshold, and what the plots draw. `quick` marks the
cheap rungs that `make validate QUICK=1` runs. A rung's `label` names its line in the
error-against-run-time plot (the scheme, and the variant where a study compares variants)."""
import functools
import os

from . import metrics

DATA = "cases/{case}/reference/{file}"


def rung(dx, np_=2, quick=False, label="delta-plus", case=None, **sets):
    """One run of a study: spacing dx [m] on np_ ranks with extra --set overrides (of the study's
    case, or of `case` when the rung runs a variant of it)."""
    return {"dx": dx, "np": np_, "quick": quick, "label": label, "case": case, "sets": sets}


def drop_study(case, title, radius, ladder, extra=(), name="R"):
    """An oscillating-drop study of a case on a ladder of (dx, ranks, quick), with `extra` rungs
    (other schemes) appended; the measured drop (phase 0) has radius [m], called name in the
    report."""
    return {"id": case, "case": case, "title": title, "length": (name, radius),
            "reference": "incompressible elliptic-drop solution (notes seeds-000-001 section 3.8)",
            "error": "max |a_SPH - a| / %s over one period, a the semi-axis of the drop (phase 0)" % name,
            "threshold": 0.02,
            "metric": functools.partial(metrics.drop_semi_axis, radius=radius),
            "rungs": [rung(dx, n, q, **{"output.interval": 0.1}) for dx, n, q in ladder] +
                     [rung(dx, n, q and not extra, label="delta-sph", **DELTA_SPH, **{"output.interval": 0.1})
                      for dx, n, q in ladder] +
                     [rung(dx, n, q, label="riemann", **RIEMANN, **{"output.interval": 0.1}) for dx, n, q in ladder] +
                     list(extra),
            "plot": "drop"}


def impact_study(study_id, case, title, rungs):
    """A dam-break study of the first rise of probe p1 against Buchner's P1."""
    ref = "dambreak_pressure_buchner2002_P1_P2_digitized_trixiparticles.csv"
    return {"id": study_id, "case": case, "title": title, "length": ("H", 0.6),
            "reference": "Buchner 2002 P1 (experiment, digitised), reference/" + ref,
            "error": "|t*_SPH - t*_exp| / t*_exp of the first rise of p1 through p* = 0.1", "threshold": 0.02,
            "metric": functools.partial(metrics.dambreak_impact, reference=DATA.format(case=case, file=ref)),
            "rungs": rungs, "plot": "impact"}


IMPACT_RUN = {"time.end": 0.8, "output.interval": 0}
FRONT_RUN = {"fluids.0.box.max": "[0.3, 0.6]", "time.end": 0.4, "output.interval": 0.01}
POSITION_ONLY = "delta-plus, position-only shifting"
HYDRO_DOMAIN = {"domain.min": "[-0.5,-0.5]", "domain.max": "[1.5,2.5]"}   # room for 4 ghost layers at dx = 0.1
HYDRO_LONG = "delta-plus, t sqrt(g/Hw) = 40"
WEIGHTED = {"physics.interface_pressure": "density-weighted"}
WEIGHTED_LABEL = "delta-plus, density-weighted interface pressure"
ALPHA_002 = {"physics.artificial_viscosity": 0.02}   # paper 000's sensitivity value of alpha
ALPHA_002_LABEL = "delta-plus, alpha = 0.02"
# issue 23: the same scheme with less work per simulated second: CFL 2 (the loader's limit, stable
# in doc/theory.md's CFL study) halves the steps, and Wendland C2's support 2h = 2.66 dx holds
# about half the neighbours of the Gaussian cut at 3h = 4 dx
CFL2 = {"time.cfl": 2}
CFL2_LABEL = "delta-plus, CFL 2"
CHEAP = {"kernel": "wendland-c2", "time.cfl": 2}
CHEAP_LABEL = "delta-plus, Wendland C2, CFL 2"
DELTA_SPH = {"scheme": "delta-sph", "physics.shifting": "none"}
# paper 001 runs its hydrostatic tank with p_b = 0.1 p_max (notes section 2.4), p_max = rho_w g Hw
DELTA_SPH_HYDRO = {**DELTA_SPH, "phases.0.p_background": 981, "phases.1.p_background": 981}
# paper 002: Wendland C2 with h = 1.3 dx, one linear EOS p = c^2 (rho - rho0) for both phases with
# c = 10 U_max, U_max = 2 sqrt(g Hw) (notes seed-002 sections 1.3, 2.1), acoustic CFL 0.6 (Eq. 25)
RIEMANN = {"scheme": "riemann", "kernel": "wendland-c2", "resolution.h_over_dx": 1.3, "time.cfl": 0.6}
RIEMANN_HYDRO = {**RIEMANN, "phases.0.c0": 62.6, "phases.0.gamma": 1, "phases.1.c0": 62.6, "phases.1.gamma": 1,
                 "physics.u_max": 6.26}
RIEMANN_DB2 = {**RIEMANN, "phases.0.gamma": 1, "phases.1.c0": 48.5, "phases.1.gamma": 1, "physics.u_max": 4.85}
# paper 002 section 3.5: the air (phase 1) at twice the water's spacing and smoothing length; its
# boxes must be whole numbers of 2 dx (the dam break's 0.6 m column: dx = 0.012 m, not 0.024)
MULTIRES = {"phases.1.dx_ratio": 2}
MULTIRES_LABEL = "riemann, multi-resolution (air at 2 dx)"
MULTIRES_HYDRO_DOMAIN = {"domain.min": "[-0.4,-0.4]", "domain.max": "[1.4,2.4]"}   # 6 ghost layers at dx = 0.05
# paper 003 (notes seeds-003-004 A3, A5, C1): one c0 = 50 m/s and the linear EOS in both phases,
# p_b = 500 Pa, alpha_w = 0.05, mu_w : mu_g = 40 : 1 (the gas viscosity that adds to alpha's),
# CFL 0.5
SPC = "same-phase-continuity"
SPC_PHASES = {"scheme": SPC, "physics.shifting": "none", "time.cfl": 0.5,
              "phases.0.c0": 50, "phases.1.c0": 50, "phases.0.gamma": 1, "phases.1.gamma": 1,
              "phases.0.p_background": 500, "phases.1.p_background": 500}


def spc_sets(dx, h_over_dx=1.33, alpha=0.05):
    """The --set overrides of a paper-003 rung at spacing dx [m]: mu_g = mu_w / 40 with
    mu_w = alpha rho_w h c0 / 8 (2D), less the gas's own alpha part."""
    mu_w = alpha * 1000 * h_over_dx * dx * 50 / 8
    return {**SPC_PHASES, "physics.artificial_viscosity": alpha,
            "phases.1.viscosity": round(mu_w / 40 - mu_w / 1000, 6)}


# paper 004: delta = 0.5 in all its examples (notes seeds-003-004 B); the case files set delta-plus's 0.1
GD = {"scheme": "generalized-dissipation", "physics.shifting": "none", "physics.delta": 0.5}
GD_NO_ALPHA = {**GD, "physics.artificial_viscosity": 0}   # paper 004's scheme with its defaults (the case sets alpha)
SPC_CASE_PHASES = {"scheme": SPC, "physics.shifting": "none"}   # paper 003's scheme with the case's phases
DB2_COARSE = {"domain.min": "[-0.3,-0.3]", "domain.max": "[3.516,2.1]"}    # room for 4 ghost layers at dx = 0.048
RT_RUNGS = [rung(dx, n, q, **{"time.end": 3.0, "output.interval": 0.05}) for dx, n, q in
            ((0.04, 1, True), (0.02, 2, True), (0.01, 2, False))]
# the 3D case (paper 004's scheme and L/dx0 = 125 in the case file): 4 ghost layers need the wider
# domain at dx = 0.1; the quick rung to t = 0.6 s, the linear window of acceptance (a)
RT3D_DOMAIN = {"domain.min": "[-0.45,-0.45,-0.45]", "domain.max": "[1.45,1.45,4.45]"}
# a second Atwood number, At = 0.2 (rho_l = 2/3; notes C9), for the linear check (a) at another
# sigma_nu; the notes' monotonicity (b) is at t = 4 s, on the finer rungs only
RT3D_AT02 = {"phases.1.rho0": 0.666666666667}
RT3D_RUNGS = [rung(0.1, 1, True, label="generalized-dissipation", **RT3D_DOMAIN, **{"time.end": 0.6}),
              rung(0.1, 1, True, label="generalized-dissipation, At = 0.2", **RT3D_DOMAIN, **RT3D_AT02,
                   **{"time.end": 0.6}),
              rung(0.05, 2, label="generalized-dissipation", **{"time.end": 1.0}),
              rung(0.02, 2, label="generalized-dissipation", **{"time.end": 4.0}),
              rung(0.008, 2, label="generalized-dissipation", **{"time.end": 4.0})]
RT_LINEAR_RUNGS = [rung(dx, n, q) for dx, n, q in
                   ((0.04, 1, True), (0.02, 2, True), (0.01, 2, True), (0.005, 2, False))]

STUDIES = [
    {
        "id": "hydrostatic-2phase",
        "case": "hydrostatic-2phase",
        "title": "Two-phase hydrostatic tank (paper 000 section 3.1)",
        "length": ("Hw", 1.0),
        "reference": "analytic hydrostatic pressure, water under air, p = 0 at the lid",
        "error": "max centreline |p - p_exact| / (rho_w g Hw), last snapshot",
        "threshold": 0.02,
        "metric": metrics.hydrostatic_centreline,
        "rungs": [rung(0.1, 1, True, **HYDRO_DOMAIN, **{"time.end": 1.0}),
                  rung(0.05, 2, True, **{"time.end": 1.0}), rung(0.025, 2, **{"time.end": 1.0}),
                  rung(0.1, 1, True, label=HYDRO_LONG, **HYDRO_DOMAIN, **{"time.end": 12.77}),
                  rung(0.05, 2, label=HYDRO_LONG, **{"time.end": 12.77}),
                  rung(0.04, 2, label=HYDRO_LONG, **{"time.end": 12.77}),
                  rung(0.1, 1, True, label=WEIGHTED_LABEL, **HYDRO_DOMAIN, **WEIGHTED, **{"time.end": 1.0}),
                  rung(0.05, 2, True, label=WEIGHTED_LABEL, **WEIGHTED, **{"time.end": 1.0}),
                  rung(0.025, 2, label=WEIGHTED_LABEL, **WEIGHTED, **{"time.end": 1.0}),
                  rung(0.1, 1, label=WEIGHTED_LABEL + ", t sqrt(g/Hw) = 40", **HYDRO_DOMAIN, **WEIGHTED,
                       **{"time.end": 12.77}),
                  rung(0.04, 2, label=WEIGHTED_LABEL + ", t sqrt(g/Hw) = 40", **WEIGHTED, **{"time.end": 12.77}),
                  rung(0.04, 2, label=WEIGHTED_LABEL + ", acoustic damper 10, t sqrt(g/Hw) = 40", **WEIGHTED,
                       **{"physics.acoustic_damper": 10, "time.end": 12.77}),
                  rung(0.1, 1, True, label="delta-sph", **HYDRO_DOMAIN, **DELTA_SPH_HYDRO, **{"time.end": 1.0}),
                  rung(0.05, 2, True, label="delta-sph", **DELTA_SPH_HYDRO, **{"time.end": 1.0}),
                  rung(0.025, 2, label="delta-sph", **DELTA_SPH_HYDRO, **{"time.end": 1.0}),
                  rung(0.1, 1, True, label="riemann", **HYDRO_DOMAIN, **RIEMANN_HYDRO, **{"time.end": 1.0}),
                  rung(0.05, 2, True, label="riemann", **RIEMANN_HYDRO, **{"time.end": 1.0}),
                  rung(0.025, 2, label="riemann", **RIEMANN_HYDRO, **{"time.end": 1.0}),
                  rung(0.1, 1, True, label=SPC, **HYDRO_DOMAIN, **spc_sets(0.1), **{"time.end": 1.0}),
                  rung(0.05, 2, True, label=SPC, **spc_sets(0.05), **{"time.end": 1.0}),
                  rung(0.025, 2, label=SPC, **spc_sets(0.025), **{"time.end": 1.0}),
                  rung(0.1, 1, True, label="generalized-dissipation", **HYDRO_DOMAIN, **GD, **{"time.end": 1.0}),
                  rung(0.05, 2, True, label="generalized-dissipation", **GD, **{"time.end": 1.0}),
                  rung(0.025, 2, label="generalized-dissipation", **GD, **{"time.end": 1.0})],
        "plot": "hydrostatic",
    },
    {
        "id": "hydrostatic-1phase",
        "case": "hydrostatic-1phase",
        "title": "Single-phase hydrostatic tank, depth H = 1 m, settling from a lattice start to t sqrt(g/H) = 40",
        "length": ("H", 1.0),
        "reference": "analytic hydrostatic pressure rho g (H - y)",
        "error": "max centreline |p - p_exact| / (rho g H), last snapshot (the threshold of the two-phase tank)",
        "threshold": 0.02,
        "metric": metrics.hydrostatic_1phase,
        "rungs": [rung(0.04, 1, True), rung(0.02, 2), rung(0.01, 2)],   # dx 0.02 (15 027 steps) left out of QUICK for its time
        "plot": "hydrostatic_1phase",
    },
    drop_study("oscillating-drop", "Oscillating drop, one fluid (paper 001 section III.B)", 1.0,
               [(0.08, 1, True), (0.04, 2, True), (0.02, 2, False)]),
    drop_study("oscillating-drop-2fluid",
               "Oscillating drop in a lighter fluid, density ratio 100 (paper 001 section III.B): "
               "the heavy drop, R_drop = R/2 = 0.5 m, inside the light ring to R = 1 m", 0.5,
               [(0.04, 2, True), (0.02, 2, False), (0.01, 2, False)],
               # generalized-dissipation's quick rung (88 s) is a fine rung, to keep QUICK within 20 min
               [rung(dx, n, q, label=label, **sets, **{"output.interval": 0.1})
                for label, sets, quick in (("generalized-dissipation", GD, False), (SPC, SPC_CASE_PHASES, True))
                for dx, n, q in [(0.04, 2, quick), (0.02, 2, False)]],
               name="R_drop"),
    {
        "id": "dambreak-front",
        "case": "dambreak-1phase",
        "title": "Dam-break surge front, column a x 2a (Martin and Moyce 1952)",
        "length": ("a", 0.3),
        "reference": "Martin and Moyce 1952, Table 2 (experiment), reference/dambreak_surge_front_martin_moyce1952_table.csv",
        "error": "RMS of (Z_SPH - Z_exp) / Z_exp over the experimental points, Z = x_front / a",
        "threshold": 0.10,
        "metric": functools.partial(metrics.dambreak_front, column_width=0.3,
                                    reference=DATA.format(case="dambreak-1phase",
                                                          file="dambreak_surge_front_martin_moyce1952_table.csv")),
        "rungs": [rung(dx, n, q, label=label, **FRONT_RUN, **sets)
                  for label, sets in (("delta-plus", {}), (CFL2_LABEL, CFL2), (CHEAP_LABEL, CHEAP))
                  for dx, n, q in ((0.02, 1, True), (0.01, 2, not sets), (0.005, 2, False))],
        "plot": "front",
    },
    impact_study("dambreak-impact", "dambreak-1phase",
                 "Dam break, first impact at the right-wall sensor P1 (Buchner 2002)",
                 [rung(dx, n, q, **IMPACT_RUN) for dx, n, q in ((0.024, 1, True), (0.012, 2, False), (0.006, 2, False))] +
                 # its viscosity alpha h c0 / 8 slows the front less
                 [rung(dx, n, q, label=label, **IMPACT_RUN, **sets)
                  for label, sets in ((ALPHA_002_LABEL, ALPHA_002), (CFL2_LABEL, CFL2), (CHEAP_LABEL, CHEAP))
                  for dx, n, q in ((0.024, 1, True), (0.012, 2, False), (0.006, 2, False))]),
    impact_study("dambreak-2phase", "dambreak-2phase",
                 "Two-phase dam break, first impact at P1 (Buchner 2002), consistent and position-only shifting",
                 [rung(0.048, 2, True, **DB2_COARSE, **IMPACT_RUN), rung(0.024, 2, **IMPACT_RUN),
                  rung(0.012, 2, **IMPACT_RUN),
                  rung(0.048, 2, label=POSITION_ONLY, **DB2_COARSE, **IMPACT_RUN, **{"physics.shifting": "position"}),
                  rung(0.024, 2, label=POSITION_ONLY, **IMPACT_RUN, **{"physics.shifting": "position"}),
                  rung(0.048, 2, label=WEIGHTED_LABEL, **DB2_COARSE, **IMPACT_RUN, **WEIGHTED),
                  rung(0.024, 2, label=WEIGHTED_LABEL, **IMPACT_RUN, **WEIGHTED),
                  rung(0.024, 2, label=ALPHA_002_LABEL, **IMPACT_RUN, **ALPHA_002),
                  # riemann re-initialises the density by summation, so the water top (0.6 m) must lie
                  # on the lattice: dx = 0.048 puts the first air row dx/2 above the last water row
                  rung(0.04, 2, True, label="riemann", **DB2_COARSE, **IMPACT_RUN, **RIEMANN_DB2),
                  rung(0.024, 2, label="riemann", **IMPACT_RUN, **RIEMANN_DB2),
                  rung(0.012, 2, label="riemann", **IMPACT_RUN, **RIEMANN_DB2),
                  rung(0.048, 2, True, label=SPC, **DB2_COARSE, **IMPACT_RUN, **spc_sets(0.048)),
                  rung(0.024, 2, label=SPC, **IMPACT_RUN, **spc_sets(0.024)),
                  rung(0.048, 2, True, label="generalized-dissipation", **DB2_COARSE, **IMPACT_RUN, **GD),
                  rung(0.024, 2, label="generalized-dissipation", **IMPACT_RUN, **GD),
                  rung(0.048, 2, label="delta-sph", **DB2_COARSE, **IMPACT_RUN, **DELTA_SPH),
                  rung(0.024, 2, label="delta-sph", **IMPACT_RUN, **DELTA_SPH)]),
    {
        "id": "hydrostatic-2phase-multires",
        "case": "hydrostatic-2phase",
        "title": "Two-phase hydrostatic tank under scheme riemann to t sqrt(g/Hw) = 40: the air at 2 dx "
                 "(multi-resolution, paper 002 sections 3.5 and 4.1) against single resolution",
        "length": ("Hw", 1.0),
        "reference": "analytic hydrostatic pressure, water under air, p = 0 at the lid",
        "error": "max centreline |p - p_exact| / (rho_w g Hw), last snapshot (the study hydrostatic-2phase's)",
        "threshold": 0.02,
        "metric": metrics.hydrostatic_centreline,
        "rungs": [rung(dx, 2, dx > 0.03, label=label, **domain, **RIEMANN_HYDRO, **sets, **{"time.end": 12.77})
                  for dx, domain in ((0.05, MULTIRES_HYDRO_DOMAIN), (0.025, {}))
                  for label, sets in (("riemann", {}), (MULTIRES_LABEL, MULTIRES))],
        "plot": "hydrostatic",
    },
    impact_study("dambreak-2phase-multires", "dambreak-2phase",
                 "Two-phase dam break under scheme riemann, first impact at P1 (Buchner 2002): the air at 2 dx "
                 "(multi-resolution, paper 002 sections 3.5 and 4.2) against single resolution",
                 [rung(0.024, 2, label="riemann", **IMPACT_RUN, **RIEMANN_DB2),
                  rung(0.012, 2, label="riemann", **IMPACT_RUN, **RIEMANN_DB2),
                  rung(0.012, 2, label=MULTIRES_LABEL, **IMPACT_RUN, **RIEMANN_DB2, **MULTIRES)]),
    {
        "id": "dambreak-pocket",
        "case": "dambreak-2phase",
        "title": "Two-phase dam break, oscillation of the air pocket (regression value)",
        "length": ("H", 0.6),
        "reference": "regression value %g s: this rung's own period, first measured with commit 976dac0 "
                     "(2026-11-24); Buchner's p1 shows no pocket oscillation, which paper 000 attributes to 3D "
                     "effects" % metrics.POCKET_PERIOD_REF,
        "error": "|T_SPH / T_reg - 1|, T_SPH = 1/f of the spectral peak of p1 in 10-40 Hz while the first "
                 "pocket is intact",
        "threshold": 0.10,
        "metric": metrics.dambreak_pocket_period,
        "rungs": [rung(0.024, 2, label=ALPHA_002_LABEL, **ALPHA_002, **{"time.end": 2.0, "output.interval": 0.02})],
        "plot": "pocket",
    },
    {
        "id": "rayleigh-taylor-growth",
        "case": "rayleigh-taylor-linear",
        "title": "Rayleigh-Taylor instability, linear growth rate (At = 0.5, Re = 256, a0 k = 0.05)",
        "length": ("W", 1.0),
        "reference": "exact viscous linear growth rate, 1.493 1/s (normal modes, Chandrasekhar 1961 ch. X; metrics.rt_viscous_rate)",
        "error": "|sigma_fit - sigma| / sigma, a(t) = A sinh(sigma t) + B cosh(sigma t) fitted over 0.6 <= t <= 1.2 s",
        "threshold": 0.10,
        "metric": metrics.rt_growth,
        "runs": "rayleigh-taylor-linear",
        "rungs": RT_LINEAR_RUNGS,
        "plot": "rt_growth",
    },
    {
        "id": "rayleigh-taylor-tips",
        "case": "rayleigh-taylor",
        "title": "Rayleigh-Taylor instability, spike and bubble tips (He, Chen and Zhang 1999)",
        "length": ("W", 1.0),
        "reference": "He et al. 1999 (lattice Boltzmann, NUMERICAL), reference/rayleigh_taylor_he1999_bubble_spike.csv",
        "error": "RMS of the tip-position differences / W over t* <= 3",
        "threshold": 0.05,
        "metric": functools.partial(metrics.rt_tip_positions,
                                    reference=DATA.format(case="rayleigh-taylor",
                                                          file="rayleigh_taylor_he1999_bubble_spike.csv")),
        "runs": "rayleigh-taylor",
        "rungs": RT_RUNGS,
        "plot": "rt_tips",
    },
    {
        "id": "rayleigh-taylor-3d",
        "case": "rayleigh-taylor-3d",
        "title": "3D Rayleigh-Taylor instability, spike tip in the linear phase (paper 004 section 4.3, At = 0.5, Re = 1024)",
        "length": ("L", 1.0),
        "reference": "linear theory, 0.1 cosh(sigma_nu t), sigma_nu = 1.716 1/s, At = 0.2: 1.076 1/s (notes seeds-003-004 C9; "
                     "metrics.rt3d_tip_linear); Lee and Kim 2013's tip curves are not digitised",
        "error": "max |dz_SPH / (0.1 cosh(sigma_nu t)) - 1| over t <= 0.5 s, dz the spike tip's depth below z = 2 m",
        "threshold": 0.25,
        "metric": metrics.rt3d_tip_linear,
        "rungs": RT3D_RUNGS,
        "plot": "rt3d_tip",
    },
]

# the standing wave's Re = 500 comes from its physical viscosities (alpha 0); mu_g = mu_w / 40
SW_SPC = {**SPC_PHASES, "phases.1.viscosity": 0.1566}
SW_RUNGS = [rung(0.05, 1, True), rung(0.025, 2, True), rung(0.0125, 2, True), rung(0.00625, 2),
            rung(0.05, 2, True, label="delta-plus, water-air (paper 003)", case="standing-wave"),
            rung(0.025, 2, label="delta-plus, water-air (paper 003)", case="standing-wave"),
            rung(0.05, 2, label="delta-plus, water-air, density-weighted interface pressure",
                 case="standing-wave", **WEIGHTED),
            rung(0.025, 2, label="delta-plus, water-air, density-weighted interface pressure",
                 case="standing-wave", **WEIGHTED),
            rung(0.05, 2, True, label=SPC, case="standing-wave", **SW_SPC),
            rung(0.025, 2, label=SPC, case="standing-wave", **SW_SPC),
            rung(0.0125, 2, label=SPC, case="standing-wave", **SW_SPC)]   # paper 003 Table 1's coarsest L/dx
STUDIES += [
    {
        "id": "standing-wave-period",
        "case": "standing-wave-1phase",
        "runs": "standing-wave",
        "title": "Standing wave, period (paper 003 section 4.2, released from rest; water only, and water-air)",
        "length": ("L", 2.0),
        "reference": "linear theory sigma^2 = g k tanh(k d): T = 0.8003 s",
        "error": "|T_SPH / T - 1|, T_SPH from the spacing of the water's kinetic-energy maxima (notes C2 (a))",
        "threshold": 0.02,
        "metric": metrics.standing_wave_period,
        "rungs": SW_RUNGS,
        "plot": "standing_wave",
    },
    {
        "id": "standing-wave-decay",
        "case": "standing-wave-1phase",
        "runs": "standing-wave",
        "title": "Standing wave, energy decay (paper 003 section 4.2, released from rest; water only, and water-air)",
        "length": ("L", 2.0),
        "reference": "Lamb's viscous decay of the wave energy, 4 nu k^2 = 0.989 1/s at Re = 500",
        "error": "|gamma_SPH / gamma - 1| of the kinetic-energy maxima's exponential decay (notes C2 (b): 15 %)",
        "threshold": 0.15,
        "metric": metrics.standing_wave_decay,
        "rungs": SW_RUNGS,
        "plot": "standing_wave",
    },
]

STUDIES.append({
    "id": "two-layer-sloshing",
    "case": "two-layer-sloshing",
    "title": "Two-layer sloshing, oil over water (paper 000 section 3.5), interface at WG2",
    "length": ("h1", 0.05),
    "reference": "the response period of the forced sloshing, the forcing period 0.830 s (notes section 3.5)",
    "error": "|T_SPH / T - 1| of the interface elevation at WG2 after t = 1.66 s; threshold 5 % (notes)",
    "threshold": 0.05,
    "metric": metrics.sloshing_period,
    "rungs": [rung(0.01, 1, True), rung(0.005, 2), rung(0.0025, 2)],
    "plot": "sloshing",
})


STUDIES.append({
    "id": "rising-bubble-hysing",
    "case": "rising-bubble-hysing",
    "title": "Rising bubble, test case 1 of Hysing et al. 2009 (density and viscosity ratio 10, Eo 10, Re 35), to t = 3",
    "length": ("R", 0.25),
    "reference": "the mean rise velocity digitised from Hysing et al. 2009 (the Lethe project's points), "
                 "reference/hysing2009_tc1_digitised.csv",
    "error": "max |v_c - v_ref| / max v_ref over the digitised points; threshold 5 % (the notes' bubble velocity bar, C7)",
    "threshold": 0.05,
    "metric": functools.partial(metrics.bubble_rise, reference=DATA.format(
        case="rising-bubble-hysing", file="hysing2009_tc1_digitised.csv")),
    "rungs": [rung(0.025, 2, True), rung(0.0125, 2),
              rung(0.025, 2, True, label="generalized-dissipation", **GD),
              rung(0.025, 2, label="delta-sph", **DELTA_SPH), rung(0.025, 2, label="riemann", **RIEMANN),
              rung(0.025, 2, label=SPC, **SPC_CASE_PHASES),
              # paper 003's conventional model (its negative control): continuity over every neighbour
              rung(0.025, 2, label=SPC + ", conventional model", **SPC_CASE_PHASES,
                   **{"physics.spc_model": "conventional"})],
    "plot": "bubble",
})

STUDIES.append({
    "id": "static-bubble",
    "case": "static-bubble",
    "title": "Static bubble, density ratio 100, no gravity (fluids and sigma of paper 004 section 4.2.1, in 2D)",
    "length": ("R", 0.005),
    "reference": "the Laplace jump sigma / R in 2D, R the radius of the bubble's area",
    "error": "|<p_in - p_out> / (sigma / R) - 1| averaged over the snapshots from t = 0.01 s; threshold 5 % (issue 7)",
    "threshold": 0.05,
    "metric": metrics.laplace_jump,
    # every scheme, with the case's phases (riemann with paper 002's kernel, h and CFL); QUICK runs
    # delta-plus only, to keep its time
    "rungs": [rung(0.0005, 1, True), rung(0.00025, 2)] +
             [rung(dx, n, label=label, **sets) for label, sets in
              (("delta-sph", DELTA_SPH), ("riemann", RIEMANN), (SPC, SPC_CASE_PHASES), ("generalized-dissipation", GD))
              for dx, n in ((0.0005, 1), (0.00025, 2))],
    "plot": "laplace",
})

def case_path(study, r=None):
    """The case file of a study, or of one of its rungs."""
    return os.path.join("cases", (r or {}).get("case") or study["case"], "case.yaml")

WEDGE_REF = "wedge_entry_yettou2006_25deg_velocity_digitized.csv"
STUDIES.append({
    "id": "wedge-entry-yettou",
    "case": "wedge-entry-yettou",
    "title": "Free-fall wedge water entry, Yettou et al. 2006 (25 deg deadrise, 94 kg/m, 5.05 m/s), 0-40 ms",
    "length": ("B", 1.2),
    "reference": "the wedge's velocity in the experiment, digitised from Sun et al. 2015, reference/" + WEDGE_REF,
    "error": "max |v_SPH - v_exp| / 5.05 m/s over the experiment's points in 0-40 ms, v_SPH linear between "
             "bodies.csv rows (0.5 ms); threshold 5 % (issue 25)",
    "threshold": 0.05,
    "metric": functools.partial(metrics.wedge_velocity, reference=DATA.format(case="wedge-entry-yettou", file=WEDGE_REF)),
    # the case's c0 = 10 x the entry velocity; c0 = 100 m/s and tensile control off as sensitivity rungs
    # (cases/wedge-entry-yettou/README.md)
    "rungs": [rung(0.02, 1, True), rung(0.01, 2), rung(0.005, 2), rung(0.0025, 2),
              rung(0.02, 1, True, label="delta-plus, c0 = 100 m/s", **{"phases.0.c0": 100}),
              rung(0.01, 2, label="delta-plus, c0 = 100 m/s", **{"phases.0.c0": 100}),
              rung(0.02, 1, True, label="delta-plus, no tensile control", **{"physics.tensile_control": "false"}),
              rung(0.01, 2, label="delta-plus, no tensile control", **{"physics.tensile_control": "false"})],
    "plot": "wedge",
})

# paper 000's two-phase cases run with the acoustic damper (alpha2 = 10); the rungs without it
# measure what it does to the impact (cases/panel-slamming/README.md)
NO_DAMPER = {"physics.acoustic_damper": 0}
STUDIES.append({
    "id": "panel-slamming",
    "case": "panel-slamming",
    "title": "LNG insulation panel slamming, water and air (paper 000 section 3.3, geometry assumed)",
    "length": ("L", 0.64),
    "reference": "paper 000's description (no digitised data): the smoke test of notes seeds-000-001 section 3.3",
    "error": "number of failed criteria of four: completes to 30 ms after contact; the largest pressure of "
             "probes 40, 47 in 9-14 ms after contact; an air pocket (air between the dents at >= half that "
             "pressure); no fluid particle inside the panel and no stray air in the water; threshold 0",
    "threshold": 0,
    "metric": metrics.panel_slamming,
    # QUICK runs dx = 0.02 only (about 6 min on this loaded machine); the rest is for the Slurm array
    "rungs": [rung(0.02, 2, True), rung(0.01, 2), rung(0.005, 2), rung(0.0025, 2), rung(0.002, 2),
              rung(0.02, 2, label="delta-plus, no acoustic damper", **NO_DAMPER),
              rung(0.01, 2, label="delta-plus, no acoustic damper", **NO_DAMPER)],
    "plot": "panel",
})

CAVITY_SLAM = {"time.end": 0.1}   # the slamming phase only: the quick rung's p1 peak and cost
STUDIES.append({
    "id": "wedge-cavity-wang",
    "case": "wedge-cavity-wang",
    "title": "Free-fall wedge entry with cavity pinch-off, water and air (paper 000 section 3.4, Wang et al. 2015 "
             "set-up: 30 deg, D = 0.166 m, 32.3 kg/m, 0.92 m/s)",
    "length": ("D", 0.166),
    "reference": "paper 000's pinch-off time 0.352 s (its Fig. 18; no experimental series is stored)",
    "error": "|t_pinch - 0.352 s| / 0.352 s, t_pinch the first snapshot (every 5 ms) with enclosed air over the "
             "wedge; threshold 5 % (notes seeds-000-001 section 3.4)",
    "threshold": 0.05,
    "metric": metrics.wedge_pinch_off,
    # D/dx = 12 is too coarse: the wedge is 3.5 dx tall and has no ghosts near its keel (README);
    # D/dx whole keeps the lattice symmetric about the wedge's axis
    "rungs": [rung(0.166 / 24, 2, True, label="delta-plus, to 0.1 s", **CAVITY_SLAM),
              rung(0.166 / 24, 2), rung(0.166 / 48, 2), rung(0.166 / 96, 2)],
    "plot": "wedge_cavity",
})

# variant #1 of paper 000 section 3.6: air over the open left tank's water too, up to 0.408 m with
# a free surface (the tank's lid at 0.51 m is out of reach), so that it stays at the atmosphere's
# pressure (cases/air-pocket-sloshing/README.md); the case file is variant #2
POCKET_V1 = {"fluids.4": "{phase: air, box: {min: [0, 0.17], max: [0.85, 0.408]}}"}
POCKET_V1_LABEL = "delta-plus, #1 air over the left tank"
POCKET_V2_LABEL = "delta-plus, #2 free surface in the left tank"
POCKET_QUICK = {"time.end": 0.6}   # the start of the 5 s ramp: the 5-12 s criteria are n.a.
STUDIES.append({
    "id": "air-pocket-sloshing",
    "case": "air-pocket-sloshing",
    "title": "Sloshing with an entrapped air pocket (paper 000 section 3.6; geometry assumed)",
    "length": ("d", 0.17),
    "reference": "internal consistency (notes section 3.6): adiabatic compression of the pocket's volume, "
                 "p_a1 in phase with p_w1, variants #1 and #2 alike; Luo et al.'s records are not available",
    "error": "the worst of RMS(p_ad - p_a1)/range(p_a1) (pocket volume against adiabatic compression, to 12 s), "
             "(1 - r)/2 of p_a1 and p_w1 over 5-12 s (0.05 at r = 0.9), and RMS(p_#1 - p_#2)/range of p_w2, p_w3, "
             "p_w1, p_a1 over 5-12 s; the last two n.a. for runs ending before 12 s; threshold 5 % (notes)",
    "threshold": 0.05,
    "metric": functools.partial(metrics.air_pocket, x_split=0.918),   # the partition's middle, tank frame
    # quick: 0.6 s on 1 rank (a folder of its own); full: 12 s, ~1.8e5 steps at dx = 0.017 m, 8x and
    # 64x that work at 0.0085 and 0.00425 m
    "rungs": [rung(0.017, 1, True, label=POCKET_V2_LABEL + ", to 0.6 s", **POCKET_QUICK),
              rung(0.017, 1, True, label=POCKET_V1_LABEL + ", to 0.6 s", **POCKET_QUICK, **POCKET_V1),
              rung(0.017, 2, label=POCKET_V2_LABEL), rung(0.017, 2, label=POCKET_V1_LABEL, **POCKET_V1),
              rung(0.0085, 4, label=POCKET_V2_LABEL), rung(0.0085, 4, label=POCKET_V1_LABEL, **POCKET_V1),
              rung(0.00425, 16, label=POCKET_V2_LABEL), rung(0.00425, 16, label=POCKET_V1_LABEL, **POCKET_V1)],
    "plot": "air_pocket",
})

KLEEF_REF = "dambreak3d_obstacle_kleefsman2005_spheric2_exp.csv"
KLEEF_QUICK = {"time.end": 1.0}   # the first impact on the box (P1 peak 0.415 s), the front at H3, H2 and H1
STUDIES.append({
    "id": "dambreak-3d-kleefsman",
    "case": "dambreak-3d-kleefsman",
    "title": "3D dam break against a box obstacle, Kleefsman et al. 2005 (SPHERIC test 2), water only",
    "length": ("H", 0.55),
    "reference": "the experiment's water heights H1-H4 and pressure P1 (MARIN, SPHERIC release), reference/" + KLEEF_REF,
    "error": "RMS over H1-H4 and the experiment's samples (1 kHz) in 0-6 s (or to the run's end) of "
             "(H_SPH - H_exp) / 0.55 m, a dry gauge read as 0; threshold 5 % (cases/dambreak-3d-kleefsman/README.md)",
    "threshold": 0.05,
    "metric": functools.partial(metrics.kleefsman_dambreak,
                                reference=DATA.format(case="dambreak-3d-kleefsman", file=KLEEF_REF)),
    # quick: H/dx = 11 to 1.0 s on 1 rank (700 steps, 714 s on this loaded machine); the full 6 s at
    # H/dx = 11, 22, 44 is for the Slurm array: about 1.2, 10 and 100 core-hours
    # (cases/dambreak-3d-kleefsman/README.md)
    # last, CHEAP at the quick rung's dx and half of it: what the Gaussian's support (about 3.4 times
    # Wendland C2's pairs in 3D) and CFL 1 buy in 3D (issue 23)
    "rungs": [rung(0.05, 1, True, label="delta-plus, to 1.0 s", **KLEEF_QUICK),
              rung(0.05, 2), rung(0.025, 8), rung(0.0125, 32),
              rung(0.05, 1, label=CHEAP_LABEL + ", to 1.0 s", **CHEAP, **KLEEF_QUICK),
              rung(0.025, 2, label=CHEAP_LABEL + ", to 1.0 s", **CHEAP, **KLEEF_QUICK)],
    "plot": "kleefsman",
})

LOBOVSKY_DATA = ("dambreak_water_level_lobovsky2014_H300.csv", "dambreak_pressure_lobovsky2014_H300_event5.csv")
LOBOVSKY_SPAN = {"time.end": 1.25}   # t sqrt(g/H) = 7.15: past every gauge's second jump and sensor #4's peak
# the case without its air and without the acoustic damper (its water column and water phase as in the
# case file): paper 003's single-phase comparison, and cheap (the air's stability sound speed, about
# 14 c0 of the water, sets the two-phase step)
WATER_ONLY = {"fluids": "[{phase: water, box: {min: [0, 0, 0], max: [0.6, 0.15, 0.3]}}]",
              "phases": "[{name: water, rho0: 1000, c0: 34.3, gamma: 7, incompressible: true}]",
              "physics.acoustic_damper": 0}
WATER_ONLY_LABEL = "delta-plus, water only, to 1.25 s"
STUDIES.append({
    "id": "dambreak-3d-lobovsky",
    "case": "dambreak-3d-lobovsky",
    "title": "3D two-phase dam break, H = 300 mm, Lobovsky et al. 2014 (paper 003 section 4.4)",
    "length": ("H", 0.3),
    "reference": "the experiment's water levels H1-H4 and pressures #1-#4 (one record), reference/%s and %s"
                 % LOBOVSKY_DATA,
    "error": "the worst of: each gauge's largest |H_SPH - H_exp| / H before its second jump, over 0.10; "
             "|peak_SPH / peak_exp - 1| of sensors #3 and #4 (5 ms running means), over 0.30; 1 is at a limit "
             "(notes seeds-003-004 C4 (d), (e); cases/dambreak-3d-lobovsky/README.md)",
    "threshold": 1.0,
    "metric": functools.partial(metrics.lobovsky_dambreak,
                                levels=DATA.format(case="dambreak-3d-lobovsky", file=LOBOVSKY_DATA[0]),
                                pressures=DATA.format(case="dambreak-3d-lobovsky", file=LOBOVSKY_DATA[1])),
    # quick: water only, H/dx = 10 on 1 rank (1075 steps, 245 s on this loaded machine); the water-air
    # case (about 15 000 steps at dx = 0.03 m) for the Slurm array (cases/dambreak-3d-lobovsky/README.md);
    # last, CHEAP at the quick rung's dx (issue 23)
    "rungs": [rung(dx, n, q, label=WATER_ONLY_LABEL, **WATER_ONLY, **LOBOVSKY_SPAN)
              for dx, n, q in ((0.03, 1, True), (0.015, 2, False), (0.01, 4, False), (0.005, 16, False))] +
             [rung(dx, n, label="delta-plus, water-air, to 1.25 s", **LOBOVSKY_SPAN)
              for dx, n in ((0.03, 2), (0.015, 8), (0.01, 16), (0.005, 32))] +
             [rung(0.03, 1, label="%s, water only, to 1.25 s" % CHEAP_LABEL, **CHEAP, **WATER_ONLY, **LOBOVSKY_SPAN)],
    "plot": "lobovsky",
})

# paper 002 section 4.2: the same experiment in 2D, in its tank (5.366 H x 2.5 H) with its settings,
# the air at 2 dx (multi-resolution) and at dx; dx = 0.005 m is the coarsest at which every air box
# is a whole number of 2 dx (1.01 m)
STUDIES.append({
    "id": "dambreak-lobovsky-2d",
    "case": "dambreak-lobovsky-2d",
    "title": "2D two-phase dam break, H = 300 mm, Lobovsky et al. 2014, in paper 002's tank (paper 002 section 4.2): "
             "multi-resolution against single resolution",
    "length": ("H", 0.3),
    "reference": "the experiment's water levels H1-H4 and pressures #1-#4 (one record), "
                 "cases/dambreak-3d-lobovsky/reference/%s and %s" % LOBOVSKY_DATA,
    "error": "as study dambreak-3d-lobovsky's: the worst of each gauge's largest |H_SPH - H_exp| / H before its second "
             "jump over 0.10 and |peak_SPH / peak_exp - 1| of sensors #3 and #4 over 0.30; 1 is at a limit",
    "threshold": 1.0,
    "metric": functools.partial(metrics.lobovsky_dambreak,
                                levels=DATA.format(case="dambreak-3d-lobovsky", file=LOBOVSKY_DATA[0]),
                                pressures=DATA.format(case="dambreak-3d-lobovsky", file=LOBOVSKY_DATA[1])),
    "rungs": [rung(0.005, 2, label=MULTIRES_LABEL), rung(0.005, 2, label="riemann", **{"phases.1.dx_ratio": 1})],
    "plot": "lobovsky",
})

# 3D sloshing at resonance, paper 004 section 4.1.1 (notes seeds-003-004 C5): no record of Liu and
# Lin's experiment is stored, so the reference is the linear resonant envelope (notes, [D])
SLOSH3D_QUICK = {"time.end": 3.0}   # the linear phase: eta < 0.04 m = h_w / 4
STUDIES.append({
    "id": "sloshing-3d-liu-lin",
    "case": "sloshing-3d-liu-lin",
    "title": "3D sloshing at the first natural frequency, Liu and Lin set-up (paper 004 section 4.1.1), water only",
    "length": ("h_w", 0.15),
    "reference": "linear potential theory of resonant sloshing from rest (notes seeds-003-004 C5): envelope "
                 "2 L A omega^3 / (g pi^2) cos(pi x_g / L) t = 0.0130 m/s x t at the gauge x_g = 0.02 m",
    "error": "|r_SPH / r - 1|, r_SPH the slope through the origin of the gauge's half-period extrema of |eta| "
             "in 0-3 s; threshold 20 % (notes C5 (a))",
    "threshold": 0.20,
    "metric": metrics.sloshing_growth,
    # quick: h_w/dx = 10 to 3 s on 1 rank; the 7 s runs at h_w/dx = 30 and 60 are paper 004's
    # two coarser resolutions (cases/sloshing-3d-liu-lin/README.md)
    "rungs": [rung(0.015, 1, True, label="delta-plus, to 3 s", **SLOSH3D_QUICK),
              rung(0.01, 1, label="delta-plus, to 3 s", **SLOSH3D_QUICK),
              rung(0.005, 4), rung(0.0025, 16),
              rung(0.015, 1, label=CHEAP_LABEL + ", to 3 s", **CHEAP, **SLOSH3D_QUICK)],   # issue 23
    "plot": "forced_sloshing",
})

# three liquids swayed in x and y, paper 004 section 4.1.2 (notes seeds-003-004 C6): no record of
# paper 004's STAR-CCM+ gauges is stored, so the reference is the linear layered solution (README)
STUDIES.append({
    "id": "sloshing-3liquid-3d",
    "case": "sloshing-3liquid-3d",
    "title": "3D sloshing of three liquid layers under a free surface, swayed in x and y (paper 004 section 4.1.2)",
    "length": ("h_layer", 0.2),
    "reference": "linear potential theory of the three layers in the swayed tank, from rest "
                 "(cases/sloshing-3liquid-3d/reference/README.md), at the gauges' positions in the tank's frame",
    "error": "max |r - 1| over the free surface and the water-cyclohexane interface at the two mid-line gauges, r the "
             "least-squares ratio of the gauge's elevation to the linear one over 0-1.5 s (one forcing period); "
             "threshold 20 % (as notes C5 (a))",
    "threshold": 0.20,
    "metric": metrics.sloshing_layers,
    # quick: h_layer/dx = 4 to 3 s on 1 rank (7200 fluid particles), delta-plus only (QUICK=1 is at its
    # 35 min already); paper 004's dx0 = 0.01 m is 900 000 fluid particles
    "rungs": [rung(0.05, 1, True), rung(0.05, 1, label="generalized-dissipation", **GD_NO_ALPHA),
              rung(0.025, 2), rung(0.025, 2, label="generalized-dissipation", **GD_NO_ALPHA),
              rung(0.0125, 8), rung(0.01, 32)],
    "plot": "sloshing_layers",
})

# non-Boussinesq lock exchange, paper 004 section 4.4 (notes seeds-003-004 C10): Lowe et al.'s front
# records are not stored, so the reference is the two-layer theory's light front (README)
STUDIES.append({
    "id": "lock-exchange-3d",
    "case": "lock-exchange-3d",
    "title": "3D non-Boussinesq lock exchange, water against NaI solution, density ratio 0.681 (paper 004 section "
             "4.4, Lowe et al. 2005 set-up)",
    "length": ("H", 0.2),
    "reference": "Benjamin's energy-conserving light current of half the depth, Fr = U / sqrt(g'H) = 1/2 "
                 "(the light front of Lowe et al.'s two-layer theory; cases/lock-exchange-3d/reference/README.md); their "
                 "front records are not stored",
    "error": "|Fr_L / 0.5 - 1|, Fr_L the light (water) front's speed along the lid, fitted over t* = 1.5-4.2, in "
             "units of sqrt(g'H) = 0.791 m/s; threshold 10 % (notes C10 (b))",
    "threshold": 0.10,
    "metric": metrics.lock_exchange_front,
    # quick: H/dx = 10 (400 steps, about 2.5 min on 2 ranks here); the paper's H/dx = 80 is 4.6 M particles
    # (at most 32 ranks: scripts/slurm/validate-sweep.sh gives every array task the largest rank count)
    "rungs": [rung(0.02, 2, True), rung(0.01, 8), rung(0.005, 16), rung(0.0025, 32)] +
             [rung(dx, n, label="generalized-dissipation", **GD_NO_ALPHA) for dx, n in ((0.02, 2), (0.01, 8))] +
             [rung(0.02, 2, label=CHEAP_LABEL, **CHEAP, **{"resolution.h_over_dx": 1.33})],   # issue 23: the
    # case leaves h/dx at its default, which for Wendland C2 would be 2 (support 4 dx)
    "plot": "lock_exchange",
})

GATE_LINEAR = "riemann, paper 002's linear solid correction"   # the elastic solids' paper correction
GATE_DATA = "fsi_elastic_gate_antoci2007_tip_displacement_digitized.csv"
# scheme delta-plus with the solids (doc/theory.md section 14) without tensile control (with it, a
# particle trapped under the gate's free end runs away at t = 0.037 s) and without the acoustic
# damper (whose step limit is ten times shorter): the gate's and the plate's delta-plus rungs
SOLIDS_DELTA_PLUS = {"scheme": "delta-plus", "physics.tensile_control": "false", "physics.acoustic_damper": 0}
SOLIDS_DELTA_PLUS_LABEL = "delta-plus, no tensile control, no damper"
# what the gate's studies share: the measured free end, the metric and the threshold
GATE_STUDY = {
    "length": ("b", 0.005),
    "error": "RMS of u_SPH - u_exp over the experiment's points in 0-0.4 s in units of max |u_exp|, the larger of "
             "the horizontal and vertical displacement; threshold 15 % (the notes' early-stage band, section 2.4)",
    "threshold": 0.15,
    "metric": functools.partial(metrics.gate_tip, reference=DATA.format(case="elastic-gate-antoci", file=GATE_DATA)),
    "plot": "gate",
}
STUDIES.append({
    **GATE_STUDY,
    "id": "elastic-gate-antoci",
    "case": "elastic-gate-antoci",
    "title": "Dam break through an elastic rubber gate (Antoci et al. 2007; paper 002 section 4.4 without air), to t = 0.4 s",
    "reference": "the gate's free-end displacement measured by Antoci et al. 2007, two digitisations, reference/" + GATE_DATA,
    # mpsph's quadratic correction needs 3 particles through the thickness (4 at dx = b/4); paper
    # 002's linear one runs at b/2 too (the quick rung)
    # b/8 (0.000625) costs about 30 minutes on 2 ranks, most of it in the solid: measured with an
    # earlier build only (cases/elastic-gate-antoci/README.md)
    "rungs": [rung(0.00125, 2, label="riemann"),
              rung(0.0025, 1, True, label=GATE_LINEAR, **{"solids.0.correction": "linear"}),
              rung(0.00125, 2, label=GATE_LINEAR, **{"solids.0.correction": "linear"}),
              rung(0.00125, 2, label=SOLIDS_DELTA_PLUS_LABEL, **SOLIDS_DELTA_PLUS)],
})

STUDIES.append({
    **GATE_STUDY,
    "id": "elastic-gate-air",
    "case": "elastic-gate-air",
    "title": "Dam break through an elastic rubber gate in a closed tank of air (Antoci et al. 2007; paper 002 section "
             "4.4 with air), to t = 0.4 s: multi-resolution against single resolution",
    "reference": "the gate's free-end displacement measured by Antoci et al. 2007 (without air), two digitisations, "
                 "cases/elastic-gate-antoci/reference/" + GATE_DATA,
    # the case's air at 2 dx (paper 002's two-level resolution), and at dx (its single resolution)
    "rungs": [rung(0.00125, 2, label=MULTIRES_LABEL), rung(0.00125, 2, label="riemann", **{"phases.1.dx_ratio": 1})],
})

PLATE_003 = {"solids.0.min": "[0.292,-0.013]"}
PLATE_REFERENCE = DATA.format(case="elastic-plate-walhorn", file="fsi_dambreak_elastic_plate_walhorn2005_numerical.csv")
STUDIES.append({
    "id": "elastic-plate-walhorn",
    "case": "elastic-plate-walhorn",
    "title": "Dam break against an elastic plate clamped to the floor (Walhorn et al. 2005 benchmark), to t = 0.5 s",
    "length": ("b", 0.012),
    "reference": "the first peak of the plate top's horizontal displacement in six published codes (PFEM, SPH, MPS, "
                 "partitioned FEM), reference/fsi_dambreak_elastic_plate_walhorn2005_numerical.csv",
    "error": "|u_peak / mean - 1| of the first peak (t <= 0.4 s) against the six codes' mean; threshold: the band the "
             "six codes span (their largest deviation from that mean, 10.9 %)",
    "threshold": metrics.plate_band(PLATE_REFERENCE),
    "metric": functools.partial(metrics.plate_peak, reference=PLATE_REFERENCE),
    # the plate's box a whole number of dx high, its root 4-6 rows into the floor (the case file's comment)
    "rungs": [rung(0.003, 1, True, label="riemann", **PLATE_003), rung(0.002, 2, label="riemann"),
              rung(0.003, 1, label=GATE_LINEAR, **PLATE_003, **{"solids.0.correction": "linear"}),
              rung(0.003, 1, label=SOLIDS_DELTA_PLUS_LABEL, **PLATE_003, **SOLIDS_DELTA_PLUS),
              rung(0.002, 2, label=SOLIDS_DELTA_PLUS_LABEL, **SOLIDS_DELTA_PLUS)],
    "plot": "plate",
})
