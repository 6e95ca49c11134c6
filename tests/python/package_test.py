"""Shared by tests/python: the vibrotherm package of the checkout under test (not one a
vibrotherm.pth names), the scene tests' Checks, and the scenes the tests shorten.

    test = package_test.setup("name")   # from argv: VIBROTHERM SOURCE_DIR
    test.vt, test.check, test.program, test.src, test.paper, test.block, test.coarse"""
import os
import sys
import types


def setup(name):
    exe, src = sys.argv[1:3]
    sys.path.insert(0, os.path.join(src, "scripts"))
    sys.path.insert(0, os.path.join(src, "tests", "scene"))
    import vibrotherm
    from checks import Checks

    return types.SimpleNamespace(vt=vibrotherm, check=Checks(name), program=os.path.abspath(exe), src=src,
                                 paper=os.path.join(src, "options", "paper.opts"),
                                 block=os.path.join(src, "options", "block3d_small.opts"),
                                 coarse={"mesh_h": 0.004, "mesh_h_crack": 0.001, "wave_degree": 1})
