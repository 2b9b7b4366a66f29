"""A simulated arm's record of true joint angles: one sample per step, in bounded memory."""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .._files import check_output_path, write_atomic

F64 = NDArray[np.float64]
_FIRST_ROWS = 4096  # the buffer starts this small and doubles up to its capacity


@dataclass(frozen=True)
class Recording:
    """True joint angles sampled once per simulation step.

    Attributes:
        joint_names: the joints, in model order.
        t: sample times [s], shape (N,), increasing.
        q: true joint angles [rad], shape (N, dof).
    """

    joint_names: tuple[str, ...]
    t: F64
    q: F64

    def between(self, t0: float, t1: float) -> Recording:
        """The samples with t0 <= t <= t1 [s]."""
        keep = (self.t >= t0 - 1e-9) & (self.t <= t1 + 1e-9)
        return Recording(self.joint_names, self.t[keep], self.q[keep])

    def write_csv(self, path: str | Path) -> int:
        """Write ``t_s,<joint>_deg,...`` and one row per sample; returns the row count.
        The path is checked first (``armkit._files.check_output_path``) and the file is
        written atomically: a reader sees the old file or the whole new one.

        Raises:
            InputError: the file cannot be written there (no such folder, a directory,
                read-only, ...); the message says why and what to do, nothing is written.
        """
        out = check_output_path(path)
        header = ",".join(["t_s", *(f"{n}_deg" for n in self.joint_names)])
        table = np.column_stack([self.t, np.degrees(self.q)])
        text = io.StringIO()
        np.savetxt(text, table, fmt="%.6f", delimiter=",", header=header, comments="")
        write_atomic(out, text.getvalue(), durable=False)
        return int(table.shape[0])


class Recorder:
    """A ring buffer of (t, q) samples holding at most ``capacity`` rows (the oldest go)."""

    def __init__(self, joint_names: tuple[str, ...], capacity: int) -> None:
        self.joint_names, self.capacity = joint_names, max(2, capacity)
        rows = min(self.capacity, _FIRST_ROWS)
        self._t = np.zeros(rows)
        self._q = np.zeros((rows, len(joint_names)))
        self._count = 0  # samples ever added

    def add(self, t: float, q: F64) -> None:
        """Append the sample at time ``t`` [s], angles ``q`` [rad], shape (dof,)."""
        rows = self._t.shape[0]
        if self._count == rows and rows < self.capacity:
            self._grow(min(self.capacity, 2 * rows))
            rows = self._t.shape[0]
        i = self._count % rows
        self._t[i] = t
        self._q[i] = q
        self._count += 1

    def add_many(self, t: F64, q: F64) -> None:
        """Append the samples at times ``t`` [s], shape (N,), angles ``q`` [rad], shape
        (N, dof) (as N calls of ``add``, at once)."""
        if len(t) >= self.capacity:  # the buffer fills with these samples alone
            self._t, self._q = t[-self.capacity :].copy(), q[-self.capacity :].copy()
            self._count = self.capacity
            return
        self._put(t, q)

    def last(self, count: int) -> F64:
        """The last ``count`` samples' angles [rad], shape (count, dof), oldest first
        (``count`` at most the samples kept)."""
        rows = self._t.shape[0]
        at = (self._count - count + np.arange(count)) % rows
        return self._q[at]

    def hold(self, t: float, dt: float, count: int, q: F64) -> None:
        """Append ``count`` samples at times ``t``, ``t + dt``, ... [s], all at angles ``q``
        [rad], shape (dof,) (as ``count`` calls of ``add``, at once)."""
        if count <= 0:
            return
        if count >= self.capacity:  # the buffer fills with these samples alone
            rows, first = self.capacity, t + (count - self.capacity) * dt
            self._t = first + dt * np.arange(rows, dtype=np.float64)
            self._q = np.tile(np.asarray(q, dtype=np.float64), (rows, 1))
            self._count = rows
            return
        self._put(t + dt * np.arange(count, dtype=np.float64), q)

    def _put(self, t: F64, q: F64) -> None:
        """Append samples at times ``t`` [s], shape (N,) (N below the capacity), angles
        ``q`` [rad], shape (N, dof) or (dof,) for all."""
        count, rows = len(t), self._t.shape[0]
        need = min(self.capacity, self._count + count)
        if self._count <= rows < need:
            self._grow(min(self.capacity, max(2 * rows, need)))
            rows = self._t.shape[0]
        first = self._count % rows
        if first + count <= rows:  # no wrap: one slice
            self._t[first : first + count] = t
            self._q[first : first + count] = q
        else:
            at = (self._count + np.arange(count)) % rows
            self._t[at] = t
            self._q[at] = q
        self._count += count

    def _grow(self, rows: int) -> None:
        t, q = np.zeros(rows), np.zeros((rows, self._q.shape[1]))
        n = min(self._count, self._t.shape[0])
        t[:n], q[:n] = self._t[:n], self._q[:n]
        self._t, self._q = t, q

    def recording(self) -> Recording:
        """The samples kept, oldest first (copies)."""
        rows = self._t.shape[0]
        if self._count <= rows:
            t, q = self._t[: self._count].copy(), self._q[: self._count].copy()
        else:
            order = np.roll(np.arange(rows), -(self._count % rows))
            t, q = self._t[order], self._q[order]
        return Recording(self.joint_names, t, q)
