"""check_talos_model.py URDF SRDF CHECK.txt: recompute from the URDF and the SRDF's half_sitting,
with a forward kinematics of its own (every joint origin has rpy = 0 in talos.urdf, so a link's
frame is its parent's, translated, then turned about the joint axis), the links' mass, the hip-
to-sole length of the straight leg, and the whole-body CoM height above the soles; compare with
what `wpg robot check` printed (to its printed precision)."""
import re
import sys
import xml.etree.ElementTree as ET

import numpy as np

urdf, srdf, check = ET.parse(sys.argv[1]).getroot(), ET.parse(sys.argv[2]).getroot(), open(sys.argv[3]).read()
posture = {j.get("name"): float(j.get("value"))
           for j in srdf.find("group_state[@name='half_sitting']").findall("joint")}


def rotation(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def vec(text):
    return np.array([float(v) for v in text.split()])


def forward_kinematics(angles):
    """Link name -> (rotation, position) in base_link's frame."""
    pose = {"base_link": (np.eye(3), np.zeros(3))}
    pending = list(urdf.findall("joint"))
    while pending:
        joint = pending.pop(0)
        parent = joint.find("parent").get("link")
        if parent not in pose:
            pending.append(joint)
            continue
        origin = joint.find("origin")
        assert vec(origin.get("rpy")).tolist() == [0, 0, 0], joint.get("name")
        r, p = pose[parent]
        angle = angles.get(joint.get("name"), 0.0) if joint.get("type") == "revolute" else 0.0
        axis = vec(joint.find("axis").get("xyz")) if joint.find("axis") is not None else [0, 0, 1]
        pose[joint.find("child").get("link")] = (r @ rotation(axis, angle),
                                                 p + r @ vec(origin.get("xyz")))
    return pose


pose = forward_kinematics(posture)
mass, moment = 0.0, np.zeros(3)
for link in urdf.findall("link"):
    inertial = link.find("inertial")
    if inertial is None:
        continue
    m = float(inertial.find("mass").get("value"))
    r, p = pose[link.get("name")]
    mass += m
    moment += m * (p + r @ vec(inertial.find("origin").get("xyz")))
com = moment / mass
soles = [pose[f"{side}_sole_link"][1] for side in ("left", "right")]
assert abs(soles[0][2] - soles[1][2]) < 1e-12, soles
height = com[2] - soles[0][2]
straight = forward_kinematics({})  # hip: the hip-yaw joint's origin, leg_left_1_link's frame
leg = np.linalg.norm(straight["left_sole_link"][1] - straight["leg_left_1_link"][1])

printed_mass = float(re.search(r"links' mass ([0-9.]+) kg", check).group(1))
printed_leg = float(re.search(r"straight ([0-9.]+) m, ([0-9.]+) m", check).group(1))
printed_height = float(re.search(r"standing posture half_sitting ([0-9.]+) m", check).group(1))
print(f"mass {mass:.6f} kg (printed {printed_mass}), straight leg {leg:.4f} m (printed "
      f"{printed_leg}), half-sitting CoM {height:.6f} m above the soles (printed {printed_height})")
assert abs(mass - 90.222192) < 1e-9 and abs(mass - printed_mass) <= 5e-4, mass
assert abs(leg - printed_leg) <= 5e-5, leg
assert abs(height - printed_height) <= 5e-5, height
