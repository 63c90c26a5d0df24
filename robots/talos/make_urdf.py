#!/usr/bin/env python3
"""Writes talos.urdf and talos.srdf (next to this script) from the TALOS parameter table.

Run with /usr/bin/python3 robots/talos/make_urdf.py (no third-party module needed).

Source of every number: the TALOS description published by PAL Robotics and LAAS-CNRS in
stack-of-tasks/talos-data (LGPL-3.0), `urdf/talos_reduced.urdf` and `srdf/talos.srdf`, read at
commit dc636c94 (2022-12-29). Its numbers were transcribed into TABLE below, one row per revolute
joint and its child link (robots/talos/README.md, "Sources"); no file was copied.

Conventions (those of the source): every joint origin has rpy = 0 and axes along the link
frame's axes; CoMs in the link frame; inertias about the CoM with link-frame axes. The source's
right-arm links 2-7 carry the left arm's CoMs and inertias unmirrored; they are kept as given.
What differs from the source, and why (README.md):
- each wrist's force sensor and gripper (eleven links on fixed joints, 1.28407 kg) are lumped
  into one massless-jointed link `arm_*_hand_link`: their summed mass at the tool frame, with the
  inertia of a solid 0.08 m cube of that mass (wpg walks with the arms still);
- the sole frames are massless (the source gives them 0.01 kg), and the 0.01 kg IMU and camera
  frames are left out: 0.05 kg of the source's 90.272192 kg.
"""
import math
import os

# joint | child link | parent | axis | origin xyz | lower / upper (rad) | velocity (rad/s) |
# effort (N m) | mass (kg) | CoM (link frame) | inertia ixx ixy ixz iyy iyz izz (kg m^2)
TABLE = r"""
| leg_right_1_joint | leg_right_1_link | base_link | 0 0 1 | -0.02 -0.085 -0.27105 | -1.57079632679 / 0.349065850399 | 3.87 | 100 | 1.88569 | 0.02320 -0.00009 0.04949 | 0.003848 0.000032 -0.000826 0.005994 0.000078 0.003222 |
| leg_right_2_joint | leg_right_2_link | leg_right_1_link | 1 0 0 | 0 0 0 | -0.5236 / 0.5236 | 5.8 | 160 | 2.37607 | 0.01583 -0.00021 0.00619 | 0.003421 -0.000113 -0.000225 0.004024 -0.000031 0.004164 |
| leg_right_3_joint | leg_right_3_link | leg_right_2_link | 0 1 0 | 0 0 0 | -2.095 / 0.7 | 5.8 | 160 | 6.82734 | 0.00658 -0.06563 -0.17278 | 0.123906 0.000412 -0.002059 0.108447 -0.016725 0.027812 |
| leg_right_4_joint | leg_right_4_link | leg_right_3_link | 0 1 0 | 0 0 -0.38 | 0 / 2.618 | 7 | 300 | 3.63668 | 0.01520 -0.02331 -0.12063 | 0.035315 -0.000029 -0.000166 0.029336 0.001305 0.01174 |
| leg_right_5_joint | leg_right_5_link | leg_right_4_link | 0 1 0 | 0 0 -0.325 | -1.309 / 0.768 | 5.8 | 160 | 1.24433 | -0.01106 -0.04708 0.05271 | 0.011487 0.000686 -0.000526 0.009526 -0.002633 0.003908 |
| leg_right_6_joint | leg_right_6_link | leg_right_5_link | 1 0 0 | 0 0 0 | -0.5236 / 0.5236 | 4.8 | 100 | 1.59457 | -0.02087 -0.00019 -0.06059 | 0.003838 0.000016 -0.001041 0.006572 -0.000017 0.005044 |
| leg_left_1_joint | leg_left_1_link | base_link | 0 0 1 | -0.02 0.085 -0.27105 | -0.349065850399 / 1.57079632679 | 3.87 | 100 | 1.88569 | 0.02320 -0.00009 0.04949 | 0.003848 0.000032 -0.000826 0.005994 0.000078 0.003222 |
| leg_left_2_joint | leg_left_2_link | leg_left_1_link | 1 0 0 | 0 0 0 | -0.5236 / 0.5236 | 5.8 | 160 | 2.37607 | 0.01583 -0.00021 0.00619 | 0.003421 -0.000113 -0.000225 0.004024 -0.000031 0.004164 |
| leg_left_3_joint | leg_left_3_link | leg_left_2_link | 0 1 0 | 0 0 0 | -2.095 / 0.7 | 5.8 | 160 | 6.82734 | 0.00658 0.06563 -0.17278 | 0.123906 -0.000412 -0.002059 0.108447 0.016725 0.027812 |
| leg_left_4_joint | leg_left_4_link | leg_left_3_link | 0 1 0 | 0 0 -0.38 | 0 / 2.618 | 7 | 300 | 3.63668 | 0.01520 0.02331 -0.12063 | 0.035315 0.000029 -0.000166 0.029336 -0.001305 0.01174 |
| leg_left_5_joint | leg_left_5_link | leg_left_4_link | 0 1 0 | 0 0 -0.325 | -1.309 / 0.768 | 5.8 | 160 | 1.24433 | -0.01106 0.04708 0.05271 | 0.011487 -0.000686 -0.000526 0.009526 0.002633 0.003908 |
| leg_left_6_joint | leg_left_6_link | leg_left_5_link | 1 0 0 | 0 0 0 | -0.5236 / 0.5236 | 4.8 | 100 | 1.59457 | -0.02087 -0.00019 -0.06059 | 0.003838 0.000016 -0.001041 0.006572 -0.000017 0.005044 |
| torso_1_joint | torso_1_link | base_link | 0 0 1 | 0 0 0.0722 | -1.308996939 / 1.308996939 | 5.4 | 78 | 3.02433 | 0.00013 -0.00001 -0.01306 | 0.007594 0.000001 -0.000048 0.004292 -0.000001 0.007497 |
| torso_2_joint | torso_2_link | torso_1_link | 0 1 0 | 0 0 0 | -0.261799387799 / 0.785398163397 | 5.4 | 78 | 17.55011 | -0.04551 -0.00053 0.16386 | 0.373769 0.000639 0.012196 0.247902 0.000007 0.281404 |
| head_1_joint | head_1_link | torso_2_link | 0 1 0 | 0 0 0.316 | -0.261799387799 / 0.785398163397 | 1 | 8 | 0.65988 | 0.00120 0.00145 0.02165 | 0.001221 -0.000004 0.00007 0.000924 -0.000041 0.001033 |
| head_2_joint | head_2_link | head_1_link | 0 0 1 | 0 0 0 | -1.308996939 / 1.308996939 | 1 | 4 | 1.40353 | -0.01036 -0.00037 0.13778 | 0.007225 -0.000025 0.000329 0.006873 0.000044 0.004373 |
| arm_right_1_joint | arm_right_1_link | torso_2_link | 0 0 1 | 0 -0.1575 0.232 | -0.523598775598 / 1.57079632679 | 2.7 | 44.64 | 1.42896 | -0.01346 -0.0913 0.04812 | 0.005551 -0.000731 0.000008 0.001673 -0.00006 0.005822 |
| arm_right_2_joint | arm_right_2_link | arm_right_1_link | 1 0 0 | 0.00493 -0.1365 0.04673 | -2.87979326579 / 0 | 3.66 | 22.32 | 1.67729 | 0.02607 0.00049 -0.05209 | 0.007087 -0.000014 0.002142 0.007936 0.00003 0.003788 |
| arm_right_3_joint | arm_right_3_link | arm_right_2_link | 0 0 1 | 0 0 0 | -2.44346095279 / 2.44346095279 | 4.58 | 17.86 | 1.47029 | 0.00841 0.01428 -0.22291 | 0.004332 0.000153 -0.000496 0.00434 -0.000609 0.002543 |
| arm_right_4_joint | arm_right_4_link | arm_right_3_link | 0 1 0 | 0.02 0 -0.273 | -2.35619449019 / 0 | 4.58 | 17.86 | 1.10216 | -0.00655 -0.02107 -0.02612 | 0.002217 -0.000101 0.000288 0.002418 -0.000393 0.001115 |
| arm_right_5_joint | arm_right_5_link | arm_right_4_link | 0 0 1 | -0.02 0 -0.2643 | -2.53072741539 / 2.53072741539 | 1.95 | 3 | 1.77792 | -0.00006 0.00326 0.07963 | 0.003495 -0.000013 -0.00001 0.004368 0.000097 0.002283 |
| arm_right_6_joint | arm_right_6_link | arm_right_5_link | 1 0 0 | 0 0 0 | -1.3962634016 / 1.3962634016 | 1.76 | 6.6 | 0.30931 | 0.00002 -0.00197 -0.00059 | 0.000107 0 0 0.000141 0 0.000154 |
| arm_right_7_joint | arm_right_7_link | arm_right_6_link | 0 1 0 | 0 0 0 | -0.698131700798 / 0.698131700798 | 1.76 | 6.6 | 0.308441 | 0.007525 0.001378 -0.02463 | 0.000309 0.000002 -0.000002 0.000219 0.000012 0.000176 |
| arm_left_1_joint | arm_left_1_link | torso_2_link | 0 0 1 | 0 0.1575 0.232 | -1.57079632679 / 0.523598775598 | 2.7 | 44.64 | 1.42896 | -0.01346 0.0913 0.04812 | 0.005551 -0.000731 0.000008 0.001673 -0.00006 0.005822 |
| arm_left_2_joint | arm_left_2_link | arm_left_1_link | 1 0 0 | 0.00493 0.1365 0.04673 | 0 / 2.87979326579 | 3.66 | 22.32 | 1.67729 | 0.02607 0.00049 -0.05209 | 0.007087 -0.000014 0.002142 0.007936 0.00003 0.003788 |
| arm_left_3_joint | arm_left_3_link | arm_left_2_link | 0 0 1 | 0 0 0 | -2.44346095279 / 2.44346095279 | 4.58 | 17.86 | 1.47029 | 0.00841 0.01428 -0.22291 | 0.004332 0.000153 -0.000496 0.00434 -0.000609 0.002543 |
| arm_left_4_joint | arm_left_4_link | arm_left_3_link | 0 1 0 | 0.02 0 -0.273 | -2.35619449019 / 0 | 4.58 | 17.86 | 1.10216 | -0.00655 -0.02107 -0.02612 | 0.002217 -0.000101 0.000288 0.002418 -0.000393 0.001115 |
| arm_left_5_joint | arm_left_5_link | arm_left_4_link | 0 0 1 | -0.02 0 -0.2643 | -2.53072741539 / 2.53072741539 | 1.95 | 3 | 1.77792 | -0.00006 0.00326 0.07963 | 0.003495 -0.000013 -0.00001 0.004368 0.000097 0.002283 |
| arm_left_6_joint | arm_left_6_link | arm_left_5_link | 1 0 0 | 0 0 0 | -1.3962634016 / 1.3962634016 | 1.76 | 6.6 | 0.30931 | 0.00002 -0.00197 -0.00059 | 0.000107 0 0 0.000141 0 0.000154 |
| arm_left_7_joint | arm_left_7_link | arm_left_6_link | 0 1 0 | 0 0 0 | -0.698131700798 / 0.698131700798 | 1.76 | 6.6 | 0.308441 | 0.007525 0.001378 -0.02463 | 0.000309 0.000002 -0.000002 0.000219 0.000012 0.000176 |
"""

# The root link (the pelvis; the free-flyer is added by the consumer): mass, CoM, inertia.
BASE = (13.5381, (-0.08222, 0.00838, -0.07261),
        (0.06989, -0.000117, 0.00023, 0.039982, -0.001325, 0.082345))

# Each wrist's force-torque sensor and gripper in the source, on fixed joints below arm_*_7_link:
# ft link 0.1, ft tool link 0.1, gripper base 0.61585, motor double 0.16889, inner double
# 0.11922, three fingertips 0.0263, motor single 0.14765, inner single 0.05356 (kg).
HAND_MASS = 0.1 + 0.1 + 0.61585 + 0.16889 + 0.11922 + 3 * 0.0263 + 0.14765 + 0.05356
# The tool frame: 0.051 (ft) + 0.012725 (tool) + 0.02875 (gripper base) m below the wrist.
HAND_DEPTH = 0.051 + 0.012725 + 0.02875
HAND_CUBE = 0.08  # m, side of the solid cube whose inertia the lumped hand is given

SOLE_DEPTH = 0.107  # m, the source's sole frames: fixed, 0.107 m below the ankle-roll frames

# The source's half_sitting group state (srdf/talos.srdf), rad.
HALF_SITTING = {
    "leg_left_3_joint": -0.411354, "leg_left_4_joint": 0.859395, "leg_left_5_joint": -0.448041,
    "leg_left_6_joint": -0.001708, "leg_right_3_joint": -0.411354, "leg_right_4_joint": 0.859395,
    "leg_right_5_joint": -0.448041, "leg_right_6_joint": -0.001708, "torso_2_joint": 0.006761,
    "arm_left_1_joint": 0.25847, "arm_left_2_joint": 0.173046, "arm_left_3_joint": -0.0002,
    "arm_left_4_joint": -0.525366, "arm_left_7_joint": 0.1, "arm_right_1_joint": -0.25847,
    "arm_right_2_joint": -0.173046, "arm_right_3_joint": 0.0002, "arm_right_4_joint": -0.525366,
    "arm_right_7_joint": 0.1,
}

# Visual geometry for `wpg view` only (nothing computed reads it): primitives placed from the
# joint origins (thigh 0.38 m, shank 0.325 m, the 0.21 m x 0.13 m sole 0.107 m below the ankle).
VISUALS = {
    "base_link": [("box", (0.2, 0.3, 0.16), (-0.04, 0, -0.06))],
    "torso_2_link": [("box", (0.26, 0.34, 0.34), (-0.04, 0, 0.15))],
    "head_2_link": [("box", (0.2, 0.18, 0.2), (0, 0, 0.13))],
}
for _side in ("left", "right"):
    VISUALS[f"leg_{_side}_3_link"] = [("cylinder", (0.06, 0.3), (0, 0, -0.19))]
    VISUALS[f"leg_{_side}_4_link"] = [("cylinder", (0.05, 0.26), (0, 0, -0.16))]
    VISUALS[f"leg_{_side}_6_link"] = [("box", (0.21, 0.13, 0.03), (0, 0, -SOLE_DEPTH + 0.015))]
    VISUALS[f"arm_{_side}_3_link"] = [("cylinder", (0.045, 0.22), (0, 0, -0.14))]
    VISUALS[f"arm_{_side}_5_link"] = [("cylinder", (0.04, 0.2), (0, 0, 0.12))]


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
        c = [x.strip() for x in line.strip().strip("|").split("|")]
        lower, upper = (float(v) for v in c[5].split("/"))
        row = {"joint": c[0], "link": c[1], "parent": c[2], "axis": vec(c[3]), "xyz": vec(c[4]),
               "lower": lower, "upper": upper, "velocity": float(c[6]), "effort": float(c[7]),
               "mass": float(c[8]), "com": vec(c[9]), "inertia": vec(c[10])}
        assert len(row["inertia"]) == 6 and row["mass"] > 0, row
        rows.append(row)
    return rows


def inertial_xml(mass, com, i, indent):
    return (f'{indent}<inertial>\n'
            f'{indent}  <origin xyz="{" ".join(fmt(v) for v in com)}" rpy="0 0 0"/>\n'
            f'{indent}  <mass value="{fmt(mass)}"/>\n'
            f'{indent}  <inertia ixx="{fmt(i[0])}" ixy="{fmt(i[1])}" ixz="{fmt(i[2])}" '
            f'iyy="{fmt(i[3])}" iyz="{fmt(i[4])}" izz="{fmt(i[5])}"/>\n'
            f'{indent}</inertial>\n')


def visual_xml(link, indent):
    out = []
    for shape, size, xyz in VISUALS.get(link, []):
        if shape == "box":
            geometry = f'<box size="{" ".join(fmt(v) for v in size)}"/>'
        else:
            geometry = f'<cylinder radius="{fmt(size[0])}" length="{fmt(size[1])}"/>'
        out.append(f'{indent}<visual>\n'
                   f'{indent}  <origin xyz="{" ".join(fmt(round(v, 6)) for v in xyz)}" rpy="0 0 0"/>\n'
                   f'{indent}  <geometry>{geometry}</geometry>\n'
                   f'{indent}  <material name="shell"/>\n'
                   f'{indent}</visual>\n')
    return "".join(out)


def fixed_joint_xml(name, parent, child, z):
    return (f'  <joint name="{name}" type="fixed">\n'
            f'    <parent link="{parent}"/>\n'
            f'    <child link="{child}"/>\n'
            f'    <origin xyz="0 0 {fmt(z)}" rpy="0 0 0"/>\n'
            f'  </joint>\n')


def main():
    rows = parse_table()
    here = os.path.dirname(os.path.abspath(__file__))
    out = ['<?xml version="1.0"?>\n',
           "<!-- TALOS humanoid (PAL Robotics): 30 revolute joints, root link base_link (the\n"
           "     free-flyer is added by the consumer). GENERATED by robots/talos/make_urdf.py: edit the\n"
           "     script, not this file. Source: stack-of-tasks/talos-data (LGPL-3.0),\n"
           "     urdf/talos_reduced.urdf and srdf/talos.srdf, transcribed in the table of make_urdf.py;\n"
           "     see robots/talos/README.md. Frames: x forward, y left, z up, every link frame parallel\n"
           "     to base_link at q = 0. Hands lumped (make_urdf.py); no collision geometry.\n"
           "     left_sole_link / right_sole_link: massless frames 0.107 m below the ankles. -->\n",
           '<robot name="talos">\n',
           '  <material name="shell"><color rgba="0.75 0.77 0.8 1"/></material>\n',
           '  <link name="base_link">\n', inertial_xml(BASE[0], BASE[1], BASE[2], "    "),
           visual_xml("base_link", "    "), "  </link>\n"]
    for row in rows:
        out.append(f'  <joint name="{row["joint"]}" type="revolute">\n'
                   f'    <parent link="{row["parent"]}"/>\n'
                   f'    <child link="{row["link"]}"/>\n'
                   f'    <origin xyz="{" ".join(fmt(v) for v in row["xyz"])}" rpy="0 0 0"/>\n'
                   f'    <axis xyz="{" ".join(fmt(v) for v in row["axis"])}"/>\n'
                   f'    <limit lower="{fmt(row["lower"])}" upper="{fmt(row["upper"])}" '
                   f'effort="{fmt(row["effort"])}" velocity="{fmt(row["velocity"])}"/>\n'
                   f'  </joint>\n')
        out.append(f'  <link name="{row["link"]}">\n'
                   + inertial_xml(row["mass"], row["com"], row["inertia"], "    ")
                   + visual_xml(row["link"], "    ") + "  </link>\n")
    cube = HAND_MASS * HAND_CUBE ** 2 / 6.0
    for side in ("left", "right"):
        out.append(fixed_joint_xml(f"arm_{side}_hand_joint", f"arm_{side}_7_link",
                                   f"arm_{side}_hand_link", -HAND_DEPTH))
        out.append(f'  <link name="arm_{side}_hand_link">\n'
                   + inertial_xml(HAND_MASS, (0, 0, 0), (cube, 0, 0, cube, 0, cube), "    ")
                   + "  </link>\n")
        out.append(fixed_joint_xml(f"leg_{side}_sole_fix_joint", f"leg_{side}_6_link",
                                   f"{side}_sole_link", -SOLE_DEPTH))
        out.append(f'  <link name="{side}_sole_link"/>\n')
    out.append("</robot>\n")
    with open(os.path.join(here, "talos.urdf"), "w") as f:
        f.write("".join(out))
    joints = [r["joint"] for r in rows]
    assert set(HALF_SITTING) <= set(joints)
    srdf = ['<?xml version="1.0"?>\n',
            "<!-- Reference postures of talos.urdf (SRDF group states). GENERATED by\n"
            "     robots/talos/make_urdf.py. half_sitting: the source's (srdf/talos.srdf);\n"
            "     the free-flyer is not part of a group state. -->\n",
            '<robot name="talos">\n', '  <group_state name="half_sitting" group="all">\n']
    srdf += [f'    <joint name="{j}" value="{fmt(HALF_SITTING.get(j, 0.0))}"/>\n' for j in joints]
    srdf += ["  </group_state>\n", "</robot>\n"]
    with open(os.path.join(here, "talos.srdf"), "w") as f:
        f.write("".join(srdf))
    total = BASE[0] + sum(r["mass"] for r in rows) + 2 * HAND_MASS
    print(f"wrote talos.urdf: {len(rows)} revolute joints, mass {total:.6f} kg")


if __name__ == "__main__":
    main()
