"""make_scaled_robot.py SOURCE_DIR OUT_DIR NAME SCALE [--thigh-twist]: a robot folder of other
proportions, made as docs/robots.md ("Add your robot") says, from HRP-2's.

The URDF: every length (joint and inertial origins, shapes) times SCALE, every mass times
SCALE^3 and every inertia times SCALE^5 (the same density), the sole frames renamed to
NAME_left_sole / NAME_right_sole; the SRDF's standing posture renamed `stand`. The walking file:
the shipped one with `multibody:` naming these, every length (sole, ankle, margins, foot
separations, feasibility polygon, step height) and speed times SCALE (the same step timing),
the mass times SCALE^3. With --thigh-twist each leg gets a seventh joint: a twist about the
thigh's axis halfway down it (a 0.2 kg link, limits +-0.5 rad, 0 standing), so that the walking
IK is the numerical one (docs/robots.md, "What the URDF must be"). `com_height` is left at the source's times SCALE: the test sets it from
`wpg robot check` (the standing posture's CoM height), as the docs' step 4 says.
"""
import re
import sys
import xml.etree.ElementTree as ET

src, out, name, scale = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
thigh_twist = sys.argv[5:] == ["--thigh-twist"]
walking = open(f"{src}/walking.yaml").read()
urdf_name = re.search(r"^\s*urdf:\s*(\S+)", walking, re.M).group(1)
left = re.search(r"^\s*left_sole_frame:\s*(\S+)", walking, re.M).group(1)
right = re.search(r"^\s*right_sole_frame:\s*(\S+)", walking, re.M).group(1)
posture = re.search(r"^\s*standing_posture:\s*(\S+)", walking, re.M).group(1)
renamed = {left: f"{name}_left_sole", right: f"{name}_right_sole"}


def scaled(text, factor):
    return " ".join(repr(float(v) * factor) for v in text.split())


tree = ET.parse(f"{src}/{urdf_name}")
for element in tree.iter():
    for attribute in ("link", "name"):
        if element.get(attribute) in renamed:
            element.set(attribute, renamed[element.get(attribute)])
    if element.tag == "origin":
        element.set("xyz", scaled(element.get("xyz", "0 0 0"), scale))
    elif element.tag == "mass":
        element.set("value", scaled(element.get("value"), scale ** 3))
    elif element.tag == "inertia":
        for key in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"):
            element.set(key, scaled(element.get(key), scale ** 5))
    elif element.tag == "box":
        element.set("size", scaled(element.get("size"), scale))
    elif element.tag in ("cylinder", "sphere"):
        for key in ("radius", "length"):
            if element.get(key) is not None:
                element.set(key, scaled(element.get(key), scale))
tree.getroot().set("name", name)
twists = []
if thigh_twist:  # HRP-2's knee: *LEG_JOINT3 on *LEG_LINK2, (0, 0, -0.3) m below the hip
    root = tree.getroot()
    for side in ("L", "R"):
        knee = root.find(f"joint[@name='{side}LEG_JOINT3']")
        thigh = knee.find("parent").get("link")
        origin = [float(v) for v in knee.find("origin").get("xyz").split()]
        half = [0.5 * v for v in origin]
        twist, link = f"{side}LEG_TWIST", f"{side}LEG_TWIST_LINK"
        mass, inertia = 0.2 * scale ** 3, 1e-4 * scale ** 5
        root.append(ET.fromstring(
            f'<joint name="{twist}" type="revolute"><parent link="{thigh}"/>'
            f'<child link="{link}"/><origin xyz="{" ".join(map(repr, half))}" rpy="0 0 0"/>'
            f'<axis xyz="0 0 1"/><limit lower="-0.5" upper="0.5" effort="100" velocity="3"/>'
            f'</joint>'))
        root.append(ET.fromstring(
            f'<link name="{link}"><inertial><origin xyz="0 0 0" rpy="0 0 0"/>'
            f'<mass value="{mass!r}"/><inertia ixx="{inertia!r}" ixy="0" ixz="0" '
            f'iyy="{inertia!r}" iyz="0" izz="{inertia!r}"/></inertial></link>'))
        knee.find("parent").set("link", link)
        knee.find("origin").set("xyz", " ".join(map(repr, half)))
        twists.append(twist)
tree.write(f"{out}/{name}.urdf", xml_declaration=True, encoding="utf-8")
srdf = open(f"{src}/{urdf_name[:-5]}.srdf").read().replace(f'name="{posture}"', 'name="stand"')
for twist in twists:
    srdf = srdf.replace("</group_state>", f'  <joint name="{twist}" value="0"/>\n  </group_state>')
open(f"{out}/{name}.srdf", "w").write(srdf)

LENGTHS = ("com_height", "foot_length", "foot_width", "ankle_height", "cop_margin_x",
           "cop_margin_y", "initial_foot_separation", "stop_foot_separation",
           "obstacle_foot_radius", "feasibility_x", "feasibility_y", "step_height",
           "push_step_capture_offset", "push_step_capture_jump", "max_forward_velocity",
           "max_lateral_velocity")


def rescale(match):
    key, value = match.group(1), match.group(2)
    factor = scale if key in LENGTHS else scale ** 3
    if key == "mass":  # the source's, scaled, and the two twist links
        return f"mass: {round(float(value) * factor + 0.2 * scale ** 3 * len(twists), 6)!r}"
    if value.startswith("["):
        numbers = [float(v) * factor for v in value.strip("[]").split(",")]
        return f"{key}: [{', '.join(repr(round(v, 6)) for v in numbers)}]"
    return f"{key}: {round(float(value) * factor, 6)!r}"


keys = "|".join(LENGTHS + ("mass",))
walking = re.sub(rf"^({keys}):\s*(\[[^\]]*\]|[-+0-9.eE]+)", rescale, walking, flags=re.M)
walking = re.sub(r"^(\s*urdf:)\s*\S+", rf"\1 {name}.urdf", walking, flags=re.M)
walking = re.sub(r"^(\s*left_sole_frame:)\s*\S+", rf"\1 {name}_left_sole", walking, flags=re.M)
walking = re.sub(r"^(\s*right_sole_frame:)\s*\S+", rf"\1 {name}_right_sole", walking, flags=re.M)
walking = re.sub(r"^(\s*standing_posture:)\s*\S+", r"\1 stand", walking, flags=re.M)
open(f"{out}/walking.yaml", "w").write(walking)
