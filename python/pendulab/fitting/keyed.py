"""A refusal of a data file or a fit setting that names itself by a message key (issue 28): the lab's
page words it in its own language (``pendulab/server/messages.json`` has the key's English words with
``{placeholders}``; ``server.<key>`` of web/src/i18n/<lang>/refusals.ts), while the message stays the
English sentence the command line prints. Values are the numbers and names the words need, as strings or
numbers (SI units as the message states them: times in s, lengths in m)."""

from __future__ import annotations

from typing import Any

from .._core import InvalidInputError


class KeyedInputError(InvalidInputError):
    """:class:`pendulab.InvalidInputError` with ``key`` (``messages.json``) and ``values`` for its words."""

    def __init__(self, message: str, key: str, **values: Any) -> None:
        super().__init__(message)
        self.key = key
        self.values = {k: v if isinstance(v, int | float) else str(v) for k, v in values.items()}
