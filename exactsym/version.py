"""The version of exactsym (its own module, so that a command can name it without loading
the package's public names)."""

__version__ = "0.1.0"
