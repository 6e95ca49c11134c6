"""Shared by the scene tests: count checks, report failures, print the closing line."""
import sys


class Checks:
    def __init__(self, name):
        self.name, self.count, self.failures = name, 0, []

    def __call__(self, ok, what):
        self.count += 1
        if not ok:
            self.failures.append(what)
            print("FAILED:", what, file=sys.stderr)

    def fail(self, what):
        self(False, what)

    def finish(self):
        print("%s: %d passed, %d failed" % (self.name, self.count - len(self.failures), len(self.failures)))
        sys.exit(1 if self.failures else 0)
