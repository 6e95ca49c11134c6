#!/usr/bin/python3
"""Requirement: vibrotherm-contact drives a law with two tangential components (the
3D contract, PHYSICS.md §3.5) from -history_b2_* or a b2 column, writes the second
components (b2, b02, btilde2, T2), and the coulomb law on a circle dissipates the
2D Jenkins closed form 2·2πF√(r² − (F/k)²) per steady cycle to its first-order step
error (independent of the code). A CSV b2 history gives the built-in one's rows; a
b2 of zero along the first axis gives the one-component rows. mmd with two components
(the vector spring bed) on a small circle r = 0.1 s0 dissipates 3.157 times the straight
cycle (PHYSICS.md §3.5).

usage: test_contact_vector_slip.py VIBROTHERM_CONTACT"""
import csv, math, os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, program_runner

check = Checks("vibrotherm-contact two tangential components")
run = program_runner(sys.argv[1])

# Coulomb on the linear normal law: N = k a, F = mu N, F/k_t = 1e-8 m; circle r = 2 F/k_t.
k, a, mu, kt, steps, cycles = 1e14, 1e-8, 0.5, 5e13, 400, 5
F = mu * k * a
r_circle = 2 * F / kt
law = ["-crack_law", "coulomb", "-contact_normal_law", "linear", "-contact_linear_k", str(k), "-contact_mu",
       str(mu), "-crack_coulomb_kt", str(kt), "-history_a_offset", str(a)]
history = ["-history_cycles", str(cycles), "-history_steps_per_cycle", str(steps)]

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "circle.csv")
    r = run(law + history + ["-history_b_amplitude", str(r_circle), "-history_b_phase", "90",
                             "-history_b2_amplitude", str(r_circle), "-o", out])
    check(r.returncode == 0, "circle run: " + r.stderr)
    rows = list(csv.DictReader(open(out)))
    check(list(rows[0].keys()) == ["t", "a", "b", "b2", "b0", "b02", "btilde", "btilde2", "N", "T", "T2", "state",
                                   "dW", "W"], "columns: %s" % list(rows[0].keys()))
    check(len(rows) == cycles * steps + 1, "row count %d" % len(rows))
    exact = 2 * 2 * math.pi * F * math.sqrt(r_circle ** 2 - (F / kt) ** 2)
    last_cycle = float(rows[-1]["W"]) - float(rows[-1 - steps]["W"])
    error = last_cycle / exact - 1
    print("circle at %d steps per cycle: relative error %.4g" % (steps, error))
    check(-2.5 / steps < error < 0, "steady cycle %.9g vs closed form %.9g (error %.3g)" % (last_cycle, exact, error))
    check(all(math.hypot(float(x["T"]), float(x["T2"])) <= mu * float(x["N"]) * (1 + 1e-12) for x in rows),
          "|T| <= mu N")
    check(all(abs(float(x["btilde2"]) - (float(x["b2"]) - float(x["b02"]))) <= 1e-22 for x in rows),
          "btilde2 = b2 - b02")

    # The same circle from a CSV file (header t,a,b,b2): the same rows.
    hist = os.path.join(tmp, "circle_history.csv")
    with open(hist, "w") as f:
        f.write("t,a,b,b2\n")
        for x in rows:
            f.write("%s,%s,%s,%s\n" % (x["t"], x["a"], x["b"], x["b2"]))
    out2 = os.path.join(tmp, "circle2.csv")
    r = run(law + ["-history", hist, "-o", out2])
    check(r.returncode == 0 and open(out2).read() == open(out).read(), "CSV b2 history differs: " + r.stderr)

    # b2 = 0 along the first axis: the one-component rows, column for column.
    line = ["-history_b_amplitude", str(1.5 * r_circle), "-history_cycles", "2"]
    one, two = os.path.join(tmp, "one.csv"), os.path.join(tmp, "two.csv")
    r1 = run(law + line + ["-o", one])
    hist0 = os.path.join(tmp, "line_history.csv")
    with open(hist0, "w") as f:
        f.write("t,a,b,b2\n")
        for x in csv.DictReader(open(one)):
            f.write("%s,%s,%s,0\n" % (x["t"], x["a"], x["b"]))
    r2 = run(law + ["-history", hist0, "-o", two])
    check(r1.returncode == 0 and r2.returncode == 0, "line runs: " + r1.stderr + r2.stderr)
    rows1, rows2 = list(csv.DictReader(open(one))), list(csv.DictReader(open(two)))
    same = len(rows1) == len(rows2) and all(
        all(x[c] == y[c] for c in x) and float(y["T2"]) == 0 and float(y["b02"]) == 0 for x, y in zip(rows1, rows2))
    check(same, "a zero b2 changes the one-component rows")

    # mmd with two components (the vector spring bed): a Hertz bed on a small circle r = 0.1 s0
    # dissipates 3.157 times the straight cycle of amplitude r (here along 45 degrees), s0 = theta mu a;
    # the tenth cycles (the circle settles slowly); the circle's first-order step error is -0.2 % here.
    nu, mu_h, levels, steps_h = 0.3, 0.5, 2000, 2000
    s0 = (2 - nu) / (2 * (1 - nu)) * mu_h * a
    r_small = 0.1 * s0
    hertz = ["-crack_law", "mmd", "-contact_normal_law", "power", "-contact_power_C", "1e18", "-contact_power_p",
             "1.5", "-contact_mu", str(mu_h), "-material_nu", str(nu), "-crack_mmd_levels", str(levels),
             "-history_a_offset", str(a), "-history_cycles", "10", "-history_steps_per_cycle", str(steps_h)]

    def last_cycle_energy(args, name):
        path = os.path.join(tmp, name)
        r = run(hertz + args + ["-o", path])
        check(r.returncode == 0, "mmd %s: %s" % (name, r.stderr))
        rows = list(csv.DictReader(open(path))) if r.returncode == 0 else []
        check(len(rows) == 10 * steps_h + 1 and "T2" in rows[0], "mmd %s: rows" % name)
        return float(rows[-1]["W"]) - float(rows[-1 - steps_h]["W"]) if rows else float("nan")

    half = r_small / math.sqrt(2)
    circle_mmd = last_cycle_energy(["-history_b_amplitude", str(r_small), "-history_b_phase", "90",
                                    "-history_b2_amplitude", str(r_small)], "mmd_circle.csv")
    line_mmd = last_cycle_energy(["-history_b_amplitude", str(half), "-history_b_phase", "90",
                                  "-history_b2_amplitude", str(half), "-history_b2_phase", "90"], "mmd_line.csv")
    ratio = circle_mmd / line_mmd
    print("mmd circle over line at r = 0.1 s0: %.5f (expected 3.157)" % ratio)
    check(abs(ratio - 3.157) < 0.01, "mmd circle over line %.5f, expected 3.157" % ratio)

check.finish()
