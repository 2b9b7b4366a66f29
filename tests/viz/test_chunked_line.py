"""A growing line shown in chunks (viz/_chunked.py): each point added re-sends only the
newest chunk, the chunks together are the line (continuous, every point once, in
order), and a kept line drops whole chunks once all their points are gone."""

from __future__ import annotations

import numpy as np
import pytest

from armkit.viz._chunked import CHUNK, ChunkedLine


@pytest.mark.parametrize("keep", [None, CHUNK + 1, 100, 600])
def test_the_chunks_shown_are_the_line_kept(keep: int | None) -> None:
    rng = np.random.default_rng(28)
    line = ChunkedLine("/l", (1, 2, 3), 2.0, keep)
    shown: dict[str, np.ndarray] = {}
    points = rng.normal(size=(700, 3))
    for k, p in enumerate(points):
        node, removed = line.add(p)
        for name in removed:
            del shown[name]
        if node is not None:
            assert len(node.points) <= CHUNK + 1  # a frame sends one chunk, not the line
            shown[node.name] = node.points
        assert list(shown) == [f"/l/{j}" for j in line.nodes]
        if k == 0:
            assert node is None and not shown
            continue
        kept = points[max(0, k + 1 - keep) if keep else 0 : k + 1]
        joined = [c if i == 0 else c[1:] for i, c in enumerate(shown.values())]  # shared ends
        whole = np.concatenate(joined)
        assert len(kept) <= len(whole) <= len(kept) + CHUNK  # at most one chunk more
        np.testing.assert_array_equal(whole[-len(kept) :], kept)
    assert line.clear() == list(shown)
    assert line.points == [] and line.nodes == []


def test_a_line_keeping_less_than_a_chunk_is_refused() -> None:
    with pytest.raises(ValueError, match="more than"):
        ChunkedLine("/l", (0, 0, 0), 1.0, CHUNK)
