"""help() says something for every public function, class, method and property of the
package, and every public function and class states its units or conventions."""
import inspect
import re

import musclesim

# what a docstring that states units or conventions holds: a unit in brackets, an SI unit
# spelled out, or a reference to SI units or to the CSV's named (and documented) columns
UNITS = re.compile(r"\[(m|N|s|m/s|-|1/m|N/m|Hz|kg)\b|\b(SI|m/s|N|[Mm]eters?|seconds)\b|"
                   r"\bunits?\b|column")


def _public(namespace):
    return [(name, inspect.getattr_static(namespace, name)) for name in dir(namespace)
            if not name.startswith("_")]


def _members(cls):
    for name, member in _public(cls):
        if isinstance(member, property) or callable(member) or hasattr(member, "__get__"):
            yield name, getattr(member, "__doc__", None)


def test_every_public_callable_and_property_has_a_docstring_with_content():
    missing = []
    for name, obj in _public(musclesim):
        if inspect.ismodule(obj) or not callable(obj):
            continue
        if len((obj.__doc__ or "").strip()) < 20:
            missing.append(name)
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            for member, doc in _members(obj):
                # an attribute without its own docstring is described in the class's
                described = re.search(rf"\b{member}\b[^\n]*:", obj.__doc__ or "")
                if len((doc or "").strip()) < 20 and not described:
                    missing.append(f"{name}.{member}")
    assert not missing, missing


def test_every_public_function_and_class_states_units_or_conventions():
    silent = [name for name, obj in _public(musclesim)
              if callable(obj) and not inspect.ismodule(obj)
              and not (inspect.isclass(obj) and issubclass(obj, BaseException))
              and not UNITS.search(obj.__doc__ or "")]
    assert not silent, silent
