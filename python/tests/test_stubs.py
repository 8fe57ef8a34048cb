"""The checked-in type stubs (musclesim/_musclesim.pyi, made by pybind11-stubgen 2.5.1 from
the built module: `pybind11-stubgen musclesim._musclesim --numpy-array-use-type-var -o DIR`,
the flag writing NumPy arrays as numpy.ndarray[Any, numpy.dtype[...]] as type checkers take
them) describe the module as it is: every public name of the extension and of each of its
classes is in the stubs, and the stubs name nothing the module lacks. A binding added or
removed without regenerating them fails here."""
import ast
import inspect
import pathlib

import musclesim
from musclesim import _musclesim

STUB = pathlib.Path(musclesim.__file__).with_name("_musclesim.pyi")


def public(names):
    return {n for n in names if not n.startswith("_")}


def stub_names():
    tree = ast.parse(STUB.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            top.add(node.name)
        if isinstance(node, ast.ClassDef):
            members[node.name] = public(
                n.name for n in node.body if isinstance(n, (ast.FunctionDef, ast.ClassDef)))
            members[node.name] |= public(
                t.id for n in node.body if isinstance(n, ast.AnnAssign)
                for t in [n.target] if isinstance(t, ast.Name))
    return public(top), members


def test_the_package_is_typed():
    assert STUB.is_file()
    assert STUB.with_name("py.typed").is_file()


def test_the_stubs_name_every_public_function_and_class_of_the_module():
    top, members = stub_names()
    module = public(n for n, v in vars(_musclesim).items()
                    if inspect.isclass(v) or callable(v))
    # the exceptions are Python classes (musclesim/_errors.py): the stubs import them
    module -= {"InputError", "ParameterError"}
    assert module == top
    for name, cls in vars(_musclesim).items():
        if not inspect.isclass(cls) or name in ("InputError", "ParameterError"):
            continue
        assert public(vars(cls)) == members[name], name
