"""The error of a bad scene field, and restating it at the field's place in a scene.

Every scene class validates itself when it is built and raises ``SceneError``
with a message that starts with the field's path (``layer.thickness: must be > 0
m, got -0.001``).  A class does not know where it sits in a scene, so the code
that places it (a scene file's third layer, a sweep's parameter) restates the
path with ``located``: ``layer.thickness`` becomes ``layer[2].thickness``.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

from materials import WavediagramError


class SceneError(WavediagramError, ValueError):
    """A scene field is missing or outside its allowed range; the message names the field."""


@contextmanager
def located(prefix: str, path: str) -> Iterator[None]:
    """Restate a ``SceneError`` about ``prefix`` or ``prefix.*`` as about ``path``.

    ``with located("layer", "layer[2]"): Layer(...)`` turns the message
    ``layer.thickness: ...`` into ``layer[2].thickness: ...``; other errors pass.
    """
    try:
        yield
    except SceneError as error:
        message = str(error)
        if message.startswith((f"{prefix}.", f"{prefix}:")):
            raise SceneError(path + message[len(prefix):]) from None
        raise
