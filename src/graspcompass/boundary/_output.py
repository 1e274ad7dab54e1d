"""Where output files go: one check before any work, one translation of write errors.

:func:`check_target` refuses, with :class:`~graspcompass.errors.OutputError`
and a one-line message naming the path, an output file that cannot be
written: an empty name, a folder, a missing folder (folders are never made
silently), a parent that is a file, no permission, a name that is too long, a
file system with no space left, a device that refuses writes (``/dev/full``).
:func:`writing` turns an :class:`OSError` during the write (a full disk,
``/dev/full``) into the same error, and removes a half-written file.  This
module is a leaf: it imports only :mod:`graspcompass.errors`.

Examples
--------
>>> import tempfile, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> check_target(folder / "d.svg").name
'd.svg'
>>> try:
...     check_target(folder / "missing" / "d.svg")
... except OutputError as err:
...     print(str(err).split(": ", 1)[1])  # doctest: +ELLIPSIS
the folder '...missing' does not exist (create it first)
"""

from __future__ import annotations

import contextlib
import errno
import os
import stat
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from .errors import OutputError

__all__ = ["check_folder", "check_target", "finite_record", "write_output", "writing"]


def _fail(path: object, why: str) -> OutputError:
    return OutputError(f"cannot write {str(path)!r}: {why}")


def _name_max(folder: Path) -> int:
    try:
        return os.pathconf(folder, "PC_NAME_MAX")
    except (OSError, ValueError, AttributeError):  # pragma: no cover - not POSIX
        return 255


def check_folder(
    folder: str | os.PathLike[str], path: str | os.PathLike[str] | None = None
) -> Path:
    """``folder`` as a :class:`~pathlib.Path` if files can be written in it.

    Parameters
    ----------
    folder : str or path-like
        An existing folder.
    path : str or path-like, optional
        The file to be written there, named in the message (default: ``folder``).

    Raises
    ------
    OutputError
        If ``folder`` does not exist, is not a folder or is not writable.
    """
    d = Path(folder)
    shown = d if path is None else path
    try:
        exists, is_dir = d.exists(), d.is_dir()
        writable = os.access(d, os.W_OK | os.X_OK)
    except OSError as exc:  # a name too long, a loop of links
        raise _fail(shown, _reason(exc)) from None
    if not exists:
        raise _fail(shown, f"the folder {str(d)!r} does not exist (create it first)")
    if not is_dir:
        raise _fail(shown, f"{str(d)!r} is not a folder")
    if not writable:
        raise _fail(shown, f"no permission to write in the folder {str(d)!r}")
    try:
        fs = os.statvfs(d)
        blocks = getattr(fs, "f_blocks", None)  # 0: a virtual file system (/proc, /sys)
        full, virtual = fs.f_bavail == 0 and blocks != 0, blocks == 0
    except (OSError, AttributeError):  # pragma: no cover - no statvfs (not POSIX)
        full = virtual = False
    if full:
        raise _fail(shown, "no space left on the device")
    if virtual and path is not None and not os.path.lexists(path):  # /proc, /sys: no storage
        raise _fail(
            shown,
            f"the folder {str(d)!r} is on a virtual file system (such as /proc "
            "or /sys), where no new file can be made",
        )
    return d


def _probe_device(p: Path, text: str) -> None:
    """Write nothing to an existing character device: ``/dev/full`` refuses even that.

    A zero-byte write changes nothing on ``/dev/null`` or a terminal; FIFOs
    (``/dev/stdout`` into a pipe) are not opened, since that could block.
    """
    try:
        if not stat.S_ISCHR(os.stat(p).st_mode):
            return
        fd = os.open(p, os.O_WRONLY | os.O_NONBLOCK | getattr(os, "O_NOCTTY", 0))
    except OSError as exc:
        raise _fail(text, _reason(exc)) from None
    try:
        os.write(fd, b"")
    except BlockingIOError:  # pragma: no cover - a device busy now may take the file later
        pass
    except OSError as exc:
        raise _fail(text, _reason(exc)) from None
    finally:
        os.close(fd)


def check_target(path: str | os.PathLike[str]) -> Path:
    """``path`` as a :class:`~pathlib.Path` if a file can be written there.

    Checks the name alone, before any work: the folder must exist (it is not
    made), the path must not be a folder, and the file, if it exists, must be
    writable.  A write can still fail later (a full disk): wrap it in
    :func:`writing`.

    Raises
    ------
    OutputError
        With a one-line message naming the path and the reason.
    """
    text = os.fspath(path)
    if isinstance(text, bytes):  # pragma: no cover - the CLI passes str
        text = os.fsdecode(text)
    if not text.strip():
        raise OutputError("cannot write a file with an empty name")
    if "\0" in text:
        raise _fail(text.replace("\0", "\\0"), "the name contains a NUL character")
    p = Path(text)
    if text.endswith(("/", os.sep)) or p.name in ("", ".", ".."):
        raise _fail(text, "that is a folder, not a file name")
    folder = check_folder(p.parent, text)
    if len(os.fsencode(p.name)) > _name_max(folder):
        raise _fail(text, f"the file name is longer than {_name_max(folder)} bytes")
    try:
        is_dir, exists, writable = p.is_dir(), p.exists(), os.access(p, os.W_OK)
    except OSError as exc:
        raise _fail(text, _reason(exc)) from None
    if is_dir:
        raise _fail(text, "that is a folder, not a file")
    if exists and not writable:
        raise _fail(text, "no permission to write the file")
    if exists:
        _probe_device(p, text)
    return p


def _reason(exc: OSError) -> str:
    if exc.errno == errno.ENOSPC:
        return "no space left on the device"
    if exc.strerror:
        return exc.strerror[:1].lower() + exc.strerror[1:]
    return str(exc).splitlines()[0] if str(exc) else type(exc).__name__


@contextmanager
def writing(path: str | os.PathLike[str]) -> Iterator[None]:
    """Turn an :class:`OSError` raised inside the block into :class:`OutputError`.

    A file the block made at ``path`` before failing (a half-written file on a
    full disk) is removed; a file that was there before is left alone.  A
    :class:`BrokenPipeError` (``-o /dev/stdout`` piped into ``head``) passes
    through: the reader has what it wanted, and the command line stops quietly.

    >>> try:
    ...     with writing("/dev/full"):
    ...         raise OSError(28, "No space left on device")
    ... except OutputError as err:
    ...     print(err)
    cannot write '/dev/full': no space left on the device
    """
    existed = os.path.lexists(path)
    try:
        yield
    except (OSError, OutputError) as exc:
        if not existed and os.path.isfile(path):
            try:
                os.unlink(path)
            except OSError:  # pragma: no cover - nothing more to do
                pass
        if isinstance(exc, (OutputError, BrokenPipeError)):
            raise
        raise _fail(os.fspath(path), _reason(exc)) from None
    except BaseException:  # out of time, interrupted: no half-written file either
        if not existed and os.path.isfile(path):
            with contextlib.suppress(OSError):
                os.unlink(path)
        raise


def write_output(path: str | os.PathLike[str], produce: Callable[[], str | bytes]) -> Path:
    """Check ``path`` (:func:`check_target`), then write what ``produce()`` makes there.

    The path is checked before any work; text is written as UTF-8, bytes as they are,
    and a failed write becomes an :class:`~graspcompass.errors.OutputError` with the
    half-written file removed (:func:`writing`).  Every file writer of the exports uses it.
    """
    p = check_target(path)
    data = produce()
    with writing(p):
        if isinstance(data, bytes):
            p.write_bytes(data)
        else:
            p.write_text(data, encoding="utf-8")
    return p


def finite_record(record: Any, advice: str, where: str = "") -> None:
    """Refuse a result holding a float that is not finite, before anything is printed.

    ``record`` is a JSON-like value (dicts, lists, numbers, text); the first
    ``inf`` or ``nan`` raises :class:`~graspcompass.errors.NonFiniteValueError`
    naming its key and ``advice`` (JSON has no infinities: ``json.dumps`` would
    write ``Infinity``, which is not JSON).
    """
    import math

    from .errors import NonFiniteValueError

    if isinstance(record, float) and not math.isfinite(record):
        raise NonFiniteValueError(
            f"{where or 'a result'} is {record}, beyond double precision: {advice}"
        )
    if isinstance(record, dict):
        for key, value in record.items():
            finite_record(value, advice, f"{where}.{key}" if where else str(key))
    elif isinstance(record, (list, tuple)):
        for i, value in enumerate(record):
            finite_record(value, advice, f"{where}[{i}]")
