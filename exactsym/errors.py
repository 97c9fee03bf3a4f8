"""Errors a user can cause. Each names where in the input it happened.

Exit code 2 of the command line (``docs/cli.md``) is exactly "an
:class:`InputError` was raised"; anything else reaching the user is a bug.
"""

from __future__ import annotations

#: Exit codes of the command line (``docs/cli.md``): done and every claim holds; a claim,
#: expectation or certificate is false; unusable input or command line; internal error.
EXIT_OK, EXIT_FALSE, EXIT_INPUT, EXIT_BUG = 0, 1, 2, 3


class InputError(Exception):
    """The input (file, expression, command line) is unusable.

    ``source`` is the file name (or ``<stdin>``), ``line`` and ``column`` are
    1-based when known.  ``str(err)`` is the one-line message shown to the user:
    ``file:line:column: message``.
    """

    def __init__(self, message: str, source: str | None = None,
                 line: int | None = None, column: int | None = None):
        super().__init__(message)
        self.message = message
        self.source = source
        self.line = line
        self.column = column

    def located(self, source: str | None = None, line: int | None = None,
                column: int | None = None) -> "InputError":
        """Return a copy with missing location parts filled in."""
        return type(self)(self.message,
                          self.source if self.source is not None else source,
                          self.line if self.line is not None else line,
                          self.column if self.column is not None else column)

    def __str__(self) -> str:
        where = [str(part) for part in (self.source, self.line, self.column) if part is not None]
        return (":".join(where) + ": " if where else "") + self.message


class ExpressionError(InputError):
    """An expression string is malformed or denotes no real algebraic number.

    ``offset`` is the 0-based character offset inside the expression string;
    the configuration reader turns it into a file line and column.
    """

    def __init__(self, message: str, source: str | None = None,
                 line: int | None = None, column: int | None = None, offset: int = 0):
        super().__init__(message, source, line, column)
        self.offset = offset

    def located(self, source=None, line=None, column=None) -> "ExpressionError":
        err = super().located(source, line, column)
        err.offset = self.offset
        return err


class FieldTooLargeError(InputError):
    """The numbers of a configuration need a number field beyond our limits."""


class MoveImpossible(Exception):
    """A move or change of frame of a :class:`~exactsym.geometry.configuration.Configuration`
    cannot be made: robots would coincide or overlap, or the new position is not exact in
    the configuration's numbers.  Not the user's fault (not an :class:`InputError`): the
    algorithm that asked for the move decides what it means."""
