"""Where an atlas's results go as the chunks finish: memory, or a Zarr checkpoint that survives a restart.

The checkpoint is a Zarr group holding the flattened grid: one float64 array per output,
the reasons (text, empty where the point has a value) and one ``done`` flag per chunk. A
chunk's values and reasons are written before its flag, so a sweep killed in the middle
of a write recomputes that chunk and nothing else. The group's ``fingerprint`` (scene,
quantity, fixed values, grid, chunk size) keeps a store from being resumed by a different
sweep.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np

from .grid import AtlasError, Grid

__all__ = ["MemoryResults", "ZarrResults", "fingerprint"]

_FORMAT = "contactsym-atlas/1"


def fingerprint(scene_name: str, quantity_key: str, values, grid: Grid, chunk: int) -> str:
    fixed = sorted((str(k), repr(v)) for k, v in dict(values or {}).items())
    text = repr((scene_name, quantity_key, fixed, chunk)).encode() + grid.token()
    return hashlib.sha256(text).hexdigest()


class MemoryResults:
    """The results of a sweep without a checkpoint."""

    def __init__(self, size: int, outputs: tuple, chunk: int):
        self.chunk = chunk
        self.values = np.full((size, len(outputs)), np.nan)
        self.reasons = np.full(size, "", dtype=object)
        self.done = np.zeros(-(-size // chunk), dtype=bool)

    def write(self, index: int, values: np.ndarray, reasons) -> None:
        start = index * self.chunk
        self.values[start : start + len(values)] = values
        self.reasons[start : start + len(values)] = reasons
        self.done[index] = True

    def read(self) -> tuple[np.ndarray, np.ndarray]:
        return self.values, self.reasons


class ZarrResults:
    """A Zarr checkpoint: opened (and checked) if it exists, created otherwise."""

    def __init__(self, path, size: int, outputs: tuple, chunk: int, token: str):
        import zarr  # optional (contactsym[atlas]): only a checkpointed sweep needs it; Zarr 2 and 3 both work

        self.path, self.outputs, self.chunk = Path(path), outputs, chunk
        n_chunks = -(-size // chunk)
        if self.path.exists():
            try:
                self.group = zarr.open_group(str(self.path), mode="r+")
            except Exception as error:  # noqa: BLE001 - any unreadable store gets the same advice
                raise AtlasError(
                    f"{self.path} exists and is not an atlas checkpoint ({error}); choose another path."
                ) from None
            found = self.group.attrs.get("fingerprint")
            if self.group.attrs.get("format") != _FORMAT or found != token:
                raise AtlasError(
                    f"the checkpoint {self.path} holds a different sweep (other scene, quantity, values, grid or "
                    "chunks); resume it with the same arguments, or choose another path."
                )
        else:
            self.group = zarr.open_group(str(self.path), mode="w")
            for name in outputs:
                self.group.full(name=f"value_{name}", shape=(size,), chunks=(chunk,), dtype="f8", fill_value=np.nan)
            self.group.full(name="reason", shape=(size,), chunks=(chunk,), dtype=str, fill_value="")
            self.group.full(name="done", shape=(n_chunks,), chunks=(1,), dtype=bool, fill_value=False)
            self.group.attrs.update({"format": _FORMAT, "fingerprint": token, "outputs": list(outputs)})
        self.done = np.asarray(self.group["done"][:], dtype=bool)

    def write(self, index: int, values: np.ndarray, reasons) -> None:
        start = index * self.chunk
        stop = start + len(values)
        for j, name in enumerate(self.outputs):
            self.group[f"value_{name}"][start:stop] = values[:, j]
        self.group["reason"][start:stop] = np.asarray(reasons, dtype=str)
        self.group["done"][index : index + 1] = True  # last: the chunk counts only once it is all there
        self.done[index] = True

    def read(self) -> tuple[np.ndarray, np.ndarray]:
        values = np.column_stack([self.group[f"value_{name}"][:] for name in self.outputs])
        return values, np.asarray(self.group["reason"][:], dtype=object)
