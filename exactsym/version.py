"""The version of exactsym (its own module, so that a command can name it without loading
the package's public names)."""

__version__ = "0.1.0"

#: The version of the JSON outputs' schemas (docs/json.md, docs/schemas/): raised when a
#: key is renamed or removed or changes meaning; adding a key keeps it.
SCHEMA_VERSION = 1


def json_head(format_name: str, file: str | None, name: str | None) -> dict:
    """The keys every JSON output of exactsym begins with (docs/json.md): ``format`` (the
    output's kind, ``exactsym-check``, ``exactsym-gather``, ...), ``schema_version``,
    ``file`` (the input as given, ``null`` when none) and ``name`` (the input's name)."""
    return {"format": format_name, "schema_version": SCHEMA_VERSION, "file": file,
            "name": name}
