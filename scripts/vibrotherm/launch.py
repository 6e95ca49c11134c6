"""Running vibrotherm from Python: one scene (run_scene), with its options as a dict.

    run = run_scene("options/paper.opts", {"final_time": 2e-4, "crack_center": (0.025, 0.05)},
                    output_dir="results/short", ranks=2)

A failed run raises RunFailed carrying the run's own error line (vibrotherm's
"vibrotherm: error: ..." or PETSc's message), its exit status and where its output went."""
import math
import os
import signal
import subprocess
import sys
import tempfile

from . import project
from .run_dir import Run


class RunFailed(RuntimeError):
    """vibrotherm exited non-zero: .returncode, .error (its error line), .output_dir, .stderr."""

    def __init__(self, returncode, error, output_dir, stderr=""):
        self.returncode, self.error, self.output_dir, self.stderr = returncode, error, output_dir, stderr
        how = "stopped by a signal, resumable with -restart" if returncode > 128 else "failed"
        super().__init__("vibrotherm %s (exit %d) in %s: %s" % (how, returncode, output_dir, error or "no error line"))


def option_value(value):
    """An option value as vibrotherm reads it: numbers in full precision (repr), sequences
    joined by commas ((0.01, 0.02) → "0.01,0.02"), booleans as true/false, text as is."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else str(value)
    if isinstance(value, (list, tuple)):
        return ",".join(option_value(v) for v in value)
    return str(value)


def option_words(options):
    """Command-line words of an options dict ({"final_time": 2e-4, "-modes": True, "camera": None}):
    a name with or without its "-"; True or None gives the flag alone, False "-name false"."""
    words = []
    for name, value in (options or {}).items():
        words.append("-" + name.lstrip("-"))
        if value is not None and value is not True:
            words.append(option_value(value))
    return words


def is_option_name(word):
    """-name is an option, -1e-3 and -inf values (as vibrotherm's options reader tells them)."""
    return (len(word) > 1 and word[0] == "-" and (word[1].isalpha() or word[1] == "_")
            and word[1:].lower() not in ("nan", "inf", "infinity"))


def option_dict(words):
    """{name: value} of command-line words "-a 1 -b -c x" in order: a flag without a value is
    True (option_words turns it back into the flag alone). ValueError on a value without its option."""
    options, k = {}, 0
    while k < len(words):
        if not is_option_name(words[k]):
            raise ValueError("%r: expected an option (-name) before %r" % (" ".join(words), words[k]))
        has_value = k + 1 < len(words) and not is_option_name(words[k + 1])
        options[words[k][1:]] = words[k + 1] if has_value else True
        k += 2 if has_value else 1
    return options


def error_line(text):
    """The line of a run's stderr that says what went wrong: vibrotherm's own error, else
    PETSc's message, else the first line that is not MPI's frame."""
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    for line in lines:
        if line.startswith("vibrotherm") and "error" in line:
            return line
    for line in lines:
        if "PETSC ERROR:" in line and not set(line.split("PETSC ERROR:", 1)[1].strip()) <= set("- ") \
                and "Error Message" not in line:
            return line
    for line in lines:
        if not line.startswith("---"):
            return line
    return ""


def command(options_file=None, options=None, output_dir=None, ranks=1, program=None):
    """The command line of a run: [mpiexec -n R] vibrotherm [-options_file F] <options> [-output_dir D]."""
    words = [program or project.executable()]
    if options_file is not None:
        words += ["-options_file", os.path.abspath(options_file)]
    words += option_words(options)
    if output_dir is not None:
        words += ["-output_dir", os.path.abspath(output_dir)]
    return (["mpiexec", "-n", str(ranks)] if ranks > 1 else []) + words


def run_scene(options_file=None, options=None, output_dir="results/run", ranks=1, overwrite=False, echo=False,
              timeout=None, program=None):
    """Runs vibrotherm on `ranks` MPI ranks and returns the finished run (a Run).

    options_file  the scene (a path; None: only `options`)
    options       overrides as a dict, given after the file's ({"source_amplitude": 2e-7})
    output_dir    where the run writes (made absolute: the run starts in the repository root,
                  where the options files' own includes are found)
    overwrite     adds -overwrite (discards an earlier run's checkpoint in output_dir)
    echo          prints the run's progress lines as they come (else they are kept in
                  output_dir/vibrotherm.log only)
    Raises RunFailed (its error line, exit status) when vibrotherm exits non-zero, and
    subprocess.TimeoutExpired after `timeout` seconds (the run is then stopped with SIGUSR1:
    checkpointed, resumable with -restart)."""
    extra = dict(options or {})
    if overwrite:
        extra["overwrite"] = True
    cmd = command(options_file, extra, output_dir, ranks, program)
    with tempfile.TemporaryFile("w+") as errors:
        process = subprocess.Popen(cmd, cwd=project.ROOT, env=project.mpi_env(), stdout=subprocess.PIPE,
                                   stderr=errors, text=True)
        try:
            if echo:
                for line in process.stdout:
                    sys.stdout.write(line)
                    sys.stdout.flush()
            process.communicate(timeout=timeout)
        except BaseException:  # a timeout or Ctrl-C: the run checkpoints and stops
            process.send_signal(signal.SIGUSR1)  # mpiexec forwards SIGUSR1 to every rank
            process.communicate()
            raise
        errors.seek(0)
        stderr = errors.read()
    if process.returncode != 0:
        raise RunFailed(process.returncode, error_line(stderr), os.path.abspath(output_dir), stderr)
    return Run(output_dir)
