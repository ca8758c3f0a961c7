"""conescope's exceptions: one base, each also the standard type a caller would catch."""

import contextlib

from . import _conescope


class Error(Exception):
    """The base of every error conescope raises on purpose."""


class MeshReadError(Error, OSError):
    """A mesh file that cannot be read; the message is the one conescope-cli prints."""


class SettingsError(Error, ValueError):
    """A setting or argument the settings schema (or the function) refuses."""


class MeshDataError(Error, ValueError):
    """Arrays that are not a mesh: a bad shape, a non-finite position, an index out of range."""


class ArgumentTypeError(Error, TypeError):
    """An argument of a type conescope cannot take (a float face array, a text where a number goes)."""


class BatchError(Error, RuntimeError):
    """A batch that could not run as a whole (its rows say what failed per mesh)."""


@contextlib.contextmanager
def translated(value_error=SettingsError):
    """Errors of the compiled part as conescope's own: its ValueErrors as `value_error`, and no
    binding library's text (a cast it could not make) reaching the caller."""
    try:
        yield
    except _conescope.MeshReadError as error:
        raise MeshReadError(str(error)) from None
    except Error:
        raise
    except ValueError as error:
        raise value_error(str(error)) from None
    except (TypeError, RuntimeError) as error:
        if "cast" in str(error).lower() or "incompatible function arguments" in str(error):
            raise ArgumentTypeError("an argument has a type conescope cannot take: check each one's "
                                    "documented type") from None
        raise


# Shown as conescope.SettingsError in tracebacks, where users import them from.
for _error in (Error, MeshReadError, SettingsError, MeshDataError, ArgumentTypeError, BatchError):
    _error.__module__ = "conescope"
