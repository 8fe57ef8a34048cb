"""Types the package's signatures share, for type checkers (and help(), which names them)."""
import os
from typing import Any, Iterable, Mapping, Optional, Protocol, Sequence, Union

# A file's path: a str or an os.PathLike (pathlib.Path).
PathLike = Union[str, os.PathLike[str]]

# Values set as --set sets them: "key=value" strings, or a dict {key: value}; None: none.
Overrides = Optional[Union[Sequence[str], Mapping[str, Any]]]


class ColumnTable(Protocol):
    """Columns by name, as the CSV files name them: a dict of 1-D arrays, or a pandas
    DataFrame (anything with keys() and [name])."""

    def keys(self) -> Iterable[Any]: ...

    def __getitem__(self, key: str, /) -> Any: ...
