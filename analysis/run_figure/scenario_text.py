"""What the stored scenario says (root or run attribute `scenario`, parsed with PyYAML by
wpg_file_reading): the velocity command, the obstacles, the pushes."""
import math

import numpy as np

from .geometry import sole_corners


def fmt_number(value):
    try:
        return ("%.3g" % float(value))
    except (TypeError, ValueError):
        return str(value)


def describe_command(scenario):
    """A short text of the velocity command(s) of the scenario, or ''."""
    request = scenario.get("request") if isinstance(scenario.get("request"), dict) else scenario
    for key in ("reference", "command", "commands", "velocity"):
        entries = request.get(key)
        if entries is None:
            continue
        if isinstance(entries, dict):
            entries = [entries]
        if not isinstance(entries, list):
            return "%s: %s" % (key, entries)
        parts = []
        for entry in entries:
            if isinstance(entry, dict):
                velocity = entry.get("velocity", entry.get("command", entry.get("v")))
                if isinstance(velocity, (list, tuple)):
                    velocity = "(" + ", ".join(fmt_number(v) for v in velocity) + ")"
                elif isinstance(velocity, dict):
                    velocity = "(" + ", ".join(
                        "%s %s" % (k, fmt_number(v)) for k, v in velocity.items()) + ")"
                t = entry.get("t", entry.get("time"))
                parts.append(("t=%ss: " % fmt_number(t) if t is not None else "") + str(velocity))
            elif isinstance(entry, (list, tuple)):
                parts.append("(" + ", ".join(fmt_number(v) for v in entry) + ")")
            else:
                parts.append(str(entry))
        if len(parts) > 4:
            parts = parts[:3] + ["... (%d commands)" % len(parts)]
        text = "command [vx m/s, vy m/s, ω rad/s] " + "; ".join(parts)
        pushes = request.get("pushes")
        if isinstance(pushes, list) and pushes:
            text += "; %d push%s" % (len(pushes), "es" if len(pushes) > 1 else "")
            first = pushes[0]
            if isinstance(first, dict) and isinstance(first.get("force"), (list, tuple)):
                text += " (%s N at t=%ss)" % (
                    ", ".join(fmt_number(v) for v in first["force"]), fmt_number(first.get("t")))
        return text
    return ""


def scenario_obstacles(scenario):
    """[(outline [(x, y)], margin, circle, known to the planner)] of the scenario's obstacles
    (circles as polygons)."""
    request = scenario.get("request") if isinstance(scenario.get("request"), dict) else scenario
    obstacles = request.get("obstacles")
    shapes = []
    for obstacle in obstacles if isinstance(obstacles, list) else []:
        try:
            kind = obstacle.get("type", "circle")
            margin = float(obstacle.get("margin", 0.0) or 0.0)
            known = obstacle.get("known_to_planner", True) is not False
            if kind == "circle":
                cx, cy = (float(v) for v in obstacle["center"])
                radius = float(obstacle["radius"])
                outline = [(cx + radius * math.cos(a), cy + radius * math.sin(a))
                           for a in np.linspace(0.0, 2.0 * math.pi, 64, endpoint=False)]
                shapes.append((outline, margin, ("circle", cx, cy, radius), known))
            elif kind == "box":
                cx, cy = (float(v) for v in obstacle["center"])
                length, width = (float(v) for v in obstacle["size"])
                outline = sole_corners(cx, cy, float(obstacle.get("yaw", 0.0) or 0.0),
                                       length, width)
                shapes.append((outline, margin, None, known))
            elif kind == "polygon":
                outline = [(float(v[0]), float(v[1])) for v in obstacle["vertices"]]
                shapes.append((outline, margin, None, known))
        except (TypeError, KeyError, ValueError, AttributeError):
            continue
    return shapes


def scenario_pushes(scenario):
    """[(t0, t1)] of the pushes of the scenario."""
    request = scenario.get("request") if isinstance(scenario.get("request"), dict) else scenario
    pushes = request.get("pushes")
    spans = []
    for push in pushes if isinstance(pushes, list) else []:
        try:
            t0 = float(push["t"])
            spans.append((t0, t0 + float(push.get("duration", 0.1))))
        except (TypeError, KeyError, ValueError):
            continue
    return spans
