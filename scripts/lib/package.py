"""Makes the vibrotherm package (scripts/vibrotherm) of this checkout importable from
scripts/lib's modules, whoever loads them (scripts/plot, the studies, tests): `import package`
before `import vibrotherm`. It comes first on sys.path, before a vibrotherm.pth of another checkout."""
import os
import sys

SCRIPTS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
if SCRIPTS not in sys.path[:1]:
    sys.path.insert(0, SCRIPTS)
