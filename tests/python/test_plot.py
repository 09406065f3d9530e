"""curvebench.plot: the edges drawn in the run pictures' colours, checked on the Axes."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.colors  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

import curvebench  # noqa: E402


def segments_by_colour(ax):
    drawn = {}
    for collection in ax.collections:
        if isinstance(collection, LineCollection):
            colour = matplotlib.colors.to_hex(collection.get_colors()[0])
            drawn[colour] = drawn.get(colour, 0) + len(collection.get_segments())
    return drawn


def test_found_wrong_and_missing_edges_get_their_colours():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    truth = [(0, 1), (1, 2), (2, 3), (0, 3)]
    found = [(0, 1), (1, 2), (0, 2)]  # two right, one wrong; two missing
    ax = curvebench.plot(square, found, truth=truth, title="square")
    assert segments_by_colour(ax) == {"#1f4e99": 2, "#e00000": 1, "#ff9900": 2}
    assert ax.get_title() == "square" and len(ax.collections[-1].get_offsets()) == 4
    plain = curvebench.plot(square, truth)
    assert segments_by_colour(plain) == {"#1f4e99": 4}


def test_bad_edges_raise_value_error():
    with pytest.raises(ValueError, match="indices below 2"):
        curvebench.plot([[0, 0], [1, 1]], [[0, 2]])
