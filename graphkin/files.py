"""Bounded reading of every file graphkin is given.

Every file the command line reads (mechanism, answers, vector and gallery
files, SVG and DXF drawings) goes through :func:`check_file` first, so that a
device (``/dev/zero``, ``/dev/urandom``), a named pipe with no writer, a
folder or a huge file ends at once with one line and exit status 2, instead
of reading for ever or filling the memory.

The limit is :data:`MAX_FILE_BYTES` (20 MB): a mechanism or answers file is a
few kilobytes, and a drawing of a construction a few hundred.

TOML text is parsed by :func:`parse_toml`, which turns every failure of
:mod:`tomllib` (syntax, integers of more than 4300 digits, arrays nested so
deep that the parser recurses too far) into an :class:`~graphkin.errors.InputError`.
"""

from __future__ import annotations

import os
import re
import stat
import tomllib
from pathlib import Path
from typing import Any

from graphkin.errors import InputError

__all__ = ["MAX_FILE_BYTES", "check_output", "check_outputs", "check_file", "read_bytes",
           "read_text",
           "parse_toml", "load_toml"]

#: The largest file graphkin reads, in bytes (20 MB).
MAX_FILE_BYTES = 20 * 1024 * 1024

#: The deepest nesting of TOML arrays and tables accepted.
MAX_TOML_DEPTH = 64


def check_file(path: str | Path, *, limit: int = MAX_FILE_BYTES) -> Path:
    """Make sure ``path`` is a regular file no larger than ``limit`` bytes.

    Raises
    ------
    InputError
        It does not exist or cannot be read, it is not a regular file (a
        folder, a device, a named pipe, a socket), or it is too large.
    """
    p = Path(path)
    try:
        st = os.stat(p)
    except OSError as exc:
        raise InputError(f"cannot read the file ({exc.strerror or exc})", file=str(p)) from None
    except ValueError:  # a NUL byte in the name
        raise InputError("cannot read the file (bad file name)", file=repr(str(p))) from None
    if stat.S_ISDIR(st.st_mode):
        raise InputError("not a regular file (it is a folder)", file=str(p))
    if not stat.S_ISREG(st.st_mode):
        raise InputError("not a regular file (a device, pipe or socket cannot be read)",
                         file=str(p))
    if st.st_size > limit:
        raise InputError(f"file too large ({st.st_size / 1e6:.1f} MB; graphkin reads files "
                         f"up to {limit / 1024 / 1024:.0f} MB)", file=str(p))
    return p


def check_output(out: str | Path, inputs: list[str | Path], option: str) -> None:
    """Refuse to write ``out`` over one of the command's own input files.

    ``graphkin steps F -o F`` or ``graphkin sweep F --csv F`` would destroy
    the mechanism file; the same file under another name (a link) is caught
    too.

    Raises
    ------
    InputError
        ``out`` is one of ``inputs``.
    """
    if str(out) == "-":
        return
    o = Path(out)
    for f in inputs:
        p = Path(f)
        try:
            same = o.exists() and p.exists() and os.path.samefile(o, p)
        except (OSError, ValueError):
            same = False
        if same or o.resolve() == p.resolve():
            raise InputError(f"refusing to write over the input file {p}", key=option)


#: The options through which a command writes one file.
OUTPUT_OPTIONS = ("output", "csv", "gif", "draw")
#: The names of the frames ``--frames DIR`` writes (steps, forces, gears, animate).
FRAME_NAME = re.compile(r"^(step|forces|gears|cycle)-\d+\.(svg|png)$")


def check_outputs(options: dict[str, Any]) -> None:
    """Refuse, before any work, an output of a command that is one of its inputs.

    ``options`` are a command's parsed options (``vars(args)``).  Every option
    that names an existing file and is not an output (``FILE``, an answers
    file, ``--drawing``) is an input; ``-o``, ``--csv``, ``--gif`` and
    ``--draw`` must not be one of them (nor a link to one), and ``--frames
    DIR`` must not hold an input named like a frame (``step-00.svg``).  The
    class check of every command, new ones included.

    Raises
    ------
    InputError
        Naming the option and the input file.
    """
    inputs: list[Path] = []
    for key, value in options.items():
        if key.startswith("_") or key in OUTPUT_OPTIONS or key == "frames":
            continue
        for v in value if isinstance(value, list) else [value]:
            if isinstance(v, (str, Path)) and str(v) not in ("", "-"):
                try:
                    if Path(v).is_file():
                        inputs.append(Path(v))
                except (OSError, ValueError):
                    continue
    if not inputs:
        return
    for key in OUTPUT_OPTIONS:
        out = options.get(key)
        if isinstance(out, (str, Path)) and str(out):
            check_output(out, list(inputs), f"--{key}")
    frames = options.get("frames")
    if isinstance(frames, (str, Path)) and str(frames):
        for p in inputs:
            try:
                inside = Path(frames).is_dir() and os.path.samefile(p.parent, frames)
            except (OSError, ValueError):
                inside = False
            if inside and FRAME_NAME.match(p.name):
                raise InputError(f"refusing to write frames over the input file {p}",
                                 key="--frames")


def read_bytes(path: str | Path, *, limit: int = MAX_FILE_BYTES) -> bytes:
    """The bytes of a regular file of at most ``limit`` bytes (see :func:`check_file`)."""
    p = check_file(path, limit=limit)
    try:
        fd = os.open(p, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(fd, "rb") as fh:
            data = fh.read(limit + 1)
    except OSError as exc:
        raise InputError(f"cannot read the file ({exc.strerror or exc})", file=str(p)) from None
    if len(data) > limit:  # it grew while we read it
        raise InputError(f"file too large (graphkin reads files up to "
                         f"{limit / 1024 / 1024:.0f} MB)", file=str(p))
    return data


def read_text(path: str | Path, *, limit: int = MAX_FILE_BYTES) -> str:
    """The UTF-8 text of a regular file of at most ``limit`` bytes.

    Raises
    ------
    InputError
        As :func:`check_file`, or the file is not UTF-8 text.
    """
    data = read_bytes(path, limit=limit)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise InputError("the file is not UTF-8 text", file=str(path)) from None


def parse_toml(text: str, source: str) -> dict[str, Any]:
    """Parse TOML text; every failure becomes one :class:`InputError` naming ``source``.

    Examples
    --------
    >>> parse_toml("a = 1", "f.toml")
    {'a': 1}
    >>> parse_toml("a = " + "[" * 2000, "f.toml")
    Traceback (most recent call last):
    ...
    graphkin.errors.InputError: arrays or tables nested too deep (more than 64 levels)
    """
    depth = _max_depth(text)
    if depth > MAX_TOML_DEPTH:
        raise InputError(f"arrays or tables nested too deep (more than {MAX_TOML_DEPTH} "
                         "levels)", file=source)
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"not valid TOML (TOML syntax error): {' '.join(str(exc).split())}"
                         f"{quote_hint(text, exc)}", file=source) from None
    except (ValueError, RecursionError, OverflowError, MemoryError) as exc:
        # ValueError: an integer of more than 4300 digits (sys.int_info)
        raise InputError(f"cannot read the TOML: {' '.join(str(exc).split())[:200]}",
                         file=source) from None


def load_toml(path: str | Path) -> dict[str, Any]:
    """Read and parse a TOML file with the bounds of :func:`read_text` and :func:`parse_toml`."""
    return parse_toml(read_text(path), str(path))


def _max_depth(text: str) -> int:
    """An upper bound of the nesting of brackets and braces outside strings and comments.

    Quotes are followed roughly (basic, literal and multi-line strings); the
    bound only has to be exact for files that tomllib would accept.
    """
    depth = best = 0
    i, n = 0, len(text)
    quote = ""
    while i < n:
        c = text[i]
        if quote:
            if c == "\\" and quote in ('"', '"""'):
                i += 2
                continue
            if text.startswith(quote, i):
                i += len(quote)
                quote = ""
                continue
            i += 1
            continue
        if c in "\"'":
            quote = c * 3 if text.startswith(c * 3, i) else c
            i += len(quote)
            continue
        if c == "#":
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if c in "[{":
            depth += 1
            best = max(best, depth)
        elif c in "]}":
            depth = max(0, depth - 1)
        i += 1
    return best


_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")
_KEY_LINE = re.compile(r"^\s*([^=\s\"'\[#][^=\"]*?)\s*=")


def quote_hint(text: str, exc: tomllib.TOMLDecodeError) -> str:
    """A hint when the line TOML refused starts with a key that must be quoted.

    The book's names are not TOML's bare keys (letters, digits, ``_`` and
    ``-``): ``ω3 = ...`` or ``A_A^c = ...`` must be written ``"ω3" = ...``.

    >>> try:
    ...     tomllib.loads('ω3 = 5')
    ... except tomllib.TOMLDecodeError as e:
    ...     print(quote_hint('ω3 = 5', e))
     (quote a key that has characters other than letters, digits, _ and -: "ω3" = ...)
    """
    at = re.search(r"at line (\d+)", str(exc))   # tomllib's message (lineno: Python 3.14)
    lineno = int(at.group(1)) if at else 0
    lines = text.splitlines()
    if not 1 <= lineno <= len(lines):
        return ""
    m = _KEY_LINE.match(lines[lineno - 1])
    if m is None:
        return ""
    key = m.group(1).strip()
    parts = [k.strip() for k in key.split(".")]
    if all(_BARE_KEY.fullmatch(k) for k in parts):
        return ""
    return (" (quote a key that has characters other than letters, digits, _ and -: "
            f"\"{key}\" = ...)")
