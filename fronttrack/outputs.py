"""Output files of the command line: checked before a solve, written whole or not at all.

A run may take minutes, so every output path is checked before it starts
(``check_output_dir``, ``check_output_file``): a directory that is a file or a
dangling link, a directory no file can be created in, a JSON path that is a
directory, a device or the scene file itself are refused with one line naming the
option.  The files are then written under temporary names beside their final
places (``OutputSet``) and renamed into place together once all are complete, with
Ctrl-C held back for the few renames: an interrupted or failed run leaves the
previous run's files as they were, never a mixture, and no temporary file.
"""

from __future__ import annotations

import os
import secrets
import shutil
import signal
import tempfile
import threading
from contextlib import contextmanager
from pathlib import Path

from materials import WavediagramError

IMAGE_FORMATS = ("png", "pdf", "svg")
"""Figure file formats (``wavediagram run --format``); PDF and SVG are vector."""


class OutputError(WavediagramError):
    """An output path cannot be written; the message names the option and the path."""


def check_output_dir(path: Path, option: str) -> None:
    """Raise ``OutputError`` unless files can be created in directory ``path`` (which
    may not exist yet: then in its nearest existing ancestor)."""
    if path.is_symlink() and not path.exists():
        raise OutputError(f"{option}: {path} is a link to {os.readlink(path)}, which does "
                          f"not exist")
    if path.exists() and not path.is_dir():
        raise OutputError(f"{option}: {path} exists and is not a directory")
    _check_writable(_nearest_existing(path), option)


def check_output_file(path: Path, option: str, inputs: tuple[Path, ...] = ()) -> None:
    """Raise ``OutputError`` unless ``path`` can be (re)written as a regular file that is
    none of ``inputs``."""
    target = Path(os.path.realpath(path))
    if target.is_dir():
        raise OutputError(f"{option}: {path} is a directory; name a file")
    if target.exists() and not target.is_file():
        raise OutputError(f"{option}: {path} is not a regular file (a device or a pipe)")
    for source in inputs:
        if target == Path(os.path.realpath(source)):
            raise OutputError(f"{option}: {path} is the scene file itself; name another file")
    if not target.parent.exists():
        check_output_dir(target.parent, option)
    elif not target.parent.is_dir():
        raise OutputError(f"{option}: {target.parent} is not a directory")
    else:
        _check_writable(target.parent, option)


def _nearest_existing(path: Path) -> Path:
    """``path`` or its nearest ancestor that exists."""
    path = Path(os.path.abspath(path))
    while not path.exists():
        path = path.parent
    return path


def _check_writable(directory: Path, option: str) -> None:
    """Create and remove a file in ``directory`` (the only test that holds for every user
    and file system); raise ``OutputError`` if it cannot be done."""
    if not directory.is_dir():
        raise OutputError(f"{option}: {directory} is not a directory")
    try:
        fd, name = tempfile.mkstemp(dir=directory, prefix=".wavediagram-check-")
    except OSError as exc:
        raise OutputError(f"{option}: cannot create files in {directory} "
                          f"({exc.strerror})") from None
    os.close(fd)
    os.unlink(name)


class OutputSet:
    """Files written under temporary names and renamed into place together.

    Use as a context manager: ``temporary(final)`` gives a temporary path in the
    directory of ``final``; ``staging_dir(directory)`` a temporary directory whose
    files all go into ``directory``; ``commit()`` renames everything into place and
    returns the final paths.  Leaving the block without ``commit()`` (an error,
    Ctrl-C) removes every temporary file.
    """

    def __init__(self):
        self._pending: list[tuple[Path, Path]] = []
        self._stages: list[tuple[Path, Path]] = []

    def __enter__(self) -> OutputSet:
        return self

    def __exit__(self, *exc) -> None:
        for temporary, _ in self._pending:
            temporary.unlink(missing_ok=True)
        for stage, _ in self._stages:
            shutil.rmtree(stage, ignore_errors=True)

    def temporary(self, final: Path) -> Path:
        """A new empty temporary file beside ``final`` that ``commit`` renames to it (to
        the file it links to, if ``final`` is a symbolic link)."""
        if final.is_symlink():
            final = Path(os.path.realpath(final))
        final.parent.mkdir(parents=True, exist_ok=True)
        while True:
            temporary = final.parent / f".{final.name}.{secrets.token_hex(4)}.part"
            try:  # created as open() would (mode 0o666 less the umask), unlike mkstemp
                os.close(os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666))
            except FileExistsError:
                continue
            self._pending.append((temporary, final))
            return temporary

    def staging_dir(self, directory: Path) -> Path:
        """A new temporary directory inside ``directory``; ``commit`` moves its files up."""
        directory.mkdir(parents=True, exist_ok=True)
        stage = Path(tempfile.mkdtemp(dir=directory, prefix=".wavediagram-"))
        self._stages.append((stage, directory))
        return stage

    def commit(self) -> list[Path]:
        """Rename every file into place (Ctrl-C held back meanwhile); the final paths."""
        moves = list(self._pending)
        for stage, directory in self._stages:
            moves += [(path, directory / path.name) for path in sorted(stage.iterdir())]
        with _interrupts_deferred():
            for temporary, final in moves:
                os.replace(temporary, final)
            self._pending.clear()
        return [final for _, final in moves]


@contextmanager
def _interrupts_deferred():
    """Hold SIGINT back inside the block and raise ``KeyboardInterrupt`` after it."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught = []
    previous = signal.signal(signal.SIGINT, lambda *_: caught.append(True))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
    if caught:
        raise KeyboardInterrupt
