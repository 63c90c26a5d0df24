"""Overrides as `wpg run --set KEY=VALUE` takes them: a dict {key: value} -> "key=<YAML text>"."""
import math
import numbers
from collections.abc import Mapping

from ._wpg import InputError


def yaml_text(value, key):
    """The YAML text of a Python value: numbers, bools, None, strings, lists/tuples/arrays, dicts."""
    if value is None:
        return "null"
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        number = float(value)
        if math.isnan(number):
            return ".nan"
        if math.isinf(number):
            return ".inf" if number > 0 else "-.inf"
        return repr(number)
    if isinstance(value, str):
        return value
    if isinstance(value, Mapping):
        return "{" + ", ".join("%s: %s" % (yaml_text(k, key), yaml_text(v, key))
                               for k, v in value.items()) + "}"
    if hasattr(value, "tolist"):  # numpy arrays and scalars
        return yaml_text(value.tolist(), key)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(yaml_text(item, key) for item in value) + "]"
    raise InputError("overrides: key '%s': expected a number, a bool, a string, a list or a "
                     "dict, got %s" % (key, type(value).__name__))


def override_items(overrides):
    """["key=value", ...] for the engine's scenario loader, from a dict (or None)."""
    if overrides is None:
        return []
    if not isinstance(overrides, Mapping):
        raise InputError("overrides: expected a dict {key: value} such as {'duration': 12}, "
                         "got %s" % type(overrides).__name__)
    items = []
    for key, value in overrides.items():
        if not isinstance(key, str) or not key or "=" in key:
            raise InputError("overrides: expected keys such as 'duration' or 'reference[1].v', "
                             "got %r" % (key,))
        items.append("%s=%s" % (key, yaml_text(value, key)))
    return items
