"""Which excitation makes a defect visible: the LDR study (scripts/study ldr).

1. modes     the scene's natural modes in the band (-modes; the crack open), each with
             its defect participation (the share of strain energy near the crack);
2. candidates the modes of the band ranked by participation, and off-resonance frequencies
             in the widest gaps between them, spread over the band;
3. common power the common input power: the scene's own drive's (its frequency and amplitude);
             each candidate run over the test time T (harmonic start, continuation) first at
             the scene's amplitude (beside the scene's own run: it does not need the power),
             then at the amplitude that puts the common power in, by the power law measured
             between its last two runs (exponent 2 at first) or, once runs lie on both sides,
             by the local law of the side nearer the power (else interpolated, else bisected),
             until within 10 % (up to 6 more runs); a run at a frequency already run starts
             warm in the saved steady state of the nearest drive (-wave_start state); the
             candidates searched side by side, the resonances first, `jobs` runs at once;
4. verdict   per candidate: input and friction power (means over the test: the energy ledger at
             T over T; the summary's last-periods figures kept as steady_*), efficiency, the defect's own peak rise
             on the camera's face within T, its SNR, contrast against the background heat,
             detectable, detection time; the LDR gain = the LDR's efficiency over the best
             non-LDR candidate's;
5. thresholds at the best few frequencies (the defect's SNR at the common power): the smallest
             drive that detects within T, bracketed on real runs from the fitted amplitude law
             (amplitude_law.py), then verified: 1.25x detects, 0.75x does not; started on idle
             slots while the last searches run (a threshold needs only its own candidate's runs).
Writes study.json and the plots (ldr_plots.py) into the output directory.
"""
import json
import math
import os
import time
from concurrent.futures import FIRST_COMPLETED, ThreadPoolExecutor, wait

import package  # noqa: F401  (scripts/vibrotherm on the path)
import vibrotherm as vt
from amplitude_law import PowerLaw, threshold_amplitude


def margin(point, criteria):
    """How far a run is from detection: its SNR and contrast over the needed ones, the smaller (1: just)."""
    snr = (point["snr"] or 0.0) / criteria[0]
    contrast = point["contrast"]
    if contrast is None or criteria[1] <= 0:
        return snr
    return min(snr, contrast / criteria[1])


WAVE_STATE = "wave_state.h5"  # a run's steady wave state (-periodic_save_state), a warm start for the next
WARM_RATIO = 2.0  # a warm start only from a drive within this factor (measured: 1.25x 2.7x faster, 3.6x none)
POWER_TOLERANCE = 0.1  # a candidate's measured input power within 10 % of the common one
RESCALE_ROUNDS = 6  # runs toward it after the first


def power_jump(runs, target):
    """Why a candidate missed the common power: the power jumps across it between two drives (the
    defect starts clapping), or the runs did not get there."""
    below = [r for r in runs if 0 < r["input_power"] < target]
    above = [r for r in runs if r["input_power"] > target]
    if below and above:
        lo, hi = max(below, key=lambda r: r["amplitude"]), min(above, key=lambda r: r["amplitude"])
        if lo["amplitude"] < hi["amplitude"]:
            return "the input power jumps from %.3g to %.3g between %.4g and %.4g m (the defect starts clapping)" % (
                lo["input_power"], hi["input_power"], lo["amplitude"], hi["amplitude"])
    return "the rescaling did not converge"


def detection_rank(c):
    """How a candidate ranks for detection: at the common power first (one that missed it, a clapping
    onset, is not comparable), then by the defect's SNR. Larger is better."""
    return c.get("at_common_power", True), c["snr"] or 0.0


class StudyError(RuntimeError):
    """A study that cannot run as asked (one line, no traceback)."""



def modes_in_band(runner, band, log):
    """(frequency, participation) of the scene's modes in the band, asking SLEPc for more until it is covered."""
    centre = math.sqrt(band[0] * band[1])
    n = 24
    while True:
        run = runner.run("modes_%d" % n, {"modes": None, "modes_n": n, "modes_target_frequency": centre})
        found = [(m["frequency"], m["participation"]) for m in run.summary.get("modes", [])]
        found = [(f, p) for f, p in found if f > 1e-3 * centre and p is not None and math.isfinite(p)]
        covered = any(f <= band[0] for f, _ in found) and any(f >= band[1] for f, _ in found)
        if covered or n >= 96 or len(found) < n - 2:
            modes = sorted((f, p) for f, p in found if band[0] <= f <= band[1])
            log("modes: %d in the band %g-%g Hz (%d sought near %.0f Hz)" % (len(modes), band[0], band[1], n, centre))
            return modes
        n *= 2


def candidates(modes, band, n_modes, n_off):
    """The modes of largest participation, and off-resonance frequencies at the (geometric) centres of
    the widest gaps between the band's modes and edges, one per gap; when the band has fewer gaps
    than n_off, the widest halves left are split again (a band with few modes still gets n_off)."""
    chosen = sorted(modes, key=lambda m: -m[1])[:n_modes]
    picks = [{"frequency": f, "participation": p, "mode": True} for f, p in chosen]
    edges = [band[0]] + sorted(f for f, _ in modes) + [band[1]]
    unpicked = sorted(((a, b) for a, b in zip(edges, edges[1:]) if b > a * 1.02), key=lambda g: g[0] / g[1])
    halves = []  # the two sides of every gap picked so far
    for _ in range(n_off):
        if unpicked:
            a, b = unpicked.pop(0)
        elif halves:
            a, b = max(halves, key=lambda g: g[1] / g[0])
            halves.remove((a, b))
        else:
            break
        middle = math.sqrt(a * b)
        halves += [(a, middle), (middle, b)]
        picks.append({"frequency": round(middle, 2), "participation": None, "mode": False})
    return sorted(picks, key=lambda c: c["frequency"])


class LdrStudy:
    def __init__(self, runner, options, band, duration, log=print, n_modes=5, n_off=None, thresholds=3,
                 ldr_participation=0.8, power=None):
        self.runner, self.options, self.band, self.duration, self.log = runner, options, band, duration, log
        self.n_modes, self.n_off, self.n_thresholds = n_modes, n_off, thresholds
        self.ldr_participation, self.power = ldr_participation, power
        self.amplitude = float(options.get("source_amplitude", "1e-7"))
        self.points = {}  # frequency -> the runs' figures at every amplitude tried
        self._reference = None  # the scene's own run (its input power: the common power), while it runs
        self.camera = self.camera_within(duration, options, log)

    @staticmethod
    def camera_within(duration, options, log):
        """The camera's settings for a test of `duration`: the scene's, unless it would take fewer
        than 10 frames in the test (a 100 fps camera films a 10 ms test once, at its start): then
        10 frames over the test, each integrating at most half its period (said once)."""
        fps = float(options.get("camera_fps", "100"))
        if fps * duration >= 10:
            return {"camera": None}
        fps = 10.0 / duration
        integration = min(float(options.get("camera_integration", "1e-3")), 0.5 / fps)
        log("camera: %g frames in the test at the scene's %s fps; filmed at %g fps, %g s integration instead" % (
            float(options.get("camera_fps", "100")) * duration, options.get("camera_fps", "100"), fps, integration))
        return {"camera": None, "camera_fps": fps, "camera_integration": integration}

    # --- runs ---------------------------------------------------------------------------
    def overrides(self, frequency, amplitude):
        """A candidate's run: the test time T of excitation, the camera's verdict at its end. Each run saves
        its steady wave state; a run at a frequency already run starts warm in the nearest drive's state."""
        T = self.duration
        run = {"source_frequency": frequency, "source_amplitude": amplitude, "source_duration": T,
               "final_time": T, "output_times": repr(T), "probe_every": 1000, "crack_state_every": 0,
               "periodic_save_state": self.state_file(self.name(frequency, amplitude)), **self.camera}
        warm = self.warm_state(frequency, amplitude)
        if warm:
            run.update({"wave_start": "state", "wave_start_state": warm})
        return run

    def state_file(self, run_name):
        return os.path.join(self.runner.output_dir, run_name, WAVE_STATE)

    def warm_state(self, frequency, amplitude):
        """The saved steady state of the run at this frequency whose drive is nearest (in ratio) to amplitude,
        within WARM_RATIO, or None (a harmonic start). Scaled to the new drive, it leaves only the mismatch
        between neighbouring drives to settle, where the harmonic start leaves a clapping crack the whole way
        from its stuck linearisation (a Q = 1000 plate settles over Q/(pi f), 50 ms at 6 kHz: most of a slow
        run's cost). Farther apart the layer's regime differs (a clapping state scaled down to a stuck drive
        is no steady state of it, where the harmonic start is exact)."""
        saved = [p for p in self.points.get(frequency, []) if 1 / WARM_RATIO <= p["amplitude"] / amplitude <= WARM_RATIO
                 and os.path.exists(os.path.join(self.runner.output_dir, p["run"], WAVE_STATE))]
        if not saved:
            return None
        nearest = min(saved, key=lambda p: (abs(math.log(p["amplitude"] / amplitude)), p["amplitude"]))
        return os.path.join(self.runner.output_dir, nearest["run"], WAVE_STATE)

    @staticmethod
    def name(frequency, amplitude):
        return "f%.2f_a%.6g" % (frequency, amplitude)

    def figures(self, run, frequency):
        s = run.summary
        camera = s.get("camera", {})
        # Powers as means over the whole test (the energy ledger at T / T; a continuation books its
        # continued periods there too), not the summary's last periods: a Q = 1000 plate re-settles
        # for Q/(pi f) (50 ms at 6 kHz) after the harmonic start's stuck linearisation, and over a
        # short test its last periods may even give energy back. The camera sees the test's heat.
        end = vt.load(run.dir).energy().iloc[-1]
        mean = {key: float(end[column]) / self.duration for key, column in
                (("input_power", "work_source"), ("friction_power", "dissipated"), ("damping_power", "damped"))}
        point = dict(mean, frequency=frequency, amplitude=run.overrides["source_amplitude"],
                     efficiency=mean["friction_power"] / mean["input_power"] if mean["input_power"] > 0 else None,
                     steady_input_power=s.get("input_power"), steady_efficiency=s.get("thermosonic_efficiency"),
                     peak_rise=camera.get("defect_peak_rise"), total_peak_rise=camera.get("peak_rise"),
                     snr=s.get("camera_peak_snr"), contrast=s.get("camera_defect_contrast"),
                     detectable=bool(s.get("camera_detectable")),
                     detection_time=s.get("camera_detection_time") if s.get("camera_detectable") else None,
                     run=os.path.relpath(run.dir, self.runner.output_dir), wall_time=s.get("wall_time_s"))
        self.points.setdefault(frequency, []).append(point)
        return point

    def run_all(self, pairs, priority=None):
        """(frequency, amplitude) pairs of one frequency, run `jobs` at a time: their figures. Waiting for a slot,
        the runs of the frequency whose runs took longest go first (the longest jobs first: its search is
        the study's critical path)."""
        if priority is None:
            priority = self.priority(pairs[0][0])
        runs = self.runner.map([(self.name(f, a), self.overrides(f, a)) for f, a in pairs], priority=priority)
        return [self.figures(run, f) for run, (f, _) in zip(runs, pairs)]

    def priority(self, frequency):
        """A run's place in the queue for a slot (lower first): minus the longest run at its frequency so far."""
        return -max((p["wall_time"] or 0.0 for p in self.points.get(frequency, [])), default=0.0)

    # --- the study ------------------------------------------------------------------------
    def reference_power(self, fallback_frequency):
        """The common input power: the scene's own drive's (its frequency and amplitude)."""
        own = float(self.options.get("source_frequency", fallback_frequency))
        (reference,) = self.run_all([(own, self.amplitude)], priority=-math.inf)  # every search waits for it
        if not reference["input_power"] or reference["input_power"] <= 0:
            raise StudyError("the scene's drive puts no power in (input_power %r): is there a source?"
                             % reference["input_power"])
        return reference["input_power"]

    def searches_and_thresholds(self, picks):
        """Every candidate at the common power, each searched on its own thread (a slow run holds up only its
        own candidate), then the thresholds at the best few. The scene's own run, which sets the common power,
        runs beside the candidates' first runs (at the scene's amplitude, they do not need it), and the
        resonances are asked first (their runs settle slowest). A threshold needs only its own candidate's
        runs: once fewer searches are left than run slots, the best candidates found so far get theirs on
        the idle slots; a late candidate that ranks among the best gets its own after."""
        with ThreadPoolExecutor(max_workers=2 * len(picks) + 1) as pool:
            if self.power is None:
                self._reference = pool.submit(self.reference_power, picks[0]["frequency"])
            # The modes' first runs wait with a higher priority (search_power); submitted first, they also
            # arrive first at the slots free at the start.
            order = sorted(picks, key=lambda c: not c["mode"])
            searching = {pool.submit(self.search_power, c["frequency"], c["mode"]): c for c in order}
            found, started, criteria = [], {}, None
            while searching:
                done, _ = wait(searching, return_when=FIRST_COMPLETED)
                for future in done:
                    found.append(self.take(searching.pop(future), *future.result()))
                criteria = criteria or self.criteria(found)
                if len(searching) < self.runner.jobs:
                    self.start_thresholds(pool, self.best(found), criteria, started)
            best = self.best(picks)
            self.start_thresholds(pool, best, criteria, started)
            unused = sorted(set(started) - {c["frequency"] for c in best})
            if unused:
                self.log("thresholds at %s not reported: a later candidate ranks above" % ", ".join(
                    "%.0f Hz" % f for f in unused))
            return criteria, [started[c["frequency"]].result() for c in best]

    def start_thresholds(self, pool, best, criteria, started):
        fresh = [c for c in best if c["frequency"] not in started]
        if fresh:
            self.log("thresholds at " + ", ".join("%.0f Hz" % c["frequency"] for c in fresh))
        for c in fresh:
            started[c["frequency"]] = pool.submit(self.threshold, c["frequency"], criteria)

    def best(self, picks):
        """The best few candidates for a threshold: ranked by the defect's SNR at equal power (a candidate
        that missed the common power, a clapping onset, comes last)."""
        return sorted(picks, key=detection_rank, reverse=True)[:self.n_thresholds]

    def take(self, c, p, runs):
        """A candidate's figures from its run nearest the common power."""
        c.update({k: p[k] for k in ("amplitude", "input_power", "friction_power", "efficiency", "steady_input_power",
                                    "steady_efficiency", "peak_rise",
                                    "snr", "contrast", "detectable", "detection_time", "run",
                                    "total_peak_rise", "damping_power")})
        c["power_error"] = p["input_power"] / self.power - 1.0
        c["at_common_power"] = abs(c["power_error"]) <= POWER_TOLERANCE
        if not c["at_common_power"]:
            self.log("  %.0f Hz: not at the common power after %d runs (closest %.3g at %.3g m): %s" % (
                c["frequency"], len(runs), p["input_power"], p["amplitude"], power_jump(runs, self.power)))
        return c

    def common(self):
        """The common input power, once the scene's own run has measured it."""
        if self.power is None:
            self.power = self._reference.result()
        return self.power

    def search_power(self, frequency, mode=False):
        """Runs at one frequency until one puts the common power in (within 10 %): the first at the
        scene's own drive amplitude (a lift-off clapping layer takes far more power than its stuck
        linearisation, so a linear probe's A^2 rule would land near the clapping onset, where runs
        take longest to settle), then each at next_amplitude. The run nearest the power, and all runs."""
        runs = self.run_all([(frequency, self.amplitude)], priority=-1.0 if mode else 0.0)  # resonances settle slowest
        self.common()

        def nearest():
            return min(runs, key=lambda q: abs(math.log(q["input_power"] / self.power))
                       if q["input_power"] > 0 else math.inf)
        for round_ in range(RESCALE_ROUNDS):
            if abs(nearest()["input_power"] / self.power - 1.0) <= POWER_TOLERANCE:
                break
            guess = self.next_amplitude(runs)
            hedge = math.sqrt(guess * nearest()["amplitude"])  # half the step (in log): a second guess
            # Not in the last round: a second guess shortens the next round, and there is none (a chaotic
            # run beside the last one may take several times as long: 317 s against 107 s measured).
            second = round_ < RESCALE_ROUNDS - 1 and self.hedges(frequency, guess, hedge)
            runs += self.run_all([(frequency, guess)] + ([(frequency, hedge)] if second else []))
        return nearest(), runs

    def hedges(self, frequency, guess, hedge):
        """Whether to run the second guess beside the first: when a run slot would be left idle (once fewer
        searches than slots are left), or, resuming a study, when it was run then (a finished first guess
        without its second was run alone: the search goes on as it went)."""
        if self.name(frequency, hedge) == self.name(frequency, guess):
            return False
        finished = [self.runner.finished(self.name(frequency, a), self.overrides(frequency, a)) for a in (guess, hedge)]
        if finished[0] or finished[1]:
            return bool(finished[1])
        return self.runner.idle_slots() > 1

    def next_amplitude(self, runs):
        """The next drive toward the common power. Between the closest runs below and above it: the local
        power law of the side nearer the power (its two runs nearest the bracket: the power curves, and a chord
        over the bracket misses where it does), from that end, if it lands inside; else the log-linear
        interpolation of power against amplitude, if not near an end; else the bracket bisected in log (a
        clapping onset makes the power jump). With one side only, the power law measured between the last two
        runs (2 at first: linear)."""
        target = math.log(self.power)
        below = sorted((r for r in runs if 0 < r["input_power"] < self.power), key=lambda r: -r["amplitude"])
        above = sorted((r for r in runs if r["input_power"] > self.power), key=lambda r: r["amplitude"])
        if not (below and above and below[0]["amplitude"] < above[0]["amplitude"]):
            return self.power_law_step(runs[-1], runs[-2] if len(runs) > 1 else None)
        a0, a1 = math.log(below[0]["amplitude"]), math.log(above[0]["amplitude"])
        p0, p1 = math.log(below[0]["input_power"]), math.log(above[0]["input_power"])
        near = below if target - p0 < p1 - target else above
        if len(near) > 1:
            x = math.log(self.power_law_step(near[0], near[1]))
            if a0 + 0.05 * (a1 - a0) <= x <= a1 - 0.05 * (a1 - a0):
                return math.exp(x)
        x = a0 + (target - p0) * (a1 - a0) / (p1 - p0)
        if not a0 + 0.1 * (a1 - a0) <= x <= a1 - 0.1 * (a1 - a0):
            x = 0.5 * (a0 + a1)
        return math.exp(x)

    def power_law_step(self, a, b):
        """The drive that puts the common power in by the power law between runs a and b (exponent 2 without b:
        linear), from a; the exponent within [1, 6]."""
        exponent = 2.0
        if b and a["input_power"] > 0 and b["input_power"] > 0 and a["amplitude"] != b["amplitude"]:
            r = math.log(a["input_power"] / b["input_power"]) / math.log(a["amplitude"] / b["amplitude"])
            exponent = min(max(r, 1.0), 6.0) if math.isfinite(r) else 2.0
        return a["amplitude"] * (self.power / a["input_power"]) ** (1.0 / exponent)

    def threshold(self, frequency, criteria):
        """The smallest drive that detects within T at this frequency, bracketed on runs, then verified."""
        below, above = 0.0, math.inf  # the largest amplitude seen not detecting, the smallest detecting
        for p in self.points[frequency]:
            if p["detectable"]:
                above = min(above, p["amplitude"])
            else:
                below = max(below, p["amplitude"])
        estimate, law = None, {}
        for _ in range(4):
            estimate, law = threshold_amplitude(self.points[frequency], *criteria)
            if estimate is None:
                break
            bracketed = below > 0 and math.isfinite(above)
            if bracketed and not below < estimate < above:  # the law points outside the bracket: halve it (in log)
                estimate = math.sqrt(below * above)
            if bracketed and above / below <= 1.25:
                break
            (point,) = self.run_all([(frequency, estimate)])
            if point["detectable"]:
                above = min(above, estimate)
            else:
                below = max(below, estimate)
            if 0.85 <= margin(point, criteria) <= 1.18:  # the law landed on it: refit once more and stop
                estimate, law = threshold_amplitude(self.points[frequency], *criteria)
                break
        if estimate is None:
            return {"frequency": frequency, "input_power": None, "amplitude": None, "verified": False,
                    "p": law.get("p"), "q": law.get("q"),
                    "note": "no drive detects: the background grows faster than the defect's heat"}
        used = list(self.points[frequency])
        low, high = self.run_all([(frequency, 0.75 * estimate), (frequency, 1.25 * estimate)])
        power = PowerLaw([p["amplitude"] for p in used], [p["input_power"] for p in used], 2.0)
        friction = PowerLaw([p["amplitude"] for p in used], [p["friction_power"] for p in used], 3.0)
        # The law against the two runs it did not use.
        law_error = max((abs(friction(p["amplitude"]) / p["friction_power"] - 1.0) for p in (low, high)
                         if p["friction_power"]), default=None)
        return {"frequency": frequency, "amplitude": estimate, "input_power": power(estimate),
                "verified": bool(high["detectable"] and not low["detectable"]), "p": law.get("p"),
                "q": law.get("q"), "law_error": law_error, "runs_used": len(used), "at_0.75": low, "at_1.25": high}

    def run(self):
        began = time.time()
        modes = modes_in_band(self.runner, self.band, self.log)
        if not modes:
            raise StudyError("--band %g,%g holds no mode of the scene: widen it (the scene's modes: -modes)" % tuple(
                self.band))
        # None: 4 off-resonance frequencies, or more so that a band with few modes still has 8 candidates.
        n_off = self.n_off if self.n_off is not None else max(4, 8 - min(len(modes), self.n_modes))
        picks = candidates(modes, self.band, self.n_modes, n_off)
        self.log("candidates: " + ", ".join("%.0f Hz%s" % (c["frequency"], " (mode, %.2f)" % c["participation"]
                                                            if c["mode"] else "") for c in picks))
        criteria, thresholds = self.searches_and_thresholds(picks)
        ldr = self.ldr(picks)
        return self.record(modes, picks, ldr, thresholds, criteria, time.time() - began)

    def ldr(self, picks):
        """The LDR (the candidate mode of largest participation, when it is >= ldr_participation) and its gain."""
        modes = [c for c in picks if c["mode"] and c["participation"] >= self.ldr_participation]
        for c in picks:
            c["ldr"] = False
        if not modes:
            return {"frequency": None, "gain": None}
        lead = max(modes, key=lambda c: c["participation"])
        for c in modes:
            c["ldr"] = True
        others = [c["efficiency"] for c in picks
                  if not c["ldr"] and c["efficiency"] is not None and c.get("at_common_power", True)]
        gain = lead["efficiency"] / max(others) if others and max(others) > 0 else None
        return {"frequency": lead["frequency"], "gain": gain}

    def criteria(self, found):
        """The camera's detection criteria (SNR, contrast), from any candidate's run."""
        with open(os.path.join(self.runner.output_dir, found[0]["run"], "summary.json")) as f:
            camera = json.load(f).get("camera", {})
        return camera.get("detect_snr", 5.0), camera.get("detect_contrast", 1.0)

    def record(self, modes, picks, ldr, thresholds, criteria, seconds):
        keys = ("frequency", "participation", "input_power", "friction_power", "efficiency", "steady_input_power",
                "steady_efficiency", "peak_rise", "snr",
                "detectable", "detection_time", "amplitude", "contrast", "total_peak_rise", "damping_power", "mode",
                "ldr", "power_error", "at_common_power", "run")
        return {"options_file": self.runner.options_file, "band": list(self.band), "duration": self.duration,
                "common_input_power": self.power, "detect_snr": criteria[0], "detect_contrast": criteria[1],
                "modes": [{"frequency": f, "participation": p} for f, p in modes],
                "candidates": [{k: c.get(k) for k in keys} for c in picks],
                "ldr_frequency": ldr["frequency"], "ldr_gain": ldr["gain"], "thresholds": thresholds,
                "runs": self.runner.made, "wall_time_s": seconds}
