#!/usr/bin/python3
"""`bearing-sim info` with [lubricant] (issue 43): film.inner and film.outer carry the four film
fields (central_thickness [m], minimum_thickness [m], lambda, entrainment_speed [m/s]) and the
units map names them; the acceptance case — a 6205 at 1800 rpm under 2 kN radial, 0.02 Pa s,
2e-8 1/Pa — has each race's central film within 5 % of Hamrock & Dowson's formula computed here
by hand from the preset's geometry (R_x = D (d_m -/+ D) / (2 d_m), R_y = f D / (2 f - 1),
k = 1.0339 (R_y/R_x)^0.636, E' = E / (1 - nu^2), u = omega (d_m^2 - D^2) / (4 d_m)) at the most
loaded ball of info's own static solution; the text shows the section; without [lubricant] no
film block and no damping.

    check_info_film.py BEARING_SIM
"""
import json
import math
import subprocess
import sys

# The 6205 preset (lumped/src/core/presets.cc): D 0.3126 in, d_m 1.537 in, f 0.52, steel
# E = 2.08e11 Pa, nu = 0.3, contact angle 0.
D = 0.3126 * 0.0254
DM = 1.537 * 0.0254
F = 0.52
E_REDUCED = 2.08e11 / (1 - 0.3 ** 2)
ETA, ALPHA, SIGMA = 0.02, 2e-8, 0.1e-6
OMEGA = 1800 * 2 * math.pi / 60

BASE = ["--set", "bearing.preset=6205", "--set", "operation.speed=1800 rpm",
        "--set", 'operation.load=["0 N", "-2000 N"]']
LUBRICANT = ["--set", "lubricant.viscosity=0.02 Pa s",
             "--set", "lubricant.pressure_viscosity=2e-8 1/Pa",
             "--set", "lubricant.roughness=0.1 um"]
FIELDS = ["central_thickness", "minimum_thickness", "lambda", "entrainment_speed"]


def hamrock_dowson(load, race):
    """h_c [m] by Hamrock & Dowson (1977) at the load [N] on `race`."""
    sign = -1 if race == "inner" else 1
    rx = D * (DM + sign * D) / (2 * DM)
    ry = F * D / (2 * F - 1)
    k = 1.0339 * (ry / rx) ** 0.636
    u = OMEGA * (DM ** 2 - D ** 2) / (4 * DM)
    U = ETA * u / (E_REDUCED * rx)
    G = ALPHA * E_REDUCED
    W = load / (E_REDUCED * rx ** 2)
    return rx * 2.69 * U ** 0.67 * G ** 0.53 * W ** -0.067 * (1 - 0.61 * math.exp(-0.73 * k)), u


def info(sim, extra):
    out = subprocess.run([sim, "info"] + BASE + extra, check=True, capture_output=True,
                         text=True).stdout
    return out


def main():
    sim = sys.argv[1]
    j = json.loads(info(sim, LUBRICANT + ["--json"]))
    film = j["film"]
    q_max = max(j["stiffness"]["ball_loads"])
    for race in ("inner", "outer"):
        f = film[race]
        for key in FIELDS + ["load", "stiffness", "damping", "ellipticity_within_fit"]:
            assert key in f, (race, key, f)
        for key in FIELDS:
            assert isinstance(f[key], float) and f[key] > 0, (race, key, f[key])
            assert ("film." + key) in j["units"], key
        assert j["units"]["film.central_thickness"] == "m"
        assert j["units"]["film.entrainment_speed"] == "m/s"
        # The inner race's load is the static solution's largest; the outer one's adds the
        # ball's centrifugal load (a fraction of a newton here).
        assert abs(f["load"] - q_max) <= 1e-3 * q_max, (race, f["load"], q_max)
        h_c, u = hamrock_dowson(q_max, race)
        assert abs(f["central_thickness"] / h_c - 1) < 0.05, (race, f["central_thickness"], h_c)
        assert abs(f["entrainment_speed"] / u - 1) < 1e-9, (race, f["entrainment_speed"], u)
        assert abs(f["lambda"] - f["minimum_thickness"] / SIGMA) < 1e-9 * f["lambda"]
        assert f["minimum_thickness"] < f["central_thickness"]
        print("%s: h_c %.5g m (hand %.5g m, %+.3f %%), h_min %.4g m, lambda %.4g, u %.5g m/s, "
              "k_f %.4g N/m, c %.4g N s/m, within fit %s" % (
                  race, f["central_thickness"], h_c, 100 * (f["central_thickness"] / h_c - 1),
                  f["minimum_thickness"], f["lambda"], f["entrainment_speed"], f["stiffness"],
                  f["damping"], f["ellipticity_within_fit"]))
    damping = j["stiffness"]["damping"]
    assert len(damping) == 5 and damping[1][1] > 0, damping
    assert j["units"]["stiffness.damping"] == "stiffness.damping_units"
    assert j["stiffness"]["damping_units"][0][0] == "N*s/m"
    assert j["stiffness"]["damping_units"][3][4] == "N*m*s/rad"
    text = info(sim, LUBRICANT)
    assert "EHL film at the most loaded ball" in text and "central film h_c [um]" in text, text
    # Without [lubricant]: no film block, no damping.
    dry = json.loads(info(sim, ["--json"]))
    assert "film" not in dry and "damping" not in dry["stiffness"], dry.keys()
    assert not any(k.startswith("film.") for k in dry["units"])
    assert "EHL film" not in info(sim, [])
    print("K with the film: k_xx %.6g, k_yy %.6g N/m; dry: k_xx %.6g, k_yy %.6g N/m" % (
        j["stiffness"]["matrix"][0][0], j["stiffness"]["matrix"][1][1],
        dry["stiffness"]["matrix"][0][0], dry["stiffness"]["matrix"][1][1]))
    print("C diagonal [N s/m, N s/m, N s/m, N m s/rad, N m s/rad]: " +
          ", ".join("%.5g" % damping[i][i] for i in range(5)))


if __name__ == "__main__":
    main()
