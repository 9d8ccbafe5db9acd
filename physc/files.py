"""Writing output files whole or not at all."""

from __future__ import annotations

import errno
import json
import os
import re
import stat
import tempfile
from pathlib import Path


def read_input(path: str, what: str = "the input", limit: int | None = None) -> tuple[bytes | None, str | None]:
    """(the bytes, None), or (None, why they cannot be read); '-' is standard input. With a
    `limit`, at most that many bytes are read (a caller that gets `limit` bytes knows the
    input is at least that large, without holding a file of any size in memory)."""
    try:
        if path == "-":
            import sys

            return sys.stdin.buffer.read(-1 if limit is None else limit), None
        with open(path, "rb") as handle:
            return handle.read(-1 if limit is None else limit), None
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


def read_json_lines(path: Path) -> list:
    """The values of a JSON Lines file, in order; a line that does not parse (the torn last line
    of a killed writer) is skipped; none when the file is missing."""
    if not path.exists():
        return []
    found = []
    for line in path.read_text(encoding="utf-8").splitlines():
        try:
            found.append(json.loads(line))
        except json.JSONDecodeError:
            continue
    return found


def ensure_folder(path: str | os.PathLike) -> Path:
    """The folder, created if missing; OutputError if that cannot be."""
    folder = Path(path)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise OutputError(folder, error) from None
    return folder


# Paths that name one of this process's open descriptors: written to that descriptor,
# where it is (`-o /dev/stdout >> log` appends; a rename would replace the log).
_DESCRIPTOR = re.compile(r"^/(?:dev/fd|proc/self/fd|proc/(\d+)/fd)/(\d+)$")
_STANDARD = {"/dev/stdin": 0, "/dev/stdout": 1, "/dev/stderr": 2}


def _descriptor(path) -> int | None:
    text = os.fspath(path)
    if text in _STANDARD:
        return _STANDARD[text]
    match = _DESCRIPTOR.match(text)
    if match is None or (match.group(1) is not None and int(match.group(1)) != os.getpid()):
        return None
    return int(match.group(2))


def _in_place(target: Path) -> bool:
    """Whether `target` (resolved) is written where it is: an existing device, FIFO or
    socket. OSError for something that exists and is neither that, a file nor a folder."""
    if not target.exists() or target.is_file() or target.is_dir():
        return False
    mode = target.stat().st_mode
    if stat.S_ISCHR(mode) or stat.S_ISFIFO(mode) or stat.S_ISSOCK(mode):
        return True
    raise OSError(errno.EINVAL, "it is neither a file nor a device or FIFO")


def check_output(path: str | os.PathLike, folder: bool = False) -> None:
    """Fail now, before any work, if `path` cannot be written (OutputError): a missing
    or unwritable folder, a directory where a file is wanted (or the reverse), something
    that is neither a file nor a device or FIFO to write to. A path that does not exist
    yet is fine where its folder takes new files."""
    try:
        _check_output(path, folder)
    except OSError as error:  # a name too long, a folder we may not look into
        raise OutputError(path, error) from None


def _check_output(path, folder: bool) -> None:
    if not folder and _descriptor(path) is not None:
        return  # written where it is; an error then is the writer's to report
    target = Path(os.path.realpath(path))  # a symlink is written through
    if folder:
        if target.exists() and not target.is_dir():
            raise NotADirectoryError(errno.ENOTDIR, "it is not a folder")
        parent = target
        while not parent.exists():
            parent = parent.parent
        _check_folder(parent)
        return
    if target.is_dir():
        raise IsADirectoryError(errno.EISDIR, "it is a directory")
    if _in_place(target):
        if not os.access(target, os.W_OK):
            raise PermissionError(errno.EACCES, "Permission denied")
        return
    if not target.parent.is_dir():
        raise FileNotFoundError(errno.ENOENT, f"no folder {target.parent}")
    _check_folder(target.parent)
    if target.is_file():  # replaced at the end: an immutable file (chattr +i) refuses even root, so try it now
        try:
            os.close(os.open(target, os.O_WRONLY))
        except PermissionError as error:
            if error.errno != errno.EPERM:  # EACCES: a read-only file in a folder we may write is replaced all the same
                return
            raise


def _check_folder(folder: Path) -> None:
    """Whether a file can be made in `folder` (tried: permissions alone say nothing to root
    on a read-only file system)."""
    descriptor, temporary = tempfile.mkstemp(prefix=".physc-check.", dir=folder)
    os.close(descriptor)
    os.unlink(temporary)


def write_atomic(path: str | os.PathLike, data: str | bytes) -> None:
    """Write `data` to `path` whole or not at all (OutputError when that cannot be done):
    a regular file by a temporary file beside it renamed into place; through a symlink to
    its target; a device, FIFO or one of our own descriptors (`/dev/stdout`) in place,
    never replaced."""
    payload = data.encode("utf-8") if isinstance(data, str) else data
    try:
        descriptor = _descriptor(path)
        if descriptor is not None:
            view = memoryview(payload)
            while view:
                view = view[os.write(descriptor, view) :]
            return
        target = Path(os.path.realpath(path))
        if _in_place(target):
            with open(target, "wb") as handle:
                handle.write(payload)
            return
        _write_atomic(target, payload)
    except OSError as error:
        raise OutputError(path, error) from None


def _write_atomic(target: Path, payload: bytes) -> None:
    descriptor, temporary = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent or ".")
    try:
        with os.fdopen(descriptor, "wb") as handle:
            handle.write(payload)
            handle.flush()
            os.fsync(handle.fileno())
        if target.exists():
            os.chmod(temporary, target.stat().st_mode & 0o777)
        else:
            os.chmod(temporary, 0o666 & ~_umask())  # as open() would have made it
        os.replace(temporary, target)
    except BaseException:
        try:
            os.unlink(temporary)
        except FileNotFoundError:
            pass
        raise


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
