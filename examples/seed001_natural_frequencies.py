#!/usr/bin/python3
"""Small-oscillation natural frequencies of the seed 001 bearing (3-DOF model, docs/model.md §4).

Linearises the 3-DOF contact forces of examples/seed001_balls_preload.toml about the static state
under the radial load W and the axial preload P_l, and prints the three natural frequencies
sqrt(eig(K_lin / m)) / 2 pi next to the ball-passage frequency Z f_c, for the ball numbers of
Fig. 3 and the preloads of Fig. 4. Python standard library only.

    examples/seed001_natural_frequencies.py [BEARING_SIM]

The series contact constant K is taken from `bearing-sim info CASE --json` (contact.K), so the
numbers follow the toolkit's Hertz solution; the geometry below repeats the case file.
"""
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "seed001_balls_preload.toml")
SIM = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "build", "lumped", "bearing-sim")

D, DM, FI, FO, PD = 7.96e-3, 54e-3, 0.51256, 0.57915, 0.2e-6  # as in the case file
MASS, MASS_Z, W = 0.6, 0.6, 6.0
SHAFT = 5000.0 / 60.0


def contact_constant():
    out = subprocess.run([SIM, "info", CASE, "--json"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)["contact"]["K"]


def solve3(a, b):
    """Gaussian elimination with partial pivoting, 3x3."""
    m = [row[:] + [b[i]] for i, row in enumerate(a)]
    for c in range(3):
        p = max(range(c, 3), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        for r in range(c + 1, 3):
            f = m[r][c] / m[c][c]
            for k in range(c, 4):
                m[r][k] -= f * m[c][k]
    x = [0.0] * 3
    for r in (2, 1, 0):
        x[r] = (m[r][3] - sum(m[r][k] * x[k] for k in range(r + 1, 3))) / m[r][r]
    return x


def sym_eig3(a):
    """Eigenvalues of a symmetric 3x3 matrix (trigonometric method)."""
    p1 = a[0][1] ** 2 + a[0][2] ** 2 + a[1][2] ** 2
    q = (a[0][0] + a[1][1] + a[2][2]) / 3
    if p1 == 0:
        return sorted([a[0][0], a[1][1], a[2][2]])
    p2 = sum((a[i][i] - q) ** 2 for i in range(3)) + 2 * p1
    p = math.sqrt(p2 / 6)
    b = [[(a[i][j] - (q if i == j else 0)) / p for j in range(3)] for i in range(3)]
    det = (b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1])
           - b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0])
           + b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]))
    phi = math.acos(max(-1.0, min(1.0, det / 2))) / 3
    e1 = q + 2 * p * math.cos(phi)
    e3 = q + 2 * p * math.cos(phi + 2 * math.pi / 3)
    return sorted([e1, 3 * q - e1 - e3, e3])


def frequencies(K, Z, Fz):
    A0 = (FI + FO - 1) * D
    h = PD / 2
    u0, w0 = A0 - h, math.sqrt(h * (2 * A0 - h))
    th = [2 * math.pi * j / Z for j in range(Z)]

    def force(q):  # restoring contact force + applied loads
        x, y, z = q
        f = [0.0, -W, Fz]
        for t in th:
            r = x * math.cos(t) + y * math.sin(t)
            L = math.hypot(w0 + z, u0 + r)
            d = L - A0
            if d <= 0:
                continue
            QL = K * d ** 1.5 / L
            f[0] -= QL * (u0 + r) * math.cos(t)
            f[1] -= QL * (u0 + r) * math.sin(t)
            f[2] -= QL * (w0 + z)
        return f

    def jac(q, e):
        J = [[0.0] * 3 for _ in range(3)]
        for i in range(3):
            qp, qm = list(q), list(q)
            qp[i] += e
            qm[i] -= e
            fp, fm = force(qp), force(qm)
            for r in range(3):
                J[r][i] = -(fp[r] - fm[r]) / (2 * e)
        return J

    q = [0.0, -5e-7, 3e-5 if Fz > 0 else -w0]
    for _ in range(200):
        f = force(q)
        if math.sqrt(sum(v * v for v in f)) < 1e-11:
            break
        step = solve3(jac(q, 1e-10), f)
        lam, n0 = 1.0, math.sqrt(sum(v * v for v in f))
        while lam > 1e-8:
            trial = [q[i] + lam * step[i] for i in range(3)]
            if math.sqrt(sum(v * v for v in force(trial))) < n0:
                break
            lam /= 2
        q = [q[i] + lam * step[i] for i in range(3)]
    J = jac(q, 1e-11)
    S = [[(J[i][j] + J[j][i]) / 2 / math.sqrt((MASS_Z if i == 2 else MASS) * (MASS_Z if j == 2 else MASS))
          for j in range(3)] for i in range(3)]
    fn = [math.sqrt(abs(v)) / (2 * math.pi) for v in sym_eig3(S)]
    alpha = math.atan2(w0 + q[2], u0)  # contact angle set by the preload (radial offset aside)
    fc = 0.5 * SHAFT * (1 - D * math.cos(alpha) / DM)
    return q, fn, Z * fc, math.degrees(alpha)


def main():
    K = contact_constant()
    print(f"K = {K:.5g} N/m^1.5; radial mass {MASS} kg, axial mass {MASS_Z} kg; W = {W} N")
    print(f"{'Z':>3} {'P_l[N]':>7} {'y[um]':>8} {'alpha[deg]':>10} {'BPF=Z*fc[Hz]':>13} "
          f"{'f_n (3 modes) [Hz]':>28}")
    for Z, Fz in [(z, 10.0) for z in range(5, 16)] + [(8, 0.0), (8, 30.0), (8, 50.0), (8, 100.0),
                                                       (9, 0.0), (5, 0.0)]:
        q, fn, bpf, alpha = frequencies(K, Z, Fz)
        print(f"{Z:>3} {Fz:>7.0f} {q[1] * 1e6:>8.4f} {alpha:>10.3f} {bpf:>13.1f}   "
              + "  ".join(f"{v:8.1f}" for v in fn))


if __name__ == "__main__":
    main()
