"""Pictures as bytes, for every domain: a matplotlib figure saved as PNG or SVG, the same
figure giving the same bytes (no timestamps; SVG's ids salted)."""

from __future__ import annotations

import io

import matplotlib
import matplotlib.pyplot as plt

matplotlib.use("Agg")  # pictures are drawn off-screen; pyplot resolves its backend lazily, so Agg it is

FORMATS = ("png", "svg")


def save(figure, fmt: str = "png") -> bytes:
    """The figure as PNG or SVG bytes, without timestamps (same figure, same bytes; SVG's
    clip-path and glyph ids are random unless salted). The figure is closed."""
    buffer = io.BytesIO()
    metadata = {"Software": None} if fmt == "png" else {"Date": None, "Creator": None}
    with plt.rc_context({"svg.hashsalt": "physc"}):
        figure.savefig(buffer, format=fmt, metadata=metadata)
    plt.close(figure)
    return buffer.getvalue()
