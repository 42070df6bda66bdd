"""A vehicle from Python dicts: the dict has the tables and keys of a vehicle file
(docs/input.md), with units as strings ("910 kgf/cm"). It is written as a vehicle file and read
by the library's own reader, so the checks and unit conversions are the file's; an error names
the dict's key path (e.g. "body.mass") rather than a line of the written file.
"""
import json
import math
import os
import re
import tempfile
import warnings

from . import _railmodal

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _input_error(message, key):
    """railmodal.InputError for a dict: file "<dict>", no line or column, the key path."""
    text = "<dict>: error: " + message
    error = _railmodal.InputError(text)
    error.file = "<dict>"
    error.line = None
    error.column = None
    error.message = message
    error.key = key
    return error


def _key(name, path):
    if not isinstance(name, str):
        raise _input_error("key '%s%r': keys must be strings" % (path + "." if path else "", name), path or None)
    return name if _BARE_KEY.match(name) else json.dumps(name, ensure_ascii=False)


def _join(path, name):
    return name if not path else path + "." + name


def _scalar(value, path):
    """A TOML value written inline (strings, numbers, booleans, arrays, inline tables)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if hasattr(value, "tolist") and not isinstance(value, (dict, list, tuple)):  # numpy scalars and arrays
        return _scalar(value.tolist(), path)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_scalar(v, "%s[%d]" % (path, i)) for i, v in enumerate(value)) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(_key(k, path) + " = " + _scalar(v, _join(path, k)) for k, v in value.items()) + " }"
    raise _input_error("key '%s': a %s cannot be written in a vehicle file (a string with its unit, a "
                       "number, a boolean, a list or a dict)" % (path, type(value).__name__), path)


def _is_table_array(value):
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(isinstance(v, dict) for v in value)


def _table(table, path, header, lines, places):
    """Writes the body of one table: its plain keys first, then its sub-tables (TOML's order)."""
    if header is not None:
        places[len(lines) + 1] = path
        lines.append(header)
    nested = []
    for name, value in table.items():
        key = _key(name, path)
        if isinstance(value, dict) or _is_table_array(value):
            nested.append((key, name, value))
            continue
        places[len(lines) + 1] = _join(path, name)
        lines.append(key + " = " + _scalar(value, _join(path, name)))
    for key, name, value in nested:
        child = _join(path, name)
        if isinstance(value, dict):
            _table(value, child, "[" + _header(path, key, header) + "]", lines, places)
        else:
            for i, item in enumerate(value):
                _table(item, "%s[%d]" % (child, i), "[[" + _header(path, key, header) + "]]", lines, places)


def _header(path, key, parent_header):
    """The dotted header of a sub-table: the parent header's keys and this key (TOML's
    [[a.b]] under [[a]] belongs to a's last element, so no index is written)."""
    if parent_header is None:
        return key
    return parent_header.strip("[]") + "." + key


def to_toml(vehicle):
    """The vehicle file a dict describes, and for each line the key path it writes."""
    if not isinstance(vehicle, dict):
        raise TypeError("vehicle_from_dict takes a dict with the tables of a vehicle file (docs/input.md)")
    lines, places = [], {}
    _table(vehicle, "", None, lines, places)
    return "\n".join(lines) + "\n", places


def vehicle_from_dict(vehicle):
    """A Vehicle from a dict with the tables and keys of a vehicle file, units as strings:

        vehicle_from_dict({"vehicle": {"name": "wagon", "template": "two-axle"},
                           "body": {"weight": "20 tf", ...}, ...})

    Read by the same reader as files (the same checks and unit conversions). Errors are
    railmodal.InputError with file "<dict>", line and column None and the key path in .key;
    warnings are railmodal.InputWarning "<dict>: warning: key '<key path>': ...".
    """
    text, places = to_toml(vehicle)
    with tempfile.TemporaryDirectory(prefix="railmodal-") as folder:
        path = os.path.join(folder, "vehicle.toml")
        with open(path, "w", encoding="utf-8") as out:
            out.write(text)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            try:
                result = _railmodal.load_vehicle(path)
            except _railmodal.InputError as error:
                if error.file != path:
                    raise
                key = error.key or places.get(error.line)
                raise _input_error(error.message, key) from None
    for warning in caught:
        _warn_again(warning, path, places)
    result.source = ""
    return result


def _warn_again(warning, path, places):
    """Issues a warning of the reader again, from the caller's line: one about the written file
    (deleted by now) names "<dict>" and the key path instead of the file, line and column, as its
    errors do (user audit 2026-11-28b, F9 d)."""
    text = str(warning.message)
    place = re.match(re.escape(path) + r":(\d+):\d+: warning: (.*)$", text, re.S)
    if place is None or not issubclass(warning.category, _railmodal.InputWarning):
        warnings.warn_explicit(warning.message, warning.category, warning.filename, warning.lineno)
        return
    message = place.group(2)
    key = places.get(int(place.group(1)))
    if key is not None and "key '" not in message:
        message = "key '%s': %s" % (key, message)
    warnings.warn("<dict>: warning: " + message, _railmodal.InputWarning, stacklevel=3)
