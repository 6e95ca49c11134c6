#!/usr/bin/python3
"""Requirement: vibrotherm-contact drives one MMD cell through a built-in and a
CSV history with the simulator's declared contact options, writes the
documented columns, and its dissipated energy per steady cycle equals the
closed form of PHYSICS.md §3.3 (independent of the code). -help lists every
option and writes nothing; unknown, retired and bad values (options, files,
histories that overflow) exit 2 with one line naming the option and write no
output file.

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
    r = run(["-crack_law", "mmd", "-contact_normal_law", "power", "-contact_power_C", str(C),
             "-contact_power_p", str(p), "-contact_mu", str(mu), "-material_nu", str(nu),
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
    opts = os.path.join(tmp, "law.opts")  # the law from an options file, PETSc syntax
    with open(opts, "w") as f:
        f.write("# Hertz law\n-contact_normal_law power\n-contact_power_C %r\n-contact_power_p %r\n" % (C, p))
    r = run(["-history", hist, "-o", out2, "-contact_a0", "1e-9", "-options_file", opts, "-contact_mu", str(mu),
             "-material_nu", str(nu)])
    check(r.returncode == 0, "CSV history run: " + r.stderr)
    check(open(hist).readline().startswith("t,a,b"), "the history file was modified")
    rows2 = list(csv.DictReader(open(out2)))
    check(abs(float(rows2[-1]["W"]) - float(rows[-1]["W"])) <= 1e-9 * float(rows[-1]["W"]),
          "CSV and built-in histories disagree")

    # The same file through -cell_history.
    out3 = os.path.join(tmp, "cell3.csv")
    r = run(["-cell_history", hist, "-o", out3, "-contact_a0", "1e-9", "-options_file", opts, "-contact_mu",
             str(mu), "-material_nu", str(nu)])
    check(r.returncode == 0 and open(out3).read() == open(out2).read(), "-cell_history differs from -history")

    # -help: every declared option with its default, exit 0, nothing written.
    r = run(["-help", "-o", os.path.join(tmp, "help.csv")])
    check(r.returncode == 0 and not os.path.exists(os.path.join(tmp, "help.csv")), "-help exit %d" % r.returncode)
    for name in ["-crack_law <mmd>", "-contact_power_C <1e18>", "-contact_power_p <1.5>", "-contact_biwa_C <1e11>",
                 "-contact_biwa_m <0.5>", "-contact_linear_k <1e14>", "-contact_table_file", "-material_nu <0.33>",
                 "-crack_linear_kn", "-crack_coulomb_kt", "-crack_mmd_tol", "-history_b_amplitude <5e-9>",
                 "-history_steps_per_cycle <100>", "-options_file", "-history "]:
        check(name in r.stdout, "-help does not list %s" % name)

    # Each bad input: exit 2, one line naming the option or file, no output file.
    bad_csv = os.path.join(tmp, "bad_history.csv")
    with open(bad_csv, "w") as f:
        f.write("t,a,b\n0,1e-8,0\n1e-6,1,5e-9,1e-8\n")  # a decimal comma: 4 fields
    nan_first = os.path.join(tmp, "nan_first.csv")
    with open(nan_first, "w") as f:
        f.write("nan,1e-8,0\n0,1e-8,0\n1e-6,1e-8,1e-9\n")  # not a header: an error
    old_opts = os.path.join(tmp, "old.opts")
    with open(old_opts, "w") as f:
        f.write("-contact_normal_m 0.5\n")
    bad = [(["-contact_mu", "-1"], "-contact_mu must be >= 0"),
           (["-material_nu", "0.7"], "-material_nu must be in (-1, 0.5)"),
           (["-crack_law", "glue"], "-crack_law: unknown value 'glue'"),
           (["-contact_normal_law", "table", "-contact_table_file", os.path.join(tmp, "none.csv")],
            "-contact_table_file " + os.path.join(tmp, "none.csv") + ": cannot open the file"),
           (["-contact_normal_law", "table"], "-contact_table_file: a file is required"),
           (["-history", os.path.join(tmp, "none.csv")], "-history"),
           (["-history", bad_csv], "-history %s line 3: expected 3 fields t,a,b, got 4" % bad_csv),
           (["-history", nan_first], "-history %s line 1: field 1 (t): expected a number, got 'nan'" % nan_first),
           (["-history", nan_first, "-cell_history", nan_first], "-history and -cell_history"),
           (["-history_steps_per_cycle", "2"], "-history_steps_per_cycle must be in [4"),
           (["-history_steps_per_cycle", "-100"], "-history_steps_per_cycle must be in [4"),
           (["-history_cycles", "-2"], "-history_cycles must be > 0"),
           (["-history_cycles", "1e300"], "-history_cycles x -history_steps_per_cycle must be <="),
           (["-history_frequency", "-1e5"], "-history_frequency must be > 0"),
           (["-history_frequency", "inf"], "-history_frequency: expected a number, got 'inf'"),
           (["-history_b_amplitude", "nan"], "-history_b_amplitude: expected a number, got 'nan'"),
           (["-history_b_amplitude", "5e191", "-history_a_offset", "1e192"], "is not finite"),
           (["-history_ramp_cycles", "-1"], "-history_ramp_cycles must be >= 0"),
           (["-contact_power_C", "-1e11"], "-contact_power_C must be > 0, got -1e+11"),
           (["-contact_biwa_C", "-1e11"], "-contact_biwa_C must be > 0, got -1e+11"),
           (["-contact_biwa_C", "0"], "-contact_biwa_C must be > 0, got 0"),
           (["-contact_biwa_m", "1.5"], "-contact_biwa_m must be in (0, 0.9]"),
           (["-contact_power_p", "nan"], "-contact_power_p: expected a number, got 'nan'"),
           (["-contact_linear_k", "1,5e14"], "-contact_linear_k: expected a number, got '1,5e14'"),
           (["-crack_coulomb_kt", "1e14x"], "-crack_coulomb_kt: expected a number, got '1e14x'"),
           (["-crack_mmd_max_breakpoints", "2"], "-crack_mmd_max_breakpoints must be in [3"),
           (["-contact_mu"], "-contact_mu: needs a value"),
           (["-contact_normal_C", "1e11"], "-contact_normal_C was renamed: use -contact_power_C"),
           (["-contact_normal_m", "0.5"], "-contact_normal_m was renamed: use -contact_biwa_m"),
           (["-contact_normal_p", "2"], "-contact_normal_p was renamed: use -contact_power_p"),
           (["-contact_normal_k", "1e14"], "-contact_normal_k was renamed: use -contact_linear_k"),
           (["-contact_normal_table", "t.csv"], "-contact_normal_table was renamed: use -contact_table_file"),
           (["-contact_nu", "0.3"], "-contact_nu was renamed: use -material_nu"),
           (["-options_file", old_opts], "-contact_normal_m was renamed: use -contact_biwa_m"),
           (["-contact_muu", "1"], "unknown option -contact_muu; did you mean -contact_mu?"),
           (["-history_b_amplitud", "1e-9"], "did you mean -history_b_amplitude?"),
           (["-specimen_width", "0.05"], "unknown option -specimen_width")]
    for args, text in bad:
        out_bad = os.path.join(tmp, "bad.csv")
        r = run(args + ["-o", out_bad])
        check(r.returncode == 2 and text in r.stderr and len(r.stderr.strip().splitlines()) == 1
              and r.stderr.startswith("vibrotherm-contact: error: "),
              "bad input %s: exit %d, stderr %r" % (args, r.returncode, r.stderr))
        check(not os.path.exists(out_bad) and not os.path.exists(out_bad + ".partial"),
              "output written despite %s" % args)
    # Without -o the rows go to standard output: none of them for a bad run.
    r = run(["-history_b_amplitude", "5e191", "-history_a_offset", "1e192"])
    check(r.returncode == 2 and r.stdout == "", "overflowing history to stdout: exit %d, %d bytes of rows"
          % (r.returncode, len(r.stdout)))

check.finish()
