"""Writing output files whole or not at all."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path


def read_input(path: str, what: str = "the input") -> tuple[bytes | None, str | None]:
    """(the bytes, None), or (None, why they cannot be read); '-' is standard input."""
    try:
        if path == "-":
            import sys

            return sys.stdin.buffer.read(), None
        return Path(path).read_bytes(), None
    except IsADirectoryError:
        return None, f"cannot read {what}: it is a directory"
    except FileNotFoundError:
        return None, f"cannot read {what}: no such file"
    except OSError as error:
        return None, f"cannot read {what}: {error.strerror or error}"


class OutputError(Exception):
    """An output cannot be written (a missing folder, no permission, a full disk)."""

    def __init__(self, path, error: OSError):
        super().__init__(f"cannot write {path}: {error.strerror or error}")
        self.path = path


def ensure_folder(path: str | os.PathLike) -> Path:
    """The folder, created if missing; OutputError if that cannot be."""
    folder = Path(path)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise OutputError(folder, error) from None
    return folder


def write_atomic(path: str | os.PathLike, data: str | bytes) -> None:
    """Write to a temporary file beside `path`, then rename it into place (OutputError
    when that cannot be done; nothing half-written is left)."""
    try:
        _write_atomic(path, data)
    except OSError as error:
        raise OutputError(path, error) from None


def _write_atomic(path, data) -> None:
    target = Path(path)
    payload = data.encode("utf-8") if isinstance(data, str) else data
    descriptor, temporary = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent or ".")
    try:
        with os.fdopen(descriptor, "wb") as handle:
            handle.write(payload)
            handle.flush()
            os.fsync(handle.fileno())
        if target.exists():
            os.chmod(temporary, target.stat().st_mode & 0o777)
        else:
            os.chmod(temporary, 0o644)
        os.replace(temporary, target)
    except BaseException:
        try:
            os.unlink(temporary)
        except FileNotFoundError:
            pass
        raise
