"""musclesim.InputError and musclesim.ParameterError: the exceptions the extension raises for
bad input, the library's own translated with the fields they carry as attributes
(python/src/errors_binding.cc). Defined here, in Python, so that the type
stubs describe them and their attributes."""
from typing import Optional

__all__ = ["InputError", "ParameterError"]


class InputError(Exception):
    """Invalid input (a scenario file, a dict, an override), with a complete message naming
    the key path, the value, where it was given and the rule broken.

    Attributes:
      key: the dotted key path, e.g. 'elements[0].activation' or 'load[0].value', or None
        when the message names none (a file that cannot be read).
      location: 'file:line:column' (1-based) where the value was written, or None (a value
        given by set() or an override, or no position known). A scenario made by
        scenario_from_dict names its file '<dict>'.
      file: the file, or the label of an input without one ('set', '<dict>', 'row 3'), or
        None when the error names no place.
      line, column: 1-based, or None when the place has no position.
      value: the value at fault as written, or None.
      rule: the rule broken (for an error naming no key, the whole message).
    """

    __module__ = "musclesim"
    # set by the extension on the errors it raises; None on one made in Python
    key: Optional[str] = None
    location: Optional[str] = None
    file: Optional[str] = None
    line: Optional[int] = None
    column: Optional[int] = None
    value: Optional[str] = None
    rule: Optional[str] = None


class ParameterError(ValueError):
    """A parameter value that breaks a rule (a ValueError).

    Attributes:
      path: the parameter's dotted path inside the block validated, e.g. 'velocity.n'.
      value: the value as text.
      rule: the rule it breaks, e.g. 'must be an integer >= 1'.
    """

    __module__ = "musclesim"
    path: Optional[str] = None
    value: Optional[str] = None
    rule: Optional[str] = None
