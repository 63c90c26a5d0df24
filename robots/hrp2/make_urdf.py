#!/usr/bin/env python3
"""Writes hrp2.urdf and hrp2.srdf (next to this script) from the HRP-2 parameter table.

Run with /usr/bin/python3 robots/hrp2/make_urdf.py (no third-party module needed).

Source of every number: `data/robots/hrp2.rob` of the Klamp't toolkit (krishauser/Klampt
commit 66cf52f8, also krishauser/Klampt-examples; BSD-3-Clause, Copyright (c) 2017, the
Trustees of Duke University), transcribed into TABLE below (one row per link, rows 5-35 of the
transcription); BOXES holds the bounding boxes of the link meshes in the link frames, used for the collision boxes; the visual geometry (VISUALS: boxes, cylinders, spheres, for
`wpg view`) is drawn from the joint origins (robots/hrp2/README.md, "Sources").

Conventions (those of the .rob file): every joint origin has rpy = 0; axes are in the child
frame; CoMs in the link frame; inertias about the CoM with link-frame axes, URDF signs.
Joint limits are written from the source's degrees (qmindeg/qmaxdeg), converted to radians
at full precision; they agree with the table's rounded radians to 5e-7.
Two massless sole frames are added (LLEG_SOLE, RLEG_SOLE: fixed joints 0.105 m below the
ankle-roll frames: the sole plane of the foot mesh is z = -0.105).
"""
import math
import os

TABLE = r"""
| 5 | BODY_PITCH | BODY | BODY_ROLL | revolute (floating-base DOF) | 1 0 0 | 0 0 0 | 0 0 0 | 15.02949000 | -0.01435142 0.00000012 0.2200769 | 0.16102617 -0.00000026 0.00070696 0.09528000 -0.00000019 0.19191383 | -inf / inf | inf | 0 |
| 6 | RLEG_JOINT0 | RLEG_LINK0 | BODY | revolute | 0 0 1 | 0 -0.06 0 | 0 0 0 | 1.16852000 | -0.01037928 0.00484329 0.06490147 | 0.00285998 -0.00001434 -0.00055582 0.00352974 0.00000884 0.00145427 | -0.785398 / 0.523599 (-45 / 30) | 3 | 100 |
| 7 | RLEG_JOINT1 | RLEG_LINK1 | RLEG_LINK0 | revolute | 1 0 0 | 0 0 0 | 0 0 0 | 0.80553000 | -0.00039826 -0.02612872 -0.00292156 | 0.00126683 0.00001211 0.00000164 0.00050656 0.00006938 0.00132021 | -0.610865 / 0.349066 (-35 / 20) | 3 | 100 |
| 8 | RLEG_JOINT2 | RLEG_LINK2 | RLEG_LINK1 | revolute | 0 1 0 | 0 0 0 | 0 0 0 | 2.07632000 | 0.00345946 -0.07794217 -0.15168400 | 0.02619757 -0.00003954 0.00057351 0.02492350 0.00067007 0.00376439 | -2.181662 / 0.733038 (-125 / 42) | 3 | 100 |
| 9 | RLEG_JOINT3 | RLEG_LINK3 | RLEG_LINK2 | revolute | 0 1 0 | 0 0 -0.3 | 0 0 0 | 1.74762000 | 0.01798781 -0.05791638 -0.13839018 | 0.02232685 -0.00009393 -0.00224776 0.02250598 -0.00074527 0.00455443 | -0.034907 / 2.617994 (-2 / 150) | 3 | 100 |
| 10 | RLEG_JOINT4 | RLEG_LINK4 | RLEG_LINK3 | revolute | 0 1 0 | 0 -0.035 -0.3 | 0 0 0 | 0.65375000 | 0.00827083 -0.00133301 -0.00241800 | 0.00027773 -0.00000526 0.00001354 0.00078966 -0.00000359 0.00086039 | -1.308997 / 0.733038 (-75 / 42) | 3 | 100 |
| 11 | RLEG_JOINT5 | RLEG_LINK5 | RLEG_LINK4 | revolute | 1 0 0 | 0 0 0 | 0 0 0 | 1.63877000 | -0.00066419 -0.00468922 -0.06538130 | 0.00400076 0.00009983 0.00079295 0.00687611 -0.00018541 0.00711516 | -0.349066 / 0.610865 (-20 / 35) | 3 | 100 |
| 12 | LLEG_JOINT0 | LLEG_LINK0 | BODY | revolute | 0 0 1 | 0 0.06 0 | 0 0 0 | 1.16852000 | -0.01037928 -0.00484329 0.06490147 | 0.00285998 0.00001434 -0.00055582 0.00352974 -0.00000884 0.00145427 | -0.523599 / 0.785398 (-30 / 45) | 3 | 100 |
| 13 | LLEG_JOINT1 | LLEG_LINK1 | LLEG_LINK0 | revolute | 1 0 0 | 0 0 0 | 0 0 0 | 0.80553000 | -0.00039826 0.02612872 -0.00292156 | 0.00126683 -0.00001211 0.00000164 0.00050656 -0.00006938 0.00132021 | -0.349066 / 0.610865 (-20 / 35) | 3 | 100 |
| 14 | LLEG_JOINT2 | LLEG_LINK2 | LLEG_LINK1 | revolute | 0 1 0 | 0 0 0 | 0 0 0 | 2.07632000 | 0.00345946 0.07794217 -0.15168400 | 0.02619757 0.00003954 0.00057351 0.02492350 -0.00067007 0.00376439 | -2.181662 / 0.733038 (-125 / 42) | 3 | 100 |
| 15 | LLEG_JOINT3 | LLEG_LINK3 | LLEG_LINK2 | revolute | 0 1 0 | 0 0 -0.3 | 0 0 0 | 1.74762000 | 0.01798781 0.05791638 -0.13839018 | 0.02232685 0.00009393 -0.00224776 0.02250598 0.00074527 0.00455443 | -0.034907 / 2.617994 (-2 / 150) | 3 | 100 |
| 16 | LLEG_JOINT4 | LLEG_LINK4 | LLEG_LINK3 | revolute | 0 1 0 | 0 0.035 -0.3 | 0 0 0 | 0.65375000 | 0.00827083 0.00133301 -0.00241800 | 0.00027773 0.00000526 0.00001354 0.00078966 0.00000359 0.00086039 | -1.308997 / 0.733038 (-75 / 42) | 3 | 100 |
| 17 | LLEG_JOINT5 | LLEG_LINK5 | LLEG_LINK4 | revolute | 1 0 0 | 0 0 0 | 0 0 0 | 1.63877000 | -0.00066419 0.00468922 -0.06538130 | 0.00400076 -0.00009983 0.00079295 0.00687611 0.00018541 0.00711516 | -0.610865 / 0.349066 (-35 / 20) | 3 | 100 |
| 18 | CHEST_JOINT0 | CHEST_LINK0 | BODY | revolute | 0 0 1 | 0.032 0 0.3477 | 0 0 0 | 0.78636922 | -0.01580159 0.00529544 -0.02519634 | 0.00181617 -0.00007322 -0.00027731 0.00185079 -0.00010749 0.00233207 | -0.785398 / 0.785398 (-45 / 45) | 3 | 40 |
| 19 | CHEST_JOINT1 | CHEST_LINK1 | CHEST_LINK0 | revolute | 0 1 0 | 0 0 0 | 0 0 0 | 11.52457000 | -0.02904963 0.00716411 0.12102458 | 0.16047572 -0.00135932 -0.00414493 0.13684576 0.00388035 0.18166852 | -0.087266 / 1.047198 (-5 / 60) | 3 | 40 |
| 20 | HEAD_JOINT0 | HEAD_LINK0 | CHEST_LINK1 | revolute | 0 0 1 | -0.007 0 0.2973 | 0 0 0 | 0.37476648 | -0.00087533 0.00426199 -0.00802747 | 0.00039945 -0.00000099 0.00000226 0.00022558 -0.00001181 0.00036246 | -0.785398 / 0.785398 (-45 / 45) | 3 | 10 |
| 21 | HEAD_JOINT1 | HEAD_LINK1 | HEAD_LINK0 | revolute | 0 1 0 | 0 0 0 | 0 0 0 | 0.99335475 | 0.01298846 0.00008605 0.07876058 | 0.00539717 -0.00002165 0.00069330 0.00457493 -0.00006372 0.00590682 | -0.523599 / 0.785398 (-30 / 45) | 3 | 10 |
| 22 | RARM_JOINT0 | RARM_LINK0 | CHEST_LINK1 | revolute | 0 1 0 | 0.008 -0.25 0.181 | 0 0 0 | 0.81007573 | -0.00989448 0.04645260 -0.00015316 | 0.00221115 -0.00030424 0.00000147 0.00184189 0.00004667 0.00344772 | -3.141593 / 1.047198 (-180 / 60) | 3 | 60 |
| 23 | RARM_JOINT1 | RARM_LINK1 | RARM_LINK0 | revolute | 1 0 0 | 0 0 0 | 0 0 0 | 1.03448000 | -0.01056459 -0.01204295 -0.00948156 | 0.00122098 0.00028119 0.00009407 0.00172216 0.00012041 0.00161319 | -1.658063 / 0.174533 (-95 / 10) | 3 | 60 |
| 24 | RARM_JOINT2 | RARM_LINK2 | RARM_LINK1 | revolute | 0 0 1 | 0 0 0 | 0 0 0 | 1.59929000 | -0.00543072 -0.00479797 -0.16687163 | 0.00973049 -0.00005133 -0.00019919 0.00970372 0.00013747 0.00135331 | -1.605703 / 1.605703 (-92 / 92) | 3 | 60 |
| 25 | RARM_JOINT3 | RARM_LINK3 | RARM_LINK2 | revolute | 0 1 0 | 0 0 -0.25 | 0 0 0 | 0.77724995 | -0.00000927 -0.01616837 -0.06270155 | 0.00232668 0.00000007 -0.00000031 0.00212476 0.00015097 0.00056363 | -2.391101 / 0.034907 (-137 / 2) | 3 | 50 |
| 26 | RARM_JOINT4 | RARM_LINK4 | RARM_LINK3 | revolute | 0 0 1 | 0 0 -0.25 | 0 0 0 | 0.55466858 | -0.00344863 -0.00361759 0.04149589 | 0.00132104 0.00001646 0.00004660 0.00119920 -0.00011959 0.00031715 | -1.605703 / 1.605703 (-92 / 92) | 3 | 20 |
| 27 | RARM_JOINT5 | RARM_LINK5 | RARM_LINK4 | revolute | 0 1 0 | 0 0 0 | 0 0 0 | 0.71190207 | -0.00072395 0.00179195 -0.07318519 | 0.00182453 0.00000457 -0.00013613 0.00175065 -0.00009446 0.00044863 | -1.605703 / 1.605703 (-92 / 92) | 3 | 10 |
| 28 | RARM_JOINT6 | RARM_LINK6 | RARM_LINK5 | revolute | 0 1 0 | 0.0219 0 -0.08525 | 0 0 0 | 0.08612730 | -0.00186922 -0.00409488 -0.03011865 | 0.00009887 -0.00000075 -0.00000810 0.00009524 -0.00001281 0.00001502 | -1.047198 / 0.279253 (-60 / 16) | 3 | 1 |
| 29 | LARM_JOINT0 | LARM_LINK0 | CHEST_LINK1 | revolute | 0 1 0 | 0.008 0.25 0.181 | 0 0 0 | 0.81007573 | -0.00989448 -0.04645260 -0.00015316 | 0.00221115 0.00030424 0.00000147 0.00184189 -0.00004667 0.00344772 | -3.141593 / 1.047198 (-180 / 60) | 3 | 60 |
| 30 | LARM_JOINT1 | LARM_LINK1 | LARM_LINK0 | revolute | 1 0 0 | 0 0 0 | 0 0 0 | 1.03448000 | -0.01056459 0.01204295 -0.00948156 | 0.00122098 -0.00028119 0.00009407 0.00172216 -0.00012041 0.00161319 | -0.174533 / 1.658063 (-10 / 95) | 3 | 60 |
| 31 | LARM_JOINT2 | LARM_LINK2 | LARM_LINK1 | revolute | 0 0 1 | 0 0 0 | 0 0 0 | 1.59929000 | -0.00543072 0.00479797 -0.16687163 | 0.00973049 0.00005133 -0.00019919 0.00970372 -0.00013747 0.00135331 | -1.605703 / 1.605703 (-92 / 92) | 3 | 60 |
| 32 | LARM_JOINT3 | LARM_LINK3 | LARM_LINK2 | revolute | 0 1 0 | 0 0 -0.25 | 0 0 0 | 0.77724995 | -0.00000927 0.01616837 -0.06270155 | 0.00232668 -0.00000007 -0.00000031 0.00212476 -0.00015097 0.00056363 | -2.391101 / 0.034907 (-137 / 2) | 3 | 50 |
| 33 | LARM_JOINT4 | LARM_LINK4 | LARM_LINK3 | revolute | 0 0 1 | 0 0 -0.25 | 0 0 0 | 0.55466858 | 0.00247694 0.00361759 0.04149589 | 0.00132103 0.00000930 -0.00003617 0.00119868 0.00011959 0.00031664 | -1.605703 / 1.605703 (-92 / 92) | 3 | 20 |
| 34 | LARM_JOINT5 | LARM_LINK5 | LARM_LINK4 | revolute | 0 1 0 | 0 0 0 | 0 0 0 | 0.71190207 | -0.00072395 -0.00179195 -0.07318519 | 0.00182453 -0.00000457 -0.00013613 0.00175065 0.00009446 0.00044863 | -1.605703 / 1.605703 (-92 / 92) | 3 | 10 |
| 35 | LARM_JOINT6 | LARM_LINK6 | LARM_LINK5 | revolute | 0 1 0 | 0.0219 0 -0.095 | 0 0 0 | 0.08612730 | -0.00186922 0.00409488 -0.03011865 | 0.00009887 0.00000075 -0.00000810 0.00009524 0.00001281 0.00001502 | -1.047198 / 0.279253 (-60 / 16) | 3 | 1 |
"""

BOXES = r"""
| BODY (hrp2/BODY.off) | -0.1733 / +0.1239 | -0.1641 / +0.1641 | +0.0615 / +0.3268 | 16865.4 |
| RLEG_LINK0 (hrp2/RLEG_LINK0.off) | -0.0640 / +0.0470 | -0.0370 / +0.0370 | -0.0370 / +0.1030 | 730.7 |
| RLEG_LINK1 (hrp2/RLEG_LINK1.off) | -0.0310 / +0.0280 | -0.0350 / +0.0340 | -0.0340 / +0.0340 | 204.2 |
| RLEG_LINK2 (hrp2/RLEG_LINK2.off) | -0.0495 / +0.0574 | -0.1360 / +0.0012 | -0.3374 / +0.0395 | 3404.9 |
| RLEG_LINK3 (hrp2/RLEG_LINK3.off) | -0.0772 / +0.1067 | -0.1267 / +0.0153 | -0.3364 / +0.1035 | 3428.3 |
| RLEG_LINK4 (hrp2/RLEG_LINK4.off) | -0.0309 / +0.0455 | -0.0245 / +0.0330 | -0.0225 / +0.0225 | 123.6 |
| RLEG_LINK5 (hrp2/RLEG_LINK5.off) | -0.1056 / +0.1356 | -0.0790 / +0.0590 | -0.1050 / +0.0350 | 2218.6 |
| LLEG_LINK0 (hrp2/LLEG_LINK0.off) | -0.0640 / +0.0470 | -0.0370 / +0.0370 | -0.0370 / +0.1030 | 730.7 |
| LLEG_LINK1 (hrp2/LLEG_LINK1.off) | -0.0310 / +0.0280 | -0.0340 / +0.0350 | -0.0340 / +0.0340 | 204.2 |
| LLEG_LINK2 (hrp2/LLEG_LINK2.off) | -0.0495 / +0.0574 | -0.0012 / +0.1360 | -0.3374 / +0.0395 | 3404.9 |
| LLEG_LINK3 (hrp2/LLEG_LINK3.off) | -0.0772 / +0.1067 | -0.0153 / +0.1267 | -0.3364 / +0.1035 | 3428.3 |
| LLEG_LINK4 (hrp2/LLEG_LINK4.off) | -0.0309 / +0.0455 | -0.0330 / +0.0245 | -0.0225 / +0.0225 | 123.6 |
| LLEG_LINK5 (hrp2/LLEG_LINK5.off) | -0.1056 / +0.1356 | -0.0590 / +0.0790 | -0.1050 / +0.0350 | 2218.6 |
| CHEST_LINK0 (hrp2/CHEST_LINK0.off) | -0.1155 / +0.0510 | -0.0760 / +0.0760 | -0.0440 / +0.0380 | 612.8 |
| CHEST_LINK1 (hrp2/CHEST_LINK1.off) | -0.2230 / +0.1315 | -0.1945 / +0.1945 | -0.0307 / +0.2885 | 28746.9 |
| HEAD_LINK0 (hrp2/HEAD_LINK0.off) | -0.0650 / +0.0535 | -0.0610 / +0.0610 | -0.0468 / +0.0504 | 595.0 |
| HEAD_LINK1 (hrp2/HEAD_LINK1.off) | -0.1736 / +0.1273 | -0.1055 / +0.1055 | +0.0012 / +0.2098 | 4273.4 |
| RARM_LINK0 (hrp2/RARM_LINK0.off) | -0.0902 / +0.0763 | -0.0565 / +0.0640 | -0.0449 / +0.0626 | 1181.6 |
| RARM_LINK1 (hrp2/RARM_LINK1.off) | -0.0646 / +0.0550 | -0.0564 / +0.0369 | -0.0415 / +0.0486 | 446.9 |
| RARM_LINK2 (hrp2/RARM_LINK2.off) | -0.0515 / +0.0404 | -0.0600 / +0.0435 | -0.2905 / -0.0395 | 1397.0 |
| RARM_LINK3 (hrp2/RARM_LINK3.off) | -0.0384 / +0.0385 | -0.0600 / +0.0385 | -0.1552 / +0.0385 | 620.1 |
| RARM_LINK4 (hrp2/RARM_LINK4.off) | -0.0404 / +0.0360 | -0.0500 / +0.0490 | -0.0315 / +0.0990 | 521.5 |
| RARM_LINK5 (hrp2/RARM_LINK5.off) | -0.0323 / +0.0484 | -0.0454 / +0.0447 | -0.2050 / +0.0285 | 623.6 |
| RARM_LINK6 (hrp2/RARM_LINK6.off) | -0.0200 / +0.0170 | -0.0227 / +0.0043 | -0.0891 / +0.0147 | 47.0 |
| LARM_LINK0 (hrp2/LARM_LINK0.off) | -0.0902 / +0.0763 | -0.0640 / +0.0565 | -0.0449 / +0.0626 | 1181.6 |
| LARM_LINK1 (hrp2/LARM_LINK1.off) | -0.0646 / +0.0550 | -0.0369 / +0.0564 | -0.0415 / +0.0486 | 446.9 |
| LARM_LINK2 (hrp2/LARM_LINK2.off) | -0.0515 / +0.0404 | -0.0435 / +0.0600 | -0.2905 / -0.0395 | 1397.0 |
| LARM_LINK3 (hrp2/LARM_LINK3.off) | -0.0384 / +0.0385 | -0.0385 / +0.0600 | -0.1552 / +0.0385 | 620.1 |
| LARM_LINK4 (hrp2/LARM_LINK4.off) | -0.0404 / +0.0360 | -0.0490 / +0.0500 | -0.0315 / +0.0990 | 521.5 |
| LARM_LINK5 (hrp2/LARM_LINK5.off) | -0.0323 / +0.0484 | -0.0447 / +0.0454 | -0.2050 / +0.0285 | 623.6 |
| LARM_LINK6 (hrp2/LARM_LINK6.off) | -0.0200 / +0.0170 | -0.0043 / +0.0227 | -0.0891 / +0.0147 | 47.0 |
"""

SOLE_DEPTH = 0.105  # m, ankle above the sole (the sole plane of the foot mesh)

# The LAAS half-sitting posture, joint values in rad, written to hrp2.srdf.
LEG_HALF_SITTING = [0, 0, -0.453786, 0.872665, -0.418879, 0]
HALF_SITTING = (
    [("RLEG_JOINT%d" % i, v) for i, v in enumerate(LEG_HALF_SITTING)]
    + [("LLEG_JOINT%d" % i, v) for i, v in enumerate(LEG_HALF_SITTING)]
    + [("CHEST_JOINT0", 0), ("CHEST_JOINT1", 0), ("HEAD_JOINT0", 0), ("HEAD_JOINT1", 0)]
    + [("RARM_JOINT%d" % i, v)
       for i, v in enumerate([0.261799, -0.17453, 0, -0.523599, 0, 0, 0.1])]
    + [("LARM_JOINT%d" % i, v)
       for i, v in enumerate([0.261799, 0.17453, 0, -0.523599, 0, 0, 0.1])]
)


def fmt(x):
    """Shortest decimal that round-trips the float; integers without a decimal point."""
    x = float(x)
    if x == int(x) and abs(x) < 1e6:
        return str(int(x))
    return repr(x)


def vec(text):
    return [float(v) for v in text.split()]


def parse_table():
    rows = []
    for line in TABLE.strip().splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        index = int(cells[0])
        row = {
            "index": index,
            "joint": cells[1],
            "link": cells[2],
            "parent": cells[3],
            "type": cells[4],
            "axis": vec(cells[5]),
            "xyz": vec(cells[6]),
            "rpy": vec(cells[7]),
            "mass": float(cells[8]),
            "com": vec(cells[9]),
            "inertia": vec(cells[10]),
            "limits": cells[11],
            "velocity": cells[12],
            "effort": cells[13],
        }
        assert row["rpy"] == [0.0, 0.0, 0.0], row
        assert len(row["inertia"]) == 6, row
        rows.append(row)
    assert [r["index"] for r in rows] == list(range(5, 36))
    return rows


def parse_limits(text):
    """'-0.785398 / 0.523599 (-45 / 30)' -> (lower, upper) in rad from the degrees."""
    rad, deg = text.split("(")
    lo_rad, hi_rad = (float(v) for v in rad.split("/"))
    lo_deg, hi_deg = (float(v) for v in deg.rstrip(")").split("/"))
    lo, hi = math.radians(lo_deg), math.radians(hi_deg)
    assert abs(lo - lo_rad) < 5e-7 and abs(hi - hi_rad) < 5e-7, text
    return lo, hi


def parse_boxes():
    boxes = {}
    for line in BOXES.strip().splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        link = cells[0].split()[0]
        ranges = []
        for cell in cells[1:4]:
            lo, hi = (float(v) for v in cell.split("/"))
            ranges.append((lo, hi))
        boxes[link] = ranges
    return boxes


def inertial_xml(row, indent):
    i = row["inertia"]
    return (
        f'{indent}<inertial>\n'
        f'{indent}  <origin xyz="{" ".join(fmt(v) for v in row["com"])}" rpy="0 0 0"/>\n'
        f'{indent}  <mass value="{fmt(row["mass"])}"/>\n'
        f'{indent}  <inertia ixx="{fmt(i[0])}" ixy="{fmt(i[1])}" ixz="{fmt(i[2])}" '
        f'iyy="{fmt(i[3])}" iyz="{fmt(i[4])}" izz="{fmt(i[5])}"/>\n'
        f'{indent}</inertial>\n'
    )


def collision_xml(ranges, indent):
    """The link's collision box: the bounding box of Klampt's mesh (appendix B)."""
    centre = [0.5 * (lo + hi) for lo, hi in ranges]
    size = [hi - lo for lo, hi in ranges]
    return (f'{indent}<collision>\n'
            f'{indent}  <origin xyz="{" ".join(fmt(round(v, 6)) for v in centre)}" rpy="0 0 0"/>\n'
            f'{indent}  <geometry><box size="{" ".join(fmt(round(v, 6)) for v in size)}"/></geometry>\n'
            f'{indent}</collision>\n')


# Visual geometry: what `wpg view` draws. Primitives sized like HRP-2's limbs (placed from the
# joint origins of TABLE: hips 0.06 m off the waist axis, thigh and shank 0.3 m, the ankle
# 0.035 m outward of the knee, sole 0.2172 x 0.138 m 0.105 m below the ankle, shoulders at
# 0.25 m, upper arm and forearm 0.25 m) and coloured like its shell (light grey panels, blue
# trim, dark joints). Visuals only: the collision boxes, masses and inertias above are
# untouched, so the multibody results do not depend on them.
MATERIALS = {"shell": "0.86 0.88 0.91 1", "trim": "0.16 0.33 0.66 1", "joint": "0.2 0.21 0.24 1",
             "visor": "0.05 0.06 0.08 1"}
SHANK_TILT = math.atan2(0.035, 0.3)  # rad, the shank leans outward from knee to ankle


def leg_visuals(side):
    """Shapes of one leg, side = 1 (left) or -1 (right)."""
    return {
        "LINK1": [("cylinder", (0.055, 0.13), (0, 0, 0), (0, math.pi / 2, 0), "joint")],
        "LINK2": [("cylinder", (0.062, 0.24), (0, 0, -0.15), (0, 0, 0), "shell"),
                  ("box", (0.1, 0.09, 0.16), (0.035, 0, -0.14), (0, 0, 0), "trim")],
        "LINK3": [("sphere", (0.062,), (0, 0, 0), (0, 0, 0), "joint"),
                  ("cylinder", (0.052, 0.27), (0, side * 0.0175, -0.15), (-side * SHANK_TILT, 0, 0), "shell"),
                  ("box", (0.05, 0.07, 0.14), (0.045, side * 0.012, -0.11), (-side * SHANK_TILT, 0, 0), "trim")],
        "LINK4": [("cylinder", (0.042, 0.1), (0, 0, 0), (math.pi / 2, 0, 0), "joint")],
        "LINK5": [("box", (0.2172, 0.138, 0.025), (0, 0, -SOLE_DEPTH + 0.0125), (0, 0, 0), "joint"),
                  ("box", (0.19, 0.12, 0.05), (0.005, 0, -0.066), (0, 0, 0), "shell")],
    }


def arm_visuals(side):
    return {
        "LINK0": [("sphere", (0.068,), (0, 0, 0), (0, 0, 0), "trim")],
        "LINK2": [("cylinder", (0.048, 0.2), (0, 0, -0.13), (0, 0, 0), "shell")],
        "LINK3": [("sphere", (0.05,), (0, 0, 0), (0, 0, 0), "joint"),
                  ("cylinder", (0.043, 0.2), (0, 0, -0.13), (0, 0, 0), "shell")],
        "LINK4": [("cylinder", (0.036, 0.05), (0, 0, -0.02), (0, 0, 0), "joint")],
        "LINK5": [("box", (0.07, 0.09, 0.1), (0.01, 0, -0.06), (0, 0, 0), "trim")],
        "LINK6": [("box", (0.025, 0.03, 0.08), (0, 0, -0.035), (0, 0, 0), "joint")],
    }


VISUALS = {
    "BODY": [("box", (0.22, 0.28, 0.13), (-0.015, 0, 0.06), (0, 0, 0), "shell"),
             ("box", (0.2, 0.24, 0.04), (-0.015, 0, 0.145), (0, 0, 0), "trim"),
             ("cylinder", (0.09, 0.2), (0.01, 0, 0.25), (0, 0, 0), "joint")],
    "CHEST_LINK1": [("box", (0.25, 0.36, 0.3), (-0.03, 0, 0.15), (0, 0, 0), "shell"),
                    ("box", (0.11, 0.28, 0.22), (-0.19, 0, 0.14), (0, 0, 0), "shell"),
                    ("box", (0.02, 0.22, 0.15), (0.1, 0, 0.16), (0, 0, 0), "trim")],
    "HEAD_LINK0": [("cylinder", (0.04, 0.08), (0, 0, 0.01), (0, 0, 0), "joint")],
    "HEAD_LINK1": [("box", (0.22, 0.2, 0.17), (-0.01, 0, 0.1), (0, 0, 0), "shell"),
                   ("box", (0.025, 0.17, 0.065), (0.1, 0, 0.11), (0, 0, 0), "visor"),
                   ("box", (0.17, 0.03, 0.05), (-0.02, 0, 0.2), (0, 0, 0), "trim")],
}
for _side, _prefix in ((1, "L"), (-1, "R")):
    VISUALS.update({_prefix + "LEG_" + k: v for k, v in leg_visuals(_side).items()})
    VISUALS.update({_prefix + "ARM_" + k: v for k, v in arm_visuals(_side).items()})


def visual_xml(link, indent):
    out = []
    for shape, size, xyz, rpy, material in VISUALS.get(link, []):
        if shape == "box":
            geometry = f'<box size="{" ".join(fmt(round(v, 6)) for v in size)}"/>'
        elif shape == "cylinder":
            geometry = f'<cylinder radius="{fmt(size[0])}" length="{fmt(size[1])}"/>'
        else:
            geometry = f'<sphere radius="{fmt(size[0])}"/>'
        out.append(f'{indent}<visual>\n'
                   f'{indent}  <origin xyz="{" ".join(fmt(round(v, 6)) for v in xyz)}" '
                   f'rpy="{" ".join(fmt(round(v, 9)) for v in rpy)}"/>\n'
                   f'{indent}  <geometry>{geometry}</geometry>\n'
                   f'{indent}  <material name="{material}"/>\n'
                   f'{indent}</visual>\n')
    return "".join(out)


def geometry_xml(link, ranges, indent):
    return visual_xml(link, indent) + collision_xml(ranges, indent)


def main():
    rows = parse_table()
    boxes = parse_boxes()
    out = []
    out.append('<?xml version="1.0"?>\n')
    out.append("<!-- HRP-2 humanoid: 30 revolute joints, root link BODY (the free-flyer is added by\n"
               "     the consumer). GENERATED by robots/hrp2/make_urdf.py: edit the script, not this file.\n"
               "     Source: the HRP-2 model of the Klamp't toolkit (data/robots/hrp2.rob, krishauser/Klampt,\n"
               "     BSD-3-Clause, Copyright (c) 2017, the Trustees of Duke University), transcribed in the\n"
               "     table of make_urdf.py; see robots/hrp2/README.md.\n"
               "     Frames: x forward, y left, z up; every link frame is parallel to BODY at q = 0.\n"
               "     Inertias about the link CoM, link-frame axes. Collision geometry: axis-aligned boxes =\n"
               "     the bounding boxes of Klampt's link meshes (coarse, overlapping: not for self-collision).\n"
               "     Visual geometry: boxes, cylinders and spheres sized like HRP-2's limbs (wpg view).\n"
               "     LLEG_SOLE / RLEG_SOLE: massless frames 0.105 m below the ankles (sole plane). -->\n")
    out.append('<robot name="hrp2">\n')
    for name, rgba in MATERIALS.items():
        out.append(f'  <material name="{name}"><color rgba="{rgba}"/></material>\n')
    body = rows[0]
    assert body["link"] == "BODY"
    out.append('  <link name="BODY">\n')
    out.append(inertial_xml(body, "    "))
    out.append(geometry_xml("BODY", boxes["BODY"], "    "))
    out.append("  </link>\n")
    for row in rows[1:]:
        assert row["type"] == "revolute", row
        lower, upper = parse_limits(row["limits"])
        out.append(f'  <joint name="{row["joint"]}" type="revolute">\n')
        out.append(f'    <parent link="{row["parent"]}"/>\n')
        out.append(f'    <child link="{row["link"]}"/>\n')
        out.append(f'    <origin xyz="{" ".join(fmt(v) for v in row["xyz"])}" rpy="0 0 0"/>\n')
        out.append(f'    <axis xyz="{" ".join(fmt(v) for v in row["axis"])}"/>\n')
        out.append(f'    <limit lower="{fmt(lower)}" upper="{fmt(upper)}" '
                   f'effort="{fmt(float(row["effort"]))}" velocity="{fmt(float(row["velocity"]))}"/>\n')
        out.append("  </joint>\n")
        out.append(f'  <link name="{row["link"]}">\n')
        out.append(inertial_xml(row, "    "))
        out.append(geometry_xml(row["link"], boxes[row["link"]], "    "))
        out.append("  </link>\n")
    for side, foot in (("L", "LLEG_LINK5"), ("R", "RLEG_LINK5")):
        out.append(f'  <joint name="{side}LEG_SOLE_JOINT" type="fixed">\n')
        out.append(f'    <parent link="{foot}"/>\n')
        out.append(f'    <child link="{side}LEG_SOLE"/>\n')
        out.append(f'    <origin xyz="0 0 {fmt(-SOLE_DEPTH)}" rpy="0 0 0"/>\n')
        out.append("  </joint>\n")
        out.append(f'  <link name="{side}LEG_SOLE"/>\n')
    out.append("</robot>\n")
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "hrp2.urdf")
    with open(path, "w") as f:
        f.write("".join(out))
    joints = [r["joint"] for r in rows[1:]]
    assert [name for name, _ in HALF_SITTING] == joints
    srdf = ['<?xml version="1.0"?>\n',
            "<!-- Reference postures of hrp2.urdf (SRDF group states, read by wpg::robots::RobotModel).\n"
            "     GENERATED by robots/hrp2/make_urdf.py. half_sitting: the LAAS half-sitting posture\n"
            "     (robots/hrp2/README.md); the free-flyer is not part of a group state. -->\n",
            '<robot name="hrp2">\n',
            '  <group_state name="half_sitting" group="all">\n']
    srdf += [f'    <joint name="{name}" value="{fmt(value)}"/>\n' for name, value in HALF_SITTING]
    srdf += ["  </group_state>\n", "</robot>\n"]
    with open(os.path.join(os.path.dirname(path), "hrp2.srdf"), "w") as f:
        f.write("".join(srdf))
    total = sum(r["mass"] for r in rows)
    print(f"wrote {path}: {len(rows) - 1} revolute joints, {len(rows)} links, mass {total:.8f} kg")


if __name__ == "__main__":
    main()
