"""Where an atlas's results go as the chunks finish: memory, or a Zarr checkpoint that survives a restart.

The checkpoint is a Zarr group holding the flattened grid: one float64 array per output,
the reasons as codes into a table of texts (code 0, text ``""``: the point has a value; the
table, which only grows, in the group's attributes), one ``done`` flag and one checksum per
chunk. A chunk's values, reasons and checksum are written before its flag, so a sweep
killed in the middle of a write recomputes that chunk and nothing else; a chunk whose
stored data no longer match its checksum (a lost or damaged file) is recomputed too, and
named in the result (``chunks_recomputed``).

A checkpoint is identified by what it computes, not by names: the scene's equations and
its derived fast subsystem, the quantity and every option (a user function by its code,
constants, closure and the globals it reads), the fixed values, the grid and the chunk
size (:func:`fingerprint`). Another sweep is refused with the part that differs named.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np

from .grid import MAX_REASONS, AtlasError, Grid
from .kernel import Reasons, code_type
from .options import content_token

__all__ = ["MemoryResults", "ZarrResults", "fingerprint", "scene_token"]

_FORMAT = "contactsym-atlas/3"

#: What each part of a fingerprint stands for, in the message that refuses a checkpoint.
_PARTS = {
    "scene": "the scene (its equations, contacts, laws or derived fast subsystem)",
    "quantity": "the quantity or its options (a function's code, constants or closure)",
    "values": "the fixed values",
    "grid": "the grid",
    "chunk": "the chunk size",
}


def _hash(text: str | bytes) -> str:
    return hashlib.sha256(text if isinstance(text, bytes) else text.encode()).hexdigest()


def scene_token(scene) -> str:
    """The scene's content: accelerations, contacts with their laws, options, and the derived fast subsystem."""
    from .. import __version__  # the package itself: importing it at the top would be circular

    contacts = [(c.coordinate, c.reaction, _law(c.compliance), _law(c.friction), c.unilateral) for c in scene.contacts]
    parts = (__version__, scene.accelerations, contacts, getattr(scene, "eps", None), scene.fast_subsystem().equations)
    return content_token(parts)


def _law(law) -> str:
    return "None" if law is None else f"{type(law).__qualname__}{content_token(getattr(law, '__dict__', repr(law)))}"


def fingerprint(scene, quantity, values, grid: Grid, chunk: int) -> dict:
    """The identity of a sweep, part by part (hex digests): see the module docstring."""
    return {
        "scene": _hash(scene_token(scene)),
        "quantity": _hash(content_token((quantity.name, quantity.builder, quantity.options))),
        "values": _hash(content_token(dict(values or {}))),
        "grid": _hash(grid.token()),
        "chunk": str(int(chunk)),
    }


def _checksum(values: np.ndarray, codes: np.ndarray, table: list[str]) -> str:
    """The chunk's values, its codes and the texts they stand for (the table only grows: the texts stay)."""
    used = [table[int(c)] for c in np.unique(codes)]
    data = np.ascontiguousarray(values, dtype=float).tobytes() + np.asarray(codes, dtype=np.uint32).tobytes()
    return _hash(data + "\x00".join(used).encode())


class _Table:
    """The sweep's reason table: texts by code (0: ``""``), at most MAX_REASONS + 1 of them."""

    FULL = f"more than {MAX_REASONS} distinct reasons in this sweep; this point's was not kept"

    def __init__(self, texts=("",)):
        self.texts = list(texts)
        self.codes = {text: code for code, text in enumerate(self.texts)}

    def mapping(self, reasons: Reasons) -> np.ndarray:
        """Codes of this table for the codes of ``reasons`` (new texts are added)."""
        out = np.empty(len(reasons.table), dtype=np.uint32)
        for local, text in enumerate(reasons.table):
            code = self.codes.get(text)
            if code is None:
                if len(self.texts) >= MAX_REASONS:  # room for one more: the entry that says so
                    text = self.FULL
                    code = self.codes.get(text)
                if code is None:
                    code = self.codes[text] = len(self.texts)
                    self.texts.append(text)
            out[local] = code
        return out


class MemoryResults:
    """The results of a sweep without a checkpoint: values, and reasons as codes into one table."""

    repaired: tuple = ()

    def __init__(self, size: int, outputs: tuple, chunk: int):
        self.chunk = chunk
        # one contiguous row per output (the Dataset's arrays), NaN only where no chunk was written (read): a
        # NaN fill first would touch every page twice
        self.values = np.empty((len(outputs), size))
        self.codes = np.zeros(size, dtype=np.uint8)
        self.table = _Table()
        self.done = np.zeros(-(-size // chunk), dtype=bool)

    def write(self, index: int, values: np.ndarray, reasons: Reasons) -> None:
        start = index * self.chunk
        stop = start + len(values)
        self.values[:, start:stop] = values.T
        if len(reasons.table) == 1:  # no reasons in the chunk (the usual case): no lookup
            self.codes[start:stop] = 0
        else:
            mapped = self.table.mapping(reasons)[reasons.codes]
            wide = code_type(len(self.table.texts))
            if wide.itemsize > self.codes.itemsize:  # the table outgrew the codes: widen them, once
                self.codes = self.codes.astype(wide)
            self.codes[start:stop] = mapped
        self.done[index] = True

    def read(self) -> tuple[np.ndarray, Reasons]:
        for index in np.flatnonzero(~self.done):
            self.values[:, index * self.chunk : (index + 1) * self.chunk] = np.nan
        return self.values.T, Reasons(self.codes, list(self.table.texts))


class ZarrResults:
    """A Zarr checkpoint: opened (and checked, chunk by chunk) if it exists, created otherwise."""

    def __init__(self, path, size: int, outputs: tuple, chunk: int, token: dict):
        import zarr  # optional (contactsym[atlas]): only a checkpointed sweep needs it; Zarr 2 and 3 both work

        self.path, self.outputs, self.chunk, self.size = Path(path), outputs, chunk, size
        n_chunks = -(-size // chunk)
        if self.path.exists():
            try:
                self.group = zarr.open_group(str(self.path), mode="r+")
            except Exception as error:  # noqa: BLE001 - any unreadable store gets the same advice
                raise AtlasError(
                    f"{self.path} exists and is not an atlas checkpoint ({type(error).__name__}); choose another path."
                ) from None
            self._check(dict(self.group.attrs), token)
            self.done = self._verified(n_chunks)
        else:
            self.group = zarr.open_group(str(self.path), mode="w")
            for name in outputs:
                self.group.full(name=f"value_{name}", shape=(size,), chunks=(chunk,), dtype="f8", fill_value=np.nan)
            self.group.full(name="reason_code", shape=(size,), chunks=(chunk,), dtype="u4", fill_value=0)
            self.group.full(name="checksum", shape=(n_chunks,), chunks=(1,), dtype=str, fill_value="")
            self.group.full(name="done", shape=(n_chunks,), chunks=(1,), dtype=bool, fill_value=False)
            self.group.attrs.update(
                {"format": _FORMAT, "fingerprint": token, "outputs": list(outputs), "reasons": [""]}
            )
            self.done, self.repaired = np.zeros(n_chunks, dtype=bool), ()
        self.table = _Table(self._stored_table())

    def _stored_table(self) -> list[str]:
        texts = self.group.attrs.get("reasons")
        ok = isinstance(texts, list) and texts[:1] == [""] and all(isinstance(t, str) for t in texts)
        return texts if ok else [""]  # a damaged table: the chunks that use it fail their checksums

    def _check(self, attrs: dict, token: dict) -> None:
        if attrs.get("format") != _FORMAT or not isinstance(attrs.get("fingerprint"), dict):
            raise AtlasError(
                f"{self.path} is not a checkpoint of this version of contactsym ({attrs.get('format')!r}); "
                "choose another path, or remove it yourself if it is no longer needed."
            )
        differ = [part for part in _PARTS if attrs["fingerprint"].get(part) != token[part]]
        if differ:
            raise AtlasError(
                f"the checkpoint {self.path} holds a different sweep: {'; '.join(_PARTS[p] for p in differ)} "
                "differ; resume it with the same arguments, or choose another path (nothing was changed)."
            )

    def _verified(self, n_chunks: int) -> np.ndarray:
        """The done flags, with every chunk whose data fail their checksum (or cannot be read) set back to undone."""
        try:
            done = np.asarray(self.group["done"][:], dtype=bool)
            sums = [str(text) for text in self.group["checksum"][:].tolist()]
        except Exception:  # noqa: BLE001 - a damaged index: every chunk is computed again
            done, sums = np.zeros(n_chunks, dtype=bool), [""] * n_chunks
        table = self._stored_table()
        repaired = []
        for index in np.nonzero(done)[0]:
            start, stop = index * self.chunk, min((index + 1) * self.chunk, self.size)
            try:
                values = np.column_stack([self.group[f"value_{name}"][start:stop] for name in self.outputs])
                codes = np.asarray(self.group["reason_code"][start:stop])
                good = int(codes.max(initial=0)) < len(table) and _checksum(values, codes, table) == sums[index]
            except Exception:  # noqa: BLE001 - an unreadable chunk file is recomputed like a lost one
                good = False
            if not good:
                done[index] = False
                repaired.append(int(index))
        self.repaired = tuple(repaired)
        return done

    def write(self, index: int, values: np.ndarray, reasons: Reasons) -> None:
        start = index * self.chunk
        stop = start + len(values)
        known = len(self.table.texts)
        codes = self.table.mapping(reasons)[reasons.codes]
        if len(self.table.texts) > known:  # new texts are stored before any code that refers to them
            self.group.attrs["reasons"] = list(self.table.texts)
        for j, name in enumerate(self.outputs):
            self.group[f"value_{name}"][start:stop] = values[:, j]
        self.group["reason_code"][start:stop] = codes
        self.group["checksum"][index : index + 1] = np.asarray([_checksum(values, codes, self.table.texts)], dtype=str)
        self.group["done"][index : index + 1] = True  # last: the chunk counts only once it is all there
        self.done[index] = True

    def read(self) -> tuple[np.ndarray, Reasons]:
        values = np.column_stack([self.group[f"value_{name}"][:] for name in self.outputs])
        return values, Reasons(np.asarray(self.group["reason_code"][:]), list(self.table.texts))
