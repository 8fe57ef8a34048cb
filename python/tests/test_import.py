"""The package imports from the build tree and says what it is."""
import musclesim


def test_the_package_imports_with_its_documentation():
    assert "SI units" in musclesim.__doc__
