"""Checks of a rigid body's bodies.csv (tests/physics_bodies.sh).

  check_bodies.py fall RUN CASE          exact free fall: position, velocity and angle against the
                                         parabola and constant spin from the case's initial values
  check_bodies.py buoyancy RUN RHO G AREA HALF_WIDTH T0
                                         the fixed body's force over t >= T0 (mean) equals the
                                         buoyancy RHO G AREA within 1 %, its torque is below 1 % of
                                         the buoyancy times HALF_WIDTH
"""
import sys
import numpy as np
import yaml


def table(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def body_of(run):
    with open(f"{run}/config.yaml") as f:
        case = yaml.safe_load(f)
    walls = [(k, w) for k, w in enumerate(case["walls"]) if "body" in w]
    assert len(walls) == 1, "one body expected"
    return case, walls[0][0], walls[0][1]["body"]


def check_fall(run):
    case, k, body = body_of(run)
    b, dim, g = table(f"{run}/bodies.csv"), case["dimension"], np.array(case["gravity"], float)
    t = b["time"]
    worst = 0.0
    for d, axis in enumerate("xyz"[:dim]):
        x0, v0 = body["centre"][d], body["velocity"][d]
        x_exact = x0 + v0 * t + 0.5 * g[d] * t * t
        v_exact = v0 + g[d] * t
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
    print(f"free fall to t = {t[-1]:.3g} s: position/velocity error {worst:.2e}, attitude error {angle_err:.2e}, "
          f"spin error {spin_err:.2e}, largest fluid force {force:.2e}")
    assert force == 0, "the body met the fluid: the case must keep it out of reach"
    assert worst < 1e-11, "position or velocity off the parabola (round-off of some hundred steps)"
    assert spin_err < 1e-11, "spin changed without torque"
    assert angle_err < (1e-11 if dim == 2 else 1e-8), "attitude off the constant spin"


def check_buoyancy(run, rho, g, area, half_width, t0):
    _, k, _ = body_of(run)
    b = table(f"{run}/bodies.csv")
    late = b["time"] >= t0
    dim = 3 if f"body{k}_fz" in b.dtype.names else 2
    up = f"body{k}_f{'xyz'[dim - 1]}"
    expected = rho * g * area
    force = np.mean(b[up][late])
    sideways = max(np.max(abs(b[f"body{k}_f{c}"][late])) for c in "xyz"[:dim - 1])
    torques = [c for c in (f"body{k}_torque", f"body{k}_tx", f"body{k}_ty", f"body{k}_tz") if c in b.dtype.names]
    torque = max(np.max(abs(b[c][late])) for c in torques)
    print(f"buoyancy over t >= {t0} s: {force:.4f} N against rho g A = {expected:.4f} N "
          f"({100 * (force / expected - 1):+.3f} %); largest sideways force {sideways:.3e} N, "
          f"largest |torque| {torque:.3e} N m ({100 * torque / (expected * half_width):.4f} % of F L/2)")
    assert abs(force / expected - 1) < 0.01, "buoyancy off by more than 1 %"
    assert torque < 0.01 * expected * half_width, "torque above 1 % of buoyancy x half-width"


if __name__ == "__main__":
    what, run, *args = sys.argv[1:]
    if what == "fall":
        check_fall(run)
    else:
        check_buoyancy(run, *map(float, args))
