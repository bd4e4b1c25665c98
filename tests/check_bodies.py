"""Checks of a rigid body's bodies.csv (tests/physics_bodies.sh).

  check_bodies.py fall RUN               exact free fall of every body: position, velocity and
                                         angle against the parabola and constant spin from the
                                         case's initial values; a prescribed translation (a
                                         sinusoid without ramp) against its law
  check_bodies.py buoyancy RUN T0        every body (a box held under the first phase's surface)
                                         carries over t >= T0 (mean) the buoyancy rho0 g A within
                                         1 %, and a torque below 1 % of the buoyancy times its
                                         half-width
  check_bodies.py draft RUN T0           every body (a box floating in the first phase) sits over
                                         t >= T0 (mean) at its draft M / (rho0 B) below the mean of
                                         the elevation probes within 2 %, carrying its weight M g
                                         within 1 %; a pressure probe it carries (the centre of
                                         its bottom face) reads the pressure M g / B that carries
                                         the weight within 2 %
"""
import sys
import numpy as np
import yaml


def table(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def bodies_of(run):
    """The run's case and its bodies as (wall index, wall) pairs."""
    with open(f"{run}/config.yaml") as f:
        case = yaml.safe_load(f)
    walls = [(k, w) for k, w in enumerate(case["walls"]) if "body" in w]
    assert walls, "no body in the case"
    return case, walls


def check_fall(run):
    case, walls = bodies_of(run)
    for k, wall in walls:
        check_fall_of(case, table(f"{run}/bodies.csv"), k, wall["body"], wall.get("motion", {}).get("translation"))


def check_fall_of(case, b, k, body, law):
    dim, g = case["dimension"], np.array(case["gravity"], float)
    t = b["time"]
    worst = 0.0
    for d, axis in enumerate("xyz"[:dim]):
        x0, v0 = body["centre"][d], body["velocity"][d]
        x_exact = x0 + v0 * t + 0.5 * g[d] * t * t
        v_exact = v0 + g[d] * t
        if axis in body["prescribed"]:
            assert law["ramp"]["shape"] == "none", "the check knows sinusoids without a ramp"
            w = 2 * np.pi / law["period"]
            x_exact = x0 + law["amplitude"][d] * np.sin(w * t + law["phase"])
            v_exact = law["amplitude"][d] * w * np.cos(w * t + law["phase"])
        worst = max(worst, np.max(abs(b[f"body{k}_{axis}"] - x_exact)), np.max(abs(b[f"body{k}_v{axis}"] - v_exact)))
    if dim == 2:
        w = body["angular_velocity"]
        angle_err = np.max(abs(b[f"body{k}_theta"] - w * t))
        spin_err = np.max(abs(b[f"body{k}_omega"] - w))
    else:   # spin about a principal axis: q = (cos(|w| t / 2), sin(|w| t / 2) w / |w|)
        w = np.array(body["angular_velocity"], float)
        n = np.linalg.norm(w)
        q = np.stack([b[f"body{k}_q{c}"] for c in "wxyz"], axis=1)
        q_exact = np.column_stack([np.cos(n * t / 2)] + [np.sin(n * t / 2) * w[d] / n for d in range(3)])
        angle_err = np.max(np.linalg.norm(q - q_exact, axis=1))
        spin_err = max(np.max(abs(b[f"body{k}_w{c}"] - w[d])) for d, c in enumerate("xyz"))
    force = max(np.max(abs(b[f"body{k}_f{c}"])) for c in "xyz"[:dim])
    print(f"body {k}: free fall to t = {t[-1]:.3g} s: position/velocity error {worst:.2e}, attitude error {angle_err:.2e}, "
          f"spin error {spin_err:.2e}, largest fluid force {force:.2e}")
    assert force == 0, "the body met the fluid: the case must keep it out of reach"
    assert worst < 1e-11, "position or velocity off the parabola (round-off of some hundred steps)"
    assert spin_err < 1e-11, "spin changed without torque"
    assert angle_err < (1e-11 if dim == 2 else 1e-8), "attitude off the constant spin"


def box_size(wall):
    """Edge lengths of a box wall."""
    return np.array(wall["box"]["max"], float) - np.array(wall["box"]["min"], float)


def check_buoyancy(run, t0):
    case, walls = bodies_of(run)
    rho, g = case["phases"][0]["rho0"], -case["gravity"][-1]
    for k, wall in walls:
        size = box_size(wall)
        check_buoyancy_of(table(f"{run}/bodies.csv"), k, rho * g * np.prod(size), size[0] / 2, t0)


def check_buoyancy_of(b, k, expected, half_width, t0):
    late = b["time"] >= t0
    dim = 3 if f"body{k}_fz" in b.dtype.names else 2
    up = f"body{k}_f{'xyz'[dim - 1]}"
    force = np.mean(b[up][late])
    sideways = max(np.max(abs(b[f"body{k}_f{c}"][late])) for c in "xyz"[:dim - 1])
    torques = [c for c in (f"body{k}_torque", f"body{k}_tx", f"body{k}_ty", f"body{k}_tz") if c in b.dtype.names]
    torque = max(np.max(abs(b[c][late])) for c in torques)
    print(f"body {k}: buoyancy over t >= {t0} s: {force:.4f} N against rho g A = {expected:.4f} N "
          f"({100 * (force / expected - 1):+.3f} %); largest sideways force {sideways:.3e} N, "
          f"largest |torque| {torque:.3e} N m ({100 * torque / (expected * half_width):.4f} % of F L/2)")
    assert abs(force / expected - 1) < 0.01, "buoyancy off by more than 1 %"
    assert torque < 0.01 * expected * half_width, "torque above 1 % of buoyancy x half-width"


def check_draft(run, t0):
    case, walls = bodies_of(run)
    rho, g = case["phases"][0]["rho0"], -case["gravity"][-1]
    b, p = table(f"{run}/bodies.csv"), table(f"{run}/probes.csv")
    gauges = [q["name"] for q in case["probes"] if q["kind"] == "elevation"]
    level = np.mean([np.mean(p[name][p["time"] >= t0]) for name in gauges])
    late = b["time"] >= t0
    for k, wall in walls:
        mass, size = wall["body"]["mass"], box_size(wall)
        dim = len(size)
        up = "xyz"[dim - 1]
        expected = mass / (rho * np.prod(size[:-1]))
        bottom = np.mean(b[f"body{k}_{up}"][late]) - size[-1] / 2
        draft = level - bottom
        heave = np.ptp(b[f"body{k}_{up}"][late])
        weight = np.mean(b[f"body{k}_f{up}"][late]) / (mass * g)
        print(f"body {k}: draft over t >= {t0} s {draft:.5f} m (level {level:.5f}, bottom {bottom:.5f}) against "
              f"M/(rho B) = {expected:.5f} m ({100 * (draft / expected - 1):+.2f} %), heave range {heave:.2e} m, "
              f"fluid force / M g {weight:.5f}")
        assert abs(draft / expected - 1) < 0.02, "draft off by more than 2 %"
        assert abs(weight - 1) < 0.01, "the fluid does not carry the body's weight within 1 %"
        for q in (q for q in case["probes"] if q.get("wall") == k):
            pressure = np.mean(p[q["name"]][p["time"] >= t0])
            carrying = mass * g / np.prod(size[:-1])
            print(f"body {k}: its probe {q['name']} reads {pressure:.2f} Pa against M g / B = {carrying:.2f} Pa "
                  f"({100 * (pressure / carrying - 1):+.2f} %; rho0 g draft = {rho * g * draft:.2f} Pa)")
            assert abs(pressure / carrying - 1) < 0.02, "the probe carried on the bottom face is off"


if __name__ == "__main__":
    what, run, *t0 = sys.argv[1:]
    {"fall": check_fall, "buoyancy": check_buoyancy, "draft": check_draft}[what](run, *map(float, t0))
