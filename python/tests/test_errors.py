"""The library's exceptions in Python: their types, messages and parsed attributes."""
import os

import pytest

import musclesim
from conftest import SOURCE

CONCENTRIC = os.path.join(SOURCE, "scenarios", "concentric.yaml")


def test_types():
    assert issubclass(musclesim.InputError, Exception)
    assert not issubclass(musclesim.InputError, ValueError)
    assert issubclass(musclesim.ParameterError, ValueError)
    # made in Python, they still have the attributes
    assert musclesim.InputError("x").key is None
    assert musclesim.ParameterError("x").rule is None


def test_parameter_error_attributes():
    with pytest.raises(musclesim.ParameterError) as error:
        musclesim._musclesim._require(False, "velocity.n", 0.0, "must be an integer >= 1")
    assert (error.value.path, error.value.value, error.value.rule) == (
        "velocity.n", "0", "must be an integer >= 1")
    assert str(error.value) == "velocity.n = 0: must be an integer >= 1"
    # no raise when the rule holds
    musclesim._musclesim._require(True, "velocity.n", 4.0, "must be an integer >= 1")


def write(tmp_path, text):
    path = tmp_path / "s.yaml"
    path.write_text(text)
    return str(path)


def test_bad_value_in_a_file(tmp_path):
    text = open(CONCENTRIC).read().replace("n: 3,", "n: 0,")
    lines = text.splitlines()
    row = next(i for i, s in enumerate(lines) if "n: 0," in s)
    path = write(tmp_path, text)
    with pytest.raises(musclesim.InputError) as error:
        musclesim.load_scenario(path)
    assert error.value.key == "model.velocity.n"
    column = lines[row].index("n: 0,") + 4  # 1-based column of the 0 after "n: "
    assert error.value.location == "%s:%d:%d" % (path, row + 1, column)
    assert str(error.value).startswith("model.velocity.n = 0 (")
    # the fields, as the library carries them (nothing parsed from the message)
    assert (error.value.file, error.value.line, error.value.column) == (path, row + 1, column)
    assert error.value.value == "0"
    assert str(error.value).endswith(": " + error.value.rule)


def test_unknown_and_missing_keys(tmp_path):
    path = write(tmp_path, open(CONCENTRIC).read().replace("  f_iso: 100.0", "  f_isoo: 100.0"))
    with pytest.raises(musclesim.InputError) as error:
        musclesim.load_scenario(path)
    # the first message names either the unknown key or the missing one; both under model
    assert error.value.key in ("model.f_isoo", "model.f_iso")
    assert error.value.location.startswith(path + ":")


def test_syntax_error_has_a_location_and_no_key(tmp_path):
    path = write(tmp_path, "name: x\nmodel: {f_iso: [1, 2}\n")
    with pytest.raises(musclesim.InputError) as error:
        musclesim.load_scenario(path)
    assert error.value.key is None
    assert error.value.location.startswith(path + ":")
    assert "YAML syntax error" in str(error.value)


def test_missing_file(tmp_path):
    with pytest.raises(musclesim.InputError) as error:
        musclesim.load_scenario(str(tmp_path / "none.yaml"))
    assert error.value.key is None and error.value.location is None
    assert "none.yaml" in str(error.value)


def test_override_naming_no_value():
    with pytest.raises(musclesim.InputError) as error:
        musclesim.load_scenario(CONCENTRIC, set=["model.nothing.n=3"])
    assert error.value.key == "model.nothing.n"
    assert error.value.location is None
    assert (error.value.file, error.value.line, error.value.value) == ("set", None, "3")
    assert str(error.value).startswith("set model.nothing.n=3: ")


def test_override_value_type_is_checked():
    scenario = musclesim.load_scenario(CONCENTRIC)
    with pytest.raises(TypeError):
        scenario.set("model.f_iso", [1.0])


def keyed_failures():
    """(call, expected key, expected location) for the forms of message each reader writes."""
    scenario = musclesim.load_scenario(CONCENTRIC, set={"time.end": 0.01})
    sweep = {"base": CONCENTRIC, "parameters": {"load[0].aftr": [1.0]}, "metrics": ["final_length"]}
    return [
        (lambda: scenario.run(sensitivities=["model.nonsense"]), "model.nonsense", None),
        # a dict has no lines: its messages name it, and give no location
        (lambda: musclesim.sweep(sweep), "parameters.load[0].aftr", None),
        (lambda: musclesim.identify_series(scenario, [{"t": [0.005], "length": [0.1]}],
                                           [{"path": "model.nope"}]),
         "parameters[0].path", None),
        (lambda: musclesim.identify_curves(passive=([0.1, 0.2], [1.0, 2.0])), "passive", None),
        (lambda: musclesim.identify_curves(active=([0.1, 0.2, 0.3, 0.4], [0, 0, 0, 1.0]),
                                           active_count=13), "active_count", None),
        (lambda: musclesim.load_scenario(CONCENTRIC, set={"model.f_iso": float("nan")}),
         "model.f_iso", None),
    ]


@pytest.mark.parametrize("case", range(6))
def test_every_kind_of_message_gives_its_key(case):
    call, key, location = keyed_failures()[case]
    with pytest.raises(musclesim.InputError) as error:
        call()
    assert (error.value.key, error.value.location) == (key, location), str(error.value)
    # the key parsed is the one the message names (an axis by its path)
    assert key.replace("parameters.load", "load") in str(error.value)


def test_a_nul_character_is_refused_before_it_cuts_a_message():
    scenario = musclesim.load_scenario(CONCENTRIC)
    with pytest.raises(ValueError, match="NUL"):
        scenario.set("model.f_iso", "120\x00junk")
    with pytest.raises(ValueError, match="NUL"):
        musclesim.load_scenario(CONCENTRIC, set=["model.f_iso=1\x00"])
