#!/usr/bin/python3
"""Requirement: vibrotherm-contact drives one MMD cell through a built-in and a
CSV history with the simulator's -contact_* options, writes the documented
columns, and its dissipated energy per steady cycle equals the closed form of
PHYSICS.md §3.3 (independent of the code); bad options are rejected by name.

usage: test_contact_app.py VIBROTHERM_CONTACT"""
import csv, math, os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks

exe = sys.argv[1]
check = Checks("vibrotherm-contact")


def run(args):
    return subprocess.run([exe] + args, capture_output=True, text=True)


with tempfile.TemporaryDirectory() as tmp:
    # Hertz law N = C a^1.5, constant a, b = b* sin: two cycles, W of the second.
    C, p, mu, nu, a, frac, steps = 1e18, 1.5, 0.5, 0.3, 2e-8, 0.6, 2000
    theta = (2 - nu) / (2 * (1 - nu))
    bs = frac * theta * mu * a
    out = os.path.join(tmp, "cell.csv")
    r = run(["-crack_law", "mmd", "-contact_normal_law", "power", "-contact_normal_C", str(C),
             "-contact_normal_p", str(p), "-contact_mu", str(mu), "-contact_nu", str(nu),
             "-history_a_offset", str(a), "-history_b_amplitude", str(bs), "-history_cycles", "2",
             "-history_steps_per_cycle", str(steps), "-o", out])
    check(r.returncode == 0, "built-in history run: " + r.stderr)
    rows = list(csv.DictReader(open(out)))
    check(list(rows[0].keys()) == ["t", "a", "b", "b0", "btilde", "N", "T", "state", "dW", "W"],
          "columns: %s" % list(rows[0].keys()))
    check(len(rows) == 2 * steps + 1, "row count %d" % len(rows))
    N = lambda x: C * x ** p if x > 0 else 0.0
    M = lambda x: C * x ** (p + 1) / (p + 1) if x > 0 else 0.0
    u = bs / (theta * mu)
    W_ref = 8 * theta * mu ** 2 * (u * (N(a) + N(a - u)) - 2 * (M(a) - M(a - u)))
    W_cycle = float(rows[-1]["W"]) - float(rows[steps]["W"])
    check(abs(W_cycle - W_ref) <= 1e-6 * W_ref, "cycle energy %.9g vs closed form %.9g" % (W_cycle, W_ref))
    check(all(float(r["dW"]) >= 0 for r in rows), "dW >= 0")
    check({r["state"] for r in rows} <= {"loss", "slide", "partial", "stick"}, "state names")
    check(all(abs(float(r["T"])) <= mu * float(r["N"]) * (1 + 1e-12) for r in rows), "|T| <= mu N")

    # The same history from a CSV file gives the same result (-history, -contact_a0 offset).
    hist = os.path.join(tmp, "history.csv")
    with open(hist, "w") as f:
        f.write("t,a,b\n")
        for r_ in rows:
            f.write("%s,%.17g,%s\n" % (r_["t"], float(r_["a"]) - 1e-9, r_["b"]))
    out2 = os.path.join(tmp, "cell2.csv")
    r = run(["-history", hist, "-o", out2, "-contact_a0", "1e-9", "-contact_normal_law", "power",
             "-contact_normal_C", str(C), "-contact_normal_p", str(p), "-contact_mu", str(mu),
             "-contact_nu", str(nu)])
    check(r.returncode == 0, "CSV history run: " + r.stderr)
    check(open(hist).readline().startswith("t,a,b"), "the history file was modified")
    rows2 = list(csv.DictReader(open(out2)))
    check(abs(float(rows2[-1]["W"]) - float(rows[-1]["W"])) <= 1e-9 * float(rows[-1]["W"]),
          "CSV and built-in histories disagree")

    for args, text in [(["-contact_mu", "-1"], "-contact_mu must be >= 0"),
                       (["-contact_nu", "0.7"], "-contact_nu must be in (-1, 0.5)"),
                       (["-crack_law", "glue"], "-crack_law: unknown value 'glue'"),
                       (["-contact_normal_law", "table", "-contact_normal_table", os.path.join(tmp, "none.csv")],
                        "-contact_normal_table"),
                       (["-history", os.path.join(tmp, "none.csv")], "-history"),
                       (["-history_steps_per_cycle", "2"], "-history_steps_per_cycle")]:
        r = run(args + ["-o", os.path.join(tmp, "bad.csv")])
        check(r.returncode == 2 and text in r.stderr and len(r.stderr.strip().splitlines()) == 1,
              "bad input %s: exit %d, stderr %r" % (args, r.returncode, r.stderr))
        check(not os.path.exists(os.path.join(tmp, "bad.csv")), "output written despite %s" % args)

check.finish()
