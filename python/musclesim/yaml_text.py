"""Python values as the text of a YAML file, for the readers of the files (a dict scenario,
sweep or identification spec is read by the same reader as a file, so the same rules and
messages apply)."""
import json
import math
from collections.abc import Mapping

__all__ = []


def _yaml_ready(value):
    """`value` as JSON can write it and the YAML reader reads it: NumPy scalars and arrays as
    Python numbers and lists, non-finite floats as YAML's .nan/.inf (JSON has none), so that
    the reader, not json, names such a value and the rule it breaks."""
    if isinstance(value, Mapping):
        return {key: _yaml_ready(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_yaml_ready(item) for item in value]
    if hasattr(value, "tolist") and not isinstance(value, (str, bytes)):
        return _yaml_ready(value.tolist())  # NumPy scalar or array
    if isinstance(value, float) and not math.isfinite(value):
        return ".nan" if math.isnan(value) else (".inf" if value > 0 else "-.inf")
    return value


def yaml_text(value):
    """The JSON text (which is YAML) of `value`, one key per line, so that a reader's
    line:column points at the key."""
    return json.dumps(_yaml_ready(value), indent=1)
