"""A Griffe extension for the documentation site (mkdocs.yml): shows the Python package's
docstrings as help() shows them.

The docstrings are plain text, not Markdown: outside `code` spans, the characters Markdown
would read as markup are escaped (`<column>` is text, not an HTML tag; `[l1, l2] [m]` is
text, not a link; `*` and `_` make no emphasis), and a paragraph laid out with indented lines
(a list of arguments, of targets) keeps its lines and their indentation.
"""
import re

import griffe

_CODE_SPAN = re.compile(r"(`[^`]*`)")
_MARKUP = re.compile(r"([\\`*_\[\]#>])")
_PARAGRAPH_BREAK = re.compile(r"\n[ \t]*\n")


def _escaped(text):
    """`text` with Markdown's markup characters escaped, `code` spans left as they are."""
    pieces = _CODE_SPAN.split(text)
    for k in range(0, len(pieces), 2):  # the text between code spans
        pieces[k] = _MARKUP.sub(r"\\\1", pieces[k]).replace("<", "&lt;")
    return "".join(pieces)


def _laid_out(paragraph):
    """A paragraph with an indented line keeps every line break and indentation."""
    lines = paragraph.split("\n")
    if not any(line[:1].isspace() for line in lines):
        return paragraph
    kept = []
    for line in lines:
        indent = len(line) - len(line.lstrip(" "))
        kept.append("&nbsp;" * indent + line[indent:])
    return "  \n".join(kept)  # two spaces: Markdown's line break


def plain_text_markdown(text):
    """The Markdown that renders the plain text `text` as written."""
    return "\n\n".join(_laid_out(_escaped(p)) for p in _PARAGRAPH_BREAK.split(text))


class PlainDocstrings(griffe.Extension):
    """Rewrites every docstring of the loaded package once, as plain_text_markdown says."""

    def on_object(self, *, obj, **kwargs):
        if obj.docstring is not None:
            obj.docstring.value = plain_text_markdown(obj.docstring.value)
