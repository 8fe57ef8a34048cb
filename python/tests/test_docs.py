"""help() says something for every public function, class and method of the package."""
import inspect

import musclesim


def _public(namespace):
    return [(name, getattr(namespace, name)) for name in dir(namespace) if not name.startswith("_")]


def test_every_public_callable_has_a_docstring_with_content():
    missing = []
    for name, obj in _public(musclesim):
        if inspect.ismodule(obj) or not callable(obj):
            continue
        if len((obj.__doc__ or "").strip()) < 20:
            missing.append(name)
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            for method, member in _public(obj):
                if callable(member) and len((member.__doc__ or "").strip()) < 20:
                    missing.append(f"{name}.{method}")
    assert not missing, missing
